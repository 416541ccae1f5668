//! ScreenGroup (Layout component, 36.4.5): its children are in
//! pixels — one unit is one pixel of the image at the group's origin — keeping the
//! position and orientation the enclosing transforms give the origin and replacing their
//! scale (as X_ITE does).
//!
//! The size of a pixel there: in a LayoutLayer, the layer's units per pixel (its camera is
//! orthographic, see [`super::layout`]); elsewhere, from the bound viewpoint: for a
//! perspective one, the image's smaller side spans 2·d·tan(fieldOfView/2) at the origin's
//! distance d along the view axis; for an OrthoViewpoint, its rectangle widened to the
//! image's aspect ratio. Without a viewpoint x3dcheck frames the scene's bounds after the
//! walk, which the ScreenGroup's size is part of: the browser's default Viewpoint
//! (0 0 10, fieldOfView π/4) sizes it then, and a note says so.

use glam::{DMat4, DVec3};

use super::camera::{default_viewpoint, ViewpointFound};
use super::{child_ids, Context, Scope, Walker};
use crate::model::NodeId;
use crate::render::draw_list::Projection;

impl Walker<'_> {
    pub(super) fn screen_group(
        &mut self,
        context: Context,
        id: NodeId,
        world: DMat4,
        scope: &Scope,
        depth: usize,
    ) {
        let (_, rotation, origin) = world.to_scale_rotation_translation();
        let (width, height) = self.layer.pixels;
        let pixel = match (self.layer.layout, self.viewpoint.clone()) {
            (Some(surface), _) => Some(surface.unit_per_pixel),
            (None, Some(viewpoint)) => pixel_size(&viewpoint, origin, width, height),
            (None, None) => {
                self.note(
                    context,
                    id,
                    "ScreenGroup without a Viewpoint: sized in pixels as seen from the \
                     default Viewpoint (0 0 10), not from the framing camera (36.4.5)"
                        .into(),
                );
                pixel_size(&default_viewpoint(), origin, width, height)
            }
        };
        let Some(pixel) = pixel.filter(|p| p.is_finite() && *p > 0.0) else {
            self.note(
                context,
                id,
                "ScreenGroup at or behind the viewpoint is not drawn (36.4.5)".into(),
            );
            return;
        };
        let world = DMat4::from_scale_rotation_translation(DVec3::splat(pixel), rotation, origin);
        let kids = child_ids(context.doc.node(id), "children");
        self.walk_children(context, &kids, world, scope, depth);
    }
}

/// The size of one image pixel at `origin` (world units), seen from `viewpoint` in an
/// image of `width` × `height` pixels; None behind a perspective viewpoint.
fn pixel_size(viewpoint: &ViewpointFound, origin: DVec3, width: u32, height: u32) -> Option<f64> {
    let (width, height) = (f64::from(width.max(1)), f64::from(height.max(1)));
    match viewpoint.projection {
        Projection::Perspective { field_of_view } => {
            let forward = viewpoint.orientation * DVec3::NEG_Z;
            let distance = (origin - viewpoint.eye).dot(forward);
            (distance > 0.0).then(|| {
                2.0 * distance * (f64::from(field_of_view) / 2.0).tan() / width.min(height)
            })
        }
        Projection::Orthographic {
            rectangle: [min_x, min_y, max_x, max_y],
        } => Some((f64::from(max_x - min_x) / width).max(f64::from(max_y - min_y) / height)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pixel_at_the_default_distance_spans_the_fov_over_the_smaller_side() {
        let at_origin = pixel_size(&default_viewpoint(), DVec3::ZERO, 160, 120).unwrap();
        let expected = 2.0 * 10.0 * (std::f64::consts::FRAC_PI_4 / 2.0).tan() / 120.0;
        // fieldOfView is an SFFloat: f32 precision.
        assert!((at_origin - expected).abs() < 1e-6 * expected);
        assert!(pixel_size(&default_viewpoint(), DVec3::new(0.0, 0.0, 11.0), 160, 120).is_none());
    }
}
