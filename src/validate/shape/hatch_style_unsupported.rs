//! HATCH_STYLE_UNSUPPORTED: a hatchStyle browsers need not support.

use crate::diagnostic::{Diagnostic, Severity};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a FillProperties with `hatched TRUE` (the default) whose `hatchStyle` is not
    /// one of 1–6, the styles every browser shall support: an info for 7–19, registered
    /// styles (Table 12.2) a browser may support; a warning for 0 and above 19, which are
    /// in no table. Negative values are FIELD_OUT_OF_RANGE; with `hatched FALSE` the style
    /// is unused and not judged.
    ///
    /// ## Why it matters
    /// 12.4.3: "If a hatchstyle that is not supported is requested, hatchstyle 1 shall be
    /// used": the scene shows horizontal lines instead of the chosen pattern.
    ///
    /// ## Example
    /// ```xml
    /// <FillProperties hatchStyle='12'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.3 FillProperties, Table 12.2.
    pub static HATCH_STYLE_UNSUPPORTED = {
        severity: Info,
        level: Standard,
        clause: "12.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("FillProperties") {
        let node = doc.node(id);
        let Some(entry) = node.entry("hatchStyle") else {
            continue;
        };
        if !node.connects.is_empty() || doc.bool_of(id, "hatched") != Some(true) {
            continue;
        }
        let Some(style) = doc.i32_of(id, "hatchStyle") else {
            continue;
        };
        let severity = match style {
            1..=6 | i32::MIN..=-1 => continue,
            7..=19 => Severity::Info,
            _ => Severity::Warning,
        };
        found.push((id, entry.span, style, severity));
    }
    for (id, span, style, severity) in found {
        let what = if severity == Severity::Info {
            "a registered style that browsers need not support"
        } else {
            "not a registered hatch style"
        };
        ctx.report(
            Diagnostic::new(
                &HATCH_STYLE_UNSUPPORTED,
                span,
                format!("hatchStyle {style} is {what}; browsers without it draw style 1"),
            )
            .node(id)
            .severity(severity)
            .value(style.to_string())
            .help("styles 1–6 are supported everywhere"),
        );
    }
}
