//! EASE_IN_EASE_OUT_COUNT_MISMATCH: an EaseInEaseOut without one easeInEaseOut pair per
//! key.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an EaseInEaseOut whose `easeInEaseOut` does not hold exactly one pair (an
    /// SFVec2f: ease in, ease out) per value of `key`, counting the defaults (both
    /// empty) of fields not written. Fields a ROUTE sends values to or that take their
    /// value through `IS` are left alone, as is a value that did not parse into whole
    /// pairs (FIELD_VALUE_SYNTAX reports that).
    ///
    /// ## Why it matters
    /// Pair i says how the fraction slows down towards key i and away from it; with
    /// fewer pairs the last keys have none, with more the extra pairs belong to no key.
    /// Browsers then read past the list, ease nothing, or stop modifying the fraction.
    ///
    /// ## Example
    /// ```xml
    /// <EaseInEaseOut key='0 0.5 1' easeInEaseOut='0 0.5 0.5 0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <EaseInEaseOut key='0 0.5 1' easeInEaseOut='0 0.5 0.5 0.5 0.5 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 19.4.4 EaseInEaseOut: "The easeInEaseOut field shall have the same size as
    /// the key field, and each Vec2f value of the easeInEaseOut field corresponds to the
    /// key value with the same index." (The EaseInEaseOut has no keyValue, so this is not
    /// KEY_VALUE_COUNT_MISMATCH's; its keys' order is KEY_DECREASING's.)
    /// > "The easeInEaseOut field shall have the same size as the key field" (19775-1 19.4.4)
    pub static EASE_IN_EASE_OUT_COUNT_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "19.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("EaseInEaseOut") {
        if any_set_elsewhere(doc, &routed, id, &["key", "easeInEaseOut"]) {
            continue;
        }
        let (Some(keys), Some(numbers)) = (
            doc.value_of(id, "key").map(|v| v.len()),
            doc.value_of(id, "easeInEaseOut").map(|v| v.len()),
        ) else {
            continue;
        };
        let pairs = numbers / 2;
        if numbers % 2 != 0 || pairs == keys {
            continue;
        }
        let node = doc.node(id);
        let Some(span) = node
            .entry("easeInEaseOut")
            .or(node.entry("key"))
            .map(|e| e.span)
        else {
            continue;
        };
        found.push((
            id,
            span,
            format!(
                "EaseInEaseOut has {} but {}: it needs one per key",
                plural(keys, "key"),
                plural(pairs, "easeInEaseOut pair")
            ),
        ));
    }
    for (id, span, message) in found {
        ctx.report(
            Diagnostic::new(&EASE_IN_EASE_OUT_COUNT_MISMATCH, span, message)
                .node(id)
                .help("give an ease-in, ease-out pair for each key"),
        );
    }
}
