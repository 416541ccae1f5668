//! VERTEX_ATTRIBUTE_COUNT_NOT_MULTIPLE: a FloatVertexAttribute whose values do not make
//! whole vertices.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a FloatVertexAttribute whose `value` does not hold a whole number of
    /// vertices: its length is not a multiple of `numComponents` (default 4). Fields a
    /// ROUTE sends values to or that take their value through `IS` are left alone, as
    /// is a `numComponents` outside 1 to 4 (FIELD_OUT_OF_RANGE's).
    ///
    /// ## Why it matters
    /// Each vertex takes `numComponents` consecutive values; with a remainder the last
    /// vertex's attribute is cut short, and a count that was meant for another
    /// `numComponents` shifts every vertex after the first. Browsers then read past the
    /// buffer, drop the attribute, or feed the shader values of the wrong vertices.
    ///
    /// ## Example
    /// ```xml
    /// <FloatVertexAttribute name='weight' numComponents='3' value='1 0 0 0 1'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <FloatVertexAttribute name='weight' numComponents='3' value='1 0 0 0 1 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 31.4.1 FloatVertexAttribute: "The numComponents field specifies how many
    /// consecutive floating point values should be grouped together per vertex. The
    /// length of the value field shall be a multiple of numComponents."
    /// > "The length of the value field shall be a multiple of numComponents" (19775-1 31.4.1)
    pub static VERTEX_ATTRIBUTE_COUNT_NOT_MULTIPLE = {
        severity: Error,
        level: Standard,
        clause: "31.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("FloatVertexAttribute") {
        if any_set_elsewhere(doc, &routed, id, &["value", "numComponents"]) {
            continue;
        }
        let Some(components) = doc
            .i32_of(id, "numComponents")
            .and_then(|n| usize::try_from(n).ok())
            .filter(|n| (1..=4).contains(n))
        else {
            continue;
        };
        let Some(entry) = doc.node(id).entry("value") else {
            continue;
        };
        let values = entry.value.len();
        if values % components != 0 {
            found.push((id, entry.span, values, components));
        }
    }
    for (id, span, values, components) in found {
        ctx.report(
            Diagnostic::new(
                &VERTEX_ATTRIBUTE_COUNT_NOT_MULTIPLE,
                span,
                format!(
                    "FloatVertexAttribute.value has {}, not a multiple of numComponents {components}: {} left over",
                    plural(values, "value"),
                    plural(values % components, "value")
                ),
            )
            .node(id)
            .help("give numComponents values for each vertex, or set numComponents to the size of one vertex's attribute"),
        );
    }
}
