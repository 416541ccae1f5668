//! KEY_DECREASING: an interpolator or sequencer key smaller than the key before it.

use crate::diagnostic::Diagnostic;
use crate::schema::clauses::SEQUENCER_KEYS;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::first_decrease;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first key of an interpolator (every node type derived from
    /// X3DInterpolatorNode, and EaseInEaseOut) or of a sequencer (X3DSequencerNode:
    /// BooleanSequencer, IntegerSequencer) that is smaller than the key before it.
    /// Equal neighbouring keys are allowed (they make a step). A `key` that a ROUTE sends
    /// values to, or that takes its value through `IS`, is left alone, as are keys that
    /// are not finite (FIELD_VALUE_NONFINITE reports those).
    ///
    /// ## Why it matters
    /// The keys split the fraction's range into intervals in order; with a key out of
    /// order the intervals overlap and "the results are undefined" (19.2.2): browsers
    /// pick different keyValues, or jump back and forth.
    ///
    /// ## Example
    /// ```xml
    /// <ScalarInterpolator key='0 0.6 0.4 1' keyValue='0 1 2 3'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ScalarInterpolator key='0 0.4 0.6 1' keyValue='0 2 1 3'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 19.2.2 Linear interpolation ("The keys shall be monotonically
    /// non-decreasing, otherwise the results are undefined"), which is said of the
    /// interpolator nodes of clause 19. Reading: EaseInEaseOut (19.4.4), listed among
    /// them in 19.2.1 and with a key field of the same role, is held to it too, and so is
    /// GeoPositionInterpolator (25), an X3DInterpolatorNode. 30.3.1 X3DSequencerNode
    /// says the same of the sequencers' keys in the same words ("The keys shall be
    /// monotonically non-decreasing, otherwise the results are undefined"), so this code
    /// covers them too; a sequencer's finding cites 30.3.1, an interpolator's 19.2.2.
    /// > "The keys shall be monotonically non-decreasing" (19775-1 19.2.2)
    pub static KEY_DECREASING = {
        severity: Error,
        level: Standard,
        clause: "19.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !(node.is_a("X3DInterpolatorNode")
            || node.is_a("X3DSequencerNode")
            || node.type_name() == "EaseInEaseOut")
        {
            continue;
        }
        if set_elsewhere(doc, &routed, id, "key") {
            continue;
        }
        let Some(entry) = node.entry("key") else {
            continue;
        };
        let Some(keys) = entry.value.as_floats() else {
            continue;
        };
        if let Some(at) = first_decrease(keys) {
            let clause = if node.is_a("X3DSequencerNode") {
                SEQUENCER_KEYS
            } else {
                KEY_DECREASING.clause
            };
            found.push((id, entry, at, node.type_name(), clause));
        }
    }
    for (id, entry, at, type_name, clause) in found {
        let (span, text) = ctx.scalar_text(entry, at);
        let (_, before) = ctx.scalar_text(entry, at - 1);
        ctx.report(
            Diagnostic::new(
                &KEY_DECREASING,
                span,
                format!(
                    "{type_name}.key[{at}] = {text} is smaller than key[{}] = {before}: keys shall not decrease",
                    at - 1
                ),
            )
            .node(id)
            .clause(clause)
            .help("sort the keys (with their keyValues) so that each key is at least the one before it"),
        );
    }
}
