//! TEXT_LENGTH_EXTRA_VALUES: a Text with more length values than strings.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Text whose `length` holds more values than `string` holds strings,
    /// counting the defaults (both empty) of fields not written. Fewer lengths than
    /// strings are allowed (the missing ones are 0: the string keeps its natural length).
    /// Fields a ROUTE sends values to or that take their value through `IS` are left
    /// alone.
    ///
    /// ## Why it matters
    /// Length i is the length string i is stretched or compressed to; a length past the
    /// last string belongs to no string and is ignored. It usually means a string was
    /// removed without its length, so the lengths after it now scale the wrong strings.
    ///
    /// ## Example
    /// ```xml
    /// <Text string='"Title"' length='4 6'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Text string='"Title" "Subtitle"' length='4 6'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 15.4.2 Text, as ISO/IEC 14772-1 6.47 for VRML97: "The length field
    /// contains an MFFloat value that specifies the length of each text string in the
    /// local coordinate system." and "If a length value is missing (for example, if there
    /// are four strings but only three length values), the missing values are considered
    /// to be 0." A warning: the text defines fewer values and says nothing of more, so
    /// an extra value is one the browser ignores, not a broken "shall".
    pub static TEXT_LENGTH_EXTRA_VALUES = {
        severity: Warning,
        level: Standard,
        clause: "15.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Text") {
        if any_set_elsewhere(doc, &routed, id, &["string", "length"]) {
            continue;
        }
        let (Some(strings), Some(lengths)) = (
            doc.value_of(id, "string").map(|v| v.len()),
            doc.value_of(id, "length").map(|v| v.len()),
        ) else {
            continue;
        };
        if lengths <= strings {
            continue;
        }
        let Some(entry) = doc.node(id).entry("length") else {
            continue;
        };
        found.push((id, entry.span, strings, lengths));
    }
    for (id, span, strings, lengths) in found {
        ctx.report(
            Diagnostic::new(
                &TEXT_LENGTH_EXTRA_VALUES,
                span,
                format!(
                    "Text has {} but {}: the lengths past the last string are ignored",
                    plural(strings, "string"),
                    plural(lengths, "length value")
                ),
            )
            .node(id)
            .help("give one length per string, in the order of the strings"),
        );
    }
}
