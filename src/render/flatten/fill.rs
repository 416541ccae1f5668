//! How many pixels a placed mesh makes the GPU shade: the fill budget's measure. On a
//! software rasterizer (lavapipe, llvmpipe) the time of a frame goes to shading fragments,
//! and each shape is shaded wherever it covers the image, however many shapes lie in front
//! of it: 300 spheres at one place cost 300 full shadings of the pixels they cover. The
//! triangle budget does not see this (one sphere is a few hundred triangles), so each mesh
//! is measured here, against the camera, before anything reaches the GPU.
//!
//! The measure errs on the side of more: a triangle counts its projected area clipped at
//! the near plane, at most the part of the image its bounding box covers (triangles facing
//! away are counted when back faces are drawn); a line counts its projected length times
//! its width, a point its square. Depth testing is not predicted (a hidden shape still
//! counts), which is exactly the case the budget is for.

use glam::{DVec3, Quat};

use crate::render::draw_list::{Camera, Mesh, Primitive, Projection};

/// A camera and an image: points relative to the eye → pixels from the image's centre.
pub struct Screen {
    to_camera: Quat,
    projection: Projection,
    near: f64,
    /// Pixels per unit at distance 1 (perspective) or per unit (orthographic).
    scale: f64,
    /// The orthographic rectangle's centre.
    centre: [f64; 2],
    half: [f64; 2],
}

impl Screen {
    pub fn new(camera: &Camera, width: u32, height: u32) -> Screen {
        let (w, h) = (f64::from(width), f64::from(height));
        let (scale, centre) = match camera.projection {
            // The field of view is that of the smaller side (Viewpoint.fieldOfView).
            Projection::Perspective { field_of_view } => (
                w.min(h) / 2.0 / (f64::from(field_of_view) / 2.0).tan(),
                [0.0; 2],
            ),
            // The smaller dimension is widened to the image's aspect ratio (23.4.5).
            Projection::Orthographic {
                rectangle: [x0, y0, x1, y1],
            } => (
                (w / f64::from(x1 - x0)).min(h / f64::from(y1 - y0)),
                [f64::from(x0 + x1) / 2.0, f64::from(y0 + y1) / 2.0],
            ),
        };
        Screen {
            to_camera: camera.orientation.inverse(),
            projection: camera.projection,
            near: f64::from(camera.near),
            scale,
            centre,
            half: [w / 2.0, h / 2.0],
        }
    }

    /// Pixels of the whole image.
    #[cfg(test)]
    fn pixels(&self) -> f64 {
        4.0 * self.half[0] * self.half[1]
    }

    /// The pixels `mesh` covers, counted once per primitive over it (see the module doc).
    pub fn covered(&self, mesh: &Mesh) -> f64 {
        let camera: Vec<DVec3> = mesh
            .positions
            .iter()
            .map(|p| (self.to_camera * glam::Vec3::from_array(*p)).as_dvec3())
            .collect();
        let corner = |i: u32| camera.get(i as usize).copied();
        let mut total = 0.0;
        match mesh.primitive {
            Primitive::Triangles => {
                let culled = mesh.back.is_none();
                for t in mesh.indices.chunks_exact(3) {
                    if let (Some(a), Some(b), Some(c)) = (corner(t[0]), corner(t[1]), corner(t[2]))
                    {
                        total += self.triangle(&[a, b, c], culled);
                    }
                }
            }
            Primitive::Lines => {
                let width = f64::from(mesh.stroke.size).max(1.0);
                for l in mesh.indices.chunks_exact(2) {
                    if let (Some(a), Some(b)) = (corner(l[0]), corner(l[1])) {
                        total += self.segment(a, b) * width + width * width;
                    }
                }
            }
            Primitive::Points => {
                for &i in &mesh.indices {
                    if let Some(p) = corner(i) {
                        let size = point_size(&mesh.stroke, p.length());
                        total += size * size;
                    }
                }
            }
        }
        total
    }

    /// A triangle's pixels: its part in front of the near plane, projected.
    fn triangle(&self, corners: &[DVec3; 3], culled: bool) -> f64 {
        let mut polygon = [[0.0; 2]; 4];
        let mut n = 0;
        for (i, &p) in corners.iter().enumerate() {
            let q = corners[(i + 1) % 3];
            let (p_in, q_in) = (self.in_front(p), self.in_front(q));
            if p_in {
                polygon[n] = self.project(p);
                n += 1;
            }
            if p_in != q_in {
                polygon[n] = self.project(self.near_crossing(p, q));
                n += 1;
            }
        }
        if n < 3 {
            return 0.0;
        }
        let polygon = &polygon[..n];
        // Twice the signed area, counter-clockwise (front facing) positive.
        let twice: f64 = (0..n)
            .map(|i| {
                let (p, q) = (polygon[i], polygon[(i + 1) % n]);
                p[0] * q[1] - q[0] * p[1]
            })
            .sum();
        if !twice.is_finite() || (culled && twice <= 0.0) {
            return 0.0;
        }
        let box_area = self.visible_box(polygon);
        (twice.abs() / 2.0).min(box_area)
    }

    /// A segment's projected length, at most the image's diagonal.
    fn segment(&self, a: DVec3, b: DVec3) -> f64 {
        let (a_in, b_in) = (self.in_front(a), self.in_front(b));
        let (a, b) = match (a_in, b_in) {
            (true, true) => (a, b),
            (true, false) => (a, self.near_crossing(a, b)),
            (false, true) => (self.near_crossing(a, b), b),
            (false, false) => return 0.0,
        };
        let (p, q) = (self.project(a), self.project(b));
        if self.visible_box(&[p, q]) == 0.0 && !self.visible_extent(&[p, q]) {
            return 0.0;
        }
        let length = (p[0] - q[0]).hypot(p[1] - q[1]);
        let diagonal = 2.0 * self.half[0].hypot(self.half[1]);
        if length.is_finite() {
            length.min(diagonal)
        } else {
            diagonal
        }
    }

    fn in_front(&self, p: DVec3) -> bool {
        match self.projection {
            Projection::Perspective { .. } => -p.z >= self.near,
            Projection::Orthographic { .. } => true,
        }
    }

    /// Where the segment p–q crosses the near plane.
    fn near_crossing(&self, p: DVec3, q: DVec3) -> DVec3 {
        let t = (-self.near - p.z) / (q.z - p.z);
        p + (q - p) * t
    }

    /// Pixels from the image's centre (+y up).
    fn project(&self, p: DVec3) -> [f64; 2] {
        match self.projection {
            Projection::Perspective { .. } => [p.x / -p.z * self.scale, p.y / -p.z * self.scale],
            Projection::Orthographic { .. } => [
                (p.x - self.centre[0]) * self.scale,
                (p.y - self.centre[1]) * self.scale,
            ],
        }
    }

    /// The area of the image the points' bounding box covers.
    fn visible_box(&self, points: &[[f64; 2]]) -> f64 {
        let extent = |axis: usize| {
            let (lo, hi) = points.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| {
                (lo.min(p[axis]), hi.max(p[axis]))
            });
            (hi.min(self.half[axis]) - lo.max(-self.half[axis])).max(0.0)
        };
        let area = extent(0) * extent(1);
        if area.is_nan() {
            0.0
        } else {
            area
        }
    }

    /// Whether the points' bounding box meets the image (a horizontal or vertical
    /// segment's box has no area).
    fn visible_extent(&self, points: &[[f64; 2]]) -> bool {
        (0..2).all(|axis| {
            let lo = points.iter().map(|p| p[axis]).fold(f64::MAX, f64::min);
            let hi = points.iter().map(|p| p[axis]).fold(f64::MIN, f64::max);
            hi >= -self.half[axis] && lo <= self.half[axis]
        })
    }
}

/// A point's size at distance `r` from the viewer (12.4.7), as the shader draws it.
fn point_size(stroke: &crate::render::draw_list::Stroke, r: f64) -> f64 {
    let [a, b, c] = stroke.attenuation.map(f64::from);
    let size = f64::from(stroke.size) / (a + b * r + c * r * r);
    if size.is_finite() {
        size.clamp(f64::from(stroke.min), f64::from(stroke.max).max(1.0))
    } else {
        f64::from(stroke.max).max(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::draw_list::Stroke;
    use crate::render::flatten::default_material;

    fn camera() -> Camera {
        Camera {
            orientation: Quat::IDENTITY,
            // 90°: at distance 1, the smaller side spans −1 … 1.
            projection: Projection::Perspective {
                field_of_view: std::f32::consts::FRAC_PI_2,
            },
            near: 0.1,
            far: 100.0,
        }
    }

    fn mesh(positions: Vec<[f32; 3]>, indices: Vec<u32>, two_sided: bool) -> Mesh {
        Mesh {
            primitive: Primitive::Triangles,
            positions,
            normals: None,
            tangents: None,
            colors: None,
            colors_have_alpha: false,
            tex_coords: Vec::new(),
            indices,
            front: default_material(),
            back: two_sided.then(default_material),
            textures: Default::default(),
            light_mask: 0,
            clip_planes: Vec::new(),
            scissor: None,
            blended: false,
            alpha_cutoff: 0.0,
            stroke: Stroke::default(),
        }
    }

    #[test]
    fn a_triangle_counts_its_projected_area_and_not_when_culled() {
        let screen = Screen::new(&camera(), 200, 100);
        // At distance 1 a unit is 50 pixels: a right triangle of legs 0.5 is 25 × 25 / 2.
        let front = mesh(
            vec![[0.0, 0.0, -1.0], [0.5, 0.0, -1.0], [0.0, 0.5, -1.0]],
            vec![0, 1, 2],
            false,
        );
        assert!((screen.covered(&front) - 312.5).abs() < 1e-3);
        let back = mesh(front.positions.clone(), vec![0, 2, 1], false);
        assert_eq!(screen.covered(&back), 0.0);
        let two_sided = mesh(front.positions.clone(), vec![0, 2, 1], true);
        assert!((screen.covered(&two_sided) - 312.5).abs() < 1e-3);
    }

    #[test]
    fn a_triangle_counts_at_most_the_image_and_nothing_behind_the_eye() {
        let screen = Screen::new(&camera(), 200, 100);
        let huge = mesh(
            vec![[-1e6, -1e6, -1.0], [1e6, -1e6, -1.0], [0.0, 1e6, -1.0]],
            vec![0, 1, 2],
            false,
        );
        assert_eq!(screen.covered(&huge), screen.pixels());
        // Crossing the near plane: only the part in front counts, at most the image.
        let crossing = mesh(
            vec![[-1.0, -1.0, 1.0], [1.0, -1.0, -1.0], [0.0, 1.0, -1.0]],
            vec![0, 1, 2],
            true,
        );
        let counted = screen.covered(&crossing);
        assert!(counted > 0.0 && counted <= screen.pixels());
        let behind = mesh(
            vec![[0.0, 0.0, 1.0], [0.5, 0.0, 1.0], [0.0, 0.5, 1.0]],
            vec![0, 1, 2],
            true,
        );
        assert_eq!(screen.covered(&behind), 0.0);
        let aside = mesh(
            vec![[10.0, 0.0, -1.0], [10.5, 0.0, -1.0], [10.0, 0.5, -1.0]],
            vec![0, 1, 2],
            true,
        );
        assert_eq!(screen.covered(&aside), 0.0);
    }

    #[test]
    fn lines_count_length_times_width() {
        let screen = Screen::new(&camera(), 200, 100);
        let mut line = mesh(vec![[0.0, 0.0, -1.0], [0.5, 0.0, -1.0]], vec![0, 1], true);
        line.primitive = Primitive::Lines;
        line.stroke.size = 2.0;
        // 25 pixels long, 2 wide, and the end caps.
        assert!((screen.covered(&line) - 54.0).abs() < 1e-3);
    }
}
