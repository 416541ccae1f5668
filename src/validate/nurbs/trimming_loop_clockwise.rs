//! TRIMMING_LOOP_CLOCKWISE: a NurbsTrimmedSurface whose outermost trimming loop runs
//! clockwise (deep level).

use super::contours::{extent, first_gap, segments, signed_area, Segment};
use crate::diagnostic::Diagnostic;
use crate::model::NodeId;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::Ctx;

/// Below this part of its extent squared, a loop's signed area is rounding: its winding
/// is not judged.
const AREA_TOLERANCE: f64 = 1e-9;

crate::declare_rule! {
    /// ## What it does
    /// Reports a NurbsTrimmedSurface whose outermost trimming loop runs clockwise in the
    /// surface's (u, v) space. Each Contour2D of `trimmingContour` is one loop; the
    /// outermost is the one of largest absolute area, and its direction is the sign of
    /// the area of the polygon through its segments' control points in order. For a
    /// simple loop a NURBS segment's control polygon winds as the curve does (each piece
    /// of the curve stays in the convex hull of its control points); that is assumed.
    ///
    /// Not judged: a surface with a contour that is not closed (CONTOUR2D_NOT_CLOSED) or
    /// whose segments are not known (see CONTOUR2D_NOT_CLOSED), contours set by a ROUTE or
    /// `IS`, and a loop whose area is negligible (1e-9 of its extent squared).
    ///
    /// ## Why it matters
    /// Browsers keep the region to the left of a trimming curve, as GLU's trimming does:
    /// a clockwise outer loop keeps what lies outside it, so the surface draws as its
    /// complement, or not at all.
    ///
    /// ## Example
    /// ```xml
    /// <NurbsTrimmedSurface uDimension='2' vDimension='2' uOrder='2' vOrder='2'>
    ///   <Coordinate containerField='controlPoint' point='0 0 0 1 0 0 0 1 0 1 1 0'/>
    ///   <Contour2D containerField='trimmingContour'>
    ///     <ContourPolyline2D controlPoint='0 0 0 1 1 1 1 0 0 0'/>
    ///   </Contour2D>
    /// </NurbsTrimmedSurface>
    /// ```
    ///
    /// ## Use instead
    /// List the loop's points the other way round (`0 0 1 0 1 1 0 1 0 0`).
    ///
    /// ## Clause
    /// 19775-1 27.4.14 NurbsTrimmedSurface, read in H3D's NurbsTrimmedSurface
    /// documentation, which quotes it after "The NurbsTrimmedSurface node defines a NURBS
    /// surface that is trimmed by a set of trimming loops.":
    /// > "The outermost trimming loop shall be defined in a counterclockwise direction." (19775-1 27.4.14)
    pub static TRIMMING_LOOP_CLOCKWISE = {
        severity: Error,
        level: Deep,
        clause: "27.4.14",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    let contours = [
        "trimmingContour",
        "addTrimmingContour",
        "removeTrimmingContour",
    ];
    for surface in doc.nodes_of_type("NurbsTrimmedSurface") {
        if any_set_elsewhere(doc, &routed, surface, &contours) {
            continue;
        }
        let mut loops: Vec<(NodeId, _, Vec<Segment>)> = Vec::new();
        let mut judged = true;
        for child in doc.node(surface).children("trimmingContour") {
            let closed = segments(doc, &routed, child.node)
                .filter(|s| !s.is_empty() && s.iter().all(|s| s.ends.is_some()))
                .filter(|s| first_gap(s).is_none());
            match closed {
                Some(segments) => loops.push((child.node, child.span, segments)),
                None => judged = false,
            }
        }
        if !judged {
            continue;
        }
        let outermost = loops
            .iter()
            .map(|(id, span, segments)| (*id, *span, signed_area(segments), extent(segments)))
            .max_by(|a, b| a.2.abs().total_cmp(&b.2.abs()));
        let Some((contour, span, area, extent)) = outermost else {
            continue;
        };
        if area < -AREA_TOLERANCE * extent * extent {
            let message = format!(
                "the outermost trimming loop of this NurbsTrimmedSurface (of its {} contours, the one of largest area) runs clockwise in (u, v)",
                loops.len()
            );
            found.push((contour, span, message));
        }
    }
    for (contour, span, message) in found {
        ctx.report(
            Diagnostic::new(&TRIMMING_LOOP_CLOCKWISE, span, message)
                .node(contour)
                .help("reverse the loop: list its segments in the opposite order, each segment's points reversed"),
        );
    }
}
