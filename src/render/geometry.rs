//! Geometry nodes to triangle, line or point meshes in the node's local coordinates.
//! Only what the material needs is computed: normals only for lit shapes, texture
//! coordinates only for textured ones.

use std::f32::consts::PI;

use super::draw_list::Primitive;
use super::fields::{boolean, child, float, floats, ints, vec3};
use super::polygons::{self, Attribute, Binding, Faces, Inputs, NormalGeneration};
use crate::model::{Document, NodeId};

/// A mesh in local coordinates.
#[derive(Clone, Debug)]
pub struct LocalMesh {
    pub primitive: Primitive,
    pub positions: Vec<[f32; 3]>,
    pub normals: Option<Vec<[f32; 3]>>,
    pub colors: Option<Vec<[f32; 4]>>,
    pub tex_coords: Option<Vec<[f32; 2]>>,
    pub indices: Vec<u32>,
}

#[derive(Copy, Clone, Debug)]
pub struct Needs {
    pub normals: bool,
    /// Where texture coordinates come from; None: not needed.
    pub tex_coords: Option<TexCoordSource>,
}

/// The texture coordinates a texture uses, as 12.2.4 resolves its mapping.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum TexCoordSource {
    /// The geometry's default texture coordinates.
    Default,
    /// This node of the geometry's texture coordinate list.
    Node(NodeId),
}

impl Needs {
    fn tex_coord_node(self) -> Option<NodeId> {
        match self.tex_coords {
            Some(TexCoordSource::Node(node)) => Some(node),
            _ => None,
        }
    }
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

pub fn build(doc: &Document, geometry: NodeId, needs: Needs) -> Built {
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
    match name {
        "Box" => surface(primitives::cuboid(vec3(doc, geometry, "size", [2.0; 3]))),
        "Sphere" => surface(primitives::sphere(float(doc, geometry, "radius", 1.0))),
        "Cylinder" => surface(primitives::cylinder(
            float(doc, geometry, "radius", 1.0),
            float(doc, geometry, "height", 2.0),
            [
                boolean(doc, geometry, "side", true),
                boolean(doc, geometry, "top", true),
                boolean(doc, geometry, "bottom", true),
            ],
        )),
        "Cone" => surface(primitives::cone(
            float(doc, geometry, "bottomRadius", 1.0),
            float(doc, geometry, "height", 2.0),
            boolean(doc, geometry, "side", true),
            boolean(doc, geometry, "bottom", true),
        )),
        "IndexedFaceSet" | "IndexedTriangleSet" | "TriangleSet" | "IndexedTriangleFanSet"
        | "IndexedTriangleStripSet" | "TriangleFanSet" | "TriangleStripSet" | "IndexedQuadSet"
        | "QuadSet" => match composed(doc, geometry, name, needs) {
            Some(mesh) => surface(mesh),
            None => Built::NotDrawn(format!(
                "{name}: its texture coordinates come from a node other than TextureCoordinate (such as TextureCoordinateGenerator), which is not applied"
            )),
        },
        "ElevationGrid" => surface(elevation_grid(doc, geometry, needs)),
        "LineSet" | "IndexedLineSet" | "PointSet" => lines_or_points(doc, geometry, name),
        other => Built::NotDrawn(format!("{other} is not drawn")),
    }
}

fn color_attribute<'d>(
    doc: &'d Document,
    geometry: NodeId,
) -> Option<(std::borrow::Cow<'d, [f32]>, usize)> {
    let color = child(doc, geometry, "color")?;
    let arity = if super::fields::type_is(doc, color, "ColorRGBA") {
        4
    } else {
        3
    };
    Some((floats(doc, color, "color"), arity))
}

/// IndexedFaceSet and the X3DComposedGeometryNode sets. None when texture coordinates
/// are needed from a node type not supported.
fn composed(doc: &Document, geometry: NodeId, name: &str, needs: Needs) -> Option<LocalMesh> {
    let points = child(doc, geometry, "coord")
        .map(|c| floats(doc, c, "point"))
        .unwrap_or_default();
    let point_count = points.len() / 3;
    let index_field = if name == "IndexedFaceSet" {
        "coordIndex"
    } else {
        "index"
    };
    let index = ints(doc, geometry, index_field);
    let mut faces = match name {
        "IndexedFaceSet" => Faces::from_index_list(&index, point_count),
        "IndexedTriangleSet" => groups(index.iter().map(|&i| i as i64), 3, point_count),
        "IndexedQuadSet" => groups(index.iter().map(|&i| i as i64), 4, point_count),
        "TriangleSet" => groups(0..point_count as i64, 3, point_count),
        "QuadSet" => groups(0..point_count as i64, 4, point_count),
        "IndexedTriangleFanSet" | "IndexedTriangleStripSet" => strips_or_fans(
            &split_at_minus_one(&index),
            name.contains("Fan"),
            point_count,
        ),
        _ => {
            let counts = ints(
                doc,
                geometry,
                if name == "TriangleFanSet" {
                    "fanCount"
                } else {
                    "stripCount"
                },
            );
            let mut runs = Vec::new();
            let mut next = 0i64;
            for &count in counts.iter() {
                let count = i64::from(count.max(0));
                runs.push((next..next + count).collect::<Vec<i64>>());
                next += count;
            }
            strips_or_fans(&runs, name.contains("Fan"), point_count)
        }
    };
    if !boolean(doc, geometry, "ccw", true) {
        faces.reverse_each();
    }
    let is_ifs = name == "IndexedFaceSet";
    let per_vertex_binding = |index_name: &str| -> Binding {
        match doc
            .node(geometry)
            .value(index_name)
            .and_then(|v| v.as_int32s())
        {
            Some(list) if is_ifs && !list.is_empty() => Binding::BySlot(list),
            _ => Binding::ByCoord,
        }
    };
    let face_binding = |index_name: &str| -> Binding {
        match doc
            .node(geometry)
            .value(index_name)
            .and_then(|v| v.as_int32s())
        {
            Some(list) if is_ifs && !list.is_empty() => Binding::ByFace(Some(list)),
            _ => Binding::ByFace(None),
        }
    };
    let normal_node = child(doc, geometry, "normal");
    let normal_values = normal_node.map(|n| floats(doc, n, "vector"));
    let normal_per_vertex = boolean(doc, geometry, "normalPerVertex", true);
    let normals = normal_values
        .as_ref()
        .filter(|_| needs.normals)
        .map(|values| Attribute {
            values,
            arity: 3,
            binding: if normal_per_vertex {
                per_vertex_binding("normalIndex")
            } else {
                face_binding("normalIndex")
            },
        });
    let color = color_attribute(doc, geometry);
    // Only IndexedFaceSet has colorPerVertex FALSE; the sets ignore it (11.4).
    let color_per_vertex = !is_ifs || boolean(doc, geometry, "colorPerVertex", true);
    let colors = color.as_ref().map(|(values, arity)| Attribute {
        values,
        arity: *arity,
        binding: if color_per_vertex {
            per_vertex_binding("colorIndex")
        } else {
            face_binding("colorIndex")
        },
    });
    let tex_node = needs.tex_coord_node();
    if tex_node.is_some_and(|t| !super::fields::type_is(doc, t, "TextureCoordinate")) {
        return None;
    }
    let tex_values = tex_node.map(|t| floats(doc, t, "point"));
    let tex_coords = tex_values.as_ref().map(|values| Attribute {
        values,
        arity: 2,
        binding: per_vertex_binding("texCoordIndex"),
    });
    let generation = match name {
        "IndexedFaceSet" => {
            let angle = float(doc, geometry, "creaseAngle", 0.0);
            if angle <= 0.0 {
                NormalGeneration::Flat
            } else if angle >= PI {
                NormalGeneration::Smooth
            } else {
                NormalGeneration::Crease(f64::from(angle))
            }
        }
        "TriangleSet" | "QuadSet" | "IndexedQuadSet" => NormalGeneration::Flat,
        _ if normal_per_vertex => NormalGeneration::Smooth,
        _ => NormalGeneration::Flat,
    };
    Some(polygons::build(Inputs {
        points: &points,
        faces,
        default_tex_coords: needs.tex_coords.is_some() && tex_coords.is_none(),
        normals,
        generation,
        need_normals: needs.normals,
        colors,
        tex_coords,
    }))
}

/// Consecutive groups of `size` indices as faces (an incomplete last group is dropped).
fn groups(index: impl Iterator<Item = i64>, size: usize, point_count: usize) -> Faces {
    let list: Vec<i64> = index.collect();
    let mut faces = Faces::new();
    for (g, group) in list.chunks_exact(size).enumerate() {
        if group.iter().all(|&i| i >= 0 && (i as usize) < point_count) {
            for (k, &i) in group.iter().enumerate() {
                faces.push_corner(i as u32, g * size + k);
            }
            faces.end_face();
        }
    }
    faces
}

fn split_at_minus_one(index: &[i32]) -> Vec<Vec<i64>> {
    index
        .split(|&i| i < 0)
        .map(|run| run.iter().map(|&i| i64::from(i)).collect())
        .collect()
}

/// Triangles of strips (alternating winding) or fans.
fn strips_or_fans(runs: &[Vec<i64>], fans: bool, point_count: usize) -> Faces {
    let mut faces = Faces::new();
    let ok = |i: i64| i >= 0 && (i as usize) < point_count;
    for run in runs {
        for k in 2..run.len() {
            let triangle = if fans {
                [run[0], run[k - 1], run[k]]
            } else if k % 2 == 0 {
                [run[k - 2], run[k - 1], run[k]]
            } else {
                [run[k - 1], run[k - 2], run[k]]
            };
            if triangle.iter().all(|&i| ok(i)) {
                for i in triangle {
                    // Vertex attributes of these sets are bound by coordinate index.
                    faces.push_corner(i as u32, i as usize);
                }
                faces.end_face();
            }
        }
    }
    faces
}

fn elevation_grid(doc: &Document, geometry: NodeId, needs: Needs) -> LocalMesh {
    let x_dim = doc.i32_of(geometry, "xDimension").unwrap_or(0).max(0) as usize;
    let z_dim = doc.i32_of(geometry, "zDimension").unwrap_or(0).max(0) as usize;
    let x_spacing = float(doc, geometry, "xSpacing", 1.0);
    let z_spacing = float(doc, geometry, "zSpacing", 1.0);
    let heights = floats(doc, geometry, "height");
    let count = x_dim.saturating_mul(z_dim).min(heights.len());
    if x_dim < 2 || z_dim < 2 || count < x_dim * z_dim {
        return polygons::build(Inputs {
            points: &[],
            faces: Faces::new(),
            normals: None,
            generation: NormalGeneration::Flat,
            need_normals: needs.normals,
            colors: None,
            tex_coords: None,
            default_tex_coords: false,
        });
    }
    let mut points = Vec::with_capacity(count * 3);
    for z in 0..z_dim {
        for x in 0..x_dim {
            points.extend_from_slice(&[
                x as f32 * x_spacing,
                heights[z * x_dim + x],
                z as f32 * z_spacing,
            ]);
        }
    }
    // Quads are (x, z), (x, z+1), (x+1, z+1), (x+1, z): counterclockwise seen from +Y.
    let mut index = Vec::with_capacity((x_dim - 1) * (z_dim - 1) * 5);
    for z in 0..z_dim - 1 {
        for x in 0..x_dim - 1 {
            let at = |x: usize, z: usize| (z * x_dim + x) as i32;
            index.extend_from_slice(&[at(x, z), at(x, z + 1), at(x + 1, z + 1), at(x + 1, z), -1]);
        }
    }
    let mut faces = Faces::from_index_list(&index, count);
    if !boolean(doc, geometry, "ccw", true) {
        faces.reverse_each();
    }
    let normal_values = child(doc, geometry, "normal").map(|n| floats(doc, n, "vector"));
    let per_vertex = |yes: bool| {
        if yes {
            Binding::ByCoord
        } else {
            Binding::ByFace(None)
        }
    };
    let normals = normal_values
        .as_ref()
        .filter(|_| needs.normals)
        .map(|values| Attribute {
            values,
            arity: 3,
            binding: per_vertex(boolean(doc, geometry, "normalPerVertex", true)),
        });
    let color = color_attribute(doc, geometry);
    let colors = color.as_ref().map(|(values, arity)| Attribute {
        values,
        arity: *arity,
        binding: per_vertex(boolean(doc, geometry, "colorPerVertex", true)),
    });
    // Default mapping (18.2.4): s along x, t along z, each from 0 to 1.
    let default_tex: Vec<f32> = (0..z_dim)
        .flat_map(|z| {
            (0..x_dim)
                .flat_map(move |x| [x as f32 / (x_dim - 1) as f32, z as f32 / (z_dim - 1) as f32])
        })
        .collect();
    let tex_values = needs
        .tex_coord_node()
        .filter(|&t| super::fields::type_is(doc, t, "TextureCoordinate"))
        .map(|t| floats(doc, t, "point"));
    let tex_coords = needs.tex_coords.is_some().then(|| Attribute {
        values: tex_values.as_deref().unwrap_or(&default_tex),
        arity: 2,
        binding: Binding::ByCoord,
    });
    let angle = float(doc, geometry, "creaseAngle", 0.0);
    let generation = if angle <= 0.0 {
        NormalGeneration::Flat
    } else if angle >= PI {
        NormalGeneration::Smooth
    } else {
        NormalGeneration::Crease(f64::from(angle))
    };
    polygons::build(Inputs {
        points: &points,
        faces,
        normals,
        generation,
        need_normals: needs.normals,
        colors,
        tex_coords,
        default_tex_coords: false,
    })
}

fn lines_or_points(doc: &Document, geometry: NodeId, name: &str) -> Built {
    let points = child(doc, geometry, "coord")
        .map(|c| floats(doc, c, "point"))
        .unwrap_or_default();
    let count = points.len() / 3;
    let positions: Vec<[f32; 3]> = points.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect();
    let color = color_attribute(doc, geometry);
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
                normals: None,
                colors,
                tex_coords: None,
                indices,
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
        normals: None,
        colors,
        tex_coords: None,
        indices,
    };
    Built::Mesh(
        mesh,
        Shading {
            solid: false,
            unlit: true,
        },
    )
}

#[path = "primitives.rs"]
mod primitives;
