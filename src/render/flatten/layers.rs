//! The Layering component (19775-1 clause 35): which layers are drawn, in which order,
//! each with its own bindable nodes (35.2.3) and its rectangle of the image (35.4.3).
//!
//! - Without a LayerSet the scene is one layer. With one (it must be a root node, and
//!   only one is allowed, 35.2.2), the root nodes other than the LayerSet are layer 0 and
//!   LayerSet.layers are layers 1, 2, …; LayerSet.order lists the layers drawn, first at
//!   the bottom; numbers that name no layer are ignored and layers it leaves out are not
//!   drawn (35.4.2). A layer listed twice is drawn twice.
//! - Each layer binds the first Viewpoint, NavigationInfo, Background and Fog in its own
//!   tree; without a viewpoint it is framed from its own bounds. Its lights light only
//!   its own shapes.
//! - Each layer is drawn over the previous ones with the depth buffer cleared, so that
//!   its shapes cover theirs wherever they are. Its Background is drawn first, within its
//!   viewport; a layer other than layer 0 binding none lets the layers below show through.
//! - X3DLayerNode.viewport confines a layer to a rectangle of the image, and its camera
//!   takes that rectangle's aspect ratio; a Viewport node among the children cuts its
//!   own children to a rectangle of the enclosing one (35.4.3).

use glam::DMat4;

use super::camera::{self, ViewpointFound};
use super::layout::{self, Layout, Surface};
use super::{CameraChoice, Context, Scope, Walker};
use crate::model::{Document, NodeId};
use crate::render::draw_list::Viewport;
use crate::render::fields::{boolean, child, floats, ints, type_is};

/// The layer being walked.
#[derive(Copy, Clone, Debug)]
pub struct LayerFrame {
    /// Its rectangle of the image.
    pub viewport: Viewport,
    /// The rectangle's width and height in image pixels.
    pub pixels: (u32, u32),
    /// Layer 0: the root scene's nodes, with a black Background by default.
    pub root: bool,
    /// A LayoutLayer: its layout units (36.2).
    pub layout: Option<Surface>,
}

impl LayerFrame {
    /// The whole image, as the root scene.
    pub fn root(image: (u32, u32)) -> LayerFrame {
        LayerFrame {
            viewport: Viewport::FULL,
            pixels: image,
            root: true,
            layout: None,
        }
    }
}

/// A layer to draw: layer 0 (the root nodes) or an X3DLayerNode.
#[derive(Copy, Clone, Debug, PartialEq)]
enum Planned {
    Root,
    Layer(NodeId),
}

/// Viewport.clipBoundary (left, right, bottom, top), missing values the defaults.
pub fn clip_boundary(doc: &Document, id: NodeId) -> [f32; 4] {
    let values = floats(doc, id, "clipBoundary");
    let mut out = [0.0, 1.0, 0.0, 1.0];
    for (slot, value) in out.iter_mut().zip(values.iter()) {
        *slot = *value;
    }
    out
}

impl Walker<'_> {
    /// Walks the layers in their drawing order, finishing each into the draw list.
    pub(super) fn walk_layers(&mut self, context: Context) -> Result<(), String> {
        let doc = context.doc;
        let roots: Vec<NodeId> = doc
            .scene
            .iter()
            .map(|c| doc.built(c.node).unwrap_or(c.node))
            .collect();
        let sets: Vec<NodeId> = roots
            .iter()
            .copied()
            .filter(|&id| type_is(doc, id, "LayerSet"))
            .collect();
        for &extra in sets.iter().skip(1) {
            self.note(
                context,
                extra,
                "only one LayerSet is allowed (35.2.2): this one is not drawn".into(),
            );
        }
        let layer0: Vec<NodeId> = roots
            .iter()
            .copied()
            .filter(|id| !sets.contains(id))
            .collect();
        let plan = match sets.first() {
            None => vec![Planned::Root],
            Some(&set) => self.order(context, set),
        };
        let trees: Vec<Vec<NodeId>> = plan
            .iter()
            .map(|planned| match planned {
                Planned::Root => layer0.clone(),
                Planned::Layer(id) => children(doc, *id, "children"),
            })
            .collect();
        // --camera DEF binds that viewpoint in the layer holding it (the first drawn when
        // none does: then it is outside the scene graph, e.g. in a prototype).
        let named = match self.options.camera {
            CameraChoice::Named(name) => Some(name),
            CameraChoice::Auto | CameraChoice::Browser => None,
        };
        let mut viewpoints: Vec<Option<ViewpointFound>> = trees
            .iter()
            .map(|tree| {
                named
                    .and_then(|n| camera::find_viewpoint(doc, tree, Some(n)))
                    .or_else(|| camera::find_viewpoint(doc, tree, None))
            })
            .collect();
        if let Some(name) = named {
            let held = trees
                .iter()
                .any(|tree| camera::find_viewpoint(doc, tree, Some(name)).is_some());
            if !held {
                let anywhere = camera::named_anywhere(doc, name)?;
                if let Some(first) = viewpoints.first_mut() {
                    *first = Some(anywhere);
                }
            }
        }
        if self.options.camera == CameraChoice::Browser {
            // A layer without a viewpoint binds the X3D default one, as a browser does (a
            // LayoutLayer has its own fixed view).
            for (planned, viewpoint) in plan.iter().zip(viewpoints.iter_mut()) {
                let layout =
                    matches!(planned, Planned::Layer(id) if type_is(doc, *id, "LayoutLayer"));
                if viewpoint.is_none() && !layout {
                    *viewpoint = Some(camera::default_viewpoint());
                }
            }
        }
        for ((planned, tree), viewpoint) in plan.iter().zip(&trees).zip(viewpoints) {
            if self.spent.stopped {
                break;
            }
            self.walk_layer(context, *planned, tree, viewpoint);
        }
        Ok(())
    }

    /// LayerSet.order as layers (35.4.2).
    fn order(&mut self, context: Context, set: NodeId) -> Vec<Planned> {
        let doc = context.doc;
        let layers = children(doc, set, "layers");
        let order = ints(doc, set, "order");
        order
            .iter()
            .filter_map(|&n| match usize::try_from(n) {
                Ok(0) => Some(Planned::Root),
                Ok(n) => layers.get(n - 1).map(|&id| Planned::Layer(id)),
                Err(_) => None,
            })
            .collect()
    }

    fn walk_layer(
        &mut self,
        context: Context,
        planned: Planned,
        tree: &[NodeId],
        viewpoint: Option<ViewpointFound>,
    ) {
        let doc = context.doc;
        let (width, height) = self.options.image;
        let mut frame = LayerFrame::root((width, height));
        if let Planned::Layer(id) = planned {
            if !boolean(doc, id, "visible", true) {
                return;
            }
            let viewport = match child(doc, id, "viewport") {
                Some(v) if doc.node(v).is_a("X3DViewportNode") => {
                    Viewport::FULL.part(clip_boundary(doc, v))
                }
                _ => Viewport::FULL,
            };
            let [_, _, w, h] = viewport.pixels(width, height);
            if w == 0 || h == 0 {
                return;
            }
            frame = LayerFrame {
                viewport,
                pixels: (w, h),
                root: false,
                layout: type_is(doc, id, "LayoutLayer")
                    .then(|| Surface::of_pixels(f64::from(w), f64::from(h))),
            };
        }
        self.layer = frame;
        let mut scope = Scope::default();
        let mut world = DMat4::IDENTITY;
        match (planned, frame.layout) {
            (Planned::Layer(id), Some(surface)) => {
                if viewpoint.is_some() {
                    self.note(
                        context,
                        id,
                        "LayoutLayer: its Viewpoint is not used; the layer is drawn in its \
                         layout's 2D coordinates (36.2.1)"
                            .into(),
                    );
                }
                self.viewpoint = None;
                scope.layout = Some(match child(doc, id, "layout") {
                    Some(l) => {
                        let (translation, region) =
                            Layout::of(doc, l).place(surface.region(), &surface);
                        world = layout::group_transform(world, translation, &region);
                        region
                    }
                    // No layout: the layer's own units.
                    None => layout::Region {
                        size: surface.size,
                        scale: glam::DVec2::ONE,
                    },
                });
            }
            _ => self.viewpoint = viewpoint,
        }
        let world = world * super::scene_root(doc);
        self.walk_children(context, tree, world, &scope, 0);
        self.finish_layer();
    }

    /// A Viewport node among the children (35.4.3): its children are cut to its rectangle
    /// of the enclosing one.
    pub(super) fn viewport_scope(&self, doc: &Document, viewport: NodeId, scope: &Scope) -> Scope {
        let outer = scope.scissor.unwrap_or(self.layer.viewport);
        Scope {
            scissor: Some(outer.part(clip_boundary(doc, viewport))),
            ..scope.clone()
        }
    }
}

/// The nodes of an MFNode field, prototype instances as the nodes they build.
fn children(doc: &Document, id: NodeId, field: &str) -> Vec<NodeId> {
    doc.node(id)
        .children(field)
        .iter()
        .map(|c| doc.built(c.node).unwrap_or(c.node))
        .collect()
}
