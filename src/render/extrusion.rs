//! Extrusion (ISO/IEC 19775-1 13.3.5): the crossSection placed at every spine point in its
//! spine-aligned cross-section plane (SCP), scaled and oriented, joined by quadrilaterals,
//! capped; handed to [`polygons::build`] as faces, which ear-clips them (concave caps
//! included) and generates the creaseAngle normals.
//!
//! Where the clause leaves a choice, this reads it so:
//! - "If two points are coincident, they both have the same SCP": the SCPs are computed
//!   on the spine with each run of coincident consecutive points taken once, and every
//!   point of a run gets that SCP. This also settles the Y axis of a first point whose
//!   neighbour coincides (the next distinct point is used). A spine whose points all
//!   coincide has the identity SCP (a surface revolved by orientation alone).
//! - Three points are collinear when |a × b| ≤ 10⁻⁶ |a| |b|, so that float noise in a
//!   straight spine does not choose Z axes.
//! - A Y axis that vanishes (spine[i+1] = spine[i−1]: the spine turns back on itself)
//!   is the direction of the next segment.
//! - "The entire spine is collinear": every SCP is the rotation taking +Y to the first
//!   segment's direction (the shortest arc, about Y × direction). For a spine along −Y
//!   the clause leaves the rotation open (every half turn about a horizontal axis takes
//!   +Y there); X_ITE (after Coin's SbRotation) turns about Z, so that the
//!   crossSection's x runs along −X and its z along +Z (view3dscene was seen drawing
//!   the same): so does this.
//! - A Z axis taken from a neighbour is made perpendicular to this point's Y axis (the
//!   test against flipping uses the Z axes as the clause computes them). X = Y × Z.
//! - Closed spine (first point = last): both ends have the first point's SCP, as the
//!   clause says, even after Z flips along the way.
//! - scale and orientation: one value applies to every spine point; a list shorter than
//!   the spine (undefined by the clause) repeats its last value.
//! - Seams: a closed crossSection (first point = last) shares its seam's coordinates, and
//!   so does a closed spine whose last cross-section lands exactly on its first, so that
//!   creaseAngle smooths across them; their texture coordinates stay 0 on one side and 1
//!   on the other.
//! - Caps have vertices of their own, never smoothed with the sides; their normal is the
//!   cap polygon's, which is the SCP's Y axis unless an orientation tilts the section.
//!   An open crossSection is closed for the caps by its first point.
//! - `convex` changes nothing: every face is ear-clipped.
//! - Texture coordinates: s from 0 to 1 along the crossSection and t from 0 to 1 along
//!   the spine, each by accumulated length (by point number when the length is zero);
//!   caps: the crossSection's bounding box, its larger side from 0 to 1, s along X and t
//!   along Z.
//! - Non-finite spine, crossSection or scale values, or more than [`MAX_TRIANGLES`]
//!   triangles: not drawn, with the reason.
//!
//! The clause is not among the project's spec extracts; its rules were read from the
//! public text (the same, for these rules, as VRML97's Extrusion).

use glam::{DMat3, DQuat, DVec3};

use super::geometry2d::bounding_rectangle;
use super::{crease_generation, Needs, TexCoordSource};
use crate::model::faces::Attribute as Kind;
use crate::model::{Document, NodeId};
use crate::render::fields::{boolean, floats, rotation_of};
use crate::render::mesh::LocalMesh;
use crate::render::polygons::{self, Attribute, Faces, Inputs, TexCoordInput};

/// Triangles one Extrusion may make: a few bytes of spine and crossSection multiply into
/// any number, so larger ones are reported instead of built.
const MAX_TRIANGLES: usize = 1_000_000;

/// |a × b| ≤ this × |a| |b|: a, b are parallel.
const COLLINEAR: f64 = 1e-6;

/// The Extrusion as triangles; Err: why it is not drawn.
pub fn build(doc: &Document, geometry: NodeId, needs: &Needs) -> Result<LocalMesh, String> {
    let spine: Vec<DVec3> = floats(doc, geometry, "spine")
        .chunks_exact(3)
        .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into()))
        .collect();
    let section = pairs(&floats(doc, geometry, "crossSection"));
    let scales = pairs(&floats(doc, geometry, "scale"));
    if spine.len() < 2 {
        return Err("Extrusion is not drawn: its spine has fewer than two points".to_string());
    }
    if section.len() < 2 {
        return Err(
            "Extrusion is not drawn: its crossSection has fewer than two points".to_string(),
        );
    }
    let finite = spine.iter().all(|p| p.is_finite())
        && section
            .iter()
            .chain(&scales)
            .flatten()
            .all(|c| c.is_finite());
    if !finite {
        return Err(
            "Extrusion is not drawn: its spine, crossSection or scale has a non-finite value"
                .to_string(),
        );
    }
    let caps = [
        boolean(doc, geometry, "beginCap", true),
        boolean(doc, geometry, "endCap", true),
    ];
    let closed_section = section[0] == section[section.len() - 1];
    let cap_corners = if closed_section {
        section.len() - 1
    } else {
        section.len()
    };
    let cap_corners = if cap_corners >= 3 { cap_corners } else { 0 };
    let triangles = triangle_count(spine.len(), section.len(), cap_corners, caps);
    if triangles > MAX_TRIANGLES {
        return Err(format!(
            "Extrusion is not drawn: {} spine points × {} crossSection points make more than \
             {MAX_TRIANGLES} triangles",
            spine.len(),
            section.len()
        ));
    }

    let orientations: Vec<DQuat> = floats(doc, geometry, "orientation")
        .chunks_exact(4)
        .map(|r| rotation_of([r[0], r[1], r[2], r[3]]))
        .collect();
    let frames = spine_frames(&spine);
    let (n, width) = (spine.len(), section.len());
    let mut points: Vec<f32> = Vec::with_capacity((n * width + 2 * cap_corners) * 3);
    for (i, (&origin, frame)) in spine.iter().zip(&frames).enumerate() {
        let [sx, sz] = value_at(&scales, i).unwrap_or([1.0, 1.0]);
        let orientation = value_at(&orientations, i).unwrap_or(DQuat::IDENTITY);
        let placing = *frame * DMat3::from_quat(orientation);
        for &[x, z] in &section {
            let p = origin + placing * DVec3::new(sx * x, 0.0, sz * z);
            points.extend_from_slice(&[p.x as f32, p.y as f32, p.z as f32]);
        }
    }
    let ring = |i: usize| &points[i * width * 3..(i + 1) * width * 3];
    let spine_seam = spine[0] == spine[n - 1] && ring(0) == ring(n - 1);
    let coord = |i: usize, j: usize| {
        let i = if spine_seam && i == n - 1 { 0 } else { i };
        let j = if closed_section && j == width - 1 {
            0
        } else {
            j
        };
        (i * width + j) as u32
    };

    let ccw = boolean(doc, geometry, "ccw", true);
    let quads = (n - 1) * (width - 1);
    let mut faces = Faces::with_capacity(quads + 2, quads * 4 + 2 * cap_corners);
    for i in 0..n - 1 {
        for j in 0..width - 1 {
            // From the earlier cross-section to the later one, as 13.3.5 orders them.
            let corners = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)];
            let mut coords = corners.map(|(i, j)| coord(i, j));
            let mut elements = corners.map(|(i, j)| (i * width + j) as u32);
            if !ccw {
                coords.reverse();
                elements.reverse();
            }
            faces.push(&coords, &elements);
        }
    }
    // Caps: viewed from the SCP's +Y, a counterclockwise section faces −Y at the begin
    // and +Y at the end (13.3.5).
    for (cap, ring_index, reversed) in [(0, 0, ccw), (1, n - 1, !ccw)] {
        if !caps[cap] || cap_corners == 0 {
            continue;
        }
        let first_coord = (points.len() / 3) as u32;
        let first_element = (n * width + cap * cap_corners) as u32;
        let start = ring_index * width * 3;
        points.extend_from_within(start..start + cap_corners * 3);
        let mut coords: Vec<u32> = (first_coord..first_coord + cap_corners as u32).collect();
        let mut elements: Vec<u32> = (first_element..first_element + cap_corners as u32).collect();
        if reversed {
            coords.reverse();
            elements.reverse();
        }
        faces.push(&coords, &elements);
    }

    let textured = needs
        .tex_coords
        .iter()
        .any(|s| *s != TexCoordSource::Generated);
    let tex_values = if textured {
        default_tex_coords(&spine, &section, cap_corners)
    } else {
        Vec::new()
    };
    let tex_attribute = Attribute {
        values: &tex_values,
        arity: 2,
        kind: Kind::TexCoord,
        by_coord: false,
    };
    let tex_coords = needs
        .tex_coords
        .iter()
        .map(|source| match source {
            TexCoordSource::Generated => TexCoordInput::Generated,
            // Extrusion has no texCoord field: every other set is the default mapping.
            _ => TexCoordInput::Given(tex_attribute),
        })
        .collect();
    Ok(polygons::build(Inputs {
        points: &points,
        faces,
        normals: None,
        generation: crease_generation(doc, geometry),
        need_normals: needs.normals,
        colors: None,
        tex_coords,
    }))
}

fn pairs(flat: &[f32]) -> Vec<[f64; 2]> {
    flat.chunks_exact(2)
        .map(|p| [p[0].into(), p[1].into()])
        .collect()
}

/// Value i of a per-spine-point list: one value applies to all, a short list repeats its
/// last; None for an empty list.
fn value_at<T: Copy>(values: &[T], i: usize) -> Option<T> {
    values.get(i).or(values.last()).copied()
}

/// Triangles of the sides and caps, saturating.
fn triangle_count(spine: usize, section: usize, cap_corners: usize, caps: [bool; 2]) -> usize {
    let sides = (spine - 1).saturating_mul(section - 1).saturating_mul(2);
    let per_cap = cap_corners.saturating_sub(2);
    caps.iter()
        .filter(|&&cap| cap)
        .fold(sides, |sum, _| sum.saturating_add(per_cap))
}

/// The SCP of every spine point (13.3.5, with its special cases) as the matrix whose
/// columns are its X, Y and Z axes.
fn spine_frames(spine: &[DVec3]) -> Vec<DMat3> {
    let mut distinct: Vec<DVec3> = Vec::with_capacity(spine.len());
    let mut run_of = Vec::with_capacity(spine.len());
    for &p in spine {
        if distinct.last() != Some(&p) {
            distinct.push(p);
        }
        run_of.push(distinct.len() - 1);
    }
    let frames = distinct_frames(&distinct);
    run_of.iter().map(|&k| frames[k]).collect()
}

/// The SCPs of a spine without coincident consecutive points.
fn distinct_frames(p: &[DVec3]) -> Vec<DMat3> {
    let m = p.len();
    if m < 2 {
        return vec![DMat3::IDENTITY; m];
    }
    let closed = p[0] == p[m - 1];
    // Neighbours: a closed spine's ends see spine[n−2] before and spine[1] after them
    // (the clause's closed-spine rules); an open spine's ends lack one.
    let previous = |i: usize| match i {
        0 if closed => Some(p[m - 2]),
        0 => None,
        _ => Some(p[i - 1]),
    };
    let next = |i: usize| match i {
        _ if i + 1 < m => Some(p[i + 1]),
        _ if closed => Some(p[1]),
        _ => None,
    };
    // Z = (spine[i+1] − spine[i]) × (spine[i−1] − spine[i]); None where the three points
    // are collinear or at an open end.
    let z_axes: Vec<Option<DVec3>> = (0..m)
        .map(|i| {
            let (a, b) = (next(i)? - p[i], previous(i)? - p[i]);
            let z = a.cross(b);
            (z.length() > COLLINEAR * a.length() * b.length()).then_some(z)
        })
        .collect();
    let Some(first_defined) = z_axes.iter().flatten().next().copied() else {
        let frame = DMat3::from_quat(rotation_from_y((p[1] - p[0]).normalize()));
        return vec![frame; m];
    };
    let mut frames = Vec::with_capacity(m);
    let mut previous_z: Option<DVec3> = None;
    for i in 0..m {
        // Y = spine[i+1] − spine[i−1], or the end segment of an open spine; a vanishing Y
        // (the spine turning back) follows the next segment.
        let y = match (previous(i), next(i)) {
            (Some(before), Some(after)) if after != before => after - before,
            (_, Some(after)) => after - p[i],
            (Some(before), None) => p[i] - before,
            (None, None) => DVec3::Y,
        };
        // Collinear points take the previous Z; the first ones the first defined.
        let mut z = z_axes[i].or(previous_z).unwrap_or(first_defined);
        // A Z axis against the previous one is flipped: no half turns between neighbours.
        if previous_z.is_some_and(|before| z.dot(before) < 0.0) {
            z = -z;
        }
        previous_z = Some(z);
        frames.push(frame_of(y.normalize(), z));
    }
    if closed {
        frames[m - 1] = frames[0];
    }
    frames
}

/// The frame with Y axis `y` (unit) and the Z axis nearest `z` perpendicular to it.
fn frame_of(y: DVec3, z: DVec3) -> DMat3 {
    let across = z - y * z.dot(y);
    let z = if across.length() > COLLINEAR * z.length() {
        across.normalize()
    } else {
        rotation_from_y(y) * DVec3::Z
    };
    DMat3::from_cols(y.cross(z), y, z)
}

/// The rotation taking +Y to the unit vector `to`: about Y × `to` (the shortest arc);
/// for −Y, where that axis vanishes, a half turn about Z, as X3D browsers take it (X_ITE
/// and Coin pick the axis Y × X: X turns to −X, Z stays).
fn rotation_from_y(to: DVec3) -> DQuat {
    if to.dot(DVec3::Y) <= -1.0 + 1e-12 {
        DQuat::from_rotation_z(std::f64::consts::PI)
    } else {
        DQuat::from_rotation_arc(DVec3::Y, to)
    }
}

/// The default texture coordinates (13.3.5), flat s, t: one per side grid point
/// (spine-major), then the begin cap's and the end cap's `cap_corners` points.
fn default_tex_coords(spine: &[DVec3], section: &[[f64; 2]], cap_corners: usize) -> Vec<f32> {
    let s = accumulated(section.windows(2).map(|w| {
        let [a, b] = [w[0], w[1]];
        (b[0] - a[0]).hypot(b[1] - a[1])
    }));
    let t = accumulated(spine.windows(2).map(|w| w[0].distance(w[1])));
    let mut out = Vec::with_capacity((spine.len() * section.len() + 2 * cap_corners) * 2);
    for &t in &t {
        for &s in &s {
            out.extend_from_slice(&[s, t]);
        }
    }
    let (lo, size) = bounding_rectangle(section).unwrap_or(([0.0; 2], [0.0; 2]));
    let larger = size[0].max(size[1]);
    let scale = if larger > 0.0 && larger.is_finite() {
        1.0 / larger
    } else {
        0.0
    };
    for _ in 0..2 {
        for p in &section[..cap_corners] {
            out.extend_from_slice(&[0, 1].map(|k| ((p[k] - lo[k]) * scale) as f32));
        }
    }
    out
}

/// 0, then each running sum of `lengths` over their total (0 to 1); by position when the
/// total is zero or not finite.
fn accumulated(lengths: impl ExactSizeIterator<Item = f64>) -> Vec<f32> {
    let count = lengths.len() + 1;
    let mut sums = Vec::with_capacity(count);
    sums.push(0.0f64);
    for length in lengths {
        sums.push(sums[sums.len() - 1] + length);
    }
    let total = sums[count - 1];
    if total > 0.0 && total.is_finite() {
        sums.iter().map(|s| (s / total) as f32).collect()
    } else {
        let last = (count - 1).max(1) as f32;
        (0..count).map(|k| k as f32 / last).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        a.distance(b) < 1e-9
    }

    fn spine(points: &[[f64; 3]]) -> Vec<DVec3> {
        points.iter().map(|&p| DVec3::from_array(p)).collect()
    }

    /// The Extrusion of `fields` built with `needs`; Err: the NotDrawn reason.
    fn extrude(fields: &str, needs: &Needs) -> Result<LocalMesh, String> {
        let source = format!("<X3D><Scene><Shape><Extrusion {fields}/></Shape></Scene></X3D>");
        let doc = crate::parse::read(source.as_bytes()).document.unwrap();
        let node = doc.nodes_of_type("Extrusion").next().unwrap();
        build(&doc, node, needs)
    }

    fn lit_and_textured() -> Needs {
        Needs {
            normals: true,
            tex_coords: vec![TexCoordSource::Default],
        }
    }

    #[test]
    fn a_straight_spine_rotates_the_y0_plane_onto_it() {
        // Along +Y: the identity, as in the default Extrusion.
        let up = spine_frames(&spine(&[[0.0; 3], [0.0, 1.0, 0.0], [0.0, 3.0, 0.0]]));
        assert!(up.iter().all(|f| f.abs_diff_eq(DMat3::IDENTITY, 1e-12)));
        // Along +X: +Y turns to +X about −Z; Z stays, X becomes −Y.
        let across = spine_frames(&spine(&[[0.0; 3], [2.0, 0.0, 0.0]]));
        assert!(close(across[1].y_axis, DVec3::X));
        assert!(close(across[1].z_axis, DVec3::Z));
        assert!(close(across[1].x_axis, -DVec3::Y));
        // Along −Y (no unique rotation): a half turn about Z, as browsers turn it.
        let down = spine_frames(&spine(&[[0.0; 3], [0.0, -1.0, 0.0]]));
        assert!(close(down[0].x_axis, -DVec3::X));
        assert!(close(down[0].y_axis, -DVec3::Y));
        assert!(close(down[0].z_axis, DVec3::Z));
        // Float noise in a straight spine does not pick Z axes.
        let noisy = spine_frames(&spine(&[[0.0; 3], [0.0, 1.0, 1e-9], [0.0, 2.0, 0.0]]));
        assert!(noisy.iter().all(|f| close(f.z_axis, DVec3::Z)));
    }

    #[test]
    fn a_bent_spine_follows_the_angle_rule() {
        // An L in the XY plane: Z = (spine[2] − spine[1]) × (spine[0] − spine[1]).
        let frames = spine_frames(&spine(&[[0.0; 3], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]));
        let z = DVec3::X.cross(-DVec3::Y).normalize();
        assert!(close(frames[1].z_axis, z));
        // Y at the corner: spine[2] − spine[0]; at the open ends, their segment.
        assert!(close(
            frames[1].y_axis,
            DVec3::new(1.0, 1.0, 0.0).normalize()
        ));
        assert!(close(frames[0].y_axis, DVec3::Y));
        assert!(close(frames[2].y_axis, DVec3::X));
        // The ends take the Z of their neighbour; X = Y × Z.
        assert!(frames.iter().all(|f| close(f.z_axis, z)));
        assert!(frames
            .iter()
            .all(|f| close(f.x_axis, f.y_axis.cross(f.z_axis))));
    }

    #[test]
    fn collinear_points_take_the_previous_z_and_leading_ones_the_first_defined() {
        // Straight for two segments, then a bend, straight again: Z is defined only at
        // spine[2].
        let frames = spine_frames(&spine(&[
            [0.0; 3],
            [0.0, 1.0, 0.0],
            [0.0, 2.0, 0.0],
            [0.0, 2.0, 1.0],
            [0.0, 2.0, 2.0],
        ]));
        let z = DVec3::Z.cross(-DVec3::Y).normalize();
        assert!(frames.iter().all(|f| close(f.z_axis, z)), "{frames:?}");
        // Y stays the spine's own direction where it is straight.
        assert!(close(frames[1].y_axis, DVec3::Y));
        assert!(close(frames[4].y_axis, DVec3::Z));
    }

    #[test]
    fn z_flips_to_keep_the_orientation_of_a_zigzag() {
        // Alternate bends give Z axes of alternate signs by the cross product alone.
        let points = spine(&[
            [0.0; 3],
            [1.0, 1.0, 0.0],
            [2.0, 0.0, 0.0],
            [3.0, 1.0, 0.0],
            [4.0, 0.0, 0.0],
        ]);
        let raw = |i: usize| (points[i + 1] - points[i]).cross(points[i - 1] - points[i]);
        assert!(raw(1).dot(raw(2)) < 0.0);
        let frames = spine_frames(&points);
        assert!(frames
            .windows(2)
            .all(|w| w[0].z_axis.dot(w[1].z_axis) > 0.0));
    }

    #[test]
    fn a_closed_spine_has_one_scp_at_its_ends() {
        let square = spine(&[
            [1.0, 0.0, 1.0],
            [1.0, 0.0, -1.0],
            [-1.0, 0.0, -1.0],
            [-1.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
        ]);
        let frames = spine_frames(&square);
        assert!(frames[0].abs_diff_eq(frames[4], 0.0));
        // Y from spine[1] − spine[n−2], Z from (spine[1] − spine[0]) × (spine[n−2] − spine[0]).
        let y = (square[1] - square[3]).normalize();
        let z = (square[1] - square[0])
            .cross(square[3] - square[0])
            .normalize();
        assert!(close(frames[0].y_axis, y));
        assert!(close(frames[0].z_axis, z));
    }

    #[test]
    fn coincident_points_share_their_scp() {
        // The first two points coincide: the first Y looks ahead to spine[2].
        let frames = spine_frames(&spine(&[
            [0.0; 3],
            [0.0; 3],
            [0.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
        ]));
        assert_eq!(frames[0], frames[1]);
        assert_eq!(frames[2], frames[3]);
        assert!(close(frames[0].y_axis, DVec3::Y));
        assert!(frames.iter().all(|f| f.is_finite()));
        // All points coincident: the identity (a surface revolved by orientation).
        let revolved = spine_frames(&spine(&[[1.0, 2.0, 3.0]; 3]));
        assert!(revolved.iter().all(|f| *f == DMat3::IDENTITY));
        // A spine turning back on itself is collinear and has no zero axis.
        let back = spine_frames(&spine(&[[0.0; 3], [0.0, 1.0, 0.0], [0.0; 3]]));
        assert!(back
            .iter()
            .all(|f| f.is_finite() && close(f.y_axis, DVec3::Y)));
    }

    #[test]
    fn scale_and_orientation_place_each_cross_section() {
        // One orientation (a quarter turn about the SCP's Y) applies to both points;
        // scales apply per point.
        let mesh = extrude(
            "crossSection='1 0 0 1' spine='0 0 0 0 2 0' scale='1 1 2 3' \
             orientation='0 1 0 1.5707963' beginCap='false' endCap='false'",
            &Needs::default(),
        )
        .unwrap();
        let has = |p: [f32; 3]| {
            mesh.positions
                .iter()
                .any(|q| (0..3).all(|k| (q[k] - p[k]).abs() < 1e-5))
        };
        // (x, z) = (1, 0) turns to (0, −1); (0, 1) to (1, 0); then scaled at spine[1].
        assert!(has([0.0, 0.0, -1.0]) && has([1.0, 0.0, 0.0]));
        assert!(has([0.0, 2.0, -2.0]) && has([3.0, 2.0, 0.0]));
    }

    #[test]
    fn a_concave_cross_section_is_capped_inside_its_outline() {
        // A 4 × 3 rectangle with a V notch (area 8), counterclockwise seen from +Y,
        // closed, starting at a corner from which a fan would fold over the notch.
        let mesh = extrude(
            "crossSection='4 -3 2 -1 0 -3 0 0 4 0 4 -3' spine='0 0 0 0 1 0'",
            &Needs {
                normals: true,
                tex_coords: Vec::new(),
            },
        )
        .unwrap();
        let normals = mesh.normals.as_ref().unwrap();
        let mut areas = [0.0f32; 2];
        let mut triangles = [0; 2];
        for t in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| mesh.positions[i as usize]);
            let n = normals[t[0] as usize];
            if n[1].abs() < 0.99 {
                continue; // a side
            }
            // Area seen from +Y (X right, −Z up), positive when counterclockwise there.
            let area = ((b[0] - a[0]) * (a[2] - c[2]) - (a[2] - b[2]) * (c[0] - a[0])) / 2.0;
            // The begin cap (y = 0) faces −Y, so it winds clockwise seen from +Y.
            let cap = usize::from(a[1] > 0.5);
            assert_eq!(n[1], [-1.0, 1.0][cap]);
            assert!(area * n[1] > 0.0, "a folded triangle");
            areas[cap] += area * n[1];
            triangles[cap] += 1;
        }
        // Each cap: 5 corners, 3 triangles inside the outline.
        assert_eq!(triangles, [3, 3]);
        assert!(areas.iter().all(|a| (a - 8.0).abs() < 1e-5), "{areas:?}");
    }

    #[test]
    fn closed_seams_share_smooth_normals_with_texture_coordinates_0_and_1() {
        // A torus: a closed 12-gon section along a closed 12-gon spine, smooth.
        let ring = |r: f64, y: bool| {
            (0..=12)
                .map(|k| {
                    let a = std::f64::consts::TAU * f64::from(k % 12) / 12.0;
                    let (x, z) = (r * a.cos(), -r * a.sin());
                    if y {
                        format!("{x} 0 {z}")
                    } else {
                        format!("{x} {z}")
                    }
                })
                .collect::<Vec<_>>()
                .join(" ")
        };
        let fields = format!(
            "crossSection='{}' spine='{}' creaseAngle='3.2' beginCap='false' endCap='false'",
            ring(0.3, false),
            ring(2.0, true)
        );
        let mesh = extrude(&fields, &lit_and_textured()).unwrap();
        let normals = mesh.normals.as_ref().unwrap();
        let tex = &mesh.tex_coords[0];
        // Every position: all its vertices (0 and 1 either side of a seam) share the
        // normal, which points away from the spine circle.
        let mut seams = 0;
        for (v, p) in mesh.positions.iter().enumerate() {
            for (w, q) in mesh.positions.iter().enumerate().skip(v + 1) {
                if (0..3).all(|k| (p[k] - q[k]).abs() < 1e-6) {
                    assert!((0..3).all(|k| (normals[v][k] - normals[w][k]).abs() < 1e-5));
                    if tex[v] != tex[w] {
                        seams += 1;
                    }
                }
            }
        }
        assert!(seams > 0);
        assert!(tex.iter().any(|t| t[0] == 1.0) && tex.iter().any(|t| t[1] == 1.0));
        for (p, n) in mesh.positions.iter().zip(normals) {
            let centre = DVec3::new(f64::from(p[0]), 0.0, f64::from(p[2])).normalize() * 2.0;
            let out = (DVec3::from_array(p.map(f64::from)) - centre).normalize();
            assert!(out.dot(DVec3::from_array(n.map(f64::from))) > 0.99);
        }
    }

    #[test]
    fn default_texture_coordinates_follow_accumulated_lengths() {
        // Section lengths 1 and 3: s = 0, 0.25, 1; spine lengths 1 and 3: t likewise.
        let mesh = extrude(
            "crossSection='0 0 1 0 1 3' spine='0 0 0 0 1 0 0 4 0'",
            &lit_and_textured(),
        )
        .unwrap();
        let tex = &mesh.tex_coords[0];
        let normals = mesh.normals.as_ref().unwrap();
        let st_at = |p: [f32; 3], side: bool| -> Vec<[f32; 2]> {
            (0..mesh.positions.len())
                .filter(|&v| mesh.positions[v] == p && (normals[v][1].abs() < 0.9) == side)
                .map(|v| tex[v])
                .collect()
        };
        assert!(st_at([1.0, 0.0, 0.0], true).contains(&[0.25, 0.0]));
        assert!(st_at([1.0, 1.0, 3.0], true).contains(&[1.0, 0.25]));
        assert!(st_at([0.0, 4.0, 0.0], true).contains(&[0.0, 1.0]));
        // Caps: the section's box (3 deep, 1 wide) scaled by its larger side.
        assert_eq!(st_at([1.0, 4.0, 3.0], false), vec![[1.0 / 3.0, 1.0]]);
        assert_eq!(st_at([0.0, 0.0, 0.0], false), vec![[0.0, 0.0]]);
    }

    #[test]
    fn ccw_false_turns_every_face() {
        let outward = |ccw: &str| {
            let mesh = extrude(&format!("ccw='{ccw}'"), &lit_and_textured()).unwrap();
            let normals = mesh.normals.unwrap();
            // The default unit box around the +Y spine: outward normals point away from
            // its centre (0, 0.5, 0).
            mesh.positions
                .iter()
                .zip(&normals)
                .map(|(p, n)| n[0] * p[0] + n[1] * (p[1] - 0.5) + n[2] * p[2])
                .all(|d| d > 0.0)
        };
        assert!(outward("true"));
        let inward = extrude("ccw='false'", &lit_and_textured()).unwrap();
        let normals = inward.normals.unwrap();
        assert!(inward
            .positions
            .iter()
            .zip(&normals)
            .all(|(p, n)| n[0] * p[0] + n[1] * (p[1] - 0.5) + n[2] * p[2] < 0.0));
    }

    #[test]
    fn degenerate_and_hostile_input_is_reported_not_built() {
        let reason = |fields: &str| extrude(fields, &lit_and_textured()).unwrap_err();
        assert!(reason("spine=''").contains("fewer than two points"));
        assert!(reason("spine='1 2 3'").contains("fewer than two points"));
        assert!(reason("crossSection='1 1'").contains("crossSection has fewer"));
        assert!(reason("spine='0 0 0 NaN 1 0'").contains("non-finite"));
        assert!(reason("crossSection='0 0 INF 1 1 1'").contains("non-finite"));
        assert!(reason("scale='1 NaN'").contains("non-finite"));
        // Ten thousand points each way: a hundred million quadrilaterals, refused before
        // anything is allocated for them.
        let many = |k: usize, arity: usize| {
            (0..k)
                .map(|i| {
                    (0..arity)
                        .map(|_| i.to_string())
                        .collect::<Vec<_>>()
                        .join(" ")
                })
                .collect::<Vec<_>>()
                .join(" ")
        };
        let huge = format!(
            "spine='{}' crossSection='{}'",
            many(10_000, 3),
            many(10_000, 2)
        );
        assert!(reason(&huge).contains("more than 1000000 triangles"));
        assert_eq!(
            triangle_count(usize::MAX, usize::MAX, usize::MAX, [true; 2]),
            usize::MAX
        );
        // Degenerate but finite: drawn, with finite normals (zero where undefined).
        for fields in [
            "spine='0 0 0 0 0 0'",
            "scale='0 0'",
            "crossSection='0 0 0 0 0 0'",
            "spine='0 0 0 0 1 0 0 0 0' orientation='1 0 0 0 0 0 0 0'",
        ] {
            let mesh = extrude(fields, &lit_and_textured()).unwrap();
            let normals = mesh.normals.unwrap();
            assert!(normals.iter().flatten().all(|c| c.is_finite()), "{fields}");
            assert!(
                mesh.positions.iter().flatten().all(|c| c.is_finite()),
                "{fields}"
            );
        }
    }
}
