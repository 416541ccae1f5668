//! Scene model → [`DrawList`]. Walks the scene graph from the Scene (and local Inline
//! files), composing transforms in f64; builds each Shape's geometry in local
//! coordinates with only the attributes its appearance needs; resolves materials,
//! textures, lights, clip planes, the camera, background and fog; finally places every
//! vertex relative to the eye in f64 and rounds once. The guarantees the GPU part relies
//! on are written in [`super::draw_list`]. What cannot be drawn is returned as [`Note`]s.

mod appearance;
mod camera;
mod environment;
mod fill;
mod lights;
mod place;
mod shape;
mod text;

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::{DMat4, DVec3, DVec4};

use super::draw_list::{DrawList, Light, MAX_CLIP_PLANES};
use super::fields::{boolean, floats};
use crate::model::bounds::{local_transform, Bounds};
use crate::model::{Document, NodeId};
use crate::validate::texturing::data_url;
use place::Pending;

/// Inline files nested deeper than this are not loaded (and cycles end here).
const MAX_INLINE_DEPTH: usize = 8;
/// Grouping nodes nested deeper than this are not walked (the checker reports nesting).
const MAX_DEPTH: usize = 256;
use crate::limits::{
    MAX_RENDER_NODE_INSTANCES as MAX_NODE_INSTANCES, MAX_RENDER_PRIMITIVES, MIN_RENDER_PRIMITIVES,
    RENDER_FILL_IMAGES, RENDER_PRIMITIVES_PER_PIXEL,
};

/// Triangles (lines, points) drawn at most for an image of this size (the bounds of
/// [`crate::limits`]), so that memory stays bounded.
pub fn primitive_budget(width: u32, height: u32) -> usize {
    (u64::from(width) * u64::from(height) * RENDER_PRIMITIVES_PER_PIXEL)
        .clamp(MIN_RENDER_PRIMITIVES, MAX_RENDER_PRIMITIVES) as usize
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
    /// The image's width and height in pixels: the shapes drawn may cover it
    /// [`RENDER_FILL_IMAGES`] times over (the fill budget, see [`fill`]).
    pub image: (u32, u32),
}

/// The material of a shape without an Appearance: unlit white (17.2.2.4).
pub fn default_material() -> super::draw_list::Material {
    appearance::default_unlit()
}

pub struct Flattened {
    pub list: DrawList,
    pub notes: Vec<Note>,
}

/// What reaches the descendants of a group besides its transform: the scoped lights
/// (bits into the light list) and the enabled ClipPlanes (world planes), 17.2.1.2, 11.4.
#[derive(Clone, Debug, Default)]
struct Scope {
    lights: u32,
    clip_planes: Vec<DVec4>,
}

struct Walker<'o> {
    options: &'o Options<'o>,
    notes: Vec<Note>,
    shapes: Vec<Pending>,
    lights: Vec<lights::PendingLight>,
    global_lights: u32,
    textures: Vec<super::draw_list::Texture>,
    /// (document serial, node) → loaded texture.
    texture_cache: HashMap<(usize, NodeId), Option<appearance::LoadedTexture>>,
    /// The chosen viewpoint, found before the walk (Billboards turn towards it).
    viewpoint: Option<camera::ViewpointFound>,
    environment: environment::Environment,
    documents: usize,
    inline_stack: Vec<PathBuf>,
    spent: Spent,
    /// World bounds of the shapes drawn (model::bounds), for framing and clip planes.
    bounds: Bounds,
    /// Glyphs tessellated for Text, each once.
    glyphs: crate::render::text::Glyphs,
}

/// What the walk has expanded so far, against the caps.
#[derive(Default)]
struct Spent {
    node_instances: u64,
    primitives: usize,
    texture_bytes: usize,
    /// Characters of Text laid out.
    text_characters: usize,
    /// A cap was hit: nothing more is walked.
    stopped: bool,
}

/// The document being walked: the checked one (serial 0) or an Inline file.
#[derive(Clone, Copy)]
struct Context<'d> {
    doc: &'d Document,
    serial: usize,
    base: &'d Path,
}

pub fn flatten(doc: &Document, options: &Options) -> Result<Flattened, String> {
    let viewpoint = camera::find_viewpoint(doc, options.camera)?;
    let mut walker = Walker {
        options,
        notes: Vec::new(),
        shapes: Vec::new(),
        lights: Vec::new(),
        global_lights: 0,
        textures: Vec::new(),
        texture_cache: HashMap::new(),
        viewpoint,
        environment: environment::Environment::default(),
        documents: 1,
        inline_stack: Vec::new(),
        spent: Spent::default(),
        bounds: Bounds::EMPTY,
        glyphs: Default::default(),
    };
    let context = Context {
        doc,
        serial: 0,
        base: &options.base_dir,
    };
    let roots: Vec<NodeId> = doc.scene.iter().map(|c| c.node).collect();
    walker.walk_children(context, &roots, DMat4::IDENTITY, &Scope::default(), 0);
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

    /// Stops the walk at a cap (LIMIT_EXCEEDED), saying how far the scene expands and
    /// what was drawn.
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
            limit: true,
        });
    }

    /// Walks a list of sibling nodes: their scoped lights and clip planes first (they
    /// reach all siblings and their descendants, 17.2.1.2), then each node.
    fn walk_children(
        &mut self,
        context: Context,
        children: &[NodeId],
        world: DMat4,
        scope: &Scope,
        depth: usize,
    ) {
        let mut scope = scope.clone();
        // A prototype instance stands for the first node of its body, with its values.
        let children: Vec<NodeId> = children
            .iter()
            .map(|&id| context.doc.built(id).unwrap_or(id))
            .collect();
        let children = &children[..];
        for &id in children {
            let node = context.doc.node(id);
            if node.is_a("X3DLightNode") {
                if let Some(bit) = self.add_light(context, id, world) {
                    if boolean(context.doc, id, "global", !node.is_a("DirectionalLight")) {
                        self.global_lights |= bit;
                    } else {
                        scope.lights |= bit;
                    }
                }
            } else if node.type_name() == "ClipPlane" {
                self.add_clip_plane(context, id, world, &mut scope);
            }
        }
        for &id in children {
            self.walk(context, id, world, &scope, depth + 1);
        }
    }

    /// ClipPlane (11.4): its plane in world coordinates, kept side a·x + b·y + c·z + d ≥ 0.
    fn add_clip_plane(&mut self, context: Context, id: NodeId, world: DMat4, scope: &mut Scope) {
        let doc = context.doc;
        if !boolean(doc, id, "enabled", true) {
            return;
        }
        let plane = match floats(doc, id, "plane").as_ref() {
            [a, b, c, d, ..] => DVec4::new((*a).into(), (*b).into(), (*c).into(), (*d).into()),
            _ => DVec4::new(0.0, 1.0, 0.0, 0.0),
        };
        // Planes transform by the inverse transpose of the point transform.
        let world_plane = world.inverse().transpose() * plane;
        if !world_plane.is_finite() || world_plane.truncate() == DVec3::ZERO {
            self.note(
                context,
                id,
                "ClipPlane with a degenerate plane is not applied".into(),
            );
        } else if scope.clip_planes.len() >= MAX_CLIP_PLANES {
            self.note(
                context,
                id,
                format!("ClipPlanes beyond {MAX_CLIP_PLANES} on one shape are not applied"),
            );
        } else {
            scope.clip_planes.push(world_plane);
        }
    }

    fn walk(&mut self, context: Context, id: NodeId, world: DMat4, scope: &Scope, depth: usize) {
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
                self.note(
                    context,
                    id,
                    "a prototype instance whose body is not known (external or undeclared) is not drawn"
                        .into(),
                );
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
                let turned = world * self.billboard_rotation(context, id, world);
                self.walk_children(context, &kids("children"), turned, scope, depth);
            }
            "Inline" => self.inline(context, id, world, scope, depth),
            "Shape" => self.shape(context, id, world, scope),
            _ if def.is_a("X3DBackgroundNode") || matches!(def.name, "Fog" | "NavigationInfo") => {
                self.environment_node(context, id, world)
            }
            _ if def.is_a("X3DLightNode")
                || camera::is_viewpoint(node)
                || def.name == "ClipPlane" => {}
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

    fn inline(&mut self, context: Context, id: NodeId, world: DMat4, scope: &Scope, depth: usize) {
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
            // The file's bytes, the directory its urls are relative to, and what the
            // stack of Inlines being walked knows it by (data: content, as browsers take
            // it, is relative to the document that holds it and is bounded by the depth).
            let (bytes, base, key) = match data_url::decode(url) {
                Some(Ok(data)) => (data.bytes, context.base.to_path_buf(), PathBuf::new()),
                Some(Err(e)) => {
                    reasons.push(format!("{}: {e}", data_url::shown(url)));
                    continue;
                }
                None => {
                    let path = match super::textures::local_file(
                        url,
                        context.base,
                        &self.options.base_dir,
                    ) {
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
                    let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
                    (bytes, base, path)
                }
            };
            let url = data_url::shown(url);
            let Some(inlined) = crate::parse::read(&bytes).document else {
                reasons.push(format!("{url}: not an X3D document"));
                continue;
            };
            let serial = self.documents;
            self.documents += 1;
            self.inline_stack.push(key);
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

    fn finish(mut self) -> Flattened {
        let bounds = (!self.bounds.is_empty()).then(|| {
            (
                DVec3::from_array(self.bounds.min),
                DVec3::from_array(self.bounds.max),
            )
        });
        let view = camera::View::choose(self.viewpoint.as_ref(), bounds);
        let (near, far) = view.depth_range(bounds, self.environment.navigation);
        let mut lights: Vec<Light> = self
            .lights
            .iter()
            .map(|l| Light {
                // Beyond f32's range a light is out of any reach it can have in f32.
                location: place::to_f32(l.location - view.eye).map(|c| {
                    if c.is_nan() {
                        f32::MAX
                    } else {
                        c.clamp(-f32::MAX, f32::MAX)
                    }
                }),
                ..l.light
            })
            .collect();
        if self.environment.headlight() {
            lights.push(lights::headlight(view.orientation));
            self.global_lights |= 1 << (lights.len() - 1);
        }
        let frame = place::EyeFrame::new(view.eye, view.orientation);
        let global_lights = self.global_lights;
        let camera = view.camera(near, far);
        let (width, height) = self.options.image;
        let screen = fill::Screen::new(&camera, width, height);
        let fill_budget = screen.pixels() * RENDER_FILL_IMAGES as f64;
        let (mut meshes, mut filled) = (Vec::with_capacity(self.shapes.len()), 0.0);
        let shapes = self.shapes.len();
        for pending in self.shapes {
            let mesh = pending.place(&frame, global_lights);
            filled += screen.covered(&mesh);
            if filled > fill_budget {
                self.notes.push(Note {
                    node: None,
                    message: format!(
                        "renderer: the scene's {shapes} shapes cover the image more than \
                         {RENDER_FILL_IMAGES} times over; drawn up to the first {} shapes",
                        meshes.len()
                    ),
                    limit: true,
                });
                break;
            }
            meshes.push(mesh);
        }
        let environment = self.environment;
        Flattened {
            list: DrawList {
                camera,
                background: environment.background.unwrap_or_default(),
                fog: environment.fog.flatten(),
                lights,
                meshes,
                textures: self.textures,
            },
            notes: self.notes,
        }
    }
}
