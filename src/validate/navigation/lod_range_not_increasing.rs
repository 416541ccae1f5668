//! LOD_RANGE_NOT_INCREASING: an LOD range not greater than the range before it.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, written_entries};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first `range` value of an LOD that is not greater than the value
    /// before it (smaller, or equal). A `range` that takes its value through `IS` (or a
    /// ROUTE) is left alone, as are NaN and infinities (FIELD_VALUE_NONFINITE's); that
    /// each range is greater than zero is FIELD_OUT_OF_RANGE's.
    ///
    /// ## Why it matters
    /// The ranges split the distance from the viewer into intervals, one level of
    /// detail each, in order from near to far. A range out of order makes the intervals
    /// overlap, an equal one leaves an interval empty: which level shows at a distance
    /// then depends on how the browser searches the list, and some levels never show.
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
    /// 19775-1 23.4.3 LOD: "The range field contains monotonic increasing values that
    /// shall be greater than zero." and "Each value in the range field shall be greater
    /// than the previous value." ISO/IEC 14772-1 6.26 LOD for VRML97, in the same words
    /// (there followed by "otherwise results are undefined").
    /// > "Each value in the range field shall be greater than the previous value" (19775-1 23.4.3)
    pub static LOD_RANGE_NOT_INCREASING = {
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
    for (id, entry) in written_entries(doc, &routed, "LOD", "range") {
        let Some(ranges) = entry.value.as_floats() else {
            continue;
        };
        // Pairs with a NaN or an infinity have no order to judge.
        let first_not_greater = ranges
            .windows(2)
            .position(|pair| pair[0].is_finite() && pair[1].is_finite() && pair[1] <= pair[0]);
        if let Some(at) = first_not_greater {
            found.push((id, entry, at + 1));
        }
    }
    for (id, entry, at) in found {
        let (span, text) = ctx.scalar_text(entry, at);
        let (_, before) = ctx.scalar_text(entry, at - 1);
        ctx.report(
            Diagnostic::new(
                &LOD_RANGE_NOT_INCREASING,
                span,
                format!(
                    "LOD.range[{at}] = {text} is not greater than range[{}] = {before}: each range shall be greater than the one before it",
                    at - 1
                ),
            )
            .node(id)
            .help("list the ranges from near to far, each greater than the last, with the levels in the same order"),
        );
    }
}
