//! NAVIGATION_TYPE_MALFORMED: a NavigationInfo `type` or `transitionType` string that is a
//! standard value miswritten: in another case, or several values in one string.

use crate::diagnostic::Diagnostic;
use crate::model::{FieldEntry, Origin};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a string of NavigationInfo `type` or `transitionType` that is not one of
    /// the values 23.4.4 defines but is made only of them: the same word in another case
    /// (`"examine"`, `"Walk"`), or several values written as one string (`"EXAMINE ANY"`,
    /// `"'FLY' 'ANY'"`, the usual result of quoting an MFString attribute wrongly). Other
    /// strings are left alone: the clause lets browsers add navigation types of their
    /// own, and x3dcheck cannot tell those from mistakes. A value passed in through `IS`
    /// is left alone too, and so is an XML attribute without any double quote
    /// (`type="EXAMINE ANY"`), which FIELD_VALUE_SYNTAX reports with the quoting that
    /// fixes it.
    ///
    /// ## Why it matters
    /// Browsers compare these strings as written. A string that is no value they know is
    /// skipped, so `type='"Examine"'` leaves the user without the examine mode the
    /// author chose (X_ITE then falls back to its default), and `type='"EXAMINE ANY"'` is
    /// a single string, not the two values it looks like, so neither applies. (A reader
    /// that turns a JSON string back into XML attribute text may split
    /// `"@type":"\"EXAMINE\" \"ANY\""` into two values; the JSON encoding writes an
    /// MFString as an array, so the file still says one string.)
    ///
    /// ## Example
    /// ```xml
    /// <NavigationInfo type='"Examine" "any"' transitionType='"teleport"'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NavigationInfo type='"EXAMINE" "ANY"' transitionType='"TELEPORT"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 23.4.4 NavigationInfo: the navigation types browsers support (`"ANY"`,
    /// `"WALK"`, `"EXAMINE"`, `"FLY"`, `"LOOKAT"`, `"NONE"`, and `"EXPLORE"` in X3D 4)
    /// and the transition types `"TELEPORT"`, `"LINEAR"` and `"ANIMATE"`; the clause also
    /// allows browser-specific navigation types, and the X3D schema treats both lists as
    /// open. Reading: since other strings are allowed, an unknown one is not an error in
    /// itself; a string that only miswrites standard values cannot be a browser-specific
    /// type on purpose, so it is reported, as a warning (the scene still loads, with
    /// another navigation than the author meant).
    pub static NAVIGATION_TYPE_MALFORMED = {
        severity: Warning,
        level: Standard,
        clause: "23.4.4",
        versions: "all",
        check: Some(check),
    }
}

const NAVIGATION_TYPES: [&str; 7] = ["ANY", "WALK", "EXAMINE", "FLY", "LOOKAT", "NONE", "EXPLORE"];
const TRANSITION_TYPES: [&str; 3] = ["TELEPORT", "LINEAR", "ANIMATE"];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter().take(doc.written_nodes().len()) {
        if node.type_name() != "NavigationInfo" {
            continue;
        }
        for (field, standard) in [
            ("type", &NAVIGATION_TYPES[..]),
            ("transitionType", &TRANSITION_TYPES[..]),
        ] {
            if node.is_connected(field) {
                continue;
            }
            let Some(entry) = node.entry(field) else {
                continue;
            };
            if unquoted_attribute(ctx.source, entry) {
                continue;
            }
            let Some(strings) = entry.value.as_strings() else {
                continue;
            };
            for text in strings {
                if let Some(meant) = miswritten(text, standard) {
                    found.push((id, entry.span, field, text.clone(), meant));
                }
            }
        }
    }
    for (id, span, field, text, meant) in found {
        let what = if meant.len() > 1 {
            format!("is one string holding {} values", meant.len())
        } else {
            "is not written as the standard value".to_string()
        };
        let fix = meant
            .iter()
            .map(|m| format!("\"{m}\""))
            .collect::<Vec<_>>()
            .join(" ");
        ctx.report(
            Diagnostic::new(
                &NAVIGATION_TYPE_MALFORMED,
                span,
                format!("NavigationInfo.{field} \"{text}\" {what}: a browser that compares the strings as written skips it"),
            )
            .node(id)
            .help(format!("write {fix}, each value its own quoted string in upper case")),
        );
    }
}

/// An XML attribute whose MFString has no double quote at all (`type="EXAMINE ANY"`):
/// FIELD_VALUE_SYNTAX reports it, with the quoting that fixes it.
fn unquoted_attribute(source: &[u8], entry: &FieldEntry) -> bool {
    let (start, end) = (entry.span.start as usize, entry.span.end as usize);
    entry.origin == Origin::Attribute
        && source
            .get(start..end)
            .is_some_and(|text| !text.contains(&b'"'))
}

/// The standard values `text` miswrites, when it is made of them alone but is not one.
fn miswritten(text: &str, standard: &[&str]) -> Option<Vec<&'static str>> {
    if standard.contains(&text) {
        return None;
    }
    let words: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || matches!(c, ',' | '\'' | '"'))
        .filter(|w| !w.is_empty())
        .collect();
    if words.is_empty() {
        return None;
    }
    words
        .iter()
        .map(|w| {
            NAVIGATION_TYPES
                .iter()
                .chain(TRANSITION_TYPES.iter())
                .copied()
                .filter(|s| standard.contains(s))
                .find(|s| s.eq_ignore_ascii_case(w))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{miswritten, NAVIGATION_TYPES};

    #[test]
    fn finds_miswritten_values() {
        let of = |t| miswritten(t, &NAVIGATION_TYPES);
        assert_eq!(of("EXAMINE"), None);
        assert_eq!(of("PLANE_create3000.github.io"), None);
        assert_eq!(of("TURNTABLE"), None);
        assert_eq!(of(""), None);
        assert_eq!(of("examine"), Some(vec!["EXAMINE"]));
        assert_eq!(of("EXAMINE ANY"), Some(vec!["EXAMINE", "ANY"]));
        assert_eq!(of("'FLY','ANY'"), Some(vec!["FLY", "ANY"]));
        assert_eq!(of(" WALK"), Some(vec!["WALK"]));
        assert_eq!(of("EXAMINE TURNTABLE"), None);
    }
}
