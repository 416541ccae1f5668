//! TextureCoordinateGenerator (18.4.8, Table 18.6): texture coordinates computed from the
//! vertices, in local or camera space. The renderer draws one still image from a known
//! camera, so the view-dependent modes are computed once per vertex when the mesh is
//! placed, in f64.
//!
//! Readings where Table 18.6 leaves a choice (each is what X_ITE, a maintained X3D
//! browser, does unless said otherwise):
//! - The 2D coordinates are the x and y of the 3D vector a mode defines.
//! - SPHERE-REFLECT and SPHERE-REFLECT-LOCAL refract the view vector with parameter[0] as
//!   the ratio of indices of refraction (1 when absent: the ray goes straight through);
//!   the -LOCAL mode takes the eye from parameter[1..=3], in local coordinates.
//! - NOISE and NOISE-EYE apply Perlin's improved gradient noise ("solid noise", 2002) to
//!   the point scaled and translated by parameter[0..3] and [3..6] (scale 1, translation
//!   0 when absent); t is the noise at the point shifted by a fixed offset, so that s and
//!   t are independent.

use glam::{DMat3, DMat4, DVec3};

use crate::model::{Document, NodeId};

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Mode {
    Sphere,
    CameraSpaceNormal,
    CameraSpacePosition,
    CameraSpaceReflectionVector,
    SphereLocal,
    Coord,
    CoordEye,
    Noise,
    NoiseEye,
    SphereReflect,
    SphereReflectLocal,
}

impl Mode {
    fn parse(text: &str) -> Option<Mode> {
        Some(match text {
            "SPHERE" => Mode::Sphere,
            "CAMERASPACENORMAL" => Mode::CameraSpaceNormal,
            "CAMERASPACEPOSITION" => Mode::CameraSpacePosition,
            "CAMERASPACEREFLECTIONVECTOR" => Mode::CameraSpaceReflectionVector,
            "SPHERE-LOCAL" => Mode::SphereLocal,
            "COORD" => Mode::Coord,
            "COORD-EYE" => Mode::CoordEye,
            "NOISE" => Mode::Noise,
            "NOISE-EYE" => Mode::NoiseEye,
            "SPHERE-REFLECT" => Mode::SphereReflect,
            "SPHERE-REFLECT-LOCAL" => Mode::SphereReflectLocal,
            _ => return None,
        })
    }

    /// Whether the mode reads the vertex normals.
    pub fn needs_normals(self) -> bool {
        matches!(
            self,
            Mode::Sphere
                | Mode::CameraSpaceNormal
                | Mode::CameraSpaceReflectionVector
                | Mode::SphereLocal
                | Mode::SphereReflect
                | Mode::SphereReflectLocal
        )
    }
}

/// A TextureCoordinateGenerator's mode and parameters.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Generator {
    pub mode: Mode,
    parameter: [f64; 6],
    parameter_count: usize,
}

/// Where the mesh is: its positions are offsets from `origin` in local coordinates;
/// local to world, and world to camera space (the eye at the origin, looking down −Z).
#[derive(Copy, Clone, Debug)]
pub struct Frame {
    pub origin: DVec3,
    pub world: DMat4,
    pub camera_from_world: DMat4,
}

impl Generator {
    /// The node's generator, or why it cannot be used.
    pub fn of(doc: &Document, node: NodeId) -> Result<Generator, String> {
        let text = doc
            .string_of(node, "mode")
            .unwrap_or_else(|| "SPHERE".into());
        let mode = Mode::parse(&text)
            .ok_or_else(|| format!("TextureCoordinateGenerator mode `{text}` is not drawn"))?;
        let values = super::fields::floats(doc, node, "parameter");
        let mut parameter = [0.0; 6];
        for (slot, value) in parameter.iter_mut().zip(values.iter()) {
            *slot = f64::from(*value);
        }
        Ok(Generator {
            mode,
            parameter,
            parameter_count: values.len().min(6),
        })
    }

    fn parameter(&self, i: usize, fallback: f64) -> f64 {
        if i < self.parameter_count && self.parameter[i].is_finite() {
            self.parameter[i]
        } else {
            fallback
        }
    }

    /// Coordinates for each vertex; `normals` (local) are present when
    /// [`Mode::needs_normals`]. Non-finite results become 0.
    pub fn generate(
        &self,
        positions: &[[f32; 3]],
        normals: Option<&[[f32; 3]]>,
        frame: &Frame,
    ) -> Vec<[f32; 2]> {
        let camera = frame.camera_from_world * frame.world;
        let linear = DMat3::from_mat4(camera);
        let normal_matrix = if linear.determinant() != 0.0 {
            linear.inverse().transpose()
        } else {
            DMat3::ZERO
        };
        let eta = self.parameter(0, 1.0);
        let local_eye = DVec3::new(
            self.parameter(1, 0.0),
            self.parameter(2, 0.0),
            self.parameter(3, 0.0),
        );
        let scale = DVec3::new(
            self.parameter(0, 1.0),
            self.parameter(1, 1.0),
            self.parameter(2, 1.0),
        );
        let translation = DVec3::new(
            self.parameter(3, 0.0),
            self.parameter(4, 0.0),
            self.parameter(5, 0.0),
        );
        positions
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let local = frame.origin + DVec3::from_array(p.map(f64::from));
                let local_normal = normals
                    .and_then(|n| n.get(i))
                    .map_or(DVec3::ZERO, |n| DVec3::from_array(n.map(f64::from)))
                    .normalize_or_zero();
                let eye_position = || camera.transform_point3(local);
                let eye_normal = || (normal_matrix * local_normal).normalize_or_zero();
                let v = match self.mode {
                    Mode::Sphere => eye_normal() * 0.5 + DVec3::splat(0.5),
                    Mode::CameraSpaceNormal => eye_normal(),
                    Mode::CameraSpacePosition | Mode::CoordEye => eye_position(),
                    Mode::CameraSpaceReflectionVector => {
                        reflect(eye_position().normalize_or_zero(), -eye_normal())
                    }
                    Mode::SphereLocal => local_normal * 0.5 + DVec3::splat(0.5),
                    Mode::Coord => local,
                    Mode::Noise => noise_pair(local * scale + translation),
                    Mode::NoiseEye => noise_pair(eye_position() * scale + translation),
                    Mode::SphereReflect => {
                        refract(eye_position().normalize_or_zero(), -eye_normal(), eta)
                    }
                    Mode::SphereReflectLocal => {
                        refract((local - local_eye).normalize_or_zero(), -local_normal, eta)
                    }
                };
                [finite(v.x), finite(v.y)]
            })
            .collect()
    }
}

fn finite(v: f64) -> f32 {
    let v = v as f32;
    if v.is_finite() {
        v
    } else {
        0.0
    }
}

/// GLSL's reflect(I, N) = I − 2 (N·I) N.
fn reflect(incident: DVec3, normal: DVec3) -> DVec3 {
    incident - 2.0 * normal.dot(incident) * normal
}

/// GLSL's refract(I, N, η): zero on total internal reflection.
fn refract(incident: DVec3, normal: DVec3, eta: f64) -> DVec3 {
    let cos = normal.dot(incident);
    let k = 1.0 - eta * eta * (1.0 - cos * cos);
    if k < 0.0 {
        DVec3::ZERO
    } else {
        eta * incident - (eta * cos + k.sqrt()) * normal
    }
}

/// (noise(p), noise(p + offset)) as the x and y of a vector.
fn noise_pair(p: DVec3) -> DVec3 {
    const OFFSET: DVec3 = DVec3::new(31.416, 27.183, 14.142);
    DVec3::new(perlin(p), perlin(p + OFFSET), 0.0)
}

/// Perlin's improved noise (SIGGRAPH 2002) in [−1, 1], with a fixed permutation.
pub fn perlin(p: DVec3) -> f64 {
    if !p.is_finite() {
        return 0.0;
    }
    let floor = p.floor();
    // The lattice repeats every 256 units; rem_euclid keeps huge inputs in range.
    let cell = |v: f64| v.rem_euclid(256.0) as usize;
    let (x, y, z) = (cell(floor.x), cell(floor.y), cell(floor.z));
    let f = p - floor;
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let (u, v, w) = (fade(f.x), fade(f.y), fade(f.z));
    let perm = permutation();
    let hash = |i: usize| perm[i & 255] as usize;
    let a = hash(x) + y;
    let (aa, ab) = (hash(a) + z, hash(a + 1) + z);
    let b = hash(x + 1) + y;
    let (ba, bb) = (hash(b) + z, hash(b + 1) + z);
    let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
    let g = |h: usize, dx: f64, dy: f64, dz: f64| gradient(perm[h & 255], dx, dy, dz);
    lerp(
        w,
        lerp(
            v,
            lerp(u, g(aa, f.x, f.y, f.z), g(ba, f.x - 1.0, f.y, f.z)),
            lerp(
                u,
                g(ab, f.x, f.y - 1.0, f.z),
                g(bb, f.x - 1.0, f.y - 1.0, f.z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                g(aa + 1, f.x, f.y, f.z - 1.0),
                g(ba + 1, f.x - 1.0, f.y, f.z - 1.0),
            ),
            lerp(
                u,
                g(ab + 1, f.x, f.y - 1.0, f.z - 1.0),
                g(bb + 1, f.x - 1.0, f.y - 1.0, f.z - 1.0),
            ),
        ),
    )
}

/// The dot product with one of the 12 edge directions of a cube, chosen by the hash.
fn gradient(hash: u8, x: f64, y: f64, z: f64) -> f64 {
    let h = hash & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
}

/// A fixed shuffle of 0..=255 (Fisher–Yates with SplitMix64), made once.
fn permutation() -> &'static [u8; 256] {
    static TABLE: std::sync::OnceLock<[u8; 256]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut table: [u8; 256] = std::array::from_fn(|i| i as u8);
        let mut state: u64 = 0x05EE_D0F7_ED15_EA5E;
        for i in (1..256).rev() {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            table.swap(i, (z % (i as u64 + 1)) as usize);
        }
        table
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn generator(mode: Mode, parameter: &[f64]) -> Generator {
        let mut p = [0.0; 6];
        p[..parameter.len()].copy_from_slice(parameter);
        Generator {
            mode,
            parameter: p,
            parameter_count: parameter.len(),
        }
    }

    /// The eye at (0, 0, 5) looking down −Z; the mesh at the world origin.
    fn frame() -> Frame {
        Frame {
            origin: DVec3::ZERO,
            world: DMat4::IDENTITY,
            camera_from_world: DMat4::from_translation(DVec3::new(0.0, 0.0, -5.0)),
        }
    }

    #[test]
    fn sphere_maps_the_camera_space_normal() {
        let g = generator(Mode::Sphere, &[]);
        let uv = g.generate(
            &[[0.0; 3], [0.0; 3]],
            Some(&[[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]),
            &frame(),
        );
        assert_eq!(uv, vec![[0.5, 0.5], [1.0, 0.5]]);
    }

    #[test]
    fn coord_modes_use_local_or_camera_space_positions() {
        let p = [[1.0, 2.0, 3.0]];
        assert_eq!(
            generator(Mode::Coord, &[]).generate(&p, None, &frame()),
            vec![[1.0, 2.0]]
        );
        let rotated = Frame {
            world: DMat4::from_translation(DVec3::new(10.0, 0.0, 0.0)),
            ..frame()
        };
        assert_eq!(
            generator(Mode::CoordEye, &[]).generate(&p, None, &rotated),
            vec![[11.0, 2.0]]
        );
    }

    #[test]
    fn reflection_of_a_head_on_view_points_back() {
        // A vertex straight ahead with its normal towards the eye reflects to (0, 0, 1).
        let g = generator(Mode::CameraSpaceReflectionVector, &[]);
        let uv = g.generate(&[[0.0; 3]], Some(&[[0.0, 0.0, 1.0]]), &frame());
        assert_eq!(uv, vec![[0.0, 0.0]]);
        // Refraction with η = 1 passes straight through.
        let straight = generator(Mode::SphereReflect, &[1.0]).generate(
            &[[3.0, 0.0, 0.0]],
            Some(&[[0.0, 0.0, 1.0]]),
            &frame(),
        );
        let expected = DVec3::new(3.0, 0.0, -5.0).normalize();
        assert!((f64::from(straight[0][0]) - expected.x).abs() < 1e-6);
    }

    #[test]
    fn noise_is_bounded_deterministic_and_finite_everywhere() {
        for p in [
            DVec3::new(0.5, 0.25, 0.75),
            DVec3::new(-1e9, 3e7, 12.5),
            DVec3::splat(f64::MAX),
            DVec3::new(f64::NAN, 0.0, 0.0),
        ] {
            let n = perlin(p);
            assert!(n.is_finite() && (-1.0..=1.0).contains(&n), "{p:?}: {n}");
            assert_eq!(n, perlin(p));
        }
        // Zero at every lattice point, not constant in between.
        assert_eq!(perlin(DVec3::new(3.0, 4.0, 5.0)), 0.0);
        assert_ne!(
            perlin(DVec3::new(0.3, 0.4, 0.5)),
            perlin(DVec3::new(0.6, 0.2, 0.9))
        );
    }

    #[test]
    fn missing_or_non_finite_parameters_take_the_defaults() {
        let g = generator(Mode::Noise, &[f64::NAN]);
        let uv = g.generate(&[[0.3, 0.4, 0.5]], None, &frame());
        let p = DVec3::new(0.3f32.into(), 0.4f32.into(), 0.5f32.into());
        assert_eq!(uv[0][0], perlin(p) as f32);
    }
}
