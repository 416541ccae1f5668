//! POLYLINE_TOO_SHORT: an IndexedLineSet polyline of a single vertex.

use super::geometry::{shape_is_known, ScalarSpans};
use crate::diagnostic::Diagnostic;
use crate::model::faces::{next_to_invalid_index, runs};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an IndexedLineSet polyline with one vertex: a single index between `-1`
    /// separators. Empty runs (two separators in a row, a leading or trailing `-1`) are
    /// not polylines and are not reported; a run cut by a negative index other than `-1`
    /// is INDEX_NEGATIVE's and is not judged here. LineSet.vertexCount values below 2 are
    /// outside the field's `[2,∞)` range and are reported as FIELD_OUT_OF_RANGE.
    ///
    /// ## Why it matters
    /// A polyline connects vertices; one vertex draws nothing. It usually means a lost
    /// index or a misplaced separator.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedLineSet coordIndex='0 1 2 -1 3 -1'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0 0 1 0'/>
    /// </IndexedLineSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.4 IndexedLineSet.
    pub static POLYLINE_TOO_SHORT = {
        severity: Warning,
        level: Standard,
        clause: "11.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for id in doc.nodes_of_type("IndexedLineSet") {
        let node = doc.node(id);
        if !shape_is_known(node) {
            continue;
        }
        let Some(entry) = node.entry("coordIndex") else {
            continue;
        };
        let Some(indices) = entry.value.as_int32s() else {
            continue;
        };
        let mut spans = ScalarSpans::new(ctx.source, entry);
        for (number, run) in runs(indices).enumerate() {
            if run.len() >= 2 || next_to_invalid_index(indices, &run) {
                continue;
            }
            ctx.report_repeated(&POLYLINE_TOO_SHORT, id, "coordIndex", run.start, || {
                let index = indices[run.start];
                let message = format!(
                    "IndexedLineSet.coordIndex[{}] = {index} is polyline {number} on its own; a polyline needs at least 2 vertices",
                    run.start
                );
                Diagnostic::new(&POLYLINE_TOO_SHORT, spans.span(run.start), message)
                    .node(id)
                    .value(index.to_string())
            });
        }
    }
}
