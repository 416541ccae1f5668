//! MARKER_TYPE_UNSUPPORTED: a markerType outside the registered 1–26.

use crate::diagnostic::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a PointProperties (X3D 4.1, where `markerType` exists) whose `markerType`
    /// is above 26 or is 0: Table 12.4 registers marker types 1–26 only. Negative values
    /// are FIELD_OUT_OF_RANGE.
    ///
    /// ## Why it matters
    /// 12.4.7: "If a markerType value that is not supported is requested, markerType value
    /// 1 shall be used": the points are drawn as dots.
    ///
    /// ## Example
    /// ```xml
    /// <PointProperties markerType='27'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.7 PointProperties, Table 12.4 (X3D 4.1).
    pub static MARKER_TYPE_UNSUPPORTED = {
        severity: Warning,
        level: Standard,
        clause: "12.4.7",
        versions: "4.1",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if ctx.version < Version::V4_1 {
        return;
    }
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("PointProperties") {
        let node = doc.node(id);
        let Some(entry) = node.entry("markerType") else {
            continue;
        };
        match doc.i32_of(id, "markerType") {
            Some(marker @ (0 | 27..)) => found.push((id, entry.span, marker)),
            _ => continue,
        }
    }
    for (id, span, marker) in found {
        ctx.report(
            Diagnostic::new(
                &MARKER_TYPE_UNSUPPORTED,
                span,
                format!("markerType {marker} is not a registered marker type (1–26); browsers draw dots (1)"),
            )
            .node(id)
            .value(marker.to_string()),
        );
    }
}
