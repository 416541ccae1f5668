//! ANCHOR_PARAMETER_MALFORMED: an Anchor.parameter string that is not `keyword=value`.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, written_entries};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first string of an Anchor's `parameter` that is not of the form
    /// `keyword=value`: one with no `=`, or with nothing but spaces before it. The value
    /// may be empty. A `parameter` that takes its value through `IS` (or a ROUTE) is
    /// left alone.
    ///
    /// ## Why it matters
    /// Browsers read each string as a keyword and its value, such as `target=_blank` to
    /// open the link in a new window; a string without a keyword, such as a bare
    /// `_blank` or a URL that belongs in `url`, is ignored or misread, and the link opens
    /// where the author did not mean.
    ///
    /// ## Example
    /// ```xml
    /// <Anchor url='"https://www.web3d.org"' parameter='"_blank"'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Anchor url='"https://www.web3d.org"' parameter='"target=_blank"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 9.4.1 Anchor, as ISO/IEC 14772-1 6.2 for VRML97: "The parameter field may
    /// be used to supply any additional information to be interpreted by the browser.
    /// Each string shall consist of "keyword=value" pairs."
    /// > "Each string shall consist of "keyword=value" pairs" (19775-1 9.4.1)
    pub static ANCHOR_PARAMETER_MALFORMED = {
        severity: Error,
        level: Standard,
        clause: "9.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, entry) in written_entries(doc, &routed, "Anchor", "parameter") {
        let Some(strings) = entry.value.as_strings() else {
            continue;
        };
        if let Some(at) = strings.iter().position(|s| !is_keyword_value(s)) {
            found.push((id, entry.span, at, strings[at].clone()));
        }
    }
    for (id, span, at, text) in found {
        ctx.report(
            Diagnostic::new(
                &ANCHOR_PARAMETER_MALFORMED,
                span,
                format!("Anchor.parameter[{at}] \"{text}\" is not of the form keyword=value"),
            )
            .node(id)
            .help("write each parameter as a keyword and its value, e.g. `\"target=_blank\"`"),
        );
    }
}

/// Whether a string has a keyword (not only spaces) followed by `=`.
fn is_keyword_value(text: &str) -> bool {
    text.split_once('=')
        .is_some_and(|(keyword, _)| !keyword.trim().is_empty())
}
