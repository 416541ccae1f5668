//! FIELD_OUT_OF_RANGE: a value outside the range of the node's interface table.

use super::failures;
use crate::diagnostic::Diagnostic;
use crate::model::{range_applies, FieldEntry, NodeId, Value};
use crate::schema::{in_range_f32, in_range_f64, range_text, FieldDef, FieldType};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a value outside the range printed in the node's interface table for the
    /// document's version (e.g. light `intensity` is `[0,1]` in 3.x and `[0,∞)` in 4.x).
    /// Every element of an MF value and every component of a vector is checked; one
    /// diagnostic per field names the first offending element, its value, the range and
    /// how many elements are out of range in all.
    ///
    /// Values are compared at the field's precision: SFFloat-based values as the f32 the
    /// text rounds to, against the bound rounded to f32 (so `1.570796327` passes a
    /// (0,π/2] bound and `1.571` does not); SFDouble and SFTime values in f64; integers
    /// exactly. NaN is never in range; -0 equals 0. Text beyond the precision's largest
    /// finite value rounds to an infinity: FIELD_VALUE_NONFINITE, and outside the range
    /// too when the range has a finite bound on that side (`1e39` is outside `[0,1]`, not
    /// outside [0,∞)). Text below half the smallest subnormal rounds to a zero (`1e-46`
    /// is outside (0,∞) in an SFFloat, inside it in an SFDouble). Geometry index fields
    /// (`coordIndex`, `index`, …) are INDEX_NEGATIVE's: it knows the -1 separator.
    ///
    /// `bboxSize` (every X3DBoundedObject, and every field of the UOM's `bboxSizeType`) is
    /// "[0,∞) or −1 −1 −1" (10.2.2, 12.4.8): each component at least 0, or the whole
    /// value exactly −1 −1 −1, which says "not given". So `0 0 0` and `-1 -1 -1` pass,
    /// `-2 -2 -2` fails, and so does `-1 2 3`: the alternative is the one value, not a
    /// bound per component (the UOM's pattern for the type says the same).
    ///
    /// The `conversionFactor` of a `unit` statement is (0,∞) (7.2.5.5: a positive factor;
    /// the UOM's minExclusive 0).
    ///
    /// ## Why it matters
    /// Browsers clamp, wrap or reject out-of-range values, each differently, so the scene
    /// looks different in each.
    ///
    /// ## Example
    /// ```xml
    /// <Material diffuseColor='1.2 0 0' transparency='-0.5'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 the node's interface table; 4.4.2.2 Field semantics.
    /// The range column of the interface table is the constraint, stated per field: e.g.
    /// DirectionalLight's `ambientIntensity` row, whose value outside `[0,1]` the file breaks.
    /// > "SFFloat `[in,out]` ambientIntensity 0 `[0,1]`" (19775-1 17.4.1, an interface table row; every field's row states its range likewise)
    pub static FIELD_OUT_OF_RANGE = {
        severity: Error,
        level: Fast,
        clause: "4.4.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    unit_factors(ctx);
    for (id, node) in ctx.doc.iter() {
        for entry in &node.fields {
            let Some(def) = entry.schema_def() else {
                continue;
            };
            if is_bbox_size(def) {
                if let Value::Floats(v) = &entry.value {
                    if let Some(first) = bbox_size_outside(v) {
                        let range = BBOX_SIZE_RANGE;
                        report(ctx, id, node.type_name(), entry, def, range, first, 1);
                    }
                }
                continue;
            }
            if !range_applies(node, def) {
                continue;
            }
            let outside = match &entry.value {
                Value::Summary(summary) => summary.out_of_range,
                Value::Floats(v) => failures(v, |x| in_range_f32(x, def)),
                Value::Doubles(v) => failures(v, |x| in_range_f64(x, def)),
                Value::Int32s(v) => failures(v, |x| in_range_f64(f64::from(x), def)),
                _ => continue,
            };
            if let Some((first, count)) = outside {
                let range = &range_text(def);
                report(ctx, id, node.type_name(), entry, def, range, first, count);
            }
        }
    }
}

/// The range of `bboxSize` as the interface tables print it.
const BBOX_SIZE_RANGE: &str = "[0,∞) or -1 -1 -1";

/// Whether `def` is a bounding box size, of the UOM's `bboxSizeType` (every field so named).
fn is_bbox_size(def: &FieldDef) -> bool {
    def.name == "bboxSize" && def.ty == FieldType::SFVec3f
}

/// The first component of a bboxSize outside "[0,∞) or −1 −1 −1": None for `-1 -1 -1`
/// exactly or three components ≥ 0. NaN is never in range.
fn bbox_size_outside(v: &[f32]) -> Option<usize> {
    if v == [-1.0, -1.0, -1.0] {
        return None;
    }
    v.iter().position(|&x| x.is_nan() || x < 0.0)
}

/// A `unit` statement's conversionFactor must be positive: (0,∞).
fn unit_factors(ctx: &mut Ctx) {
    for unit in &ctx.doc.head.units {
        let Some((Some(factor), span)) = unit.conversion_factor else {
            continue;
        };
        if factor > 0.0 {
            continue;
        }
        let text =
            String::from_utf8_lossy(ctx.source.get(span.range()).unwrap_or_default()).into_owned();
        let category = unit.category.as_ref().map_or("", |c| c.text.as_str());
        ctx.report(
            Diagnostic::new(
                &FIELD_OUT_OF_RANGE,
                span,
                format!(
                    "unit.conversionFactor = {} is outside (0,∞) in X3D {}: a factor converts the {category} base unit and must be positive",
                    text.trim(),
                    ctx.version
                ),
            )
            .value(text),
        );
    }
}

#[allow(clippy::too_many_arguments)]
fn report(
    ctx: &mut Ctx,
    id: NodeId,
    type_name: &str,
    entry: &FieldEntry,
    def: &FieldDef,
    range: &str,
    first: usize,
    count: usize,
) {
    let (span, text) = ctx.scalar_text(entry, first);
    let arity = def.ty.arity();
    let place = match (def.ty.is_mf(), arity) {
        (true, 1) => format!("[{first}]"),
        (true, _) => format!("[{}] component {}", first / arity, first % arity),
        (false, 1) => String::new(),
        (false, _) => format!(" component {first}"),
    };
    let more = if count > 1 {
        format!(" ({count} values out of range in all)")
    } else {
        String::new()
    };
    let mut diagnostic = Diagnostic::new(
        &FIELD_OUT_OF_RANGE,
        span,
        format!(
            "{type_name}.{}{place} = {text} is outside {range} in {}{more}",
            def.name,
            ctx.version.name()
        ),
    )
    .node(id)
    .index(if def.ty.is_mf() { first / arity } else { first })
    .value(text);
    diagnostic.count = count;
    ctx.report(diagnostic);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bbox_size_is_non_negative_or_exactly_minus_one() {
        assert_eq!(bbox_size_outside(&[-1.0, -1.0, -1.0]), None);
        assert_eq!(bbox_size_outside(&[0.0, 0.0, 0.0]), None);
        assert_eq!(bbox_size_outside(&[-0.0, 2.0, 1e30]), None);
        assert_eq!(bbox_size_outside(&[-2.0, -2.0, -2.0]), Some(0));
        assert_eq!(bbox_size_outside(&[-1.0, 2.0, 3.0]), Some(0));
        assert_eq!(bbox_size_outside(&[1.0, -1.0, -1.0]), Some(1));
        assert_eq!(bbox_size_outside(&[1.0, 1.0, f32::NAN]), Some(2));
    }
}
