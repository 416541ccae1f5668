//! DISK2D_RADII_INVERTED: a Disk2D whose inner radius is greater than its outer radius.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Disk2D whose effective `innerRadius` (default 0) is greater than its
    /// effective `outerRadius` (default 1), compared as the f32 values the fields hold.
    /// Equal radii are allowed (they draw a circle). Fields that take their value through
    /// `IS` (or a ROUTE) are left alone, as are NaN and infinities
    /// (FIELD_VALUE_NONFINITE's); a negative radius is FIELD_OUT_OF_RANGE's.
    ///
    /// ## Why it matters
    /// The disk is the ring between the two circles; with the inner circle outside the
    /// outer one there is no ring, and browsers draw nothing, a full disk, or a ring
    /// with its faces turned inside out. Often only `innerRadius` was set, larger than
    /// the default outer radius of 1.
    ///
    /// ## Example
    /// ```xml
    /// <Shape>
    ///   <Disk2D innerRadius='2'/>
    /// </Shape>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Shape>
    ///   <Disk2D innerRadius='2' outerRadius='3'/>
    /// </Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 14.4.4 Disk2D: "The value of innerRadius shall be greater than or equal to
    /// zero and less than or equal to outerRadius." The bound at zero is the field's
    /// range, which FIELD_OUT_OF_RANGE checks.
    /// > "The value of innerRadius shall be greater than or equal to zero and less than or equal to outerRadius" (19775-1 14.4.4)
    pub static DISK2D_RADII_INVERTED = {
        severity: Error,
        level: Standard,
        clause: "14.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Disk2D") {
        if any_set_elsewhere(doc, &routed, id, &["innerRadius", "outerRadius"]) {
            continue;
        }
        let (Some(inner), Some(outer)) =
            (doc.f32_of(id, "innerRadius"), doc.f32_of(id, "outerRadius"))
        else {
            continue;
        };
        // A non-finite value is FIELD_VALUE_NONFINITE's: it has no order to judge.
        if !(inner > outer && inner.is_finite() && outer.is_finite()) {
            continue;
        }
        let node = doc.node(id);
        let (inner_entry, outer_entry) = (node.entry("innerRadius"), node.entry("outerRadius"));
        let span = inner_entry
            .or(outer_entry)
            .map_or(node.name_span, |e| e.span);
        let related = outer_entry
            .filter(|_| inner_entry.is_some())
            .map(|e| e.span);
        let message = format!(
            "Disk2D.innerRadius {} is greater than outerRadius {}{}",
            readable(inner.into()),
            readable(outer.into()),
            if outer_entry.is_none() {
                " (its default)"
            } else {
                ""
            }
        );
        found.push((id, span, related, message));
    }
    for (id, span, related, message) in found {
        let mut diagnostic = Diagnostic::new(&DISK2D_RADII_INVERTED, span, message)
            .node(id)
            .help("the inner radius shall not exceed the outer one: swap the values or raise outerRadius");
        if let Some(related) = related {
            diagnostic = diagnostic.related(related, "outerRadius");
        }
        ctx.report(diagnostic);
    }
}
