//! POINT_SIZE_MIN_EXCEEDS_MAX: PointProperties.pointSizeMinValue above pointSizeMaxValue.

use crate::diagnostic::Diagnostic;
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a PointProperties whose effective `pointSizeMinValue` (default 1) is greater
    /// than its effective `pointSizeMaxValue` (default 1), compared as the f32 values the
    /// fields hold. NaN and infinities (`1e39` overflows an SFFloat) are left to
    /// FIELD_VALUE_NONFINITE.
    ///
    /// ## Why it matters
    /// 12.4.7: "The provided value for pointSizeMinValue must be less than or equal to value
    /// for pointSizeMaxValue." The point size is clipped to the minimum, then to the
    /// maximum, so the minimum silently loses.
    ///
    /// ## Example
    /// ```xml
    /// <PointProperties pointSizeMinValue='4' pointSizeMaxValue='2'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.7 PointProperties.
    /// > "The provided value for pointSizeMinValue must be less than or equal to value for pointSizeMaxValue" (19775-1 12.4.7)
    pub static POINT_SIZE_MIN_EXCEEDS_MAX = {
        severity: Error,
        level: Standard,
        clause: "12.4.7",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("PointProperties") {
        let node = doc.node(id);
        if !node.connects.is_empty() {
            continue;
        }
        let (Some(min), Some(max)) = (
            doc.f32_of(id, "pointSizeMinValue"),
            doc.f32_of(id, "pointSizeMaxValue"),
        ) else {
            continue;
        };
        // A non-finite value is FIELD_VALUE_NONFINITE's: it has no order to judge.
        if min > max && min.is_finite() && max.is_finite() {
            let (min_entry, max_entry) = (
                node.entry("pointSizeMinValue"),
                node.entry("pointSizeMaxValue"),
            );
            let span = min_entry.or(max_entry).map_or(node.name_span, |e| e.span);
            let related = max_entry.filter(|_| min_entry.is_some()).map(|e| e.span);
            found.push((id, span, related, min, max));
        }
    }
    for (id, span, related, min, max) in found {
        let mut diagnostic = Diagnostic::new(
            &POINT_SIZE_MIN_EXCEEDS_MAX,
            span,
            format!(
                "PointProperties.pointSizeMinValue {} is greater than pointSizeMaxValue {}",
                readable(min.into()),
                readable(max.into())
            ),
        )
        .node(id);
        if let Some(related) = related {
            diagnostic = diagnostic.related(related, "pointSizeMaxValue");
        }
        ctx.report(diagnostic);
    }
}
