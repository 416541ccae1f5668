//! FIELD_VALUE_NONFINITE: NaN or infinity in a numeric field.

use super::failures;
use crate::diagnostic::Diagnostic;
use crate::model::Value;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports NaN or an infinity in a float or double field: written as `NaN`/`INF`, or
    /// a number too large for the field's precision (`1e39` in an SFFloat overflows to
    /// infinity). One diagnostic per field, naming the first element and the count.
    ///
    /// ## Why it matters
    /// X3D values are finite numbers. NaN and infinity poison transforms, bounds and
    /// lighting: geometry vanishes or the whole scene renders black, differently in each
    /// browser.
    ///
    /// ## Example
    /// ```xml
    /// <Transform translation='0 1e39 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 5.3.4 SFFloat and MFFloat, 5.3.2 SFDouble (IEEE 754 finite values).
    /// The widest range an interface table gives a float field is the open interval (-∞,∞):
    /// an infinity is outside it, and NaN is in no range.
    /// > "SFVec3f `[in,out]` direction 0 0 -1 (-∞,∞)" (19775-1 17.4.1, an interface table row; unbounded fields are stated so throughout)
    pub static FIELD_VALUE_NONFINITE = {
        severity: Error,
        level: Fast,
        clause: "5.3.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        for entry in &node.fields {
            let failures = match &entry.value {
                Value::Summary(summary) => summary.nonfinite,
                Value::Floats(v) => failures(v, f32::is_finite),
                Value::Doubles(v) => failures(v, f64::is_finite),
                _ => continue,
            };
            let Some((first, count)) = failures else {
                continue;
            };
            let (_, text) = ctx.scalar_text(entry, first);
            let more = if count > 1 {
                format!(" ({count} values in all)")
            } else {
                String::new()
            };
            let mut diagnostic = Diagnostic::new(
                &FIELD_VALUE_NONFINITE,
                ctx.scalar_span(entry, first),
                format!(
                    "{}.{}: `{text}` is not a finite number{more}",
                    node.type_name(),
                    entry.name()
                ),
            )
            .node(id)
            .index(first)
            .value(text);
            diagnostic.count = count;
            ctx.report(diagnostic);
        }
    }
}
