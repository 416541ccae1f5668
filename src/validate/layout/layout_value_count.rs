//! LAYOUT_VALUE_COUNT: a Layout field without its one or two values.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Layout field holding a number of values it has no meaning for:
    /// `align`, `offsetUnits`, `scaleMode` or `sizeUnits` with none or more than two
    /// strings (one value serves both directions, two are the horizontal and the
    /// vertical), and `offset` or `size` with other than two numbers. A field that takes
    /// its value through `IS` (or a ROUTE) is left alone; whether each string is one of
    /// the field's words is FIELD_ENUM_INVALID's.
    ///
    /// ## Why it matters
    /// Each field describes the horizontal and the vertical direction of the layout
    /// rectangle: a third value has no direction to apply to and is dropped, and an
    /// `offset` or `size` with one number leaves the vertical one to the browser. The
    /// extra values are usually a second Layout's, or `"LEFT TOP"`-style words written
    /// as separate strings twice.
    ///
    /// ## Example
    /// ```xml
    /// <Layout align='"LEFT" "TOP" "CENTER"' size='0.5'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Layout align='"LEFT" "TOP"' size='0.5 0.5'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 36.4.1 Layout, read in X_ITE's copy of the X3D tooltips for the node (the
    /// 4.0 IS page's node section was not reached): for `align`, "Two quoted string values
    /// are provided. The first value is for horizontal direction (LEFT or CENTER or RIGHT)
    /// and the second value is for vertical direction (BOTTOM or CENTER or TOP)", with the
    /// warning "Two values (or possibly one value) only"; `offsetUnits`, `scaleMode` and
    /// `sizeUnits` likewise; and in instantreality's copy of the node's text, "The width
    /// and height of the layout rectangle is defined by two values in the size field." A
    /// warning: no "shall" of the published clause was read against another count.
    pub static LAYOUT_VALUE_COUNT = {
        severity: Warning,
        level: Standard,
        clause: "36.4.1",
        versions: "all",
        check: Some(check),
    }
}

/// The fields of words, each one or two values (horizontal, vertical).
const WORD_FIELDS: [&str; 4] = ["align", "offsetUnits", "scaleMode", "sizeUnits"];

/// The fields of numbers, each exactly two (horizontal, vertical).
const NUMBER_FIELDS: [&str; 2] = ["offset", "size"];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Layout") {
        let node = doc.node(id);
        for entry in &node.fields {
            let field = entry.name();
            let expected = if WORD_FIELDS.contains(&field) {
                "one or two (horizontal, vertical)"
            } else if NUMBER_FIELDS.contains(&field) {
                "two (horizontal, vertical)"
            } else {
                continue;
            };
            let count = match (entry.value.as_strings(), entry.value.as_floats()) {
                (Some(strings), _) if (1..=2).contains(&strings.len()) => continue,
                (Some(strings), _) => strings.len(),
                (_, Some(numbers)) if numbers.len() == 2 => continue,
                (_, Some(numbers)) => numbers.len(),
                _ => continue,
            };
            if !set_elsewhere(doc, &routed, id, field) {
                found.push((id, entry.span, field.to_string(), count, expected));
            }
        }
    }
    for (id, span, field, count, expected) in found {
        ctx.report(
            Diagnostic::new(
                &LAYOUT_VALUE_COUNT,
                span,
                format!(
                    "Layout.{field} has {}: it takes {expected}",
                    plural(count, "value")
                ),
            )
            .node(id)
            .help(format!("give Layout.{field} one value for the horizontal direction and one for the vertical")),
        );
    }
}
