//! NURBS_KNOT_DECREASING: a knot vector with a knot smaller than the one before it.

use super::{is_surface, CURVES};
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::first_decrease;
use crate::validate::rendering::geometry::ScalarSpans;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a written knot vector (`knot` of NurbsCurve, NurbsCurve2D,
    /// NurbsPositionInterpolator and NurbsOrientationInterpolator; `uKnot` and `vKnot` of
    /// the NURBS surfaces, NurbsSurfaceInterpolator and NurbsTextureCoordinate) in which a
    /// knot is smaller than the knot before it, once per vector, at the first such knot.
    /// Equal knots (multiplicity) are fine. Fields a ROUTE sends values to or that take
    /// their value through `IS` are left alone, and a pair with NaN or an infinity
    /// (FIELD_VALUE_NONFINITE's) is not judged.
    ///
    /// ## Why it matters
    /// A B-spline's basis functions are defined over the intervals between consecutive
    /// knots; a decreasing step makes a negative interval, for which the recursive
    /// definition divides by a negative length: browsers draw a broken curve, nothing, or
    /// fall back to a uniform knot vector, and the shape the author meant is lost. A
    /// decreasing run is usually two knots typed in the wrong order or a knot vector of
    /// another curve pasted in.
    ///
    /// ## Example
    /// ```xml
    /// <NurbsCurve order='3' knot='0 0 0 1 0.5 1 1'>
    ///   <Coordinate containerField='controlPoint' point='0 0 0 1 1 0 2 0 0 3 1 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NurbsCurve order='3' knot='0 0 0 0.5 1 1 1'>
    ///   <Coordinate containerField='controlPoint' point='0 0 0 1 1 0 2 0 0 3 1 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 27.4.4 NurbsCurve, and the same text for the other curves (27.4.5, 27.4.6,
    /// 27.4.8) and per direction for the surfaces (27.3.2): "The number of knots shall be
    /// equal to the number of control points plus the order of the curve. The order shall
    /// be non-decreasing." The order is one number, so the second sentence can only be
    /// about the knot vector just described, and it is read so: the knots shall be
    /// non-decreasing (27.2.3 takes NURBS "according to the mathematical definitions",
    /// in which a knot vector is a non-decreasing sequence). The next sentence, "Within
    /// the knot vector there may not be more than order−1 consecutive knots of equal
    /// value", is not checked: read to the letter it forbids the clamped end knots
    /// (`0 0 0 … 1 1 1` for order 3) that the clause's own examples and every exporter
    /// write.
    /// > "The order shall be non-decreasing" (19775-1 27.4.4; read as said of the knots)
    pub static NURBS_KNOT_DECREASING = {
        severity: Error,
        level: Standard,
        clause: "27.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        let fields: &[&str] = if CURVES.contains(&node.type_name()) {
            &["knot"]
        } else if is_surface(doc, id) {
            &["uKnot", "vKnot"]
        } else {
            continue;
        };
        for &field in fields {
            let Some(entry) = node.entry(field) else {
                continue;
            };
            if set_elsewhere(doc, &routed, id, field) {
                continue;
            }
            let Some(knots) = entry.value.as_doubles() else {
                continue;
            };
            if let Some(at) = first_decrease(knots) {
                let span = ScalarSpans::new(ctx.source, entry).span(at);
                let message = format!(
                    "{}.{field}[{at}] = {} is smaller than the knot before it ({}): knots are non-decreasing",
                    node.type_name(),
                    knots[at],
                    knots[at - 1]
                );
                found.push((id, span, message, at));
            }
        }
    }
    for (id, span, message, index) in found {
        ctx.report(
            Diagnostic::new(&NURBS_KNOT_DECREASING, span, message)
                .node(id)
                .index(index)
                .help("sort the knots into non-decreasing order, or leave the knot vector empty for a uniform one"),
        );
    }
}
