//! STRIP_FAN_TOO_SHORT: an indexed strip or fan of fewer than three indices.

use super::geometry::{shape_is_known, ScalarSpans};
use crate::diagnostic::Diagnostic;
use crate::model::faces::{next_to_invalid_index, runs};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a strip of an IndexedTriangleStripSet or a fan of an IndexedTriangleFanSet
    /// with one or two indices between `-1` separators. Empty runs (two separators in a
    /// row, a leading or trailing `-1`) are not strips and are not reported.
    /// A run cut by a negative index other than `-1` is INDEX_NEGATIVE's and is not
    /// judged here.
    /// TriangleStripSet.stripCount and TriangleFanSet.fanCount values below 3 are outside
    /// the fields' `[3,∞)` range and are reported as FIELD_OUT_OF_RANGE.
    ///
    /// ## Why it matters
    /// "Each strip shall have at least three non-coincident vertices" (11.4.8; fans
    /// likewise, 11.4.6): a shorter one draws nothing and usually means a lost index or a
    /// misplaced separator.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedTriangleStripSet index='0 1 2 3 -1 4 5 -1'>
    ///   <Coordinate point='0 0 0 1 0 0 0 1 0 1 1 0 2 0 0 2 1 0'/>
    /// </IndexedTriangleStripSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.6 IndexedTriangleFanSet, 11.4.8 IndexedTriangleStripSet.
    /// > "Each fan shall have at least three non-coincident vertices" (19775-1 11.4.6)
    /// > "Each strip shall have at least three non-coincident vertices" (19775-1 11.4.8)
    pub static STRIP_FAN_TOO_SHORT = {
        severity: Error,
        level: Standard,
        clause: "11.4.8",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        let what = match def.name {
            "IndexedTriangleStripSet" => "strip",
            "IndexedTriangleFanSet" => "fan",
            _ => continue,
        };
        if !shape_is_known(node) {
            continue;
        }
        let Some(entry) = node.entry("index") else {
            continue;
        };
        let Some(indices) = entry.value.as_int32s() else {
            continue;
        };
        let mut spans = ScalarSpans::new(ctx.source, entry);
        for (number, run) in runs(indices).enumerate() {
            if run.len() >= 3 || next_to_invalid_index(indices, &run) {
                continue;
            }
            ctx.report_repeated(&STRIP_FAN_TOO_SHORT, id, "index", run.start, || {
                let listed: Vec<String> = indices[run.clone()].iter().map(i32::to_string).collect();
                let message = format!(
                    "{}.index[{}] starts {what} {number} with only {} {} ({}); a {what} needs at least 3",
                    def.name,
                    run.start,
                    run.len(),
                    if run.len() == 1 { "index" } else { "indices" },
                    listed.join(" "),
                );
                Diagnostic::new(&STRIP_FAN_TOO_SHORT, spans.span_of(run.start, run.end - 1), message)
                    .node(id)
                    .value(listed.join(" "))
            });
        }
    }
}
