//! The Geometry2D nodes (ISO/IEC 19775-1 clause 14), in the Z=0 plane of their local
//! coordinates: the surfaces (ArcClose2D, Disk2D, Rectangle2D, TriangleSet2D) as
//! triangles with normals and default texture coordinates, like the primitives; the
//! lines and points (Arc2D, Circle2D, Polyline2D, Polypoint2D) unlit, like LineSet and
//! PointSet.
//!
//! Where the clause leaves a choice, this reads it so:
//! - Arcs run counterclockwise (from +X towards +Y) from startAngle to endAngle; equal
//!   angles, or angles 2π or more apart, make the whole circle (14.3.1, 14.3.2), and a
//!   whole ArcClose2D is a disk whatever its closureType. A closureType other than
//!   "CHORD" is "PIE" (the default).
//! - Curves have [`SEGMENTS`] segments around a whole circle, an arc its share (at
//!   least one).
//! - Every surface faces +Z (TriangleSet2D triangles given clockwise are turned), with
//!   normal +Z; −Z is its back face, culled when solid (FALSE by default) is TRUE.
//! - Texture coordinates: "on the front (+Z) and back (−Z) faces … the texture is mapped
//!   onto each face with the same orientation as if the image were displayed normally in
//!   2D": s along X, t along Y. Rectangle2D spans the image; Disk2D and ArcClose2D are
//!   cut from the image laid on the square around their circle; TriangleSet2D spans the
//!   image over the bounding rectangle of its vertices (the clause gives no extent; this
//!   is what X3DOM does).
//! - Disk2D: innerRadius 0 is a full disk; innerRadius equal to outerRadius is the circle
//!   line (14.3.4); an innerRadius above outerRadius (invalid) draws the ring between
//!   the two.
//! - Non-finite radii and angles take their defaults (render::fields); non-finite points
//!   make primitives that placing drops.

use std::f64::consts::{FRAC_PI_2, TAU};

use super::primitives::SEGMENTS;
use crate::model::{Document, NodeId};
use crate::render::draw_list::Primitive;
use crate::render::fields::{float, floats};
use crate::render::mesh::LocalMesh;

/// What a Geometry2D node is drawn as.
pub enum Planar {
    /// Triangles with normals and one default texture coordinate set.
    Surface(LocalMesh),
    /// Unlit lines or points.
    Lines(LocalMesh),
}

/// The Geometry2D node `geometry` of type `name` (one of the eight).
pub fn build(doc: &Document, geometry: NodeId, name: &str) -> Planar {
    let radius = |field: &str| f64::from(float(doc, geometry, field, 1.0));
    match name {
        "Arc2D" => {
            let (start, sweep) = arc(doc, geometry);
            Planar::Lines(curve(&circle_points(radius("radius"), start, sweep)))
        }
        "Circle2D" => Planar::Lines(curve(&circle_points(radius("radius"), 0.0, TAU))),
        "Polyline2D" => Planar::Lines(curve(&plane_points(doc, geometry, "lineSegments"))),
        "Polypoint2D" => {
            let positions = plane_points(doc, geometry, "point");
            Planar::Lines(LocalMesh {
                primitive: Primitive::Points,
                indices: (0..positions.len() as u32).collect(),
                positions,
                ..LocalMesh::default()
            })
        }
        "ArcClose2D" => {
            let (start, sweep) = arc(doc, geometry);
            let r = radius("radius");
            let chord = doc.string_of(geometry, "closureType").as_deref() == Some("CHORD");
            Planar::Surface(if sweep >= TAU {
                disk(r, 0.0)
            } else {
                arc_close(r, start, sweep, chord)
            })
        }
        "Disk2D" => {
            let inner = f64::from(float(doc, geometry, "innerRadius", 0.0)).abs();
            let outer = radius("outerRadius").abs();
            if inner == outer {
                Planar::Lines(curve(&circle_points(outer, 0.0, TAU)))
            } else {
                Planar::Surface(disk(outer.max(inner), outer.min(inner)))
            }
        }
        "Rectangle2D" => {
            let half = match floats(doc, geometry, "size").as_ref() {
                [x, y, ..] => [*x, *y].map(|v| if v.is_finite() { v.abs() / 2.0 } else { 0.0 }),
                _ => [1.0; 2],
            };
            Planar::Surface(rectangle(half))
        }
        _ => Planar::Surface(triangle_set(&floats(doc, geometry, "vertices"))),
    }
}

/// The points of an MFVec2f field in the Z=0 plane.
fn plane_points(doc: &Document, geometry: NodeId, field: &str) -> Vec<[f32; 3]> {
    floats(doc, geometry, field)
        .chunks_exact(2)
        .map(|p| [p[0], p[1], 0.0])
        .collect()
}

/// The lower corner and the size of the rectangle around the finite `points`; None when
/// there are none.
pub(super) fn bounding_rectangle<'a>(
    points: impl IntoIterator<Item = &'a [f64; 2]>,
) -> Option<([f64; 2], [f64; 2])> {
    let [mut lo, mut hi] = [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]];
    for p in points
        .into_iter()
        .filter(|p| p.iter().all(|c| c.is_finite()))
    {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo[0] <= hi[0]).then(|| (lo, [hi[0] - lo[0], hi[1] - lo[1]]))
}

/// The start angle and counterclockwise sweep (in (0, 2π]) of an arc's fields.
fn arc(doc: &Document, geometry: NodeId) -> (f64, f64) {
    let start = f64::from(float(doc, geometry, "startAngle", 0.0));
    let end = f64::from(float(doc, geometry, "endAngle", FRAC_PI_2 as f32));
    let difference = end - start;
    if difference == 0.0 || difference.abs() >= TAU {
        (start, TAU)
    } else {
        (start, difference.rem_euclid(TAU))
    }
}

/// Points along a circle of radius `r` from angle `start` over `sweep`: [`SEGMENTS`] for
/// the whole circle (the last point back on the first), in proportion for an arc.
fn circle_points(r: f64, start: f64, sweep: f64) -> Vec<[f32; 3]> {
    // Angles read as f32 land a hair past whole segments: that hair is not a segment.
    let segments = (f64::from(SEGMENTS) * sweep / TAU - 1e-3).ceil().max(1.0) as u32;
    (0..=segments)
        .map(|k| {
            let angle = start + sweep * f64::from(k) / f64::from(segments);
            [(r * angle.cos()) as f32, (r * angle.sin()) as f32, 0.0]
        })
        .collect()
}

/// Lines joining consecutive points.
fn curve(points: &[[f32; 3]]) -> LocalMesh {
    let count = points.len() as u32;
    LocalMesh {
        primitive: Primitive::Lines,
        positions: points.to_vec(),
        indices: (1..count).flat_map(|k| [k - 1, k]).collect(),
        ..LocalMesh::default()
    }
}

/// Triangles in the Z=0 plane facing +Z.
#[derive(Default)]
struct Surface {
    positions: Vec<[f32; 3]>,
    tex_coords: Vec<[f32; 2]>,
    indices: Vec<u32>,
}

impl Surface {
    /// A vertex at (x, y), textured by `texture`: the rectangle (lower left, size) the
    /// image spans.
    fn vertex(&mut self, [x, y]: [f64; 2], texture: &([f64; 2], [f64; 2])) -> u32 {
        let (lo, size) = texture;
        let st = [0, 1].map(|k| {
            let v = if size[k] > 0.0 {
                ([x, y][k] - lo[k]) / size[k]
            } else {
                0.0
            };
            v as f32
        });
        self.positions.push([x as f32, y as f32, 0.0]);
        self.tex_coords.push(st);
        self.positions.len() as u32 - 1
    }

    fn finish(self) -> LocalMesh {
        let count = self.positions.len();
        LocalMesh {
            primitive: Primitive::Triangles,
            positions: self.positions,
            normals: Some(vec![[0.0, 0.0, 1.0]; count]),
            tex_coords: vec![self.tex_coords],
            indices: self.indices,
            ..LocalMesh::default()
        }
    }
}

/// The image laid on the square around a circle of radius `r` at the origin.
fn circle_texture(r: f64) -> ([f64; 2], [f64; 2]) {
    ([-r, -r], [2.0 * r, 2.0 * r])
}

fn angle_point(r: f64, angle: f64) -> [f64; 2] {
    [r * angle.cos(), r * angle.sin()]
}

/// Disk2D (and a whole ArcClose2D): a fan around the centre, or the ring between the
/// radii.
fn disk(outer: f64, inner: f64) -> LocalMesh {
    let texture = circle_texture(outer);
    let mut surface = Surface::default();
    let angle = |k: u32| TAU * f64::from(k) / f64::from(SEGMENTS);
    if inner == 0.0 {
        let centre = surface.vertex([0.0, 0.0], &texture);
        let first = surface.positions.len() as u32;
        for k in 0..SEGMENTS {
            surface.vertex(angle_point(outer, angle(k)), &texture);
        }
        for k in 0..SEGMENTS {
            let next = first + (k + 1) % SEGMENTS;
            surface
                .indices
                .extend_from_slice(&[centre, first + k, next]);
        }
    } else {
        for k in 0..SEGMENTS {
            surface.vertex(angle_point(inner, angle(k)), &texture);
            surface.vertex(angle_point(outer, angle(k)), &texture);
        }
        for k in 0..SEGMENTS {
            let (a, b) = (2 * k, 2 * ((k + 1) % SEGMENTS));
            // inner k, outer k, outer k+1, inner k+1: counterclockwise about +Z.
            surface
                .indices
                .extend_from_slice(&[a, a + 1, b + 1, a, b + 1, b]);
        }
    }
    surface.finish()
}

/// ArcClose2D short of a whole circle: a fan from the centre (PIE) or from the arc's
/// first point (CHORD: a circular segment, convex).
fn arc_close(r: f64, start: f64, sweep: f64, chord: bool) -> LocalMesh {
    let texture = circle_texture(r);
    let mut surface = Surface::default();
    let centre = (!chord).then(|| surface.vertex([0.0, 0.0], &texture));
    let first = surface.positions.len() as u32;
    for p in circle_points(r, start, sweep) {
        surface.vertex([p[0].into(), p[1].into()], &texture);
    }
    let last = surface.positions.len() as u32 - 1;
    let apex = centre.unwrap_or(first);
    for k in first..last {
        if k != apex {
            surface.indices.extend_from_slice(&[apex, k, k + 1]);
        }
    }
    surface.finish()
}

/// Rectangle2D: the image spans it.
fn rectangle([x, y]: [f32; 2]) -> LocalMesh {
    let (x, y) = (f64::from(x), f64::from(y));
    let texture = ([-x, -y], [2.0 * x, 2.0 * y]);
    let mut surface = Surface::default();
    for corner in [[-x, -y], [x, -y], [x, y], [-x, y]] {
        surface.vertex(corner, &texture);
    }
    surface.indices = vec![0, 1, 2, 0, 2, 3];
    surface.finish()
}

/// TriangleSet2D: three vertices a triangle, the rest ignored; each turned to face +Z.
fn triangle_set(vertices: &[f32]) -> LocalMesh {
    let points: Vec<[f64; 2]> = vertices
        .chunks_exact(2)
        .map(|p| [p[0].into(), p[1].into()])
        .collect();
    let texture = bounding_rectangle(&points).unwrap_or(([0.0; 2], [0.0; 2]));
    let mut surface = Surface::default();
    for triangle in points.chunks_exact(3) {
        let [a, b, c] = [triangle[0], triangle[1], triangle[2]];
        let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        let ids = [a, b, c].map(|p| surface.vertex(p, &texture));
        if area < 0.0 {
            surface.indices.extend_from_slice(&[ids[0], ids[2], ids[1]]);
        } else {
            surface.indices.extend_from_slice(&ids);
        }
    }
    surface.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(element: &str) -> Planar {
        let source = format!("<X3D><Scene><Shape>{element}</Shape></Scene></X3D>");
        let doc = crate::parse::read(source.as_bytes()).document.unwrap();
        let id = doc.node_ids().last().unwrap();
        let name = doc.node(id).type_name().to_string();
        build(&doc, id, &name)
    }

    fn surface(element: &str) -> LocalMesh {
        match node(element) {
            Planar::Surface(mesh) => mesh,
            Planar::Lines(_) => panic!("{element} drew lines"),
        }
    }

    fn lines(element: &str) -> LocalMesh {
        match node(element) {
            Planar::Lines(mesh) => mesh,
            Planar::Surface(_) => panic!("{element} drew a surface"),
        }
    }

    /// The triangles' areas seen from +Z (negative: facing −Z).
    fn areas(mesh: &LocalMesh) -> Vec<f64> {
        mesh.indices
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] =
                    [t[0], t[1], t[2]].map(|i| mesh.positions[i as usize].map(f64::from));
                ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2.0
            })
            .collect()
    }

    fn angle_of(p: [f32; 3]) -> f64 {
        f64::from(p[1]).atan2(f64::from(p[0]))
    }

    #[test]
    fn arcs_run_counterclockwise_from_start_to_end() {
        // The default: a quarter circle, 12 of the 48 segments.
        let quarter = lines("<Arc2D radius='2'/>");
        assert_eq!(quarter.primitive, Primitive::Lines);
        assert_eq!(quarter.indices.len(), 2 * 12);
        assert_eq!(quarter.positions[0], [2.0, 0.0, 0.0]);
        assert!((angle_of(*quarter.positions.last().unwrap()) - FRAC_PI_2).abs() < 1e-6);
        // From 0 to −π/2 counterclockwise: three quarters, through π.
        let three_quarters = lines("<Arc2D startAngle='0' endAngle='-1.5707963'/>");
        assert_eq!(three_quarters.indices.len(), 2 * 36);
        assert!(three_quarters
            .positions
            .iter()
            .any(|p| (angle_of(*p).abs() - std::f64::consts::PI).abs() < 1e-6));
        // Equal angles: the whole circle, back to its start.
        let circle = lines("<Arc2D startAngle='1' endAngle='1'/>");
        assert_eq!(circle.indices.len(), 2 * 48);
        let [first, last] = [circle.positions[0], *circle.positions.last().unwrap()];
        assert!((0..2).all(|k| (first[k] - last[k]).abs() < 1e-6));
        assert_eq!(lines("<Circle2D radius='3'/>").indices.len(), 2 * 48);
    }

    #[test]
    fn arc_close_pie_and_chord_fill_their_region_facing_z() {
        // A half disk of radius 1: PIE and CHORD cover the same area π/2.
        for closure in ["PIE", "CHORD"] {
            let mesh = surface(&format!(
                "<ArcClose2D closureType='{closure}' startAngle='0' endAngle='3.14159265'/>"
            ));
            let areas = areas(&mesh);
            assert!(areas.iter().all(|&a| a > 0.0), "{closure}");
            let total: f64 = areas.iter().sum();
            // 24 chords inscribed in the half circle.
            let inscribed = 12.0 * (std::f64::consts::PI / 24.0).sin();
            assert!((total - inscribed).abs() < 1e-5, "{closure}: {total}");
        }
        // A three-quarter CHORD is a circular segment, without the centre.
        let chord = surface("<ArcClose2D closureType='CHORD' startAngle='0' endAngle='4.712389'/>");
        assert!(!chord.positions.contains(&[0.0, 0.0, 0.0]));
        let pie = surface("<ArcClose2D startAngle='0' endAngle='4.712389'/>");
        assert!(pie.positions.contains(&[0.0, 0.0, 0.0]));
        // Past a half turn the chord encloses the triangle (centre, start, end): ½ more.
        let extra = areas(&chord).iter().sum::<f64>() - areas(&pie).iter().sum::<f64>();
        assert!((extra - 0.5).abs() < 1e-6, "{extra}");
        // Texture: the image on the circle's square, so the centre is (0.5, 0.5).
        let centre = pie.positions.iter().position(|p| *p == [0.0; 3]).unwrap();
        assert_eq!(pie.tex_coords[0][centre], [0.5, 0.5]);
        assert!(pie.normals.unwrap().iter().all(|n| *n == [0.0, 0.0, 1.0]));
    }

    #[test]
    fn disk_with_inner_radius_is_a_ring() {
        let ring = surface("<Disk2D innerRadius='1' outerRadius='2'/>");
        let total: f64 = areas(&ring).iter().sum();
        let polygon = |r: f64| 24.0 * r * r * (std::f64::consts::TAU / 48.0).sin();
        assert!(areas(&ring).iter().all(|&a| a > 0.0));
        assert!(
            (total - (polygon(2.0) - polygon(1.0))).abs() < 1e-4,
            "{total}"
        );
        // No vertex inside the hole; texture over the outer circle's square.
        let tex = &ring.tex_coords[0];
        for (p, t) in ring.positions.iter().zip(tex) {
            assert!(p[0].hypot(p[1]) > 0.999);
            assert!((t[0] - (p[0] / 4.0 + 0.5)).abs() < 1e-6);
            assert!((t[1] - (p[1] / 4.0 + 0.5)).abs() < 1e-6);
        }
        let full = surface("<Disk2D/>");
        assert!((areas(&full).iter().sum::<f64>() - polygon(1.0)).abs() < 1e-5);
        // Equal radii: the circle line.
        assert_eq!(
            lines("<Disk2D innerRadius='2' outerRadius='2'/>")
                .indices
                .len(),
            96
        );
    }

    #[test]
    fn rectangle_spans_the_image() {
        let mesh = surface("<Rectangle2D size='4 2'/>");
        assert_eq!(mesh.positions[0], [-2.0, -1.0, 0.0]);
        assert_eq!(mesh.positions[2], [2.0, 1.0, 0.0]);
        assert_eq!(
            mesh.tex_coords[0],
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
        );
        assert_eq!(areas(&mesh).iter().sum::<f64>(), 8.0);
    }

    #[test]
    fn triangle_set_faces_z_and_ignores_excess_vertices() {
        // One counterclockwise triangle, one clockwise, then two spare vertices.
        let mesh = surface("<TriangleSet2D vertices='0 0 2 0 0 1  3 0 3 1 5 0  9 9 9 8'/>");
        assert_eq!(mesh.indices.len(), 6);
        assert!(areas(&mesh).iter().all(|&a| a > 0.0));
        // The image spans the box of the drawn vertices, (0, 0) to (9, 9).
        let tex = &mesh.tex_coords[0];
        assert_eq!(tex[4], [3.0 / 9.0, 1.0 / 9.0]);
        // Not enough vertices, or none: nothing, and no panic.
        assert!(surface("<TriangleSet2D vertices='0 0 1 1'/>")
            .indices
            .is_empty());
        assert!(surface("<TriangleSet2D/>").indices.is_empty());
    }

    #[test]
    fn polylines_and_polypoints_are_lines_and_points() {
        let polyline = lines("<Polyline2D lineSegments='0 0 1 0 1 1'/>");
        assert_eq!(polyline.indices, vec![0, 1, 1, 2]);
        assert_eq!(polyline.positions[2], [1.0, 1.0, 0.0]);
        let points = lines("<Polypoint2D point='0 0 1 0 1 1'/>");
        assert_eq!(points.primitive, Primitive::Points);
        assert_eq!(points.indices, vec![0, 1, 2]);
        assert!(lines("<Polyline2D/>").indices.is_empty());
        assert!(lines("<Polyline2D lineSegments='1 1'/>").indices.is_empty());
    }
}
