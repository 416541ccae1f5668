//! KEY_VALUE_COUNT_MISMATCH: an interpolator or sequencer whose keyValue (or keyVelocity)
//! count does not match its key count.

use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, Span, Value};
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields, set_elsewhere};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an interpolator (every node type derived from X3DInterpolatorNode) whose
    /// `keyValue` does not hold one value per key: exactly as many values as keys for the
    /// interpolators that output one value (ColorInterpolator, PositionInterpolator,
    /// OrientationInterpolator, ScalarInterpolator, the 2D and spline interpolators,
    /// SquadOrientationInterpolator, GeoPositionInterpolator), and an integer multiple
    /// of the key count for those that output an array (CoordinateInterpolator,
    /// CoordinateInterpolator2D, NormalInterpolator). A sequencer (X3DSequencerNode:
    /// BooleanSequencer, IntegerSequencer) needs one keyValue per key. A value is one
    /// tuple of the field's type (three numbers of an MFVec3f, four of an MFRotation). For the
    /// spline interpolators a `keyVelocity` that is neither empty nor one velocity per
    /// key is reported too. An interpolator with no keys and no values is left alone
    /// (it produces no events, 19.3.1), as are fields a ROUTE sends values to or that
    /// take their value through `IS`: their written value is not what the node uses.
    ///
    /// ## Why it matters
    /// Key i selects keyValue i (19.2.2): with fewer values the last keys have none, and
    /// browsers differ (stop animating, repeat the last value, read past the end); with
    /// more, the extra values are never reached, which usually means a key was lost.
    ///
    /// ## Example
    /// ```xml
    /// <PositionInterpolator key='0 0.5 1' keyValue='0 0 0 0 1 0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <PositionInterpolator key='0 0.5 1' keyValue='0 0 0 0 1 0 0 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 19.3.1 X3DInterpolatorNode ("the keyValue field contains values for the
    /// target field, one complete set of values for each key"); 19.4.6
    /// OrientationInterpolator ("shall contain exactly as many rotations as there are key
    /// frames in the key field") and 19.4.7 PositionInterpolator ("shall contain exactly
    /// as many values as in the key field"); 19.4.2 CoordinateInterpolator ("The number of
    /// coordinates in the keyValue field shall be an integer multiple of the number of key
    /// frames in the key field"); 19.4.10 SplinePositionInterpolator ("The keyValue,
    /// keyVelocity, and key fields shall each have the same number of values").
    /// Readings: the other single-output interpolators are held to 19.3.1's one set per
    /// key, which for them is one value; NormalInterpolator and CoordinateInterpolator2D,
    /// which output arrays like CoordinateInterpolator, to its integer multiple. The
    /// spline clauses' "same number" is not applied to an empty keyVelocity, the default,
    /// from which 19.2.4 computes the velocities. Values with no keys are reported (no
    /// integer multiple of zero is non-zero). 30.3.1 X3DSequencerNode: "The
    /// piecewise-linear function is defined by n values of t, called key, and the n
    /// corresponding values of f(t), called keyValue" (the same one value per key).
    /// > "shall contain exactly as many values as in the key field" (19775-1 19.4.7)
    pub static KEY_VALUE_COUNT_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "19.3.1",
        versions: "all",
        check: Some(check),
    }
}

/// The interpolators whose keyValue holds a whole array per key.
const ARRAY_OUTPUT: [&str; 3] = [
    "CoordinateInterpolator",
    "CoordinateInterpolator2D",
    "NormalInterpolator",
];

struct Mismatch {
    id: NodeId,
    span: Span,
    message: String,
    help: &'static str,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !(node.is_a("X3DInterpolatorNode") || node.is_a("X3DSequencerNode")) {
            continue;
        }
        if any_set_elsewhere(doc, &routed, id, &["key", "keyValue"]) {
            continue;
        }
        let Some(keys) = doc.value_of(id, "key").map(|v| v.len()) else {
            continue;
        };
        let type_name = node.type_name();
        if let Some((values, span)) = tuples(ctx, id, "keyValue") {
            let wrong = if ARRAY_OUTPUT.contains(&type_name) {
                if keys == 0 {
                    values != 0
                } else {
                    values % keys != 0
                }
            } else {
                values != keys
            };
            if wrong {
                let wanted = if ARRAY_OUTPUT.contains(&type_name) {
                    "a whole multiple of the key count (the same number of values for each key)"
                } else {
                    "one per key"
                };
                found.push(Mismatch {
                    id,
                    span: span.unwrap_or_else(|| key_span(ctx, id)),
                    message: format!(
                        "{type_name} has {} but {}: it needs {wanted}",
                        plural(keys, "key"),
                        plural(values, "keyValue value")
                    ),
                    help: "add or remove keys or values so that each key has its value",
                });
            }
        }
        if set_elsewhere(doc, &routed, id, "keyVelocity") {
            continue;
        }
        if let Some((velocities, Some(span))) = tuples(ctx, id, "keyVelocity") {
            if velocities != 0 && velocities != keys {
                found.push(Mismatch {
                    id,
                    span,
                    message: format!(
                        "{type_name} has {} but {}: it needs one per key, or none",
                        plural(keys, "key"),
                        plural(velocities, "keyVelocity value")
                    ),
                    help: "give a velocity for each key, or leave keyVelocity empty to have them computed from the key values",
                });
            }
        }
    }
    for m in found {
        ctx.report(
            Diagnostic::new(&KEY_VALUE_COUNT_MISMATCH, m.span, m.message)
                .node(m.id)
                .help(m.help),
        );
    }
}

/// The number of values (tuples of the field's type) of `field` and the place it is set
/// (None: the default, unset); None when the field is unknown to the node or did not
/// parse into whole tuples (FIELD_VALUE_SYNTAX reports that).
fn tuples(ctx: &Ctx, id: NodeId, field: &str) -> Option<(usize, Option<Span>)> {
    let node = ctx.doc.node(id);
    let arity = node.def()?.field(field)?.ty.arity().max(1);
    let value = ctx.doc.value_of(id, field)?;
    if matches!(*value, Value::Unparsed(_)) || value.len() % arity != 0 {
        return None;
    }
    Some((value.len() / arity, node.entry(field).map(|e| e.span)))
}

/// Where to point when keyValue is not written: the key field, else the node.
fn key_span(ctx: &Ctx, id: NodeId) -> Span {
    let node = ctx.doc.node(id);
    node.entry("key").map_or(node.name_span, |e| e.span)
}
