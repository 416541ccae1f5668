//! Box, Sphere, Cylinder and Cone as triangle meshes with the normals and the default
//! texture coordinates of 13.3 (Geometry3D). All three attributes are always produced
//! (one texture coordinate set): they are cheap at these sizes, and the caller drops
//! what the material does not need.

use std::f32::consts::{PI, TAU};

use crate::render::draw_list::Primitive;
use crate::render::mesh::LocalMesh;

/// Segments around the axis of round primitives.
pub(super) const SEGMENTS: u32 = 48;
/// Rings from pole to pole of a sphere.
const RINGS: u32 = 24;

#[derive(Default)]
struct Builder {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    tex_coords: Vec<[f32; 2]>,
    indices: Vec<u32>,
}

impl Builder {
    fn vertex(&mut self, p: [f32; 3], n: [f32; 3], t: [f32; 2]) -> u32 {
        self.positions.push(p);
        self.normals.push(n);
        self.tex_coords.push(t);
        self.positions.len() as u32 - 1
    }

    /// Two counterclockwise triangles a-b-c, a-c-d.
    fn quad(&mut self, [a, b, c, d]: [u32; 4]) {
        self.indices.extend_from_slice(&[a, b, c, a, c, d]);
    }

    fn finish(self) -> LocalMesh {
        LocalMesh {
            primitive: Primitive::Triangles,
            positions: self.positions,
            normals: Some(self.normals),
            tex_coords: vec![self.tex_coords],
            indices: self.indices,
            ..LocalMesh::default()
        }
    }
}

fn finite_or(v: f32, fallback: f32) -> f32 {
    if v.is_finite() {
        v
    } else {
        fallback
    }
}

/// Box: each face textured with the whole image, upright as seen from outside (13.3.1).
pub fn cuboid(size: [f32; 3]) -> LocalMesh {
    let [x, y, z] = size.map(|s| finite_or(s, 0.0) / 2.0);
    let mut b = Builder::default();
    // (normal, u axis, v axis) per face; corners go (−u,−v), (+u,−v), (+u,+v), (−u,+v).
    let faces: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
    ];
    let half = [x, y, z];
    for (n, u, v) in faces {
        let corner = |su: f32, sv: f32| [0, 1, 2].map(|k| (n[k] + su * u[k] + sv * v[k]) * half[k]);
        let ids = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .map(|(su, sv)| b.vertex(corner(su, sv), n, [(su + 1.0) / 2.0, (sv + 1.0) / 2.0]));
        b.quad(ids);
    }
    b.finish()
}

/// Sphere (13.3.6): the seam at the back (−Z), s increasing counterclockwise seen from
/// above, t from 0 at the south pole to 1 at the north pole.
pub fn sphere(radius: f32) -> LocalMesh {
    let r = finite_or(radius, 0.0);
    let mut b = Builder::default();
    for ring in 0..=RINGS {
        let t = ring as f32 / RINGS as f32;
        let polar = PI * (1.0 - t); // from the south pole (t = 0) up
        let (sin_p, cos_p) = polar.sin_cos();
        for seg in 0..=SEGMENTS {
            let s = seg as f32 / SEGMENTS as f32;
            let azimuth = TAU * s;
            // s = 0 at −Z, then −X, +Z (s = 0.5), +X: counterclockwise seen from above.
            let n = [-azimuth.sin() * sin_p, cos_p, -azimuth.cos() * sin_p];
            b.vertex(n.map(|c| c * r), n, [s, t]);
        }
    }
    let row = SEGMENTS + 1;
    for ring in 0..RINGS {
        for seg in 0..SEGMENTS {
            let a = ring * row + seg;
            b.quad([a, a + 1, a + 1 + row, a + row]);
        }
    }
    b.finish()
}

fn side(b: &mut Builder, bottom_radius: f32, top_radius: f32, half: f32) {
    let slope = (bottom_radius - top_radius) / (2.0 * half).max(f32::MIN_POSITIVE);
    let base = b.positions.len() as u32;
    for seg in 0..=SEGMENTS {
        let s = seg as f32 / SEGMENTS as f32;
        let azimuth = TAU * s;
        let (x, z) = (-azimuth.sin(), -azimuth.cos());
        let normal_len = (1.0 + slope * slope).sqrt();
        let n = [x / normal_len, slope / normal_len, z / normal_len];
        b.vertex([x * bottom_radius, -half, z * bottom_radius], n, [s, 0.0]);
        b.vertex([x * top_radius, half, z * top_radius], n, [s, 1.0]);
    }
    for seg in 0..SEGMENTS {
        let a = base + seg * 2;
        b.quad([a, a + 2, a + 3, a + 1]);
    }
}

/// A disc cap at height y facing up (+1) or down (−1); textured as a circle cut from the
/// image (13.3.2: seen from above for the top, from below for the bottom).
fn cap(b: &mut Builder, radius: f32, y: f32, facing: f32) {
    let centre = b.vertex([0.0, y, 0.0], [0.0, facing, 0.0], [0.5, 0.5]);
    let first = b.positions.len() as u32;
    for seg in 0..=SEGMENTS {
        let azimuth = TAU * seg as f32 / SEGMENTS as f32;
        let (x, z) = (azimuth.sin(), azimuth.cos());
        b.vertex(
            [x * radius, y, z * radius],
            [0.0, facing, 0.0],
            [0.5 + x / 2.0, 0.5 - facing * z / 2.0],
        );
    }
    for seg in 0..SEGMENTS {
        let (p, q) = (first + seg, first + seg + 1);
        if facing > 0.0 {
            b.indices.extend_from_slice(&[centre, p, q]);
        } else {
            b.indices.extend_from_slice(&[centre, q, p]);
        }
    }
}

pub fn cylinder(radius: f32, height: f32, [has_side, top, bottom]: [bool; 3]) -> LocalMesh {
    let r = finite_or(radius, 0.0);
    let half = finite_or(height, 0.0) / 2.0;
    let mut b = Builder::default();
    if has_side {
        side(&mut b, r, r, half);
    }
    if top {
        cap(&mut b, r, half, 1.0);
    }
    if bottom {
        cap(&mut b, r, -half, -1.0);
    }
    b.finish()
}

pub fn cone(bottom_radius: f32, height: f32, has_side: bool, bottom: bool) -> LocalMesh {
    let r = finite_or(bottom_radius, 0.0);
    let half = finite_or(height, 0.0) / 2.0;
    let mut b = Builder::default();
    if has_side {
        side(&mut b, r, 0.0, half);
    }
    if bottom {
        cap(&mut b, r, -half, -1.0);
    }
    b.finish()
}
