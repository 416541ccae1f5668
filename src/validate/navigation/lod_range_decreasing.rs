//! LOD_RANGE_DECREASING: an LOD range smaller than the range before it.

use crate::report::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::first_decrease;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first `range` value of an LOD that is smaller than the value before
    /// it. A `range` that takes its value through `IS` (or a ROUTE) is left alone, as
    /// are NaN and infinities (FIELD_VALUE_NONFINITE's); that each range is greater
    /// than zero is FIELD_OUT_OF_RANGE's. Equal neighbours are not reported: the clause
    /// says "monotonic increasing" without saying whether equal values are allowed, and
    /// they only make a level that is never shown.
    ///
    /// ## Why it matters
    /// The ranges split the distance from the viewer into intervals, one level of
    /// detail each, in order from near to far. A range out of order makes the intervals
    /// overlap: which level shows at a distance then depends on how the browser
    /// searches the list, and some levels may never show.
    ///
    /// ## Example
    /// ```xml
    /// <LOD range='10 50 30'>
    ///   <Shape/> <Shape/> <Shape/> <WorldInfo/>
    /// </LOD>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <LOD range='10 30 50'>
    ///   <Shape/> <Shape/> <Shape/> <WorldInfo/>
    /// </LOD>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 23.4.3 LOD (X3D 3.x; the same text in 4.0): "The range field contains
    /// monotonic increasing values that shall be greater than zero." ISO/IEC 14772-1
    /// 6.26 LOD for VRML97, in the same words.
    pub static LOD_RANGE_DECREASING = {
        severity: Error,
        level: Standard,
        clause: "23.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("LOD") {
        if set_elsewhere(doc, &routed, id, "range") {
            continue;
        }
        let Some(entry) = doc.node(id).entry("range") else {
            continue;
        };
        if let Some(at) = entry.value.as_floats().and_then(first_decrease) {
            found.push((id, entry, at));
        }
    }
    for (id, entry, at) in found {
        let (span, text) = ctx.scalar_text(entry, at);
        let (_, before) = ctx.scalar_text(entry, at - 1);
        ctx.report(
            Diagnostic::new(
                &LOD_RANGE_DECREASING,
                span,
                format!(
                    "LOD.range[{at}] = {text} is smaller than range[{}] = {before}: the ranges shall increase",
                    at - 1
                ),
            )
            .node(id)
            .help("list the ranges from near to far, with the levels in the same order"),
        );
    }
}
