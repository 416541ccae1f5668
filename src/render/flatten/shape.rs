//! One Shape: its look, the texture coordinate sets its textures sample (12.2.4 resolved
//! against this geometry and Appearance, the same resolution the checker uses), its
//! geometry built with only what those need, waiting in local coordinates for the camera.

use glam::{DMat4, DVec3, Vec3};

use super::appearance::{unlit_from, Role, Rule};
use super::place::{Channel, Pending, TextureTransform};
use super::{Context, Scope, Walker};
use crate::limits::{MAX_FACE_CORNERS, MAX_RENDER_SHAPES};
use crate::model::bounds::{geometry_bounds, Affine, Bounds};
use crate::model::texture_mapping::{texture_coordinates, texture_transforms, MappingList};
use crate::model::NodeId;
use crate::render::draw_list::{
    CubeLookup, LightingModel, Primitive, Stage, Stroke, TextureRef, Textures, MAX_TEX_COORD_SETS,
};
use crate::render::fields::{child, type_is};
use crate::render::geometry::{self, Built, Needs, TexCoordSource};
use crate::render::mesh::LocalMesh;
use crate::render::texgen::{Generator, Mode};

/// A texture coordinate set as the shape's textures ask for it: its source node (None:
/// the default coordinates) and its transformation node.
type SetKey = (Option<NodeId>, Option<NodeId>);

impl Walker<'_> {
    pub(super) fn shape(&mut self, context: Context, id: NodeId, world: DMat4, scope: &Scope) {
        let doc = context.doc;
        let Some(geometry) = child(doc, id, "geometry") else {
            return;
        };
        let appearance = child(doc, id, "appearance");
        let look = self.appearance(context, appearance);
        let coordinates = texture_coordinates(doc, geometry);
        let transforms = texture_transforms(doc, appearance);

        // Each texture's set, shared by the textures that ask for the same one.
        let mut keys: Vec<SetKey> = Vec::new();
        let mut sets_of_uses = Vec::with_capacity(look.textures.len());
        for used in &look.textures {
            let key = set_key(doc, &coordinates, &transforms, &used.rule);
            let set = match keys.iter().position(|k| *k == key) {
                Some(set) => set,
                None if keys.len() < MAX_TEX_COORD_SETS => {
                    keys.push(key);
                    keys.len() - 1
                }
                None => {
                    self.note(
                        context,
                        id,
                        format!(
                            "textures needing more than {MAX_TEX_COORD_SETS} texture coordinate sets use the first"
                        ),
                    );
                    0
                }
            };
            sets_of_uses.push(set);
        }
        let mut sources = Vec::with_capacity(keys.len());
        let mut channels = Vec::with_capacity(keys.len());
        for &(source, transform) in &keys {
            let (source, generator) = self.tex_coord_source(context, source);
            sources.push(source);
            channels.push(Channel {
                generator,
                transform: transform.and_then(|t| self.texture_transform(context, t)),
            });
        }

        let lit = |m: &crate::render::draw_list::Material| m.model != LightingModel::Unlit;
        let any_lit = lit(&look.front) || look.back.as_ref().is_some_and(lit);
        let generators_need_normals = channels
            .iter()
            .any(|c| c.generator.is_some_and(|g| g.mode.needs_normals()));
        // Cube maps are looked up by the normal (34.2).
        let cube_maps = look.textures.iter().any(|t| t.texture.cube);
        let generators_need_normals = generators_need_normals || cube_maps;
        let needs = Needs {
            normals: any_lit || generators_need_normals,
            tex_coords: sources,
        };
        if self.shapes.len() >= MAX_RENDER_SHAPES {
            self.stop(context, format!("{MAX_RENDER_SHAPES} shape instances"));
            return;
        }
        // Checked before building too, so that a geometry past the budget costs nothing.
        let budget = self.options.primitive_budget;
        let bound = geometry::primitive_bound(doc, geometry);
        if self.spent.primitives.saturating_add(bound) > budget {
            self.stop(context, format!("{budget} triangles, lines and points"));
            return;
        }
        let built = if type_is(doc, geometry, "Text") {
            match self.text(context, geometry, &needs, budget - self.spent.primitives) {
                Some((mesh, shading)) => Built::Mesh(mesh, shading),
                None => return,
            }
        } else {
            geometry::build(doc, geometry, &needs)
        };
        let (mut mesh, shading) = match built {
            Built::Mesh(mesh, shading) => (mesh, shading),
            Built::NotDrawn(reason) => {
                self.note(context, geometry, reason);
                return;
            }
        };
        if mesh.faces_over_limit > 0 {
            let message = format!(
                "{} faces of more than {MAX_FACE_CORNERS} corners are not drawn",
                mesh.faces_over_limit
            );
            self.push_note(context, geometry, message, true);
        }
        let mut front = look.front;
        let mut back = look.back;
        if shading.unlit {
            // Lines and points without normals are unlit: the emissive colour (17.2.2.4).
            front = unlit_from(front);
            back = back.map(unlit_from);
        }
        let lit_now = lit(&front) || back.as_ref().is_some_and(lit);
        if !(lit_now || generators_need_normals) {
            mesh.normals = None;
        }
        // Lines and points have no texture coordinates: their textures are not sampled.
        let textured = mesh.tex_coords.len() == keys.len() && !keys.is_empty();
        if !textured {
            mesh.tex_coords.clear();
            channels.clear();
        }
        let mut textures = Textures {
            factor: look.factor,
            ..Textures::default()
        };
        if textured {
            for (used, &set) in look.textures.iter().zip(&sets_of_uses) {
                let texture = TextureRef {
                    texture: used.texture.index,
                    tex_coords: set,
                };
                let mut cube = None;
                if used.texture.cube {
                    let first_stage =
                        matches!(used.role, Role::Stage { .. }) && textures.main.is_empty();
                    if !first_stage || mesh.normals.is_none() {
                        self.note(
                            context,
                            id,
                            "a cube map texture is drawn only as the first texture of a surface; this one is not drawn".into(),
                        );
                        continue;
                    }
                    cube = Some(self.cube_lookup(context, id, channels.get(set)));
                }
                match used.role {
                    Role::Stage {
                        mode,
                        alpha_mode,
                        source,
                        function,
                    } => textures.main.push(Stage {
                        texture,
                        cube,
                        mode,
                        alpha_mode,
                        source,
                        function,
                    }),
                    // Only the lit models sample the other textures.
                    _ if !lit_now => {}
                    Role::Emissive => textures.emissive = Some(texture),
                    Role::Normal => textures.normal = Some(texture),
                    Role::Occlusion => textures.occlusion = Some(texture),
                    Role::Specular => textures.specular = Some(texture),
                    Role::Shininess => textures.shininess = Some(texture),
                    Role::Ambient => textures.ambient = Some(texture),
                    Role::MetallicRoughness => textures.metallic_roughness = Some(texture),
                }
            }
        }
        let tangents_for = textures
            .normal
            .filter(|_| mesh.normals.is_some())
            .map(|t| t.tex_coords);
        if textures.normal.is_some() && tangents_for.is_none() {
            textures.normal = None;
        }

        let back = if shading.solid {
            None
        } else {
            Some(back.unwrap_or(front))
        };
        let translucent_colors = mesh.colors_have_alpha
            && mesh
                .colors
                .as_ref()
                .is_some_and(|c| c.iter().any(|c| c[3] < 1.0));
        let blended = match look.alpha_mode.as_str() {
            "OPAQUE" | "MASK" => false,
            "BLEND" => true,
            _ => {
                front.alpha < 1.0
                    || back.is_some_and(|b| b.alpha < 1.0)
                    || (!textures.main.is_empty() && look.translucent_texture())
                    || translucent_colors
            }
        };
        let mesh_primitive = mesh.primitive;
        let primitives = mesh.indices.len() / mesh.primitive.arity();
        if self.spent.primitives + primitives > budget {
            self.stop(context, format!("{budget} triangles, lines and points"));
            return;
        }
        self.spent.primitives += primitives;
        // Geometry whose bounds the model does not know (Text) is framed as built.
        if let Some(b) =
            geometry_bounds(doc, geometry, &affine(world)).or_else(|| mesh_bounds(&mesh, world))
        {
            self.bounds = self.bounds.union(&b);
        }
        self.shapes.push(Pending {
            mesh,
            world,
            front,
            back,
            textures,
            channels,
            tangents_for,
            scope: scope.clone(),
            blended,
            alpha_cutoff: if look.alpha_mode == "MASK" {
                look.alpha_cutoff
            } else {
                0.0
            },
            stroke: match mesh_primitive {
                Primitive::Lines => look.line,
                Primitive::Points => look.point,
                Primitive::Triangles => Stroke::default(),
            },
        });
    }

    /// How the geometry supplies a set whose source node is `source` (None: default).
    fn tex_coord_source(
        &mut self,
        context: Context,
        source: Option<NodeId>,
    ) -> (TexCoordSource, Option<Generator>) {
        let doc = context.doc;
        let Some(node) = source else {
            return (TexCoordSource::Default, None);
        };
        match doc.node(node).type_name() {
            "TextureCoordinate" => (TexCoordSource::Given(node), None),
            "TextureCoordinateGenerator" => match Generator::of(doc, node) {
                Ok(generator) => (TexCoordSource::Generated, Some(generator)),
                Err(reason) => {
                    self.note(context, node, reason);
                    (TexCoordSource::Default, None)
                }
            },
            other => {
                self.note(
                    context,
                    node,
                    format!("{other} is not drawn: the default texture coordinates are used"),
                );
                (TexCoordSource::Default, None)
            }
        }
    }

    /// The direction a cube map is looked up with: by the TextureCoordinateGenerator of
    /// its coordinates, or the world reflection vector (none given: the environment keeps
    /// still as the viewer turns, as a reflection of the surroundings does).
    fn cube_lookup(
        &mut self,
        context: Context,
        id: NodeId,
        channel: Option<&Channel>,
    ) -> CubeLookup {
        match channel.and_then(|c| c.generator).map(|g| g.mode) {
            None => CubeLookup::WorldReflection,
            Some(Mode::CameraSpaceReflectionVector) => CubeLookup::CameraReflection,
            Some(Mode::CameraSpaceNormal) => CubeLookup::CameraNormal,
            Some(other) => {
                self.note(
                    context,
                    id,
                    format!("a cube map with TextureCoordinateGenerator {other:?} is drawn with the world reflection vector"),
                );
                CubeLookup::WorldReflection
            }
        }
    }

    fn texture_transform(&mut self, context: Context, node: NodeId) -> Option<TextureTransform> {
        let doc = context.doc;
        if type_is(doc, node, "TextureTransform") {
            return Some(TextureTransform::of(doc, node));
        }
        let name = doc.node(node).type_name().to_string();
        self.note(context, node, format!("{name} is not applied"));
        None
    }
}

/// The set a texture samples: by its xxxTextureMapping (12.2.4, unresolved mappings fall
/// back as 4.1 says), or as MultiTexture stage i (18.4.4: the i-th coordinates, the last
/// when there are fewer; 18.4.5: the i-th transformation, none when there are fewer).
fn set_key(
    doc: &crate::model::Document,
    coordinates: &MappingList,
    transforms: &MappingList,
    rule: &Rule,
) -> SetKey {
    match rule {
        Rule::Mapping(mapping) => (
            coordinates.resolve(doc, mapping).used(),
            transforms.resolve(doc, mapping).used(),
        ),
        Rule::Stage(i) => (
            coordinates
                .items
                .get(*i)
                .or(coordinates.items.last())
                .map(|c| c.node),
            transforms.items.get(*i).map(|c| c.node),
        ),
    }
}

/// The world bounds of a built mesh's vertices; None when it has none.
fn mesh_bounds(mesh: &LocalMesh, world: DMat4) -> Option<Bounds> {
    let origin = DVec3::from_array(mesh.origin);
    let mut bounds = Bounds::EMPTY;
    for p in &mesh.positions {
        let q = world.transform_point3(origin + Vec3::from_array(*p).as_dvec3());
        if q.is_finite() {
            bounds.min = DVec3::from_array(bounds.min).min(q).to_array();
            bounds.max = DVec3::from_array(bounds.max).max(q).to_array();
        }
    }
    (!bounds.is_empty()).then_some(bounds)
}

/// A transform as model::bounds takes it.
fn affine(m: DMat4) -> Affine {
    Affine {
        linear: std::array::from_fn(|r| std::array::from_fn(|c| m.col(c)[r])),
        translation: m.w_axis.truncate().to_array(),
    }
}
