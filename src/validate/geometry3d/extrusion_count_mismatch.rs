//! EXTRUSION_COUNT_MISMATCH: an Extrusion with more than one but fewer scale or
//! orientation values than spine points.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an Extrusion whose `scale` or `orientation` holds more than one value but
    /// fewer values than `spine` holds points (a value is one SFVec2f of `scale`, one
    /// SFRotation of `orientation`; the defaults of fields not written count: two spine
    /// points, one scale, one orientation). One value, or one per spine point (extra
    /// values are ignored), is what the clause defines. Fields a ROUTE sends values to
    /// or that take their value through `IS` are left alone, as are values that did not
    /// parse into whole tuples (FIELD_VALUE_SYNTAX reports those).
    ///
    /// ## Why it matters
    /// Each spine point takes the scale and orientation of the same index. With a list
    /// that stops short, the last cross-sections have none: browsers reuse the last
    /// value, fall back to the default, or read past the list, and the shape differs
    /// from one browser to the next.
    ///
    /// ## Example
    /// ```xml
    /// <Extrusion spine='0 0 0 0 1 0 0 2 0' scale='1 1 0.5 0.5'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Extrusion spine='0 0 0 0 1 0 0 2 0' scale='1 1 0.5 0.5 0.25 0.25'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 13.3.5 Extrusion (ISO/IEC 14772-1 6.18 for VRML97, in the same words): "If
    /// the number of scale or orientation values is greater than the number of spine
    /// points, the excess values are ignored. If they contain one value, it is applied at
    /// all spine points. The results are undefined if the number of scale or orientation
    /// values is greater than one but less than the number of spine points." Undefined
    /// results, not a "shall": a warning. An empty list is not covered by these sentences
    /// and is not reported.
    pub static EXTRUSION_COUNT_MISMATCH = {
        severity: Warning,
        level: Standard,
        clause: "13.3.5",
        versions: "all",
        check: Some(check),
    }
}

/// The per-spine-point fields, with the numbers in one of their values.
const PER_POINT: [(&str, usize); 2] = [("scale", 2), ("orientation", 4)];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Extrusion") {
        if set_elsewhere(doc, &routed, id, "spine") {
            continue;
        }
        let Some(spine) = doc.value_of(id, "spine").map(|v| v.len()) else {
            continue;
        };
        if spine % 3 != 0 {
            continue;
        }
        let points = spine / 3;
        let node = doc.node(id);
        for (field, arity) in PER_POINT {
            if set_elsewhere(doc, &routed, id, field) {
                continue;
            }
            let Some(numbers) = doc.value_of(id, field).map(|v| v.len()) else {
                continue;
            };
            let values = numbers / arity;
            if numbers % arity != 0 || values <= 1 || values >= points {
                continue;
            }
            let Some(span) = node.entry(field).or(node.entry("spine")).map(|e| e.span) else {
                continue;
            };
            found.push((
                id,
                span,
                format!(
                    "Extrusion.{field} has {values} values for {points} spine points: give one, or one per spine point"
                ),
            ));
        }
    }
    for (id, span, message) in found {
        ctx.report(
            Diagnostic::new(&EXTRUSION_COUNT_MISMATCH, span, message)
                .node(id)
                .help("with more than one value, each spine point needs its own; the results are undefined otherwise"),
        );
    }
}
