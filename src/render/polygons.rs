//! Polygonal geometry (IndexedFaceSet and the triangle/quad sets of clause 11) turned into
//! a triangle mesh: polygons triangulated (earcut, so concave ones come out right),
//! attributes bound per vertex or per face, normals generated when the node gives none
//! and the material needs them (flat, smooth, or by creaseAngle).

use super::draw_list::Primitive;
use super::mesh::LocalMesh;
use crate::limits::MAX_FACE_CORNERS;
use crate::model::faces::{Attribute as Kind, Binding, Polygonal};

/// An attribute: flat values, values per element, and which of the node's attributes it
/// is (model::faces binds it to the corners).
#[derive(Clone, Copy)]
pub struct Attribute<'a> {
    pub values: &'a [f32],
    pub arity: usize,
    pub kind: Kind,
    /// Bound by coordinate index (grid vertex), as coordinates are: vertices can be shared.
    pub by_coord: bool,
}

impl<'a> Attribute<'a> {
    pub fn of(geometry: &Polygonal, kind: Kind, values: &'a [f32], arity: usize) -> Self {
        Attribute {
            values,
            arity,
            kind,
            by_coord: geometry.binding(kind) == Binding::PerVertex { index: None },
        }
    }
}

#[derive(Clone, Copy, PartialEq)]
pub enum NormalGeneration {
    Flat,
    /// Averaged over every face sharing the coordinate index.
    Smooth,
    /// Averaged over the faces around the vertex within this angle (radians).
    Crease(f64),
}

const KINDS: [Kind; 3] = [Kind::Color, Kind::Normal, Kind::TexCoord];

fn slot(kind: Kind) -> usize {
    KINDS.iter().position(|&k| k == kind).unwrap_or(0)
}

/// The faces of a polygonal node (read by model::faces) whose corners all index existing
/// points, wound counterclockwise; each corner is its coordinate index and, for the
/// attributes not bound by coordinate, the element of that attribute it uses.
#[derive(Default)]
pub struct Faces {
    pub corner_coords: Vec<u32>,
    /// Per attribute (in [`KINDS`] order): the element each corner uses (u32::MAX: none).
    elements: [Vec<u32>; 3],
    /// Face k is corners `starts[k]..starts[k + 1]`.
    pub starts: Vec<usize>,
}

impl Faces {
    /// Faces with an index outside `0..point_count` are dropped, as are faces of fewer than
    /// three corners; `ccw FALSE` faces are reversed. `per_corner` lists the attributes
    /// whose elements are looked up per corner.
    pub fn of(geometry: &Polygonal, point_count: usize, per_corner: &[Kind]) -> Faces {
        let mut faces = Faces {
            starts: vec![0],
            ..Faces::default()
        };
        let coord = |position| {
            geometry
                .coord_index(position)
                .filter(|&c| c < point_count)
                .map(|c| c as u32)
        };
        for face in geometry.faces() {
            if face.len() < 3 || !face.corners().all(|p| coord(p).is_some()) {
                continue;
            }
            let start = faces.corner_coords.len();
            for position in face.corners() {
                faces.corner_coords.extend(coord(position));
                for &kind in per_corner {
                    let element = geometry.attribute_index(kind, &face, position);
                    faces.elements[slot(kind)].push(
                        element
                            .and_then(|e| u32::try_from(e).ok())
                            .unwrap_or(u32::MAX),
                    );
                }
            }
            let end = faces.corner_coords.len();
            if !geometry.ccw {
                faces.corner_coords[start..end].reverse();
                for &kind in per_corner {
                    faces.elements[slot(kind)][start..end].reverse();
                }
            }
            faces.starts.push(end);
        }
        faces
    }

    /// No faces yet: geometry not read by model::faces (Extrusion) adds its own with
    /// [`Faces::push`].
    pub fn with_capacity(faces: usize, corners: usize) -> Faces {
        let mut starts = Vec::with_capacity(faces + 1);
        starts.push(0);
        let mut elements: [Vec<u32>; 3] = Default::default();
        elements[slot(Kind::TexCoord)].reserve(corners);
        Faces {
            corner_coords: Vec::with_capacity(corners),
            elements,
            starts,
        }
    }

    /// Adds a face of at least three corners, wound counterclockwise: each corner's
    /// coordinate index (below the point count) and texture coordinate element.
    pub fn push(&mut self, coords: &[u32], tex_coord_elements: &[u32]) {
        debug_assert!(coords.len() >= 3 && coords.len() == tex_coord_elements.len());
        self.corner_coords.extend_from_slice(coords);
        self.elements[slot(Kind::TexCoord)].extend_from_slice(tex_coord_elements);
        self.starts.push(self.corner_coords.len());
    }

    pub fn face_count(&self) -> usize {
        self.starts.len() - 1
    }

    fn face(&self, k: usize) -> std::ops::Range<usize> {
        self.starts[k]..self.starts[k + 1]
    }
}

/// A texture coordinate set to produce.
#[derive(Clone, Copy)]
pub enum TexCoordInput<'a> {
    /// From a TextureCoordinate node (or a geometry's own default values).
    Given(Attribute<'a>),
    /// The bounding-box default mapping (13.3.6).
    Default,
    /// Left empty: generated once the mesh is placed (TextureCoordinateGenerator).
    Generated,
}

pub struct Inputs<'a> {
    pub points: &'a [f32],
    pub faces: Faces,
    pub normals: Option<Attribute<'a>>,
    pub generation: NormalGeneration,
    pub need_normals: bool,
    pub colors: Option<Attribute<'a>>,
    pub tex_coords: Vec<TexCoordInput<'a>>,
}

/// Builds the triangle mesh. Vertices are shared by coordinate index when every attribute
/// is bound by coordinate (the common IndexedTriangleSet case); otherwise one per corner.
pub fn build(inputs: Inputs) -> LocalMesh {
    let point = |i: u32| -> [f64; 3] {
        let p = &inputs.points[i as usize * 3..i as usize * 3 + 3];
        [f64::from(p[0]), f64::from(p[1]), f64::from(p[2])]
    };
    let faces = &inputs.faces;
    let generate = inputs.need_normals && inputs.normals.is_none();
    let face_normals: Vec<[f64; 3]> =
        if generate || faces.starts.windows(2).any(|w| w[1] - w[0] > 3) {
            (0..faces.face_count())
                .map(|k| newell(faces.corner_coords[faces.face(k)].iter().map(|&c| point(c))))
                .collect()
        } else {
            Vec::new()
        };
    // A face of n corners gives at most n − 2 triangles: a mesh of triangles needs a third
    // of its corner count, not the corner count (the benchmark scene's peak heap while
    // flattening, by heaptrack: 214 MB before, 206 MB after).
    let at_most = faces
        .starts
        .windows(2)
        .map(|w| (w[1] - w[0]).saturating_sub(2))
        .sum();
    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(at_most);
    let mut faces_over_limit = 0;
    for k in 0..faces.face_count() {
        let range = faces.face(k);
        if range.len() > MAX_FACE_CORNERS {
            faces_over_limit += 1;
        } else if range.len() == 3 {
            triangles.push([
                range.start as u32,
                range.start as u32 + 1,
                range.start as u32 + 2,
            ]);
        } else {
            let corners: Vec<[f64; 3]> = range
                .clone()
                .map(|c| point(faces.corner_coords[c]))
                .collect();
            for [a, b, c] in triangulate(&corners, face_normals[k]) {
                let s = range.start as u32;
                triangles.push([s + a, s + b, s + c]);
            }
        }
    }

    let by_coord = |a: &Option<Attribute>| a.as_ref().is_none_or(|a| a.by_coord);
    let tex_by_coord = inputs.tex_coords.iter().all(|t| match t {
        TexCoordInput::Given(a) => a.by_coord,
        _ => true,
    });
    let shared = by_coord(&inputs.normals)
        && by_coord(&inputs.colors)
        && tex_by_coord
        && (!generate || inputs.generation == NormalGeneration::Smooth);
    let point_count = inputs.points.len() / 3;
    let colors_have_alpha = inputs.colors.as_ref().is_some_and(|c| c.arity == 4);
    // The default mapping spans the bounding box of all the node's points.
    let default_mapping = inputs
        .tex_coords
        .iter()
        .any(|t| matches!(t, TexCoordInput::Default))
        .then(|| BoundingBoxMapping::of(inputs.points));
    if shared {
        let indices: Vec<u32> = triangles
            .iter()
            .flat_map(|t| t.map(|c| faces.corner_coords[c as usize]))
            .collect();
        let positions: Vec<[f32; 3]> = inputs
            .points
            .chunks_exact(3)
            .map(|p| [p[0], p[1], p[2]])
            .collect();
        let normals = if !inputs.need_normals {
            None
        } else if let Some(n) = &inputs.normals {
            Some(per_coord(n, point_count, [0.0, 0.0, 1.0]))
        } else {
            Some(smooth_by_coord(faces, &face_normals, point_count))
        };
        let tex_coords = inputs
            .tex_coords
            .iter()
            .map(|t| match t {
                TexCoordInput::Given(a) => to_vec2(&per_coord_any(a, point_count)),
                TexCoordInput::Default => default_mapping
                    .as_ref()
                    .map_or_else(Vec::new, |m| m.map(&positions)),
                TexCoordInput::Generated => Vec::new(),
            })
            .collect();
        return LocalMesh {
            primitive: Primitive::Triangles,
            positions,
            normals,
            colors: inputs
                .colors
                .as_ref()
                .map(|c| rgba_with_arity(&per_coord_any(c, point_count), c.arity)),
            colors_have_alpha,
            tex_coords,
            indices,
            faces_over_limit,
            ..LocalMesh::default()
        };
    }

    // One vertex per corner.
    let corner_count = faces.corner_coords.len();
    let face_of: Vec<usize> = (0..faces.face_count())
        .flat_map(|k| std::iter::repeat_n(k, faces.face(k).len()))
        .collect();
    let positions: Vec<[f32; 3]> = faces
        .corner_coords
        .iter()
        .map(|&c| {
            let p = &inputs.points[c as usize * 3..c as usize * 3 + 3];
            [p[0], p[1], p[2]]
        })
        .collect();
    let gather = |a: &Attribute, fallback: &[f32]| -> Vec<f32> {
        let mut out = Vec::with_capacity(corner_count * a.arity);
        for corner in 0..corner_count {
            let element = if a.by_coord {
                faces.corner_coords[corner]
            } else {
                faces.elements[slot(a.kind)][corner]
            };
            out.extend_from_slice(value_at(a, element).unwrap_or(fallback));
        }
        out
    };
    let normals = if !inputs.need_normals {
        None
    } else if let Some(n) = &inputs.normals {
        Some(to_vec3(&gather(n, &[0.0, 0.0, 1.0])))
    } else {
        Some(generated_per_corner(
            faces,
            &face_of,
            &face_normals,
            inputs.generation,
            point_count,
        ))
    };
    let tex_coords = inputs
        .tex_coords
        .iter()
        .map(|t| match t {
            TexCoordInput::Given(a) => to_vec2(&gather(a, &[0.0, 0.0])),
            TexCoordInput::Default => default_mapping
                .as_ref()
                .map_or_else(Vec::new, |m| m.map(&positions)),
            TexCoordInput::Generated => Vec::new(),
        })
        .collect();
    LocalMesh {
        primitive: Primitive::Triangles,
        positions,
        normals,
        colors: inputs
            .colors
            .as_ref()
            .map(|c| rgba_with_arity(&gather(c, &WHITE[..c.arity]), c.arity)),
        colors_have_alpha,
        tex_coords,
        indices: triangles.iter().flatten().copied().collect(),
        faces_over_limit,
        ..LocalMesh::default()
    }
}

const WHITE: [f32; 4] = [1.0; 4];

fn value_at<'a>(a: &Attribute<'a>, element: u32) -> Option<&'a [f32]> {
    let e = element as usize;
    a.values.get(e * a.arity..e * a.arity + a.arity)
}

fn per_coord_any(a: &Attribute, count: usize) -> Vec<f32> {
    let fallback = &WHITE[..a.arity];
    let mut out = Vec::with_capacity(count * a.arity);
    for i in 0..count {
        out.extend_from_slice(value_at(a, i as u32).unwrap_or(fallback));
    }
    out
}

fn per_coord(a: &Attribute, count: usize, fallback: [f32; 3]) -> Vec<[f32; 3]> {
    (0..count)
        .map(|i| value_at(a, i as u32).map_or(fallback, |v| [v[0], v[1], v[2]]))
        .collect()
}

fn to_vec3(flat: &[f32]) -> Vec<[f32; 3]> {
    flat.chunks_exact(3).map(|v| [v[0], v[1], v[2]]).collect()
}

fn to_vec2(flat: &[f32]) -> Vec<[f32; 2]> {
    flat.chunks_exact(2).map(|v| [v[0], v[1]]).collect()
}

/// RGB (alpha 1) or RGBA values, clamped to [0, 1].
pub fn rgba_with_arity(flat: &[f32], arity: usize) -> Vec<[f32; 4]> {
    let u = super::fields::unit;
    flat.chunks_exact(arity)
        .map(|c| {
            [
                u(c[0]),
                u(c[1]),
                u(c[2]),
                if arity == 4 { u(c[3]) } else { 1.0 },
            ]
        })
        .collect()
}

/// The polygon's normal by Newell's method (robust for concave and slightly non-planar
/// polygons), unnormalized: its length is twice the area.
pub fn newell(points: impl Iterator<Item = [f64; 3]>) -> [f64; 3] {
    let points: Vec<[f64; 3]> = points.collect();
    let mut n = [0.0; 3];
    for (i, p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    n
}

pub fn normalize(v: [f64; 3]) -> [f32; 3] {
    let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if length > 0.0 && length.is_finite() {
        [
            (v[0] / length) as f32,
            (v[1] / length) as f32,
            (v[2] / length) as f32,
        ]
    } else {
        [0.0; 3]
    }
}

fn add(a: &mut [f64; 3], b: [f64; 3]) {
    a[0] += b[0];
    a[1] += b[1];
    a[2] += b[2];
}

fn smooth_by_coord(faces: &Faces, face_normals: &[[f64; 3]], count: usize) -> Vec<[f32; 3]> {
    let mut sums = vec![[0.0f64; 3]; count];
    for k in 0..faces.face_count() {
        for c in faces.face(k) {
            add(&mut sums[faces.corner_coords[c] as usize], face_normals[k]);
        }
    }
    sums.into_iter().map(normalize).collect()
}

fn generated_per_corner(
    faces: &Faces,
    face_of: &[usize],
    face_normals: &[[f64; 3]],
    generation: NormalGeneration,
    point_count: usize,
) -> Vec<[f32; 3]> {
    match generation {
        NormalGeneration::Flat => face_of
            .iter()
            .map(|&k| normalize(face_normals[k]))
            .collect(),
        NormalGeneration::Smooth => {
            let smooth = smooth_by_coord(faces, face_normals, point_count);
            faces
                .corner_coords
                .iter()
                .map(|&c| smooth[c as usize])
                .collect()
        }
        NormalGeneration::Crease(angle) => {
            // Faces around each coordinate index.
            let mut around: Vec<Vec<u32>> = vec![Vec::new(); point_count];
            for (corner, &c) in faces.corner_coords.iter().enumerate() {
                let list = &mut around[c as usize];
                let face = face_of[corner] as u32;
                if list.last() != Some(&face) {
                    list.push(face);
                }
            }
            let unit: Vec<[f32; 3]> = face_normals.iter().map(|&n| normalize(n)).collect();
            let cos_limit = angle.min(std::f64::consts::PI).cos();
            faces
                .corner_coords
                .iter()
                .zip(face_of)
                .map(|(&c, &k)| {
                    let own = unit[k];
                    let mut sum = [0.0f64; 3];
                    for &other in &around[c as usize] {
                        let o = unit[other as usize];
                        let cos = f64::from(own[0] * o[0] + own[1] * o[1] + own[2] * o[2]);
                        if other as usize == k || cos > cos_limit {
                            add(&mut sum, face_normals[other as usize]);
                        }
                    }
                    normalize(sum)
                })
                .collect()
        }
    }
}

/// The default mapping of 13.3.6 for IndexedFaceSet and the composed sets: S along the
/// longest side of the bounding box from 0 to 1, T along the second longest, with the
/// same scale.
struct BoundingBoxMapping {
    lo: [f64; 3],
    s_axis: usize,
    t_axis: usize,
    scale: f64,
}

impl BoundingBoxMapping {
    /// The box of `points` (flat x, y, z), non-finite points left out.
    fn of(points: &[f32]) -> BoundingBoxMapping {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in points.chunks_exact(3) {
            if p.iter().all(|c| c.is_finite()) {
                for k in 0..3 {
                    lo[k] = lo[k].min(f64::from(p[k]));
                    hi[k] = hi[k].max(f64::from(p[k]));
                }
            }
        }
        let size = [0, 1, 2].map(|k| (hi[k] - lo[k]).max(0.0));
        let mut axes = [0usize, 1, 2];
        // Stable: ties keep X before Y before Z.
        axes.sort_by(|&a, &b| size[b].total_cmp(&size[a]));
        let (s_axis, t_axis) = (axes[0], axes[1]);
        let scale = if size[s_axis] > 0.0 && size[s_axis].is_finite() {
            1.0 / size[s_axis]
        } else {
            0.0
        };
        BoundingBoxMapping {
            lo: lo.map(|l| if l.is_finite() { l } else { 0.0 }),
            s_axis,
            t_axis,
            scale,
        }
    }

    fn map(&self, positions: &[[f32; 3]]) -> Vec<[f32; 2]> {
        positions
            .iter()
            .map(|p| {
                [self.s_axis, self.t_axis].map(|axis| {
                    let v = ((f64::from(p[axis]) - self.lo[axis]) * self.scale) as f32;
                    if v.is_finite() {
                        v
                    } else {
                        0.0
                    }
                })
            })
            .collect()
    }
}

/// Triangulates a polygon (counterclockwise about `normal`) with the `earcut` crate, a
/// port of Mapbox's earcut: ear clipping sped up by a z-order hash of the corners, so a
/// face of n corners costs about n log n rather than the n² to n³ of plain ear clipping,
/// and concave, self-touching and slightly non-planar faces come out inside their
/// outline. Zero-area corners are dropped, so degenerate faces give fewer (or no)
/// triangles. Faces whose corners are not finite, or whose normal is zero, fall back to
/// a fan. The caller bounds the corners of one face ([`MAX_FACE_CORNERS`]).
pub fn triangulate(points: &[[f64; 3]], normal: [f64; 3]) -> Vec<[u32; 3]> {
    let n = points.len();
    let fan = || (1..n as u32 - 1).map(|i| [0, i, i + 1]).collect::<Vec<_>>();
    let abs = normal.map(f64::abs);
    let spread = abs[0] + abs[1] + abs[2];
    if !spread.is_finite() || spread <= 0.0 {
        return fan();
    }
    // Project onto the plane most facing the normal, keeping the orientation.
    let drop = if abs[0] >= abs[1] && abs[0] >= abs[2] {
        0
    } else if abs[1] >= abs[2] {
        1
    } else {
        2
    };
    let (u, v) = match drop {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    };
    let flip = normal[drop] < 0.0;
    let projected: Vec<[f64; 2]> = points
        .iter()
        .map(|p| if flip { [p[v], p[u]] } else { [p[u], p[v]] })
        .collect();
    if projected.iter().flatten().any(|c| !c.is_finite()) {
        return fan();
    }
    // A convex face is a fan around its last corner, the triangles the ear clipper this
    // replaced made (earcut may pick the other diagonal of a quad, which shades
    // per-vertex colours differently): in O(n), and the render references stand.
    if turns_left_everywhere(&projected) {
        let last = n as u32 - 1;
        return (0..last - 1).map(|i| [last, i, i + 1]).collect();
    }
    let mut indices: Vec<u32> = Vec::with_capacity(3 * (n - 2));
    earcut::Earcut::new().earcut(projected.iter().copied(), &[], &mut indices);
    let mut triangles: Vec<[u32; 3]> = indices
        .chunks_exact(3)
        .map(|t| [t[0], t[1], t[2]])
        .collect();
    // earcut winds its triangles one way whatever the input's orientation: turn them to
    // the face's (counterclockwise in this projection).
    let cross = |[a, b, c]: [u32; 3]| {
        let [a, b, c] = [a, b, c].map(|i| projected[i as usize]);
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    if triangles.iter().map(|&t| cross(t)).sum::<f64>() < 0.0 {
        for t in &mut triangles {
            t.swap(1, 2);
        }
    }
    triangles
}

/// Whether every corner of a polygon turns strictly left: the polygon is convex and
/// counterclockwise.
fn turns_left_everywhere(points: &[[f64; 2]]) -> bool {
    let n = points.len();
    (0..n).all(|i| {
        let [a, b, c] = [points[i], points[(i + 1) % n], points[(i + 2) % n]];
        (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) > 0.0
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn concave_polygon_is_clipped_inside_its_outline() {
        // An L shape: a fan from corner 0 would cover the notch.
        let l = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ];
        let triangles = triangulate(&l, newell(l.iter().copied()));
        assert_eq!(triangles.len(), 4);
        let area: f64 = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| l[i as usize]);
                ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2.0
            })
            .sum();
        assert!((area - 3.0).abs() < 1e-12, "area {area}");
    }

    #[test]
    fn degenerate_polygons_do_not_panic() {
        let line = [[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 0.0]];
        assert_eq!(triangulate(&line, newell(line.iter().copied())).len(), 2);
        let nan = [[f64::NAN; 3]; 4];
        assert_eq!(triangulate(&nan, newell(nan.iter().copied())).len(), 2);
        let mut some_nan = [[0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        some_nan[2][0] = f64::INFINITY;
        assert_eq!(triangulate(&some_nan, [0.0, 0.0, 1.0]).len(), 2);
        assert_eq!(normalize([0.0; 3]), [0.0; 3]);
        assert_eq!(normalize([f64::INFINITY, 0.0, 0.0]), [0.0; 3]);
    }

    #[test]
    fn faces_with_bad_indices_are_dropped_and_attributes_keep_face_numbers() {
        // Face 1 has index 9 (out of range), face 2 only two corners; colours per face.
        let source = "<X3D><Scene><Shape><IndexedFaceSet colorPerVertex='false' \
                      coordIndex='0 1 2 -1 0 9 2 -1 0 1 -1 2 1 0'>\
                      <Coordinate point='0 0 0 1 0 0 0 1 0'/></IndexedFaceSet></Shape></Scene></X3D>";
        let doc = crate::parse::read(source.as_bytes()).document.unwrap();
        let ifs = doc.nodes_of_type("IndexedFaceSet").next().unwrap();
        let polygonal = Polygonal::read(&doc, ifs, 3).unwrap();
        let faces = Faces::of(&polygonal, 3, &[Kind::Color]);
        assert_eq!(faces.face_count(), 2);
        assert_eq!(faces.corner_coords, vec![0, 1, 2, 2, 1, 0]);
        // The last face is face number 3 of the node, whatever was dropped before it.
        assert_eq!(faces.elements[slot(Kind::Color)], vec![0, 0, 0, 3, 3, 3]);
    }
}
