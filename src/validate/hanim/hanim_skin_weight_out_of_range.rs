//! HANIM_SKIN_WEIGHT_OUT_OF_RANGE: a skinCoordWeight outside [0, 1].

use super::name_suffix;
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::rendering::geometry::ScalarSpans;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a `skinCoordWeight` value of an HAnimJoint that is below 0 or above 1 (or
    /// not a number), unless a ROUTE or `IS` sets the field.
    ///
    /// ## Why it matters
    /// A weight is the share of the joint's motion a skin vertex follows. A negative
    /// weight moves the vertex against the joint and one above 1 moves it further than the
    /// joint itself, which tears the skin as soon as the humanoid moves. Such values
    /// usually come from an exporter that wrote something else (a bone index, a
    /// percentage) into the weights.
    ///
    /// ## Example
    /// ```xml
    /// <HAnimJoint name='r_knee' skinCoordIndex='4 5' skinCoordWeight='50 50'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <HAnimJoint name='r_knee' skinCoordIndex='4 5' skinCoordWeight='0.5 0.5'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 26.3.3 HAnimJoint, with the Joint object of ISO/IEC 19774 and 19774-1: "The
    /// skinCoordWeight field contains a list of floating point values between 0.0 and 1.0
    /// that describe an amount of weighting". Reading: the interface gives the field no
    /// range of its own (the X3D tables list none), so this is a warning, not
    /// FIELD_OUT_OF_RANGE.
    pub static HANIM_SKIN_WEIGHT_OUT_OF_RANGE = {
        severity: Warning,
        level: Standard,
        clause: "26.3.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    for id in doc.nodes_of_type("HAnimJoint") {
        if set_elsewhere(doc, &routed, id, "skinCoordWeight") {
            continue;
        }
        let node = doc.node(id);
        let Some(entry) = node.entry("skinCoordWeight") else {
            continue;
        };
        let Some(weights) = entry.value.as_floats() else {
            continue;
        };
        let name = name_suffix(doc, id);
        let mut spans = ScalarSpans::new(ctx.source, entry);
        for (at, &weight) in weights.iter().enumerate() {
            if (0.0..=1.0).contains(&weight) {
                continue;
            }
            ctx.report_repeated(&HANIM_SKIN_WEIGHT_OUT_OF_RANGE, id, "skinCoordWeight", at, || {
                let message = format!(
                    "HAnimJoint{name}.skinCoordWeight[{at}] = {weight} is outside [0, 1]"
                );
                Diagnostic::new(&HANIM_SKIN_WEIGHT_OUT_OF_RANGE, spans.span(at), message)
                    .node(id)
                    .value(weight.to_string())
                    .help("give each weight as the share of the joint's motion, from 0 (none) to 1 (all)")
            });
        }
    }
}
