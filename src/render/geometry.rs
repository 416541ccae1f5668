//! Geometry nodes to triangle, line or point meshes in the node's local coordinates.
//! Only what the material needs is computed: normals only for lit shapes (or texture
//! coordinate generators that read them), texture coordinate sets only those sampled.

use std::borrow::Cow;
use std::f32::consts::PI;

use super::draw_list::Primitive;
use super::fields::{boolean, child, float, floats, ints, type_is, vec3};
use super::mesh::LocalMesh;
use super::polygons::{self, Attribute, Faces, Inputs, NormalGeneration, TexCoordInput};
use crate::model::faces::{Attribute as Kind, Polygonal};
use crate::model::{Document, NodeId};

#[derive(Clone, Debug, Default)]
pub struct Needs {
    pub normals: bool,
    /// The texture coordinate sets to produce.
    pub tex_coords: Vec<TexCoordSource>,
}

/// Where a texture coordinate set comes from (12.2.4).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum TexCoordSource {
    /// The geometry's default texture coordinates.
    Default,
    /// This TextureCoordinate node of the geometry's texture coordinate list.
    Given(NodeId),
    /// A TextureCoordinateGenerator: computed later, from the placed vertices.
    Generated,
}

pub enum Built {
    Mesh(LocalMesh, Shading),
    /// The renderer cannot draw this node type (the reason, for the report).
    NotDrawn(String),
}

/// What the geometry says about how to draw it.
#[derive(Copy, Clone, Debug)]
pub struct Shading {
    /// Back faces are culled (solid TRUE).
    pub solid: bool,
    /// Lines and points without normals are unlit (17.2.2.4 note).
    pub unlit: bool,
}

pub fn build(doc: &Document, geometry: NodeId, needs: &Needs) -> Built {
    let name = doc.node(geometry).type_name();
    let solid = boolean(doc, geometry, "solid", true);
    let surface = |mesh| {
        Built::Mesh(
            mesh,
            Shading {
                solid,
                unlit: false,
            },
        )
    };
    // The primitives have no texCoord field: every set is their default mapping.
    let primitive = |mut mesh: LocalMesh| {
        let default = mesh.tex_coords.pop().unwrap_or_default();
        mesh.tex_coords = vec![default; needs.tex_coords.len()];
        surface(mesh)
    };
    match name {
        "Box" => primitive(primitives::cuboid(vec3(doc, geometry, "size", [2.0; 3]))),
        "Sphere" => primitive(primitives::sphere(float(doc, geometry, "radius", 1.0))),
        "Cylinder" => primitive(primitives::cylinder(
            float(doc, geometry, "radius", 1.0),
            float(doc, geometry, "height", 2.0),
            [
                boolean(doc, geometry, "side", true),
                boolean(doc, geometry, "top", true),
                boolean(doc, geometry, "bottom", true),
            ],
        )),
        "Cone" => primitive(primitives::cone(
            float(doc, geometry, "bottomRadius", 1.0),
            float(doc, geometry, "height", 2.0),
            boolean(doc, geometry, "side", true),
            boolean(doc, geometry, "bottom", true),
        )),
        "IndexedFaceSet"
        | "IndexedTriangleSet"
        | "TriangleSet"
        | "IndexedTriangleFanSet"
        | "IndexedTriangleStripSet"
        | "TriangleFanSet"
        | "TriangleStripSet"
        | "IndexedQuadSet"
        | "QuadSet" => match composed(doc, geometry, name, needs) {
            Some(mesh) => surface(mesh),
            None => Built::NotDrawn(format!("{name} has no usable coordinates")),
        },
        "ElevationGrid" => match elevation_grid(doc, geometry, needs) {
            Some(mesh) => surface(mesh),
            None => Built::NotDrawn("ElevationGrid is not drawn".to_string()),
        },
        "LineSet" | "IndexedLineSet" | "PointSet" => lines_or_points(doc, geometry, name),
        "Extrusion" => match extrusion::build(doc, geometry, needs) {
            Ok(mesh) => surface(mesh),
            Err(reason) => Built::NotDrawn(reason),
        },
        "Arc2D" | "ArcClose2D" | "Circle2D" | "Disk2D" | "Polyline2D" | "Polypoint2D"
        | "Rectangle2D" | "TriangleSet2D" => match geometry2d::build(doc, geometry, name) {
            geometry2d::Planar::Surface(mesh) => primitive(mesh),
            geometry2d::Planar::Lines(mesh) => Built::Mesh(
                mesh,
                Shading {
                    solid: false,
                    unlit: true,
                },
            ),
        },
        other => Built::NotDrawn(format!("{other} is not drawn")),
    }
}

/// At most how many triangles, lines or points [`build`] makes of `geometry`, from the
/// sizes of its fields alone, before anything is built: the renderer's budget is checked
/// against it, so a geometry past the budget costs no memory. The primitives and the
/// Geometry2D nodes make a few thousand at most (0 here; they are counted once built),
/// and Extrusion has its own cap.
pub fn primitive_bound(doc: &Document, geometry: NodeId) -> usize {
    let len = |node: NodeId, field: &str| doc.value_of(node, field).map_or(0, |v| v.len());
    let points = || child(doc, geometry, "coord").map_or(0, |c| len(c, "point") / 3);
    match doc.node(geometry).type_name() {
        // A face of n corners makes n − 2 triangles; a strip or fan of n indices n − 2.
        "IndexedFaceSet" | "IndexedLineSet" => len(geometry, "coordIndex"),
        "IndexedTriangleSet"
        | "IndexedTriangleFanSet"
        | "IndexedTriangleStripSet"
        | "IndexedQuadSet" => len(geometry, "index"),
        "TriangleSet" | "TriangleFanSet" | "TriangleStripSet" | "QuadSet" | "LineSet"
        | "PointSet" => points(),
        // Two triangles per grid cell, and fewer cells than heights.
        "ElevationGrid" => len(geometry, "height").saturating_mul(2),
        _ => 0,
    }
}

/// The Color or ColorRGBA values of a geometry, with their arity.
fn color_attribute(doc: &Document, geometry: NodeId) -> Option<(Cow<'_, [f32]>, usize)> {
    let color = child(doc, geometry, "color")?;
    let arity = if type_is(doc, color, "ColorRGBA") {
        4
    } else {
        3
    };
    Some((floats(doc, color, "color"), arity))
}

/// The points of a geometry's Coordinate or CoordinateDouble node, as f32 offsets from
/// an f64 origin (the first point of a CoordinateDouble; zero for a Coordinate).
fn coordinates(doc: &Document, geometry: NodeId) -> (Cow<'_, [f32]>, [f64; 3]) {
    let Some(coord) = child(doc, geometry, "coord") else {
        return (Cow::Borrowed(&[]), [0.0; 3]);
    };
    if !type_is(doc, coord, "CoordinateDouble") {
        return (floats(doc, coord, "point"), [0.0; 3]);
    }
    let value = doc.value_of(coord, "point");
    let doubles = value.as_deref().and_then(|v| v.as_doubles()).unwrap_or(&[]);
    let origin = match doubles {
        [x, y, z, ..] if x.is_finite() && y.is_finite() && z.is_finite() => [*x, *y, *z],
        _ => [0.0; 3],
    };
    let offsets = doubles
        .chunks_exact(3)
        .flat_map(|p| [0, 1, 2].map(|k| (p[k] - origin[k]) as f32))
        .collect();
    (Cow::Owned(offsets), origin)
}

/// The texture coordinate sets `needs` asks for, as polygons::build takes them.
fn tex_coord_inputs<'a>(
    polygonal: &Polygonal,
    needs: &Needs,
    given: &'a [(NodeId, Cow<'a, [f32]>)],
    default: Option<&'a [f32]>,
) -> Vec<TexCoordInput<'a>> {
    needs
        .tex_coords
        .iter()
        .map(|source| match source {
            TexCoordSource::Given(node) => given.iter().find(|(n, _)| n == node).map_or(
                TexCoordInput::Default,
                |(_, values)| {
                    TexCoordInput::Given(Attribute::of(polygonal, Kind::TexCoord, values, 2))
                },
            ),
            TexCoordSource::Default => match default {
                Some(values) => {
                    TexCoordInput::Given(Attribute::of(polygonal, Kind::TexCoord, values, 2))
                }
                None => TexCoordInput::Default,
            },
            TexCoordSource::Generated => TexCoordInput::Generated,
        })
        .collect()
}

/// The point values of each TextureCoordinate node `needs` names.
fn given_values<'d>(doc: &'d Document, needs: &Needs) -> Vec<(NodeId, Cow<'d, [f32]>)> {
    needs
        .tex_coords
        .iter()
        .filter_map(|source| match source {
            TexCoordSource::Given(node) => Some((*node, floats(doc, *node, "point"))),
            _ => None,
        })
        .collect()
}

/// IndexedFaceSet and the X3DComposedGeometryNode sets. None when the node's indices
/// cannot be read.
fn composed(doc: &Document, geometry: NodeId, name: &str, needs: &Needs) -> Option<LocalMesh> {
    let (points, origin) = coordinates(doc, geometry);
    let polygonal = Polygonal::read(doc, geometry, points.len() / 3)?;
    let normal_values = child(doc, geometry, "normal").map(|n| floats(doc, n, "vector"));
    let normals = normal_values
        .as_deref()
        .filter(|_| needs.normals)
        .map(|values| Attribute::of(&polygonal, Kind::Normal, values, 3));
    // Only IndexedFaceSet has colorPerVertex FALSE; the sets ignore it (model::faces).
    let color = color_attribute(doc, geometry);
    let colors = color
        .as_ref()
        .map(|(values, arity)| Attribute::of(&polygonal, Kind::Color, values, *arity));
    let given = given_values(doc, needs);
    let tex_coords = tex_coord_inputs(&polygonal, needs, &given, None);
    let normal_per_vertex = boolean(doc, geometry, "normalPerVertex", true);
    let generation = match name {
        "IndexedFaceSet" => crease_generation(doc, geometry),
        "TriangleSet" | "QuadSet" | "IndexedQuadSet" => NormalGeneration::Flat,
        _ if normal_per_vertex => NormalGeneration::Smooth,
        _ => NormalGeneration::Flat,
    };
    let mut mesh = polygons::build(Inputs {
        points: &points,
        faces: faces_of(&polygonal, points.len() / 3, normals, colors, &tex_coords),
        normals,
        generation,
        need_normals: needs.normals,
        colors,
        tex_coords,
    });
    mesh.origin = origin;
    Some(mesh)
}

/// The faces, with per-corner elements for the attributes not bound by coordinate.
fn faces_of(
    polygonal: &Polygonal,
    point_count: usize,
    normals: Option<Attribute>,
    colors: Option<Attribute>,
    tex_coords: &[TexCoordInput],
) -> Faces {
    let given = tex_coords.iter().find_map(|t| match t {
        TexCoordInput::Given(a) => Some(*a),
        _ => None,
    });
    let per_corner: Vec<Kind> = [normals, colors, given]
        .iter()
        .flatten()
        .filter(|a| !a.by_coord)
        .map(|a| a.kind)
        .collect();
    Faces::of(polygonal, point_count, &per_corner)
}

/// Normals from creaseAngle (13.3.6): flat at 0, smooth from π.
fn crease_generation(doc: &Document, geometry: NodeId) -> NormalGeneration {
    let angle = float(doc, geometry, "creaseAngle", 0.0);
    if angle <= 0.0 {
        NormalGeneration::Flat
    } else if angle >= PI {
        NormalGeneration::Smooth
    } else {
        NormalGeneration::Crease(f64::from(angle))
    }
}

/// ElevationGrid: its grid cut to the rows its heights fill (model::faces).
fn elevation_grid(doc: &Document, geometry: NodeId, needs: &Needs) -> Option<LocalMesh> {
    let polygonal = Polygonal::read(doc, geometry, 0)?;
    let x_dim = doc.i32_of(geometry, "xDimension").unwrap_or(0).max(0) as usize;
    let z_dim = doc.i32_of(geometry, "zDimension").unwrap_or(0).max(0) as usize;
    let x_spacing = float(doc, geometry, "xSpacing", 1.0);
    let z_spacing = float(doc, geometry, "zSpacing", 1.0);
    let heights = floats(doc, geometry, "height");
    let count = polygonal.stream_len();
    let mut points = Vec::with_capacity(count * 3);
    for (k, &height) in heights.iter().take(count).enumerate() {
        let (x, z) = (k % x_dim, k / x_dim);
        points.extend_from_slice(&[x as f32 * x_spacing, height, z as f32 * z_spacing]);
    }
    let normal_values = child(doc, geometry, "normal").map(|n| floats(doc, n, "vector"));
    let normals = normal_values
        .as_deref()
        .filter(|_| needs.normals)
        .map(|values| Attribute::of(&polygonal, Kind::Normal, values, 3));
    let color = color_attribute(doc, geometry);
    let colors = color
        .as_ref()
        .map(|(values, arity)| Attribute::of(&polygonal, Kind::Color, values, *arity));
    // Default mapping (13.3.4): s along x, t along z, each from 0 to 1.
    let step = |n: usize| 1.0 / n.saturating_sub(1).max(1) as f32;
    let default_tex: Vec<f32> = if needs.tex_coords.contains(&TexCoordSource::Default) {
        (0..count)
            .flat_map(|k| {
                [
                    (k % x_dim) as f32 * step(x_dim),
                    (k / x_dim) as f32 * step(z_dim),
                ]
            })
            .collect()
    } else {
        Vec::new()
    };
    let given = given_values(doc, needs);
    let tex_coords = tex_coord_inputs(&polygonal, needs, &given, Some(&default_tex));
    Some(polygons::build(Inputs {
        points: &points,
        faces: faces_of(&polygonal, count, normals, colors, &tex_coords),
        normals,
        generation: crease_generation(doc, geometry),
        need_normals: needs.normals,
        colors,
        tex_coords,
    }))
}

fn lines_or_points(doc: &Document, geometry: NodeId, name: &str) -> Built {
    let (points, origin) = coordinates(doc, geometry);
    let count = points.len() / 3;
    let positions: Vec<[f32; 3]> = points.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect();
    let color = color_attribute(doc, geometry);
    let colors_have_alpha = color.as_ref().is_some_and(|(_, arity)| *arity == 4);
    let mut indices = Vec::new();
    let mut colors = color.as_ref().map(|(values, arity)| {
        let mut per_point = polygons::rgba_with_arity(values, *arity);
        per_point.resize(count, [1.0; 4]);
        per_point
    });
    let primitive = match name {
        "PointSet" => {
            indices.extend(0..count as u32);
            Primitive::Points
        }
        "LineSet" => {
            let mut next = 0usize;
            for &n in ints(doc, geometry, "vertexCount").iter() {
                let n = n.max(0) as usize;
                for k in 1..n {
                    if next + k < count {
                        indices.extend_from_slice(&[(next + k - 1) as u32, (next + k) as u32]);
                    }
                }
                next += n;
            }
            Primitive::Lines
        }
        _ => {
            let index = ints(doc, geometry, "coordIndex");
            let color_index = doc
                .node(geometry)
                .value("colorIndex")
                .and_then(|v| v.as_int32s());
            let per_vertex = boolean(doc, geometry, "colorPerVertex", true);
            // Colours per polyline or per index slot need a vertex per segment end.
            let source_colors = colors.take();
            let color_of = |slot: usize, polyline: usize, i: i32| -> [f32; 4] {
                let Some(c) = &source_colors else {
                    return [1.0; 4];
                };
                let element = match (per_vertex, color_index) {
                    (true, Some(ci)) if !ci.is_empty() => ci.get(slot).copied().unwrap_or(-1),
                    (true, _) => i,
                    (false, Some(ci)) if !ci.is_empty() => ci.get(polyline).copied().unwrap_or(-1),
                    (false, _) => polyline as i32,
                };
                usize::try_from(element)
                    .ok()
                    .and_then(|e| c.get(e))
                    .copied()
                    .unwrap_or([1.0; 4])
            };
            let mut expanded_positions = Vec::new();
            let mut expanded_colors = Vec::new();
            let mut polyline = 0usize;
            let mut previous: Option<(usize, i32)> = None;
            for (slot, &i) in index.iter().enumerate() {
                if i < 0 {
                    polyline += 1;
                    previous = None;
                    continue;
                }
                if let (Some((prev_slot, prev)), Some(_)) = (previous, positions.get(i as usize)) {
                    if let Some(p) = positions.get(prev as usize) {
                        expanded_positions.extend_from_slice(&[*p, positions[i as usize]]);
                        expanded_colors.extend_from_slice(&[
                            color_of(prev_slot, polyline, prev),
                            color_of(slot, polyline, i),
                        ]);
                    }
                }
                previous = Some((slot, i));
            }
            if source_colors.is_some() {
                colors = Some(expanded_colors);
            }
            indices.extend(0..expanded_positions.len() as u32);
            let mesh = LocalMesh {
                primitive: Primitive::Lines,
                positions: expanded_positions,
                origin,
                colors,
                colors_have_alpha,
                indices,
                ..LocalMesh::default()
            };
            return Built::Mesh(
                mesh,
                Shading {
                    solid: false,
                    unlit: true,
                },
            );
        }
    };
    let mesh = LocalMesh {
        primitive,
        positions,
        origin,
        colors,
        colors_have_alpha,
        indices,
        ..LocalMesh::default()
    };
    Built::Mesh(
        mesh,
        Shading {
            solid: false,
            unlit: true,
        },
    )
}

#[path = "extrusion.rs"]
mod extrusion;
#[path = "geometry2d.rs"]
mod geometry2d;
#[path = "primitives.rs"]
mod primitives;
