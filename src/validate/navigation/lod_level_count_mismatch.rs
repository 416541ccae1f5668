//! LOD_LEVEL_COUNT_MISMATCH: an LOD without one level more than it has ranges.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an LOD with a non-empty `range` whose levels (X3D: `children`; VRML97:
    /// `level`) are not exactly one more than its range values. An empty `range` is
    /// left alone: it lets the browser choose the level itself, with any number of
    /// levels. So is an LOD whose `range` or levels take their value through `IS` or
    /// that a ROUTE changes (`addChildren`, `removeChildren`, …).
    ///
    /// ## Why it matters
    /// N ranges cut the distance from the viewer into N+1 intervals, one level each, from
    /// near to far. With too few levels the last level is shown for every farther
    /// interval, so the intended "nothing at this distance" or coarsest level is missing;
    /// with too many the extra levels are never shown.
    ///
    /// ## Example
    /// ```xml
    /// <LOD range='10 50'>
    ///   <Shape><Sphere/></Shape>
    ///   <Shape><Box/></Shape>
    /// </LOD>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <LOD range='10 50'>
    ///   <Shape><Sphere/></Shape>
    ///   <Shape><Box/></Shape>
    ///   <WorldInfo/>
    /// </LOD>
    /// ```
    ///
    /// ## Clause
    /// ISO/IEC 14772-1 6.26 LOD (VRML97): "The number of nodes in the level field shall
    /// exceed the number of values in the range field by one (i.e., N+1 level values for
    /// N range values)." followed by "Specifying too few levels will result in the last
    /// level being used repeatedly for the lowest levels of detail. If more levels than
    /// ranges are specified, the extra levels are ignored. An empty range field is an
    /// exception to this rule." 19775-1 23.4.3 LOD carries the sentence over with
    /// `children` for `level`. An error, as the sentence says "shall", even though it
    /// also says what browsers do otherwise.
    /// > "The number of nodes in the level field shall exceed the number of values in the range field by one" (ISO/IEC 14772-1 6.26)
    pub static LOD_LEVEL_COUNT_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "23.4.3",
        versions: "all",
        check: Some(check),
    }
}

/// The fields a ROUTE or IS can change an LOD's ranges or levels through.
const LEVEL_FIELDS: [&str; 5] = [
    "range",
    "children",
    "level",
    "addChildren",
    "removeChildren",
];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("LOD") {
        if any_set_elsewhere(doc, &routed, id, &LEVEL_FIELDS) {
            continue;
        }
        let node = doc.node(id);
        let Some(range) = node.entry("range") else {
            continue;
        };
        let ranges = range.value.len();
        let field = if node.entry("level").is_some() {
            "level"
        } else {
            "children"
        };
        let levels = node.children(field).len();
        if ranges == 0 || levels == ranges + 1 {
            continue;
        }
        found.push((id, range.span, ranges, field, levels));
    }
    for (id, span, ranges, field, levels) in found {
        let consequence = if levels <= ranges {
            "the last level is shown for every farther range"
        } else {
            "the levels past the last range are never shown"
        };
        ctx.report(
            Diagnostic::new(
                &LOD_LEVEL_COUNT_MISMATCH,
                span,
                format!(
                    "LOD has {} but {}: it needs {} ({consequence})",
                    plural(ranges, "range value"),
                    plural(levels, if field == "level" { "level node" } else { "child node" }),
                    plural(ranges + 1, "level")
                ),
            )
            .node(id)
            .help("give one level more than there are ranges, e.g. an empty WorldInfo or Group as the farthest level"),
        );
    }
}
