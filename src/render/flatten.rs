//! Scene model → [`DrawList`]. Walks the scene graph from the Scene (and local Inline
//! files), composing transforms in f64; builds each Shape's geometry in local
//! coordinates with only the attributes its material needs; resolves materials,
//! textures, lights, the camera, background and fog; finally places every vertex
//! relative to the eye in f64 and rounds once. The guarantees the GPU part relies on are
//! written in [`super::draw_list`]. What cannot be drawn is returned as [`Note`]s.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::{DMat3, DMat4, DQuat, DVec3};

use super::draw_list::{
    Camera, DrawList, Fog, Light, LightKind, LightingModel, Material, Mesh, Primitive, MAX_LIGHTS,
};
use super::fields::{boolean, child, color, float, floats, rotation, type_is, unit, vec3};
use super::geometry::{self, Built, LocalMesh, Needs, TexCoordSource};
use super::textures;
use crate::model::bounds::{geometry_bounds, local_transform, Affine, Bounds};
use crate::model::texture_mapping::{texture_coordinates, texture_transforms};
use crate::model::{Document, NodeId};

/// Inline files nested deeper than this are not loaded (and cycles end here).
const MAX_INLINE_DEPTH: usize = 8;
/// Grouping nodes nested deeper than this are not walked (the checker reports nesting).
const MAX_DEPTH: usize = 256;
/// Node instances walked at most (so at most as many shape instances): DEF/USE can make a
/// small file stand for 2^199 of them.
const MAX_NODE_INSTANCES: u64 = 1_000_000;
/// Texture bytes (RGBA8) loaded at most, over all textures.
const MAX_TEXTURE_BYTES: usize = 512 << 20;

/// Triangles (lines, points) drawn at most for an image of this size: 16 per pixel, at
/// least 4 million and at most 16 million, so that memory stays bounded (~150 bytes each).
pub fn primitive_budget(width: u32, height: u32) -> usize {
    (u64::from(width) * u64::from(height) * 16).clamp(4_000_000, 16_000_000) as usize
}

/// Something in the scene that is not drawn, or drawn approximately.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    /// The node in the checked document (None inside an Inline file).
    pub node: Option<NodeId>,
    pub message: String,
    /// Reported as LIMIT_EXCEEDED rather than VALIDATION_INCOMPLETE.
    pub limit: bool,
}

pub struct Options<'a> {
    /// The DEF name of the Viewpoint to use; None: the first one, else automatic.
    pub camera: Option<&'a str>,
    /// The document's directory (relative urls), and the tree files may be read from.
    pub base_dir: PathBuf,
    pub x3d_version_3: bool,
    /// Triangles, lines and points drawn at most (see [`primitive_budget`]).
    pub primitive_budget: usize,
}

pub struct Flattened {
    pub list: DrawList,
    pub notes: Vec<Note>,
}

/// A shape in local coordinates, waiting for the camera.
struct Pending {
    mesh: LocalMesh,
    world: DMat4,
    front: Material,
    back: Option<Material>,
    scoped_lights: u32,
    blended: bool,
    alpha_cutoff: f32,
}

/// A loaded texture: its index in the draw list, channel count, and translucency.
type TextureEntry = (usize, u8, bool);

/// A TextureTransform as a function of texture coordinates.
type TexCoordTransform = Box<dyn Fn([f32; 2]) -> [f32; 2]>;

struct PendingLight {
    light: Light,
    location: DVec3,
}

struct ViewpointFound {
    world: DMat4,
    position: DVec3,
    orientation: DQuat,
    field_of_view: f32,
}

struct Walker<'o> {
    options: &'o Options<'o>,
    notes: Vec<Note>,
    shapes: Vec<Pending>,
    lights: Vec<PendingLight>,
    global_lights: u32,
    textures: Vec<super::draw_list::Texture>,
    /// (document serial, node) → texture index, channels, translucent.
    texture_cache: HashMap<(usize, NodeId), Option<TextureEntry>>,
    viewpoint: Option<ViewpointFound>,
    background: Option<[f32; 3]>,
    fog: Option<Fog>,
    navigation: Option<Navigation>,
    documents: usize,
    inline_stack: Vec<PathBuf>,
    spent: Spent,
    /// World bounds of the shapes drawn (model::bounds), for framing and clip planes.
    bounds: Bounds,
}

/// What the walk has expanded so far, against the caps.
#[derive(Default)]
struct Spent {
    node_instances: u64,
    primitives: usize,
    texture_bytes: usize,
    /// A cap was hit: nothing more is walked.
    stopped: bool,
}

#[derive(Clone, Copy)]
struct Navigation {
    headlight: bool,
    avatar_size: Option<f32>,
    visibility_limit: f32,
}

/// The document being walked: the checked one (serial 0) or an Inline file.
#[derive(Clone, Copy)]
struct Context<'d> {
    doc: &'d Document,
    serial: usize,
    base: &'d Path,
}

pub fn flatten(doc: &Document, options: &Options) -> Result<Flattened, String> {
    let mut walker = Walker {
        options,
        notes: Vec::new(),
        shapes: Vec::new(),
        lights: Vec::new(),
        global_lights: 0,
        textures: Vec::new(),
        texture_cache: HashMap::new(),
        viewpoint: None,
        background: None,
        fog: None,
        navigation: None,
        documents: 1,
        inline_stack: Vec::new(),
        spent: Spent::default(),
        bounds: Bounds::EMPTY,
    };
    if let Some(name) = options.camera {
        let found = doc.iter().find(|(_, n)| {
            n.is_a("X3DViewpointNode") && n.def_name.as_ref().is_some_and(|d| d.text == name)
        });
        if found.is_none() {
            return Err(format!(
                "--camera {name}: the scene has no Viewpoint DEF'd `{name}`"
            ));
        }
    }
    let context = Context {
        doc,
        serial: 0,
        base: &options.base_dir,
    };
    let roots: Vec<NodeId> = doc.scene.iter().map(|c| c.node).collect();
    walker.walk_children(context, &roots, DMat4::IDENTITY, 0, 0);
    Ok(walker.finish())
}

impl Walker<'_> {
    fn note(&mut self, context: Context, node: NodeId, message: String) {
        self.push_note(context, node, message, false);
    }

    /// A note; `limit` when a limit of [`crate::limits`] was reached.
    fn push_note(&mut self, context: Context, node: NodeId, message: String, limit: bool) {
        let in_main = context.serial == 0;
        let message = if in_main {
            message
        } else {
            format!("in an Inline file: {message}")
        };
        let note = Note {
            node: in_main.then_some(node),
            message: format!("renderer: {message}"),
            limit,
        };
        if !self.notes.contains(&note) {
            self.notes.push(note);
        }
    }

    /// The transformation a grouping node applies (model::bounds, 10.4.4); None, noted,
    /// when a value is not finite: its children are not drawn.
    fn local_transform(&mut self, context: Context, id: NodeId) -> Option<DMat4> {
        let Some(a) = local_transform(context.doc, id) else {
            let name = context.doc.node(id).type_name();
            self.note(
                context,
                id,
                format!("{name} with a non-finite value: its children are not drawn"),
            );
            return None;
        };
        let l = a.linear;
        Some(DMat4::from_cols_array_2d(&[
            [l[0][0], l[1][0], l[2][0], 0.0],
            [l[0][1], l[1][1], l[2][1], 0.0],
            [l[0][2], l[1][2], l[2][2], 0.0],
            [a.translation[0], a.translation[1], a.translation[2], 1.0],
        ]))
    }

    /// Stops the walk at a cap, saying how far the scene expands and what was drawn.
    fn stop(&mut self, context: Context, drawn: String) {
        self.spent.stopped = true;
        let expands = match context.doc.instances() {
            u64::MAX => "more than 10^19".to_string(),
            n => n.to_string(),
        };
        self.notes.push(Note {
            node: None,
            message: format!(
                "renderer: the scene expands to {expands} node instances; drawn up to {drawn}"
            ),
            limit: false,
        });
    }

    /// Walks a list of sibling nodes: their scoped lights first (they light all
    /// siblings and their descendants, 17.2.1.2), then each node.
    fn walk_children(
        &mut self,
        context: Context,
        children: &[NodeId],
        world: DMat4,
        scope: u32,
        depth: usize,
    ) {
        let mut scope = scope;
        for &id in children {
            let node = context.doc.node(id);
            if node.is_a("X3DLightNode") {
                if let Some(bit) = self.add_light(context, id, world) {
                    if boolean(context.doc, id, "global", !node.is_a("DirectionalLight")) {
                        self.global_lights |= bit;
                    } else {
                        scope |= bit;
                    }
                }
            }
        }
        for &id in children {
            self.walk(context, id, world, scope, depth + 1);
        }
    }

    fn walk(&mut self, context: Context, id: NodeId, world: DMat4, scope: u32, depth: usize) {
        if depth > MAX_DEPTH || self.spent.stopped {
            return;
        }
        self.spent.node_instances += 1;
        if self.spent.node_instances > MAX_NODE_INSTANCES {
            self.stop(
                context,
                format!("the first {MAX_NODE_INSTANCES} node instances"),
            );
            return;
        }
        let doc = context.doc;
        let node = doc.node(id);
        let Some(def) = node.def() else {
            if matches!(node.kind, crate::model::NodeKind::ProtoInstance { .. }) {
                self.note(context, id, "prototype instances are not drawn".into());
            }
            return;
        };
        let kids =
            |name: &str| -> Vec<NodeId> { node.children(name).iter().map(|c| c.node).collect() };
        match def.name {
            "Transform" => {
                if let Some(local) = self.local_transform(context, id) {
                    self.walk_children(context, &kids("children"), world * local, scope, depth);
                }
            }
            "Switch" => {
                let which = doc.i32_of(id, "whichChoice").unwrap_or(-1);
                let choices = kids(if node.entry("choice").is_some() {
                    "choice"
                } else {
                    "children"
                });
                if let Some(&chosen) = usize::try_from(which).ok().and_then(|w| choices.get(w)) {
                    self.walk_children(context, &[chosen], world, scope, depth);
                }
            }
            "LOD" => {
                let levels = kids(if node.entry("level").is_some() {
                    "level"
                } else {
                    "children"
                });
                if levels.len() > 1 {
                    self.note(
                        context,
                        id,
                        "LOD: only the first (most detailed) level is drawn".into(),
                    );
                }
                if let Some(&first) = levels.first() {
                    self.walk_children(context, &[first], world, scope, depth);
                }
            }
            "Billboard" => {
                self.note(
                    context,
                    id,
                    "Billboard is drawn as a Group (not turned to the viewer)".into(),
                );
                self.walk_children(context, &kids("children"), world, scope, depth);
            }
            "Inline" => self.inline(context, id, world, scope, depth),
            "Shape" => self.shape(context, id, world, scope),
            "Viewpoint" | "OrthoViewpoint" => self.viewpoint(context, id, world),
            "Background" | "TextureBackground"
                if self.background.is_none() && context.serial == 0 =>
            {
                let sky = floats(doc, id, "skyColor");
                self.background = Some(match sky.as_ref() {
                    [r, g, b, ..] => [unit(*r), unit(*g), unit(*b)],
                    _ => [0.0; 3],
                });
                if sky.len() > 3
                    || !floats(doc, id, "groundColor").is_empty()
                    || !doc.node(id).children("frontTexture").is_empty()
                    || node.entry("frontUrl").is_some()
                {
                    self.note(
                        context,
                        id,
                        format!("{}: only the first sky colour is drawn", def.name),
                    );
                }
            }
            "Fog" if self.fog.is_none() && context.serial == 0 => {
                let range = float(doc, id, "visibilityRange", 0.0);
                if range > 0.0 {
                    self.fog = Some(Fog {
                        color: color(doc, id, "color", [1.0; 3]),
                        exponential: doc.string_of(id, "fogType").as_deref() == Some("EXPONENTIAL"),
                        visibility_range: range,
                    });
                }
            }
            "NavigationInfo" if self.navigation.is_none() && context.serial == 0 => {
                let avatar = floats(doc, id, "avatarSize");
                self.navigation = Some(Navigation {
                    headlight: boolean(doc, id, "headlight", true),
                    avatar_size: avatar
                        .first()
                        .copied()
                        .filter(|a| a.is_finite() && *a > 0.0),
                    visibility_limit: float(doc, id, "visibilityLimit", 0.0).max(0.0),
                });
            }
            _ if def.is_a("X3DLightNode") => {}
            _ if def.is_a("X3DGroupingNode") => {
                // Group, StaticGroup, Collision (not its proxy), Anchor, CAD groups
                // (CADPart transforms like a Transform).
                if let Some(local) = self.local_transform(context, id) {
                    self.walk_children(context, &kids("children"), world * local, scope, depth);
                }
            }
            _ if def.is_a("X3DShapeNode") => {
                self.note(context, id, format!("{} is not drawn", def.name));
            }
            _ => {}
        }
    }

    fn inline(&mut self, context: Context, id: NodeId, world: DMat4, scope: u32, depth: usize) {
        let doc = context.doc;
        if !boolean(doc, id, "load", true) {
            return;
        }
        if self.inline_stack.len() >= MAX_INLINE_DEPTH {
            self.note(
                context,
                id,
                format!("Inline nested deeper than {MAX_INLINE_DEPTH} files is not drawn"),
            );
            return;
        }
        let urls = doc
            .value_of(id, "url")
            .and_then(|v| v.as_strings().map(<[String]>::to_vec))
            .unwrap_or_default();
        let mut reasons = Vec::new();
        for url in &urls {
            let path = match textures::local_file(url, context.base, &self.options.base_dir) {
                Ok(path) => path,
                Err(e) => {
                    reasons.push(format!("{url}: {e}"));
                    continue;
                }
            };
            if self.inline_stack.contains(&path) {
                reasons.push(format!("{url}: inlines itself"));
                continue;
            }
            let bytes = match std::fs::read(&path) {
                Ok(bytes) => bytes,
                Err(e) => {
                    reasons.push(format!("{url}: {e}"));
                    continue;
                }
            };
            let Some(inlined) = crate::parse::read(&bytes).document else {
                reasons.push(format!("{url}: not an X3D document"));
                continue;
            };
            let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
            let serial = self.documents;
            self.documents += 1;
            self.inline_stack.push(path);
            let inner = Context {
                doc: &inlined,
                serial,
                base: &base,
            };
            let roots: Vec<NodeId> = inlined.scene.iter().map(|c| c.node).collect();
            self.walk_children(inner, &roots, world, scope, depth);
            self.inline_stack.pop();
            return;
        }
        if !reasons.is_empty() {
            self.note(
                context,
                id,
                format!("Inline not drawn ({})", reasons.join("; ")),
            );
        }
    }

    fn viewpoint(&mut self, context: Context, id: NodeId, world: DMat4) {
        if context.serial != 0 || self.viewpoint.is_some() && self.options.camera.is_none() {
            return;
        }
        let doc = context.doc;
        if let Some(name) = self.options.camera {
            if doc
                .node(id)
                .def_name
                .as_ref()
                .is_none_or(|d| d.text != name)
            {
                return;
            }
        }
        if type_is(doc, id, "OrthoViewpoint") {
            self.note(
                context,
                id,
                "OrthoViewpoint is drawn with a perspective projection".into(),
            );
        }
        let position = vec3(doc, id, "position", [0.0, 0.0, 10.0]).map(f64::from);
        self.viewpoint = Some(ViewpointFound {
            world,
            position: DVec3::from_array(position),
            orientation: rotation(doc, id, "orientation"),
            field_of_view: float(doc, id, "fieldOfView", std::f32::consts::FRAC_PI_4),
        });
    }

    /// Registers a light; its bit, or None when it is off or over the limit.
    fn add_light(&mut self, context: Context, id: NodeId, world: DMat4) -> Option<u32> {
        let doc = context.doc;
        if !boolean(doc, id, "on", true) {
            return None;
        }
        if self.lights.len() >= MAX_LIGHTS - 1 {
            // One slot stays free for the headlight.
            self.note(
                context,
                id,
                format!("lights beyond the first {} are not drawn", MAX_LIGHTS - 1),
            );
            return None;
        }
        let kind = match doc.node(id).type_name() {
            "DirectionalLight" => LightKind::Directional,
            "PointLight" => LightKind::Point,
            "SpotLight" => LightKind::Spot,
            other => {
                self.note(context, id, format!("{other} is not drawn"));
                return None;
            }
        };
        let direction = world.transform_vector3(DVec3::from_array(
            vec3(doc, id, "direction", [0.0, 0.0, -1.0]).map(f64::from),
        ));
        let location = world.transform_point3(DVec3::from_array(
            vec3(doc, id, "location", [0.0; 3]).map(f64::from),
        ));
        let mut attenuation = vec3(doc, id, "attenuation", [1.0, 0.0, 0.0]).map(|c| c.max(0.0));
        if attenuation == [0.0; 3] {
            attenuation = [1.0, 0.0, 0.0];
        }
        let scale = world.to_scale_rotation_translation().0.abs().max_element();
        let radius = f64::from(float(doc, id, "radius", 100.0).max(0.0)) * scale;
        let light = Light {
            kind,
            color: color(doc, id, "color", [1.0; 3]),
            intensity: float(doc, id, "intensity", 1.0).max(0.0),
            ambient_intensity: unit(float(doc, id, "ambientIntensity", 0.0)),
            location: [0.0; 3],
            direction: unit_vector(direction),
            attenuation,
            radius: radius as f32,
            beam_width: float(doc, id, "beamWidth", std::f32::consts::FRAC_PI_4),
            cut_off_angle: float(doc, id, "cutOffAngle", std::f32::consts::FRAC_PI_2),
        };
        self.lights.push(PendingLight { light, location });
        Some(1 << (self.lights.len() - 1))
    }

    fn shape(&mut self, context: Context, id: NodeId, world: DMat4, scope: u32) {
        let doc = context.doc;
        let Some(geometry) = child(doc, id, "geometry") else {
            return;
        };
        let appearance = child(doc, id, "appearance");
        let look = self.appearance(context, appearance);
        let normals = look.front.model != LightingModel::Unlit
            || look.back.is_some_and(|b| b.model != LightingModel::Unlit);
        // 12.2.4: each side's texture takes the coordinates and transform its mapping names.
        let coordinates = texture_coordinates(doc, geometry);
        let transforms = texture_transforms(doc, appearance);
        let mapped = |material: Option<&Material>, mapping: &str| {
            material.and_then(|m| m.texture).map(|_| {
                let source = match coordinates.resolve(doc, mapping).used() {
                    Some(node) => TexCoordSource::Node(node),
                    None => TexCoordSource::Default,
                };
                (source, transforms.resolve(doc, mapping).used())
            })
        };
        let front_mapping = mapped(Some(&look.front), &look.front_mapping);
        let back_mapping = mapped(look.back.as_ref(), &look.back_mapping);
        if front_mapping.is_some() && back_mapping.is_some() && front_mapping != back_mapping {
            // 12.2.3 forbids this (BACK_MATERIAL_MAPPING_MISMATCH); one set is drawn.
            self.note(
                context,
                id,
                "the backMaterial's texture is drawn on the material's texture coordinates".into(),
            );
        }
        let Some((mesh, shading)) =
            self.textured_mesh(context, geometry, normals, front_mapping.or(back_mapping))
        else {
            return;
        };
        let mut front = look.front;
        let mut back = look.back;
        if mesh.tex_coords.is_none() {
            front.texture = None;
            if let Some(b) = back.as_mut() {
                b.texture = None;
            }
        }
        if shading.unlit {
            // Lines and points without normals are unlit: the emissive colour (17.2.2.4).
            front = unlit_from(front);
            back = back.map(unlit_from);
        }
        let back = if shading.solid {
            None
        } else {
            Some(back.unwrap_or(front))
        };
        let translucent_colors = mesh
            .colors
            .as_ref()
            .is_some_and(|c| c.iter().any(|c| c[3] < 1.0));
        let blended = match look.alpha_mode.as_str() {
            "OPAQUE" | "MASK" => false,
            "BLEND" => true,
            _ => {
                front.alpha < 1.0
                    || back.is_some_and(|b| b.alpha < 1.0)
                    || look.translucent_texture
                    || translucent_colors
            }
        };
        let per = match mesh.primitive {
            Primitive::Triangles => 3,
            Primitive::Lines => 2,
            Primitive::Points => 1,
        };
        let primitives = mesh.indices.len() / per;
        if self.spent.primitives + primitives > self.options.primitive_budget {
            let budget = self.options.primitive_budget;
            self.stop(context, format!("{budget} triangles, lines and points"));
            return;
        }
        self.spent.primitives += primitives;
        if let Some(b) = geometry_bounds(doc, geometry, &affine(world)) {
            self.bounds = self.bounds.union(&b);
        }
        self.shapes.push(Pending {
            mesh,
            world,
            front,
            back,
            scoped_lights: scope,
            blended,
            alpha_cutoff: if look.alpha_mode == "MASK" {
                look.alpha_cutoff
            } else {
                0.0
            },
        });
    }

    /// The mesh of a geometry with texture coordinates from `mapping` (when textured)
    /// already transformed; None (and a note) when it cannot be drawn.
    fn textured_mesh(
        &mut self,
        context: Context,
        geometry: NodeId,
        normals: bool,
        mapping: Option<(TexCoordSource, Option<NodeId>)>,
    ) -> Option<(LocalMesh, geometry::Shading)> {
        let doc = context.doc;
        let needs = Needs {
            normals,
            tex_coords: mapping.map(|(source, _)| source),
        };
        let (mut mesh, shading) = match geometry::build(doc, geometry, needs) {
            Built::Mesh(mesh, shading) => (mesh, shading),
            Built::NotDrawn(reason) => {
                self.note(context, geometry, reason);
                return None;
            }
        };
        if !needs.normals || shading.unlit {
            mesh.normals = None;
        }
        if needs.tex_coords.is_none() {
            mesh.tex_coords = None;
        }
        if let (Some((_, Some(transform))), Some(coords)) = (mapping, mesh.tex_coords.as_mut()) {
            if type_is(doc, transform, "TextureTransform") {
                let transform = texture_transform(doc, transform);
                for t in coords.iter_mut() {
                    *t = transform(*t);
                }
            } else {
                self.note(
                    context,
                    transform,
                    format!("{} is not applied", doc.node(transform).type_name()),
                );
            }
        }
        Some((mesh, shading))
    }

    fn appearance(&mut self, context: Context, appearance: Option<NodeId>) -> Look {
        let doc = context.doc;
        let mut look = Look {
            front: default_unlit(),
            back: None,
            front_mapping: String::new(),
            back_mapping: String::new(),
            translucent_texture: false,
            alpha_mode: "AUTO".to_string(),
            alpha_cutoff: 0.5,
        };
        let Some(appearance) = appearance else {
            return look;
        };
        look.alpha_mode = doc
            .string_of(appearance, "alphaMode")
            .unwrap_or_else(|| "AUTO".into());
        look.alpha_cutoff = unit(float(doc, appearance, "alphaCutoff", 0.5));
        for field in [
            "shaders",
            "lineProperties",
            "pointProperties",
            "fillProperties",
        ] {
            if !doc.node(appearance).children(field).is_empty() {
                self.note(
                    context,
                    appearance,
                    format!("Appearance.{field} is not applied"),
                );
            }
        }
        let appearance_texture = child(doc, appearance, "texture");
        let material = child(doc, appearance, "material");
        if let Some(material) = material {
            let (front, back) = self.material(context, material);
            look.front = front;
            look.back = back;
        }
        if let Some(back_material) = child(doc, appearance, "backMaterial") {
            look.back = Some(self.material(context, back_material).0);
        }
        // 12.2.5: the material's main texture with its xxxTextureMapping, else
        // Appearance.texture, which has no mapping (the first coordinates, 12.2.4).
        let main_texture = |material_node: Option<NodeId>, m: &Material| {
            let field = match m.model {
                LightingModel::Unlit => "emissiveTexture",
                LightingModel::Phong => "diffuseTexture",
                LightingModel::Physical => "baseTexture",
            };
            material_node
                .and_then(|n| {
                    let mapping = doc
                        .string_of(n, &format!("{field}Mapping"))
                        .unwrap_or_default();
                    child(doc, n, field).map(|t| (t, mapping))
                })
                .or(appearance_texture.map(|t| (t, String::new())))
        };
        if let Some((texture, mapping)) = main_texture(material, &look.front) {
            self.apply_texture(
                context,
                texture,
                &mut look.front,
                &mut look.translucent_texture,
            );
            look.front_mapping = mapping;
        }
        if let Some(back) = look.back.as_mut() {
            let back_node = child(doc, appearance, "backMaterial").or(material);
            if let Some((texture, mapping)) = main_texture(back_node, back) {
                self.apply_texture(context, texture, back, &mut look.translucent_texture);
                look.back_mapping = mapping;
            }
        }
        look
    }

    fn apply_texture(
        &mut self,
        context: Context,
        texture: NodeId,
        material: &mut Material,
        translucent: &mut bool,
    ) {
        let doc = context.doc;
        let mut texture = texture;
        if type_is(doc, texture, "MultiTexture") {
            self.note(
                context,
                texture,
                "MultiTexture: only the first texture is drawn, without its modes".into(),
            );
            match child(doc, texture, "texture") {
                Some(first) => texture = first,
                None => return,
            }
        }
        let key = (context.serial, texture);
        if !self.texture_cache.contains_key(&key) {
            let loaded = match textures::load(doc, texture, context.base, &self.options.base_dir) {
                Ok(loaded)
                    if self.spent.texture_bytes + loaded.texture.rgba.len() > MAX_TEXTURE_BYTES =>
                {
                    let mib = MAX_TEXTURE_BYTES >> 20;
                    self.note(
                        context,
                        texture,
                        format!("texture not drawn: the textures would take more than {mib} MiB"),
                    );
                    None
                }
                Ok(loaded) => {
                    self.spent.texture_bytes += loaded.texture.rgba.len();
                    self.textures.push(loaded.texture);
                    Some((self.textures.len() - 1, loaded.channels, loaded.translucent))
                }
                Err(not_drawn) => {
                    self.push_note(context, texture, not_drawn.message, not_drawn.limit);
                    None
                }
            };
            self.texture_cache.insert(key, loaded);
        }
        if let Some(&Some((index, channels, texture_translucent))) = self.texture_cache.get(&key) {
            material.texture = Some(index);
            if self.options.x3d_version_3 {
                material.texture_replaces_rgb = channels >= 3;
                material.texture_replaces_alpha = channels == 2 || channels == 4;
            }
            *translucent |= texture_translucent;
        }
    }

    /// The front material and, for TwoSidedMaterial, the back one.
    fn material(&mut self, context: Context, id: NodeId) -> (Material, Option<Material>) {
        let doc = context.doc;
        let alpha = |field: &str| 1.0 - unit(float(doc, id, field, 0.0));
        let name = doc.node(id).type_name();
        for field in [
            "normalTexture",
            "occlusionTexture",
            "specularTexture",
            "shininessTexture",
            "ambientTexture",
            "metallicRoughnessTexture",
        ] {
            if child(doc, id, field).is_some() {
                self.note(context, id, format!("{name}.{field} is not applied"));
            }
        }
        if name != "UnlitMaterial" && child(doc, id, "emissiveTexture").is_some() {
            self.note(
                context,
                id,
                format!("{name}.emissiveTexture is not applied"),
            );
        }
        let phong = |prefix: &str| {
            let field = |f: &str| {
                if prefix.is_empty() {
                    f.to_string()
                } else {
                    let mut c = f.chars();
                    let first = c.next().map(|c| c.to_ascii_uppercase()).unwrap_or('x');
                    format!("{prefix}{first}{}", c.as_str())
                }
            };
            Material {
                model: LightingModel::Phong,
                diffuse: color(doc, id, &field("diffuseColor"), [0.8; 3]),
                emissive: color(doc, id, &field("emissiveColor"), [0.0; 3]),
                specular: color(doc, id, &field("specularColor"), [0.0; 3]),
                ambient_intensity: unit(float(doc, id, &field("ambientIntensity"), 0.2)),
                shininess: unit(float(doc, id, &field("shininess"), 0.2)) * 128.0,
                alpha: alpha(&field("transparency")),
                ..default_unlit()
            }
        };
        match name {
            "Material" => (phong(""), None),
            "TwoSidedMaterial" => {
                let front = phong("");
                let back = if boolean(doc, id, "separateBackColor", false) {
                    phong("back")
                } else {
                    front
                };
                (front, Some(back))
            }
            "PhysicalMaterial" => (
                Material {
                    model: LightingModel::Physical,
                    diffuse: color(doc, id, "baseColor", [1.0; 3]),
                    emissive: color(doc, id, "emissiveColor", [0.0; 3]),
                    metallic: unit(float(doc, id, "metallic", 1.0)),
                    roughness: unit(float(doc, id, "roughness", 1.0)),
                    alpha: alpha("transparency"),
                    ..default_unlit()
                },
                None,
            ),
            "UnlitMaterial" => (
                Material {
                    emissive: color(doc, id, "emissiveColor", [1.0; 3]),
                    alpha: alpha("transparency"),
                    ..default_unlit()
                },
                None,
            ),
            other => {
                self.note(
                    context,
                    id,
                    format!("{other} is not drawn; drawn unlit white"),
                );
                (default_unlit(), None)
            }
        }
    }

    fn finish(mut self) -> Flattened {
        let bounds = (!self.bounds.is_empty()).then(|| {
            (
                DVec3::from_array(self.bounds.min),
                DVec3::from_array(self.bounds.max),
            )
        });
        let aspect_fov = std::f32::consts::FRAC_PI_4;
        let (eye, orientation, field_of_view) = match &self.viewpoint {
            Some(v) => {
                let (_, world_rotation, _) = v.world.to_scale_rotation_translation();
                (
                    v.world.transform_point3(v.position),
                    (world_rotation * v.orientation).normalize(),
                    v.field_of_view,
                )
            }
            None => match bounds {
                Some((lo, hi)) => {
                    let centre = (lo + hi) / 2.0;
                    let radius = ((hi - lo).length() / 2.0).max(f64::MIN_POSITIVE);
                    let distance = radius / (f64::from(aspect_fov) / 2.0).sin();
                    (
                        centre + DVec3::new(0.0, 0.0, distance),
                        DQuat::IDENTITY,
                        aspect_fov,
                    )
                }
                None => (DVec3::new(0.0, 0.0, 10.0), DQuat::IDENTITY, aspect_fov),
            },
        };
        let field_of_view = if field_of_view > 0.0 && field_of_view < std::f32::consts::PI {
            field_of_view
        } else {
            aspect_fov
        };
        let (near, far) = self.clip_planes(bounds, eye);

        let navigation = self.navigation.unwrap_or(Navigation {
            headlight: true,
            avatar_size: None,
            visibility_limit: 0.0,
        });
        let mut lights: Vec<Light> = self
            .lights
            .iter()
            .map(|l| Light {
                location: to_f32(l.location - eye),
                ..l.light
            })
            .collect();
        if navigation.headlight {
            let forward = orientation * DVec3::NEG_Z;
            lights.push(Light {
                kind: LightKind::Directional,
                color: [1.0; 3],
                intensity: 1.0,
                ambient_intensity: 0.0,
                location: [0.0; 3],
                direction: unit_vector(forward),
                attenuation: [1.0, 0.0, 0.0],
                radius: f32::INFINITY,
                beam_width: 0.0,
                cut_off_angle: 0.0,
            });
            self.global_lights |= 1 << (lights.len() - 1);
        }
        let to_eye = DMat4::from_translation(-eye);
        let meshes = self
            .shapes
            .into_iter()
            .map(|p| place(p, to_eye, self.global_lights))
            .collect();
        Flattened {
            list: DrawList {
                camera: Camera {
                    orientation: orientation.as_quat(),
                    field_of_view,
                    near,
                    far,
                },
                background: self.background.unwrap_or([0.0; 3]),
                fog: self.fog,
                lights,
                meshes,
                textures: self.textures,
            },
            notes: self.notes,
        }
    }

    /// Near and far: from NavigationInfo (avatarSize / 2, visibilityLimit) where the scene
    /// has one, else from the distance of the scene's bounds.
    fn clip_planes(&self, bounds: Option<(DVec3, DVec3)>, eye: DVec3) -> (f32, f32) {
        let (nearest, farthest) = match bounds {
            Some((lo, hi)) => {
                let closest = eye.clamp(lo, hi);
                let corner = DVec3::new(
                    if (eye.x - lo.x).abs() > (eye.x - hi.x).abs() {
                        lo.x
                    } else {
                        hi.x
                    },
                    if (eye.y - lo.y).abs() > (eye.y - hi.y).abs() {
                        lo.y
                    } else {
                        hi.y
                    },
                    if (eye.z - lo.z).abs() > (eye.z - hi.z).abs() {
                        lo.z
                    } else {
                        hi.z
                    },
                );
                ((closest - eye).length(), (corner - eye).length())
            }
            None => (1.0, 100.0),
        };
        let mut far = (farthest * 1.01).max(f64::MIN_POSITIVE * 1e6);
        let mut near = (nearest * 0.99).max(far * 1e-6);
        if let Some(n) = self.navigation {
            if let Some(avatar) = n.avatar_size {
                near = f64::from(avatar) / 2.0;
            }
            if n.visibility_limit > 0.0 {
                far = f64::from(n.visibility_limit);
            }
        }
        if !(near > 0.0 && near.is_finite()) {
            near = 0.1;
        }
        if !(far > near && far.is_finite()) {
            far = near * 1e6;
        }
        (near as f32, (far as f32).max(near as f32 * 2.0))
    }
}

struct Look {
    front: Material,
    back: Option<Material>,
    /// The xxxTextureMapping of each side's texture ("" for none or Appearance.texture).
    front_mapping: String,
    back_mapping: String,
    translucent_texture: bool,
    alpha_mode: String,
    alpha_cutoff: f32,
}

fn default_unlit() -> Material {
    Material {
        model: LightingModel::Unlit,
        diffuse: [1.0; 3],
        emissive: [1.0; 3],
        specular: [0.0; 3],
        ambient_intensity: 0.0,
        shininess: 0.0,
        metallic: 0.0,
        roughness: 1.0,
        alpha: 1.0,
        texture: None,
        texture_replaces_rgb: false,
        texture_replaces_alpha: false,
    }
}

fn unlit_from(m: Material) -> Material {
    Material {
        model: LightingModel::Unlit,
        ..m
    }
}

/// TextureTransform (18.4.10): P' = −C × S × R × C × T × P.
fn texture_transform(doc: &Document, id: NodeId) -> TexCoordTransform {
    let pair = |name: &str, fallback: [f32; 2]| match floats(doc, id, name).as_ref() {
        [a, b, ..] if a.is_finite() && b.is_finite() => [f64::from(*a), f64::from(*b)],
        _ => fallback.map(f64::from),
    };
    let center = pair("center", [0.0; 2]);
    let scale = pair("scale", [1.0; 2]);
    let translation = pair("translation", [0.0; 2]);
    let angle = f64::from(float(doc, id, "rotation", 0.0));
    let (sin, cos) = angle.sin_cos();
    Box::new(move |[s, t]| {
        let (s, t) = (
            f64::from(s) + translation[0] + center[0],
            f64::from(t) + translation[1] + center[1],
        );
        let (s, t) = (s * cos - t * sin, s * sin + t * cos);
        [
            (s * scale[0] - center[0]) as f32,
            (t * scale[1] - center[1]) as f32,
        ]
    })
}

/// A transform as model::bounds takes it.
fn affine(m: DMat4) -> Affine {
    Affine {
        linear: std::array::from_fn(|r| std::array::from_fn(|c| m.col(c)[r])),
        translation: m.w_axis.truncate().to_array(),
    }
}

fn to_f32(v: DVec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn unit_vector(v: DVec3) -> [f32; 3] {
    let length = v.length();
    if length > 0.0 && length.is_finite() {
        to_f32(v / length)
    } else {
        [0.0, 0.0, -1.0]
    }
}

/// Places a shape relative to the eye: positions through (−eye) × world in f64, normals
/// through the inverse transpose; mirrored transforms keep front faces in front. The
/// mesh's vectors are reused: a large mesh is not copied on its way to the GPU.
fn place(p: Pending, to_eye: DMat4, global_lights: u32) -> Mesh {
    let matrix = to_eye * p.world;
    let mut mesh = p.mesh;
    for q in &mut mesh.positions {
        *q = to_f32(matrix.transform_point3(DVec3::from_array(q.map(f64::from))));
    }
    let linear = DMat3::from_mat4(p.world);
    let normal_matrix = if linear.determinant().abs() > 0.0 {
        linear.inverse().transpose()
    } else {
        DMat3::ZERO
    };
    if let Some(normals) = mesh.normals.as_mut() {
        for n in normals.iter_mut() {
            let w = normal_matrix * DVec3::from_array(n.map(f64::from));
            let length = w.length();
            *n = if length > 0.0 && length.is_finite() {
                to_f32(w / length)
            } else {
                [0.0; 3]
            };
        }
    }
    let positions = &mesh.positions;
    let finite = |i: u32| {
        positions
            .get(i as usize)
            .is_some_and(|q| q.iter().all(|c| c.is_finite()))
    };
    let mirrored = linear.determinant() < 0.0;
    let per = match mesh.primitive {
        Primitive::Triangles => 3,
        Primitive::Lines => 2,
        Primitive::Points => 1,
    };
    // Compacts the kept groups to the front of the index list, in place.
    let mut kept = 0;
    for start in (0..mesh.indices.len() / per * per).step_by(per) {
        if mesh.indices[start..start + per].iter().all(|&i| finite(i)) {
            mesh.indices.copy_within(start..start + per, kept);
            if mirrored && per == 3 {
                mesh.indices.swap(kept + 1, kept + 2);
            }
            kept += per;
        }
    }
    mesh.indices.truncate(kept);
    if let Some(coords) = mesh.tex_coords.as_mut() {
        for t in coords.iter_mut() {
            *t = t.map(|c| if c.is_finite() { c } else { 0.0 });
        }
    }
    Mesh {
        primitive: mesh.primitive,
        positions: mesh.positions,
        normals: mesh.normals,
        colors: mesh.colors,
        tex_coords: mesh.tex_coords,
        indices: mesh.indices,
        front: p.front,
        back: p.back,
        light_mask: p.scoped_lights | global_lights,
        blended: p.blended,
        alpha_cutoff: p.alpha_cutoff,
    }
}
