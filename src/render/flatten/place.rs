//! Placing a shape: its texture coordinate sets generated and transformed, tangents for
//! a normal texture, then every vertex through its world transform and relative to the
//! eye, in f64, rounded once (the draw list's guarantees).

use glam::{DMat3, DMat4, DQuat, DVec3, DVec4};

use super::Scope;
use crate::render::draw_list::{Material, Mesh, Primitive, Stroke, Textures};
use crate::render::mesh::LocalMesh;
use crate::render::tangents::tangents;
use crate::render::texgen::{Frame, Generator};

/// A shape in local coordinates, waiting for the camera.
pub struct Pending {
    pub mesh: LocalMesh,
    pub world: DMat4,
    pub front: Material,
    pub back: Option<Material>,
    pub textures: Textures,
    /// How each texture coordinate set of the mesh is finished.
    pub channels: Vec<Channel>,
    /// The texture coordinate set of the normal texture, when tangents are needed.
    pub tangents_for: Option<usize>,
    pub scope: Scope,
    pub blended: bool,
    pub alpha_cutoff: f32,
    pub stroke: Stroke,
}

/// What turns a texture coordinate set into the one sampled.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Channel {
    /// Computed from the placed vertices (the set is empty until then).
    pub generator: Option<Generator>,
    pub transform: Option<TextureTransform>,
}

/// TextureTransform (18.4.10) as a function of texture coordinates:
/// P' = −C × S × R × C × T × P.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct TextureTransform {
    center: [f64; 2],
    scale: [f64; 2],
    translation: [f64; 2],
    sin: f64,
    cos: f64,
}

impl TextureTransform {
    pub fn of(doc: &crate::model::Document, id: crate::model::NodeId) -> TextureTransform {
        use crate::render::fields::{float, floats};
        let pair = |name: &str, fallback: [f64; 2]| match floats(doc, id, name).as_ref() {
            [a, b, ..] if a.is_finite() && b.is_finite() => [f64::from(*a), f64::from(*b)],
            _ => fallback,
        };
        let (sin, cos) = f64::from(float(doc, id, "rotation", 0.0)).sin_cos();
        TextureTransform {
            center: pair("center", [0.0; 2]),
            scale: pair("scale", [1.0; 2]),
            translation: pair("translation", [0.0; 2]),
            sin,
            cos,
        }
    }

    pub fn apply(&self, [s, t]: [f32; 2]) -> [f32; 2] {
        let (s, t) = (
            f64::from(s) + self.translation[0] + self.center[0],
            f64::from(t) + self.translation[1] + self.center[1],
        );
        let (s, t) = (s * self.cos - t * self.sin, s * self.sin + t * self.cos);
        [
            (s * self.scale[0] - self.center[0]) as f32,
            (t * self.scale[1] - self.center[1]) as f32,
        ]
    }
}

/// The eye: where it is and how it looks (camera space is −Z forward, +Y up).
pub struct EyeFrame {
    eye: DVec3,
    to_eye: DMat4,
    camera_from_world: DMat4,
}

impl EyeFrame {
    pub fn new(eye: DVec3, orientation: DQuat) -> EyeFrame {
        let to_eye = DMat4::from_translation(-eye);
        EyeFrame {
            eye,
            to_eye,
            camera_from_world: DMat4::from_quat(orientation.inverse()) * to_eye,
        }
    }
}

impl Pending {
    /// The mesh relative to the eye, with `global_lights` added to its scoped ones. The
    /// local mesh's vectors are reused: a large mesh is not copied on its way.
    pub fn place(self, frame: &EyeFrame, global_lights: u32) -> Mesh {
        let origin = DVec3::from_array(self.mesh.origin);
        let texgen_frame = Frame {
            origin,
            world: self.world,
            camera_from_world: frame.camera_from_world,
        };
        let world = self.world * DMat4::from_translation(origin);
        let mut mesh = self.mesh;
        for (set, channel) in mesh.tex_coords.iter_mut().zip(&self.channels) {
            if let Some(generator) = &channel.generator {
                *set = generator.generate(&mesh.positions, mesh.normals.as_deref(), &texgen_frame);
            }
            if let Some(transform) = &channel.transform {
                for t in set.iter_mut() {
                    *t = transform.apply(*t);
                }
            }
            for t in set.iter_mut() {
                *t = t.map(|c| if c.is_finite() { c } else { 0.0 });
            }
        }
        let local_tangents = match (self.tangents_for, &mesh.normals) {
            (Some(set), Some(normals)) if mesh.primitive == Primitive::Triangles => mesh
                .tex_coords
                .get(set)
                .filter(|uv| uv.len() == mesh.positions.len())
                .map(|uv| tangents(&mesh.positions, normals, uv, &mesh.indices)),
            _ => None,
        };

        let matrix = frame.to_eye * world;
        for q in &mut mesh.positions {
            *q = to_f32(matrix.transform_point3(DVec3::from_array(q.map(f64::from))));
        }
        let linear = DMat3::from_mat4(world);
        let determinant = linear.determinant();
        let normal_matrix = if determinant != 0.0 && determinant.is_finite() {
            linear.inverse().transpose()
        } else {
            DMat3::ZERO
        };
        if let Some(normals) = mesh.normals.as_mut() {
            for n in normals.iter_mut() {
                *n = unit_or_zero(normal_matrix * DVec3::from_array(n.map(f64::from)));
            }
        }
        let mirrored = determinant < 0.0;
        let tangents = local_tangents.map(|local| {
            local
                .into_iter()
                .map(|t| {
                    let [x, y, z] =
                        unit_or_zero(linear * DVec3::new(t[0].into(), t[1].into(), t[2].into()));
                    // A mirroring transform flips the handedness of the tangent frame.
                    [x, y, z, if mirrored { -t[3] } else { t[3] }]
                })
                .collect()
        });
        drop_non_finite(&mut mesh, mirrored);
        Mesh {
            primitive: mesh.primitive,
            positions: mesh.positions,
            normals: mesh.normals,
            tangents,
            colors: mesh.colors,
            colors_have_alpha: mesh.colors_have_alpha,
            tex_coords: mesh.tex_coords,
            indices: mesh.indices,
            front: self.front,
            back: self.back,
            textures: self.textures,
            light_mask: self.scope.lights | global_lights,
            clip_planes: self
                .scope
                .clip_planes
                .iter()
                .map(|&plane| relative_plane(plane, frame.eye))
                .collect(),
            scissor: self.scope.scissor,
            blended: self.blended,
            alpha_cutoff: self.alpha_cutoff,
            stroke: self.stroke,
        }
    }
}

/// Drops the primitives with a non-finite corner (compacting the index list in place)
/// and keeps front faces in front under a mirroring transform.
fn drop_non_finite(mesh: &mut LocalMesh, mirrored: bool) {
    let positions = &mesh.positions;
    let finite = |i: u32| {
        positions
            .get(i as usize)
            .is_some_and(|q| q.iter().all(|c| c.is_finite()))
    };
    let per = mesh.primitive.arity();
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
}

/// A world plane (a, b, c, d) with the eye as origin: d grows by (a, b, c)·eye.
fn relative_plane(plane: DVec4, eye: DVec3) -> [f32; 4] {
    let normal = plane.truncate();
    let scale = normal.length();
    let d = (plane.w + normal.dot(eye)) / scale;
    let n = normal / scale;
    [n.x as f32, n.y as f32, n.z as f32, d as f32]
}

pub fn to_f32(v: DVec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn unit_or_zero(v: DVec3) -> [f32; 3] {
    let length = v.length();
    if length > 0.0 && length.is_finite() {
        to_f32(v / length)
    } else {
        [0.0; 3]
    }
}

/// A unit vector, or −Z (the default light direction) for a zero or non-finite one.
pub fn unit_vector(v: DVec3) -> [f32; 3] {
    let length = v.length();
    if length > 0.0 && length.is_finite() {
        to_f32(v / length)
    } else {
        [0.0, 0.0, -1.0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texture_transform_follows_the_matrix_product_of_18_4_10() {
        // Tc' = −C × S × R × C × T × Tc, applied right to left (as X_ITE does): with
        // centre 0.5 and scale 2, (0.75 + 0.5) × 2 − 0.5 = 2.
        let t = TextureTransform {
            center: [0.5, 0.5],
            scale: [2.0, 2.0],
            translation: [0.0, 0.0],
            sin: 0.0,
            cos: 1.0,
        };
        assert_eq!(t.apply([0.75, 0.5]), [2.0, 1.5]);
        let shifted = TextureTransform {
            translation: [0.25, 0.0],
            scale: [1.0, 1.0],
            ..t
        };
        assert_eq!(shifted.apply([0.0, 0.0]), [0.25, 0.0]);
    }

    #[test]
    fn clip_planes_move_with_the_eye() {
        // y ≥ 5 in the world; with the eye at y = 2 that is y' ≥ 3.
        let p = relative_plane(DVec4::new(0.0, 2.0, 0.0, -10.0), DVec3::new(0.0, 2.0, 0.0));
        assert_eq!(p, [0.0, 1.0, 0.0, -3.0]);
    }
}
