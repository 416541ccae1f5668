//! Tangents for normal textures (12.3.4): per vertex, the direction in which the normal
//! texture's s grows, made orthogonal to the normal, with the handedness of t in w. Each
//! triangle's tangent and bitangent (from its positions and texture coordinates) are
//! summed at its corners, weighted by the triangle's area in texture space through the
//! determinant, as the common per-vertex form of MikkTSpace does; computed in f64.

use glam::DVec3;

/// One tangent per vertex of an indexed triangle list. Vertices with no usable triangle
/// (degenerate texture coordinates) get any direction orthogonal to their normal.
pub fn tangents(
    positions: &[[f32; 3]],
    normals: &[[f32; 3]],
    tex_coords: &[[f32; 2]],
    indices: &[u32],
) -> Vec<[f32; 4]> {
    let count = positions.len();
    let mut sum_t = vec![DVec3::ZERO; count];
    let mut sum_b = vec![DVec3::ZERO; count];
    let p = |i: u32| DVec3::from_array(positions[i as usize].map(f64::from));
    let uv = |i: u32| tex_coords[i as usize].map(f64::from);
    for t in indices.chunks_exact(3) {
        let (a, b, c) = (t[0], t[1], t[2]);
        let (e1, e2) = (p(b) - p(a), p(c) - p(a));
        let (ua, ub, uc) = (uv(a), uv(b), uv(c));
        let (s1, t1) = (ub[0] - ua[0], ub[1] - ua[1]);
        let (s2, t2) = (uc[0] - ua[0], uc[1] - ua[1]);
        // Unnormalized: dividing by the determinant would only rescale, and flips sign.
        let det = s1 * t2 - s2 * t1;
        if det == 0.0 || !det.is_finite() {
            continue;
        }
        let sign = det.signum();
        let tangent = (e1 * t2 - e2 * t1) * sign;
        let bitangent = (e2 * s1 - e1 * s2) * sign;
        if !(tangent.is_finite() && bitangent.is_finite()) {
            continue;
        }
        for &i in t {
            sum_t[i as usize] += tangent;
            sum_b[i as usize] += bitangent;
        }
    }
    (0..count)
        .map(|i| {
            let n = DVec3::from_array(normals.get(i).map_or([0.0; 3], |n| n.map(f64::from)))
                .normalize_or_zero();
            let mut t = (sum_t[i] - n * n.dot(sum_t[i])).normalize_or_zero();
            if t == DVec3::ZERO {
                t = n.any_orthonormal_vector();
            }
            let handedness = if n.cross(t).dot(sum_b[i]) < 0.0 {
                -1.0
            } else {
                1.0
            };
            let t = t.as_vec3();
            if t.is_finite() {
                [t.x, t.y, t.z, handedness]
            } else {
                [0.0, 0.0, 0.0, 1.0]
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quad_in_the_xy_plane_has_tangents_along_s() {
        // s along +x, t along +y, normal +z: tangent +x, right-handed.
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let normals = [[0.0, 0.0, 1.0]; 4];
        let uv = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let t = tangents(&positions, &normals, &uv, &[0, 1, 2, 0, 2, 3]);
        assert!(t.iter().all(|t| *t == [1.0, 0.0, 0.0, 1.0]), "{t:?}");
        // Mirrored texture (t running down): left-handed.
        let flipped = [[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]];
        let t = tangents(&positions, &normals, &flipped, &[0, 1, 2, 0, 2, 3]);
        assert!(t.iter().all(|t| *t == [1.0, 0.0, 0.0, -1.0]), "{t:?}");
    }

    #[test]
    fn degenerate_and_extreme_input_stays_finite_and_orthogonal() {
        let positions = [[0.0; 3], [f32::MAX, 0.0, 0.0], [0.0, f32::MAX, 0.0]];
        let normals = [[0.0, 0.0, 1.0]; 3];
        for uv in [[[0.0, 0.0]; 3], [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]] {
            for t in tangents(&positions, &normals, &uv, &[0, 1, 2]) {
                assert!(t.iter().all(|c| c.is_finite()), "{t:?}");
                let dot = t[2]; // with the normal (0, 0, 1)
                assert!(dot.abs() < 1e-6);
                assert!(((t[0] * t[0] + t[1] * t[1]).sqrt() - 1.0).abs() < 1e-6);
            }
        }
    }
}
