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
mod hanim;
mod layers;
mod layout;
mod lights;
mod place;
mod screen_group;
mod shape;
mod text;

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::{DMat4, DVec3, DVec4};

use super::draw_list::{DrawList, Light, Viewport, MAX_CLIP_PLANES};
use super::fields::{boolean, floats};
use crate::model::bounds::{local_transform, Bounds};
use crate::model::data_url;
use crate::model::{units, Document, Node, NodeId};
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

/// The transformation at the root of a file's scene: its UNIT length factor as a uniform
/// scale (see [`crate::model::units`]; its angles are converted as values).
/// The nodes of a node field, in order (empty when unset or NULL).
fn child_ids(node: &Node, field: &str) -> Vec<NodeId> {
    node.children(field).iter().map(|c| c.node).collect()
}

fn scene_root(doc: &Document) -> DMat4 {
    DMat4::from_scale(DVec3::splat(doc.units().length))
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

/// Which view the image is taken from (`--camera`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraChoice<'a> {
    /// The first Viewpoint, else a framing of the scene's bounds.
    Auto,
    /// The first Viewpoint, else the X3D default Viewpoint (position 0 0 10, looking down
    /// −Z, fieldOfView π/4): the view a browser binds (see `camera::default_viewpoint`).
    Browser,
    /// The Viewpoint DEF'd so.
    Named(&'a str),
}

impl<'a> CameraChoice<'a> {
    /// `auto`, `browser`, or a DEF name.
    pub fn parse(text: &'a str) -> CameraChoice<'a> {
        match text {
            "auto" => CameraChoice::Auto,
            "browser" => CameraChoice::Browser,
            name => CameraChoice::Named(name),
        }
    }
}

pub struct Options<'a> {
    pub camera: CameraChoice<'a>,
    /// The document's directory (relative urls).
    pub base_dir: PathBuf,
    /// The directory tree Inlines and textures may be read from, at or above `base_dir`.
    pub root: PathBuf,
    pub x3d_version_3: bool,
    /// Triangles, lines and points drawn at most (see [`primitive_budget`]).
    pub primitive_budget: usize,
    /// The image's width and height in pixels: the shapes drawn may cover it
    /// [`RENDER_FILL_IMAGES`] times over (the fill budget, see `fill`).
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
/// (bits into the light list) and the enabled ClipPlanes (world planes), 17.2.1.2, 11.4;
/// the rectangle of an enclosing Viewport node (35.4.3) and the region of an enclosing
/// layout (36.2).
#[derive(Clone, Debug, Default)]
struct Scope {
    lights: u32,
    clip_planes: Vec<DVec4>,
    scissor: Option<Viewport>,
    layout: Option<layout::Region>,
}

struct Walker<'o> {
    options: &'o Options<'o>,
    notes: Vec<Note>,
    /// The layers finished so far, in drawing order.
    layers: Vec<super::draw_list::Layer>,
    /// The layer being walked; the fields below up to `bounds` belong to it.
    layer: layers::LayerFrame,
    shapes: Vec<Pending>,
    lights: Vec<lights::PendingLight>,
    global_lights: u32,
    /// The layer's first EnvironmentLight drawn.
    image_light: Option<super::draw_list::Environment>,
    textures: Vec<super::draw_list::Texture>,
    cube_textures: Vec<super::cube_map::CubeImage>,
    /// (document serial, node) → loaded texture.
    texture_cache: HashMap<(usize, NodeId), Option<appearance::LoadedTexture>>,
    /// The chosen viewpoint, found before the walk (Billboards turn towards it).
    viewpoint: Option<camera::ViewpointFound>,
    environment: environment::Environment,
    documents: usize,
    inline_stack: Vec<PathBuf>,
    spent: Spent,
    /// World bounds of the layer's shapes drawn (model::bounds), for framing and clip
    /// planes.
    bounds: Bounds,
    /// Pixels the shapes of the layers finished so far cover (the fill budget, [`fill`]).
    filled: f64,
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
    let converted = units::in_base_units(doc);
    let doc = converted.as_ref().unwrap_or(doc);
    let mut walker = Walker {
        options,
        notes: Vec::new(),
        layers: Vec::new(),
        layer: layers::LayerFrame::root(options.image),
        shapes: Vec::new(),
        lights: Vec::new(),
        global_lights: 0,
        image_light: None,
        textures: Vec::new(),
        cube_textures: Vec::new(),
        texture_cache: HashMap::new(),
        viewpoint: None,
        environment: environment::Environment::default(),
        documents: 1,
        inline_stack: Vec::new(),
        spent: Spent::default(),
        bounds: Bounds::EMPTY,
        filled: 0.0,
        glyphs: Default::default(),
    };
    let context = Context {
        doc,
        serial: 0,
        base: &options.base_dir,
    };
    walker.walk_layers(context)?;
    Ok(Flattened {
        list: DrawList {
            layers: walker.layers,
            textures: walker.textures,
            cube_textures: walker.cube_textures,
        },
        notes: walker.notes,
    })
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
            "HAnimHumanoid" => self.humanoid(context, id, world, scope, depth),
            "HAnimJoint" => self.joint(context, id, world, scope, depth),
            "Shape" => self.shape(context, id, world, scope),
            _ if def.is_a("X3DViewportNode") => {
                let inner = self.viewport_scope(doc, id, scope);
                self.walk_children(context, &kids("children"), world, &inner, depth);
            }
            "LayoutGroup" => self.layout_group(context, id, world, scope, depth),
            "ScreenGroup" => self.screen_group(context, id, world, scope, depth),
            "LayerSet" => self.note(
                context,
                id,
                "LayerSet is drawn only as a root node (35.2.2)".into(),
            ),
            _ if def.is_a("X3DLayerNode") => self.note(
                context,
                id,
                format!("{} is drawn only in LayerSet.layers (35.2.3)", def.name),
            ),
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

    /// LayoutGroup (36.4.2): its Layout places a rectangle within the enclosing layout's
    /// and scales its children; its viewport cuts them. Outside a LayoutLayer there is no
    /// layout to place it in: a Group.
    fn layout_group(
        &mut self,
        context: Context,
        id: NodeId,
        world: DMat4,
        scope: &Scope,
        depth: usize,
    ) {
        let doc = context.doc;
        let node = doc.node(id);
        let kids = child_ids(node, "children");
        let mut inner = match super::fields::child(doc, id, "viewport") {
            Some(v) if doc.node(v).is_a("X3DViewportNode") => self.viewport_scope(doc, v, scope),
            _ => scope.clone(),
        };
        let mut world = world;
        match (
            self.layer.layout,
            scope.layout,
            super::fields::child(doc, id, "layout"),
        ) {
            (Some(surface), Some(parent), Some(l)) => {
                let (translation, region) = layout::Layout::of(doc, l).place(parent, &surface);
                world = layout::group_transform(world, translation, &region);
                inner.layout = Some(region);
            }
            (None, _, Some(_)) => self.note(
                context,
                id,
                "LayoutGroup outside a LayoutLayer: drawn as a Group, its Layout is not applied \
                 (36.2.1)"
                    .into(),
            ),
            _ => {}
        }
        self.walk_children(context, &kids, world, &inner, depth);
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
                    let path =
                        match super::textures::local_file(url, context.base, &self.options.root) {
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
            let Some(mut inlined) = crate::parse::read(&bytes).document else {
                reasons.push(format!("{url}: not an X3D document"));
                continue;
            };
            if let Some(converted) = units::in_base_units(&inlined) {
                inlined = converted;
            }
            let serial = self.documents;
            self.documents += 1;
            self.inline_stack.push(key);
            let inner = Context {
                doc: &inlined,
                serial,
                base: &base,
            };
            let roots: Vec<NodeId> = inlined.scene.iter().map(|c| c.node).collect();
            let world = world * scene_root(&inlined);
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

    /// Ends the layer being walked: its camera (the bound viewpoint, or a framing of its
    /// bounds), its lights relative to the eye, its meshes placed within what is left of
    /// the fill budget.
    fn finish_layer(&mut self) {
        let bounds = (!self.bounds.is_empty()).then(|| {
            (
                DVec3::from_array(self.bounds.min),
                DVec3::from_array(self.bounds.max),
            )
        });
        let view = if self.layer.layout.is_some() {
            camera::View::layout(bounds)
        } else {
            camera::View::choose(self.viewpoint.as_ref(), bounds)
        };
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
        let (width, height) = self.layer.pixels;
        let screen = fill::Screen::new(&camera, width, height);
        let (image_width, image_height) = self.options.image;
        let fill_budget =
            f64::from(image_width) * f64::from(image_height) * RENDER_FILL_IMAGES as f64;
        let shapes = std::mem::take(&mut self.shapes);
        let (mut meshes, count) = (Vec::with_capacity(shapes.len()), shapes.len());
        for pending in shapes {
            let mesh = pending.place(&frame, global_lights);
            self.filled += screen.covered(&mesh);
            if self.filled > fill_budget {
                self.spent.stopped = true;
                self.notes.push(Note {
                    node: None,
                    message: format!(
                        "renderer: the scene's shapes cover the image more than \
                         {RENDER_FILL_IMAGES} times over; drawn up to the first {} of the \
                         layer's {count} shapes",
                        meshes.len()
                    ),
                    limit: true,
                });
                break;
            }
            meshes.push(mesh);
        }
        let environment = std::mem::take(&mut self.environment);
        let background = match environment.background {
            Some(background) => Some(background),
            // The root scene's default Background is black; other layers show the ones
            // below where they bind none.
            None if self.layer.root => Some(Default::default()),
            None => None,
        };
        self.layers.push(super::draw_list::Layer {
            camera,
            viewport: self.layer.viewport,
            background,
            fog: environment.fog.flatten(),
            lights,
            environment: self.image_light.take(),
            meshes,
        });
        self.lights.clear();
        self.global_lights = 0;
        self.viewpoint = None;
        self.bounds = Bounds::EMPTY;
    }
}
