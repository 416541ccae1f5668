//! JUSTIFY_EXTRA_VALUES: a FontStyle.justify with more than two values.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a FontStyle or ScreenFontStyle whose `justify` holds more than two
    /// strings. A `justify` that takes its value through `IS` (or a ROUTE) is left alone;
    /// whether each value is one of `BEGIN`, `FIRST`, `MIDDLE`, `END` is
    /// FIELD_ENUM_INVALID's.
    ///
    /// ## Why it matters
    /// The first value aligns the text along the major axis, the second along the minor
    /// axis; there is no third direction, so the extra values do nothing. They are
    /// usually a major and a minor alignment written twice, or two alignments meant for
    /// two FontStyles.
    ///
    /// ## Example
    /// ```xml
    /// <FontStyle justify='"MIDDLE" "MIDDLE" "BEGIN"'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <FontStyle justify='"MIDDLE" "MIDDLE"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 15.2.2.3 Direction and justification (and 36.4.4 ScreenFontStyle), as
    /// ISO/IEC 14772-1 6.20.3 for VRML97: "The justify field is an MFString which can
    /// contain 2 values. The first value specifies alignment along the major axis and the
    /// second value specifies alignment along the minor axis". A warning, not an error:
    /// "can contain 2 values" describes the field, no "shall" forbids a third.
    pub static JUSTIFY_EXTRA_VALUES = {
        severity: Warning,
        level: Standard,
        clause: "15.2.2",
        versions: "all",
        check: Some(check),
    }
}

/// Major and minor alignment.
const MAX_VALUES: usize = 2;

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !node.is_a("X3DFontStyleNode") || set_elsewhere(doc, &routed, id, "justify") {
            continue;
        }
        let Some(entry) = node.entry("justify") else {
            continue;
        };
        let Some(values) = entry.value.as_strings() else {
            continue;
        };
        if values.len() > MAX_VALUES {
            found.push((id, entry.span, node.type_name().to_string(), values.len()));
        }
    }
    for (id, span, type_name, count) in found {
        ctx.report(
            Diagnostic::new(
                &JUSTIFY_EXTRA_VALUES,
                span,
                format!(
                    "{type_name}.justify has {count} values: only the first two (major and minor alignment) are used"
                ),
            )
            .node(id)
            .help("keep one major and at most one minor alignment, e.g. `\"MIDDLE\" \"MIDDLE\"`"),
        );
    }
}
