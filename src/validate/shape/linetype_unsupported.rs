//! LINETYPE_UNSUPPORTED: a linetype browsers need not support.

use crate::diagnostic::{Diagnostic, Severity};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a LineProperties with `applied TRUE` (the default) whose `linetype` is not one
    /// of 1–5, the types every browser shall support: an info for the registered types of
    /// Table 12.3 (6–8 and 10–16) a browser may support; a warning for 9, which Table 12.3
    /// leaves out (no such registered linetype), and for values above 16. Values below 1
    /// are FIELD_OUT_OF_RANGE; with `applied FALSE` the type is unused and not judged.
    ///
    /// ## Why it matters
    /// 12.4.4: "If a linetype that is not supported is requested, value 1 shall be used":
    /// the scene shows solid lines instead of the chosen pattern.
    ///
    /// ## Example
    /// ```xml
    /// <LineProperties linetype='9'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.4 LineProperties, Table 12.3.
    pub static LINETYPE_UNSUPPORTED = {
        severity: Info,
        level: Standard,
        clause: "12.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("LineProperties") {
        let node = doc.node(id);
        let Some(entry) = node.entry("linetype") else {
            continue;
        };
        if !node.connects.is_empty() || doc.bool_of(id, "applied") != Some(true) {
            continue;
        }
        let Some(linetype) = doc.i32_of(id, "linetype") else {
            continue;
        };
        let severity = match linetype {
            i32::MIN..=5 => continue,
            6..=8 | 10..=16 => Severity::Info,
            _ => Severity::Warning,
        };
        found.push((id, entry.span, linetype, severity));
    }
    for (id, span, linetype, severity) in found {
        let what = if severity == Severity::Info {
            "a registered linetype that browsers need not support"
        } else {
            "not a registered linetype"
        };
        ctx.report(
            Diagnostic::new(
                &LINETYPE_UNSUPPORTED,
                span,
                format!("linetype {linetype} is {what}; browsers without it draw solid lines (1)"),
            )
            .node(id)
            .severity(severity)
            .value(linetype.to_string())
            .help("linetypes 1–5 are supported everywhere"),
        );
    }
}
