//! The trimming loops of NurbsTrimmedSurface as CONTOUR2D_NOT_CLOSED and
//! TRIMMING_LOOP_CLOCKWISE read them: each Contour2D's segments (ContourPolyline2D,
//! NurbsCurve2D) with their control points and, where they are known, their end points.

use std::collections::HashSet;

use super::super::events::wiring::any_set_elsewhere;
use crate::model::{Document, NodeId, Span};

/// How far apart two end points may lie and still count as the same point, relative to
/// the contour's extent (the larger side of its control points' bounding box). Exporters
/// write each shared end point twice, rounded the same way or to 5 digits: 1e-4 leaves
/// their rounding alone and catches a gap a tessellation would show.
pub(crate) const CLOSURE_TOLERANCE: f64 = 1e-4;

/// One segment of a contour.
pub(crate) struct Segment {
    /// Where the segment stands in the contour's `children`.
    pub span: Span,
    /// Its control points in (u, v).
    pub points: Vec<[f64; 2]>,
    /// Its first and last points: a polyline's first and last control points, a NURBS
    /// curve's when its knot vector is clamped (the default one is). None for an
    /// unclamped curve, whose ends only an evaluation finds (not made here).
    pub ends: Option<([f64; 2], [f64; 2])>,
}

/// A Contour2D's segments in order; None when any is not known: the contour's children
/// or a segment's fields are set by a ROUTE or `IS`, a child is not a ContourPolyline2D or
/// NurbsCurve2D (a prototype instance), or its values did not parse. An empty contour
/// gives an empty list.
pub(crate) fn segments(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    contour: NodeId,
) -> Option<Vec<Segment>> {
    let children = ["children", "addChildren", "removeChildren"];
    if any_set_elsewhere(doc, routed, contour, &children) {
        return None;
    }
    doc.node(contour)
        .children("children")
        .iter()
        .map(|child| {
            let id = child.node;
            if any_set_elsewhere(doc, routed, id, &["controlPoint", "knot", "order"]) {
                return None;
            }
            let points = points_2d(doc, id)?;
            let ends = match doc.node(id).type_name() {
                "ContourPolyline2D" => Some(()),
                "NurbsCurve2D" => is_clamped(doc, id, points.len())?.then_some(()),
                _ => return None,
            }
            .and_then(|()| Some((*points.first()?, *points.last()?)));
            Some(Segment {
                span: child.span,
                points,
                ends,
            })
        })
        .collect()
}

/// The `controlPoint` of a segment as (u, v) pairs, whether written as MFVec2d or (in
/// older versions) MFVec2f; None when it did not parse or has an odd number of values.
fn points_2d(doc: &Document, id: NodeId) -> Option<Vec<[f64; 2]>> {
    let value = doc.value_of(id, "controlPoint")?;
    let values: Vec<f64> = match (value.as_doubles(), value.as_floats()) {
        (Some(doubles), _) => doubles.to_vec(),
        (None, Some(floats)) => floats.iter().map(|&x| f64::from(x)).collect(),
        (None, None) => return None,
    };
    if !values.len().is_multiple_of(2) || values.iter().any(|x| !x.is_finite()) {
        return None;
    }
    Some(values.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
}

/// Whether a NurbsCurve2D of `points` control points passes through its first and last
/// control points: its knot vector is empty (the default, which browsers make clamped:
/// taken so here), or it has `order` equal knots at each end. None when the knots or order
/// are not usable (a wrong knot count or too few points are other rules' findings).
fn is_clamped(doc: &Document, id: NodeId, points: usize) -> Option<bool> {
    let order = usize::try_from(doc.i32_of(id, "order")?).ok()?;
    let value = doc.value_of(id, "knot")?;
    let knots = value.as_doubles()?;
    if order < 2 || points < order {
        return None;
    }
    if knots.is_empty() {
        return Some(true);
    }
    if knots.len() != points + order {
        return None;
    }
    let (head, tail) = (&knots[..order], &knots[knots.len() - order..]);
    Some(head.iter().all(|&k| k == head[0]) && tail.iter().all(|&k| k == tail[0]))
}

/// The larger side of the bounding box of every control point of `segments`.
pub(crate) fn extent(segments: &[Segment]) -> f64 {
    let mut low = [f64::INFINITY; 2];
    let mut high = [f64::NEG_INFINITY; 2];
    for p in segments.iter().flat_map(|s| &s.points) {
        for axis in 0..2 {
            low[axis] = low[axis].min(p[axis]);
            high[axis] = high[axis].max(p[axis]);
        }
    }
    (high[0] - low[0]).max(high[1] - low[1]).max(0.0)
}

/// Whether two end points are the same point within [`CLOSURE_TOLERANCE`] of `extent`.
pub(crate) fn meet(a: [f64; 2], b: [f64; 2], extent: f64) -> bool {
    (a[0] - b[0]).abs().max((a[1] - b[1]).abs()) <= CLOSURE_TOLERANCE * extent
}

/// The first place where the loop breaks: `Some(k)` when segment `k`'s last point is not
/// the next segment's first (the last segment's next is the first). None when the loop
/// closes, and when an end is not known.
pub(crate) fn first_gap(segments: &[Segment]) -> Option<usize> {
    let extent = extent(segments);
    let ends: Vec<_> = segments.iter().map(|s| s.ends).collect::<Option<_>>()?;
    (0..ends.len()).find(|&k| !meet(ends[k].1, ends[(k + 1) % ends.len()].0, extent))
}

/// Twice the signed area of the polygon through every control point of `segments` in
/// order (positive counterclockwise in (u, v)). For a simple loop the control polygon
/// winds as the curve does: a NURBS curve stays within its control points' convex hull
/// piece by piece, so it cannot go round the other way without its control polygon doing
/// so too.
pub(crate) fn signed_area(segments: &[Segment]) -> f64 {
    let points: Vec<[f64; 2]> = segments.iter().flat_map(|s| s.points.clone()).collect();
    let Some(&origin) = points.first() else {
        return 0.0;
    };
    let n = points.len();
    (0..n)
        .map(|k| {
            let (a, b) = (points[k], points[(k + 1) % n]);
            let (a, b) = (
                [a[0] - origin[0], a[1] - origin[1]],
                [b[0] - origin[0], b[1] - origin[1]],
            );
            a[0] * b[1] - a[1] * b[0]
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polyline(points: &[[f64; 2]]) -> Segment {
        Segment {
            span: Span::default(),
            points: points.to_vec(),
            ends: Some((points[0], *points.last().unwrap())),
        }
    }

    #[test]
    fn gaps_and_winding() {
        let ccw = [
            polyline(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]),
            polyline(&[[1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]),
        ];
        assert_eq!(first_gap(&ccw), None);
        assert!(signed_area(&ccw) > 0.0);
        let open = [
            polyline(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]),
            polyline(&[[1.0, 0.9], [0.0, 1.0], [0.0, 0.0]]),
        ];
        assert_eq!(first_gap(&open), Some(0));
        let unclosed = [polyline(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])];
        assert_eq!(first_gap(&unclosed), Some(0));
        let cw = [polyline(&[[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.0, 0.0]])];
        assert_eq!(first_gap(&cw), None);
        assert!(signed_area(&cw) < 0.0);
        // Rounding within the tolerance closes.
        let rounded = [polyline(&[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 0.000001],
        ])];
        assert_eq!(first_gap(&rounded), None);
    }
}
