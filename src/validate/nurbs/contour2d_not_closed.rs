//! CONTOUR2D_NOT_CLOSED: a Contour2D whose segments do not join end to end into a closed
//! loop (deep level).

use super::contours::{first_gap, segments};
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::routed_fields;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Contour2D whose segments (ContourPolyline2D, NurbsCurve2D children) do
    /// not join end to end: a segment's last point is not the next one's first, or the
    /// last segment's last point is not the first segment's first (for one segment, its
    /// two ends differ). A segment's ends are a polyline's first and last control points,
    /// and a NURBS curve's when its knot vector is clamped (`order` equal knots at each
    /// end, or the default empty knot vector, taken as clamped as browsers make it).
    /// Points meet when they differ by at most 1e-4 of the contour's extent (the larger
    /// side of its control points' bounding box) in u and in v. One diagnostic per
    /// contour, at the first segment that does not start where the one before ends.
    ///
    /// Not judged: an empty contour; a contour with a NurbsCurve2D whose knot vector is
    /// not clamped (its ends need an evaluation, not made), whose knot count or order is
    /// wrong (NURBS_KNOT_COUNT_MISMATCH, NURBS_CONTROL_POINTS_TOO_FEW), or a child that is
    /// a prototype instance; children or control points set by a ROUTE or `IS`.
    ///
    /// ## Why it matters
    /// A trimming contour bounds a region of the surface's (u, v) space: an open one has no
    /// inside, so which part of the surface is kept is up to the browser (some draw the
    /// whole surface, some nothing, some leak the trim along the gap).
    ///
    /// ## Example
    /// ```xml
    /// <Contour2D>
    ///   <ContourPolyline2D controlPoint='0 0 1 0 1 1'/>
    ///   <ContourPolyline2D controlPoint='1 1 0 1 0 0.5'/>
    /// </Contour2D>
    /// ```
    ///
    /// ## Use instead
    /// End the last segment at the first point (`0 0`).
    ///
    /// ## Clause
    /// 19775-1 27.4.1 Contour2D, read in H3D's and x3dom's Contour2D documentation, which
    /// quote it, and in the appinfo of the X3D NURBS prototypes:
    /// > "The children shall form a closed loop with the first point of the first child repeated as the last point of the last child and the last point of a segment repeated as the first point of the consecutive one." (19775-1 27.4.1)
    pub static CONTOUR2D_NOT_CLOSED = {
        severity: Error,
        level: Deep,
        clause: "27.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for contour in doc.nodes_of_type("Contour2D") {
        let Some(segments) = segments(doc, &routed, contour) else {
            continue;
        };
        let Some(k) = first_gap(&segments) else {
            continue;
        };
        let next = (k + 1) % segments.len();
        let (Some((_, end)), Some((start, _))) = (segments[k].ends, segments[next].ends) else {
            continue;
        };
        let message = if segments.len() == 1 {
            format!(
                "Contour2D is not a closed loop: its one segment starts at ({} {}) and ends at ({} {})",
                start[0], start[1], end[0], end[1]
            )
        } else if next == 0 {
            format!(
                "Contour2D is not a closed loop: its last segment ends at ({} {}), not at the first segment's first point ({} {})",
                end[0], end[1], start[0], start[1]
            )
        } else {
            format!(
                "Contour2D is not a closed loop: segment {k} ends at ({} {}) but segment {next} starts at ({} {})",
                end[0], end[1], start[0], start[1]
            )
        };
        found.push((contour, segments[next].span, message));
    }
    for (contour, span, message) in found {
        ctx.report(
            Diagnostic::new(&CONTOUR2D_NOT_CLOSED, span, message)
                .node(contour)
                .help("repeat each segment's last point as the next segment's first, and the first segment's first point as the last segment's last"),
        );
    }
}
