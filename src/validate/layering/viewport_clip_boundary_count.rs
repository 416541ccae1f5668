//! VIEWPORT_CLIP_BOUNDARY_COUNT: a Viewport.clipBoundary without exactly four values.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, written_entries};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

/// Left, right, bottom, top.
const SIDES: usize = 4;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Viewport whose `clipBoundary` holds other than four numbers. A
    /// `clipBoundary` that takes its value through `IS` (or a ROUTE) is left alone; that
    /// each number is within `[0,1]` is FIELD_OUT_OF_RANGE's.
    ///
    /// ## Why it matters
    /// The four numbers are the left, right, bottom and top edges of the clip rectangle,
    /// as fractions of the render surface. With fewer, a side is missing and browsers
    /// make up their own (0, 1, or nothing drawn); with more, the extra numbers are
    /// dropped, and they are often a second rectangle meant for another Viewport.
    ///
    /// ## Example
    /// ```xml
    /// <Viewport clipBoundary='0 0.5 0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Viewport clipBoundary='0 0.5 0 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 35.4.4 Viewport, read in instantreality's and X_ITE's copies of the node's
    /// text (the 4.0 IS page's node section was not reached): "The clipBoundary field is
    /// specified in fractions of the normal render surface in the sequence
    /// left/right/bottom/top." A warning: the sentence names the four values but no
    /// "shall" was read against another count.
    pub static VIEWPORT_CLIP_BOUNDARY_COUNT = {
        severity: Warning,
        level: Standard,
        clause: "35.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, entry) in written_entries(doc, &routed, "Viewport", "clipBoundary") {
        let Some(values) = entry.value.as_floats() else {
            continue;
        };
        if values.len() != SIDES {
            found.push((id, entry.span, values.len()));
        }
    }
    for (id, span, count) in found {
        ctx.report(
            Diagnostic::new(
                &VIEWPORT_CLIP_BOUNDARY_COUNT,
                span,
                format!(
                    "Viewport.clipBoundary has {}: it takes four (left, right, bottom, top)",
                    plural(count, "value")
                ),
            )
            .node(id)
            .help("give the left, right, bottom and top edges as fractions of the surface, e.g. `0 1 0 1` (the whole surface)"),
        );
    }
}
