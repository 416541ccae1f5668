//! Where on the target a piece of a mesh can draw, so that a tile skips what cannot reach
//! it: every tile draws the same projection (see `frame`), and on a software driver each
//! tile otherwise pays the vertex work of the whole scene again.

use crate::render::draw_list::{Mesh, Primitive};

/// Target pixels added on every side of a projected box: the shader's f32 arithmetic and
/// the rasterizer's sample positions may differ from this projection by a little.
const MARGIN: f32 = 2.0;

/// A layer's camera as the vertex shaders apply it.
#[derive(Copy, Clone, Debug)]
pub struct Camera {
    /// Eye-relative world positions to clip space (`Globals::view_projection`).
    pub view_projection: glam::Mat4,
    /// The viewing direction and, in `w`, the near plane's distance.
    pub forward_near: glam::Vec4,
    /// The layer's rectangle of the target (x, y, width, height), the pass's viewport.
    pub rect: [u32; 4],
}

/// The rectangle of the target (x, y, width, height, within `camera.rect`) that the
/// vertices `indices` names of `mesh` can draw into, with `pad` target pixels around them
/// (half a line's width or a point's size); the whole layer's rectangle when any corner
/// of their bounding box is nearer than the near plane (or behind the eye), or when
/// anything is not finite.
pub fn reach(camera: &Camera, mesh: &Mesh, indices: &[u32], pad: f32) -> [u32; 4] {
    if indices.is_empty() {
        return [0; 4];
    }
    let mut lo = glam::Vec3::splat(f32::INFINITY);
    let mut hi = glam::Vec3::splat(f32::NEG_INFINITY);
    for &i in indices {
        let p = glam::Vec3::from(mesh.positions[i as usize]);
        lo = lo.min(p);
        hi = hi.max(p);
    }
    box_reach(camera, lo, hi, pad)
}

/// [`reach`] of a box (its corners `lo` and `hi`).
pub fn box_reach(camera: &Camera, lo: glam::Vec3, hi: glam::Vec3, pad: f32) -> [u32; 4] {
    let whole = camera.rect;
    let [x, y, w, h] = whole.map(|v| v as f32);
    let (mut min, mut max) = (glam::Vec2::INFINITY, glam::Vec2::NEG_INFINITY);
    for corner in 0..8 {
        let p = glam::Vec3::new(
            if corner & 1 == 0 { lo.x } else { hi.x },
            if corner & 2 == 0 { lo.y } else { hi.y },
            if corner & 4 == 0 { lo.z } else { hi.z },
        );
        let clip = camera.view_projection * p.extend(1.0);
        if !(p.dot(camera.forward_near.truncate()) >= camera.forward_near.w && clip.w > 0.0) {
            return whole;
        }
        // The viewport transform: clip x, y in [-1, 1] (y up) to target pixels (y down).
        let pixel = glam::Vec2::new(
            x + (clip.x / clip.w + 1.0) * 0.5 * w,
            y + (1.0 - clip.y / clip.w) * 0.5 * h,
        );
        if pixel.is_nan() {
            return whole;
        }
        min = min.min(pixel);
        max = max.max(pixel);
    }
    let pad = pad + MARGIN;
    clamp(min - pad, max + pad, whole)
}

/// Pixels from `min` to `max` (rounded outwards) within `rect`; none: zero width or height.
fn clamp(min: glam::Vec2, max: glam::Vec2, rect: [u32; 4]) -> [u32; 4] {
    let [x, y, w, h] = rect;
    let span = |lo: f32, hi: f32, start: u32, size: u32| {
        let (start_f, end_f) = (start as f32, (start + size) as f32);
        let a = lo.floor().clamp(start_f, end_f) as u32;
        let b = hi.ceil().clamp(start_f, end_f) as u32;
        (a, b.saturating_sub(a))
    };
    let (x0, width) = span(min.x, max.x, x, w);
    let (y0, height) = span(min.y, max.y, y, h);
    [x0, y0, width, height]
}

/// How far beyond its vertices a mesh draws, in target pixels: half a line's width, half
/// a point's largest size across its diagonal (the shader's quads); nothing for surfaces.
pub fn stroke_pad(mesh: &Mesh, scale: u32) -> f32 {
    let stroke = &mesh.stroke;
    let size = match mesh.primitive {
        Primitive::Triangles => return 0.0,
        Primitive::Lines => stroke.size,
        Primitive::Points => stroke.size.max(stroke.min).max(stroke.max),
    };
    size * scale as f32 * std::f32::consts::FRAC_1_SQRT_2
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A perspective camera at the origin looking down −Z (90° vertical field of view,
    /// near 0.1, far 100) over an 800×600 target.
    fn camera() -> Camera {
        // The projection of `uniforms` (reversed depth): 1 / tan(45°) = 1.
        let (near, far) = (0.1, 100.0);
        let projection = glam::Mat4::from_cols(
            glam::Vec4::new(0.75, 0.0, 0.0, 0.0),
            glam::Vec4::new(0.0, 1.0, 0.0, 0.0),
            glam::Vec4::new(0.0, 0.0, near / (far - near), -1.0),
            glam::Vec4::new(0.0, 0.0, near * far / (far - near), 0.0),
        );
        Camera {
            view_projection: projection,
            forward_near: glam::Vec4::new(0.0, 0.0, -1.0, 0.1),
            rect: [0, 0, 800, 600],
        }
    }

    #[test]
    fn a_box_reaches_where_it_projects() {
        let camera = camera();
        // Straight ahead at distance 10, ±1 across: the centre ±30 pixels (1/10 of the
        // half height 300), and the margin.
        let [x, y, w, h] = box_reach(
            &camera,
            glam::Vec3::new(-1.0, -1.0, -10.0),
            glam::Vec3::new(1.0, 1.0, -10.0),
            0.0,
        );
        assert!(
            (366..=370).contains(&x) && (430..=434).contains(&(x + w)),
            "{x} {w}"
        );
        assert!(
            (266..=270).contains(&y) && (330..=334).contains(&(y + h)),
            "{y} {h}"
        );
        // The pad widens it.
        let padded = box_reach(
            &camera,
            glam::Vec3::new(-1.0, -1.0, -10.0),
            glam::Vec3::new(1.0, 1.0, -10.0),
            10.0,
        );
        assert_eq!(padded, [x - 10, y - 10, w + 20, h + 20]);
    }

    #[test]
    fn a_box_outside_the_view_reaches_nothing() {
        let camera = camera();
        // Far to the right of the view.
        let [.., w, h] = box_reach(
            &camera,
            glam::Vec3::new(50.0, -1.0, -10.0),
            glam::Vec3::new(60.0, 1.0, -10.0),
            0.0,
        );
        assert!(w == 0 || h == 0);
        // Within the layer, but only its left half: misses a tile on the right.
        let reach = box_reach(
            &camera,
            glam::Vec3::new(-12.0, -1.0, -10.0),
            glam::Vec3::new(-2.0, 1.0, -10.0),
            0.0,
        );
        assert_eq!(
            super::super::frame::in_tile(reach, [400, 0, 400, 600]),
            [0; 4]
        );
    }

    #[test]
    fn a_box_crossing_the_near_plane_reaches_the_whole_layer() {
        let camera = camera();
        for (lo_z, hi_z) in [(-10.0, -0.05), (-10.0, 5.0), (1.0, 5.0), (-0.09, -0.01)] {
            assert_eq!(
                box_reach(
                    &camera,
                    glam::Vec3::new(50.0, 50.0, lo_z),
                    glam::Vec3::new(60.0, 60.0, hi_z),
                    0.0,
                ),
                camera.rect,
                "z from {lo_z} to {hi_z}"
            );
        }
        // Not finite: the whole layer too.
        assert_eq!(
            box_reach(
                &camera,
                glam::Vec3::new(f32::NAN, 0.0, -10.0),
                glam::Vec3::new(1.0, 1.0, -10.0),
                0.0,
            ),
            camera.rect
        );
    }

    #[test]
    fn a_tile_edge_on_the_rectangle_edge() {
        // A rectangle ending exactly where a tile begins misses it; one pixel more
        // reaches it.
        let tile = [400, 300, 400, 300];
        assert_eq!(
            super::super::frame::in_tile([300, 300, 100, 50], tile),
            [0; 4]
        );
        assert_eq!(
            super::super::frame::in_tile([300, 300, 101, 50], tile),
            [0, 0, 1, 50]
        );
        // Rounded outwards: a box edge at exactly pixel 400 reaches the pixel before it
        // and (with the margin) the tile from 400 on.
        let camera = Camera {
            // x from 0 to 800 and y from 0 to 600 onto the target.
            view_projection: glam::Mat4::from_cols(
                glam::Vec4::new(1.0 / 400.0, 0.0, 0.0, 0.0),
                glam::Vec4::new(0.0, 1.0 / 300.0, 0.0, 0.0),
                glam::Vec4::new(0.0, 0.0, 0.01, 0.0),
                glam::Vec4::new(-1.0, -1.0, 0.5, 1.0),
            ),
            forward_near: glam::Vec4::new(0.0, 0.0, -1.0, 0.1),
            rect: [0, 0, 800, 600],
        };
        let reach = box_reach(
            &camera,
            glam::Vec3::new(300.0, 250.0, -1.0),
            glam::Vec3::new(400.0, 300.0, -1.0),
            0.0,
        );
        assert_eq!(reach, [298, 298, 104, 54]);
        assert_eq!(
            super::super::frame::in_tile(reach, [400, 0, 400, 300]),
            [0, 298, 2, 2]
        );
    }
}
