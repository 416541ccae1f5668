//! Whether a polygonal face crosses itself, for FACE_SELF_INTERSECTING: the face is
//! projected onto its plane and each pair of non-adjacent edges is tested for a proper
//! crossing in 2D.

use super::face_not_convex::is_warped;
use super::geometry::{cross, dot, sub, unit, DEGENERATE_SINE};

/// Faces with up to this many distinct corners have every pair of edges tested; larger
/// ones (cylinder caps, outlines of text or terrain) go through a sweep over the edges'
/// x-extents, which compares only edges that overlap in x.
const PAIRWISE_LIMIT: usize = 64;

/// Two edges of a face that cross: each as the positions in the face of its two corners.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct Crossing {
    pub first: (usize, usize),
    pub second: (usize, usize),
}

/// Buffers [`self_crossing`] fills for each face, kept between faces to spare their
/// allocation.
#[derive(Default)]
pub struct Scratch {
    /// The distinct corners' positions in the face.
    positions: Vec<usize>,
    /// Their points, then relative to the first and scaled.
    points: Vec<[f64; 3]>,
    /// Their projection onto a coordinate plane.
    flat: Vec<[f64; 2]>,
}

/// The first pair of edges of the face through `corners` (in order, the face's corner
/// `k` at `corners[k]`) that cross properly, in the face's own plane; None when none do,
/// or the face cannot be judged: fewer than four distinct corners (a triangle cannot
/// cross itself), zero size, no plane (all corners collinear) or not planar (corners off
/// the plane by more than FACE_NOT_PLANAR's tolerance: a warped face has no outline to
/// cross, and the planar rules report it).
pub fn self_crossing(
    corners: impl Iterator<Item = [f64; 3]>,
    scratch: &mut Scratch,
) -> Option<Crossing> {
    let Scratch {
        positions,
        points,
        flat,
    } = scratch;
    // Distinct corners with their positions in the face: a corner repeated next to
    // itself (or the first one repeated at the end) closes no edge of its own.
    positions.clear();
    points.clear();
    for (k, p) in corners.enumerate() {
        if points.last() != Some(&p) {
            positions.push(k);
            points.push(p);
        }
    }
    while points.len() > 1 && points.first() == points.last() {
        positions.pop();
        points.pop();
    }
    let n = points.len();
    if n < 4 {
        return None;
    }
    // Relative to the first corner and scaled by the face's extent, every coordinate
    // lies within [-1, 1]: no product below overflows or underflows.
    let origin = points[0];
    let extent = points
        .iter()
        .flat_map(|&p| sub(p, origin))
        .fold(0.0, |m: f64, c| m.max(c.abs()));
    if !(extent.is_finite() && extent > 0.0) {
        return None;
    }
    for p in points.iter_mut() {
        *p = sub(*p, origin).map(|c| c / extent);
    }
    let normal = plane_normal(points)?;
    if is_warped(points, normal)? {
        return None;
    }
    // Dropping the normal's largest component projects onto the coordinate plane the
    // face is least tilted against; the projection keeps which edges cross.
    let axis = (0..3)
        .max_by(|&a, &b| normal[a].abs().total_cmp(&normal[b].abs()))
        .unwrap_or(2);
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    flat.clear();
    flat.extend(points.iter().map(|p| [p[u], p[v]]));
    let (i, j) = crossing_edges(flat)?;
    let position = |k: usize| positions[k % n];
    Some(Crossing {
        first: (position(i), position(i + 1)),
        second: (position(j), position(j + 1)),
    })
}

/// The unit normal of a face whose corners are within [-1, 1]: Newell's (the sum of its
/// fan's cross products); when that cancels out, as for a bow-tie whose two loops have
/// equal areas of opposite sign, the largest cross product of the fan, which a planar
/// face's others are parallel to. None when every corner lies on one line.
fn plane_normal(corners: &[[f64; 3]]) -> Option<[f64; 3]> {
    let first = corners[0];
    let (mut sum, mut scale) = ([0.0; 3], 0.0);
    // The largest cross product of the fan, with its edges' length product.
    let (mut largest, mut largest_edges) = ([0.0; 3], 0.0);
    for pair in corners[1..].windows(2) {
        let (e1, e2) = (sub(pair[0], first), sub(pair[1], first));
        let c = cross(e1, e2);
        for (s, x) in sum.iter_mut().zip(c) {
            *s += x;
        }
        let edges = (dot(e1, e1) * dot(e2, e2)).sqrt();
        scale += edges;
        if dot(c, c) > dot(largest, largest) {
            (largest, largest_edges) = (c, edges);
        }
    }
    if dot(sum, sum).sqrt() > DEGENERATE_SINE * scale {
        return unit(sum);
    }
    // Collinear corners leave only rounding in their largest cross product.
    (dot(largest, largest).sqrt() > DEGENERATE_SINE * largest_edges)
        .then(|| unit(largest))
        .flatten()
}

/// The first pair (i, j), i < j, of non-adjacent edges that cross properly; edge `k`
/// runs from `points[k]` to the next point, the last back to the first.
fn crossing_edges(points: &[[f64; 2]]) -> Option<(usize, usize)> {
    let n = points.len();
    let edge = |k: usize| (points[k], points[(k + 1) % n]);
    let adjacent = |i: usize, j: usize| i.abs_diff(j) == 1 || i.abs_diff(j) == n - 1;
    if n <= PAIRWISE_LIMIT {
        return (0..n)
            .flat_map(|i| (i + 2..n).map(move |j| (i, j)))
            .find(|&(i, j)| !adjacent(i, j) && crosses(edge(i), edge(j)));
    }
    let low = |k: usize| points[k][0].min(points[(k + 1) % n][0]);
    let high = |k: usize| points[k][0].max(points[(k + 1) % n][0]);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| low(a).total_cmp(&low(b)));
    let mut active: Vec<usize> = Vec::new();
    let mut found: Option<(usize, usize)> = None;
    for i in order {
        active.retain(|&j| high(j) >= low(i));
        for &j in &active {
            if !adjacent(i, j) && crosses(edge(i), edge(j)) {
                let pair = (i.min(j), i.max(j));
                found = Some(found.map_or(pair, |f| f.min(pair)));
            }
        }
        active.push(i);
    }
    found
}

/// Whether segments ab and cd cross properly: each one's ends lie strictly on opposite
/// sides of the other's line. An end on or near the other line (a sine below
/// [`DEGENERATE_SINE`]) is no crossing: touching at a vertex and collinear overlap are
/// a degenerate face's faults, not a crossing.
fn crosses((a, b): ([f64; 2], [f64; 2]), (c, d): ([f64; 2], [f64; 2])) -> bool {
    // Disjoint bounding boxes: no crossing, and most pairs end here.
    if a[0].max(b[0]) < c[0].min(d[0])
        || c[0].max(d[0]) < a[0].min(b[0])
        || a[1].max(b[1]) < c[1].min(d[1])
        || c[1].max(d[1]) < a[1].min(b[1])
    {
        return false;
    }
    side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0
}

/// Which side of the line through a and b the point p lies on: 1 left, −1 right, 0 on it
/// or within [`DEGENERATE_SINE`] of it (as the sine of the angle at a).
fn side(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> i32 {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [p[0] - a[0], p[1] - a[1]]);
    let area = u[0] * v[1] - u[1] * v[0];
    let bound = DEGENERATE_SINE * (u[0].hypot(u[1]) * v[0].hypot(v[1]));
    if area > bound {
        1
    } else if area < -bound {
        -1
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn judge(corners: &[[f64; 3]]) -> Option<Crossing> {
        self_crossing(corners.iter().copied(), &mut Scratch::default())
    }

    #[test]
    fn a_bow_tie_crosses_and_a_square_does_not() {
        let bow_tie = [
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        assert_eq!(
            judge(&bow_tie),
            Some(Crossing {
                first: (0, 1),
                second: (2, 3)
            })
        );
        let square = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        assert_eq!(judge(&square), None);
        // Tilted out of every coordinate plane, and far from the origin in f32 terms.
        let tilt = |p: [f64; 3]| [p[0] + 1e6, p[1] + p[0] * 0.5, p[1] * 0.7 - p[0] * 0.3];
        assert!(judge(&bow_tie.map(tilt)).is_some());
        assert_eq!(judge(&square.map(tilt)), None);
    }

    #[test]
    fn touching_collinear_concave_and_warped_faces_do_not_cross() {
        // A concave arrow head.
        let concave = [
            [0.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [0.0, 2.0, 0.0],
            [1.0, 1.0, 0.0],
        ];
        assert_eq!(judge(&concave), None);
        // A hole joined to its outline by a bridge traversed twice: edges touch, none cross.
        let keyhole = [
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [4.0, 4.0, 0.0],
            [0.0, 4.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 3.0, 0.0],
            [3.0, 3.0, 0.0],
            [3.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
        ];
        assert_eq!(judge(&keyhole), None);
        // A vertex on a non-adjacent edge.
        let touching = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 2.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 2.0, 0.0],
        ];
        assert_eq!(judge(&touching), None);
        // All collinear; and a bow-tie warped far off its plane.
        let line = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
        ];
        assert_eq!(judge(&line), None);
        let warped = [
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 0.0, 0.5],
            [0.0, 1.0, 0.5],
        ];
        assert_eq!(judge(&warped), None);
        // Triangles and repeated corners.
        let triangle = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        assert_eq!(judge(&triangle), None);
    }

    #[test]
    fn large_faces_are_swept() {
        // A circle of 200 corners, then with two corners swapped (a crossing).
        let circle: Vec<[f64; 3]> = (0..200)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 200.0;
                [t.cos(), t.sin(), 0.0]
            })
            .collect();
        assert_eq!(judge(&circle), None);
        let mut swapped = circle.clone();
        swapped.swap(50, 51);
        let found = judge(&swapped).expect("crossing");
        assert_eq!(found.first, (49, 50));
        assert_eq!(found.second, (51, 52));
    }
}
