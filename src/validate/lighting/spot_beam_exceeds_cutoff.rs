//! SPOT_BEAM_EXCEEDS_CUTOFF: a SpotLight whose beamWidth is wider than its cutOffAngle.

use crate::diagnostic::Diagnostic;
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a SpotLight whose written `beamWidth` is greater than its effective
    /// `cutOffAngle` (default π/2), compared as the f32 values the fields hold. A
    /// `beamWidth` left at its default (π/4 in X3D 3.x and 4.0) is not reported: a small
    /// written cutOffAngle then asks for a hard-edged beam, which is what 17.4.4 gives.
    /// NaN and infinities are left to FIELD_VALUE_NONFINITE.
    ///
    /// ## Why it matters
    /// 17.4.4: "If the beamWidth is greater than the cutOffAngle, beamWidth is defined to be
    /// equal to the cutOffAngle and the light source emits full intensity within the entire
    /// solid angle defined by cutOffAngle." The soft edge the author asked for is not drawn.
    ///
    /// ## Example
    /// ```xml
    /// <SpotLight beamWidth='1.2' cutOffAngle='0.6'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 17.4.4 SpotLight.
    pub static SPOT_BEAM_EXCEEDS_CUTOFF = {
        severity: Warning,
        level: Standard,
        clause: "17.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    // UNIT statements rescale angles and lengths (not modelled here): judge nothing.
    if !doc.head.units.is_empty() {
        return;
    }
    for id in doc.nodes_of_type("SpotLight") {
        let node = doc.node(id);
        let (beam_entry, cutoff_entry) = (node.entry("beamWidth"), node.entry("cutOffAngle"));
        // Only a written beamWidth is a soft edge the author asked for.
        let Some(beam_entry) = beam_entry else {
            continue;
        };
        if node.is_connected("beamWidth") || node.is_connected("cutOffAngle") {
            continue;
        }
        let (Some(beam), Some(cutoff)) =
            (doc.f32_of(id, "beamWidth"), doc.f32_of(id, "cutOffAngle"))
        else {
            continue;
        };
        // A non-finite value is FIELD_VALUE_NONFINITE's: it has no order to judge.
        if beam > cutoff && beam.is_finite() && cutoff.is_finite() {
            let mut diagnostic = Diagnostic::new(
                &SPOT_BEAM_EXCEEDS_CUTOFF,
                beam_entry.span,
                format!(
                    "SpotLight.beamWidth {} is greater than cutOffAngle {}: it is treated as equal, so the light has no soft edge",
                    readable(beam.into()),
                    readable(cutoff.into())
                ),
            )
            .node(id);
            if let Some(cutoff_entry) = cutoff_entry {
                diagnostic = diagnostic.related(cutoff_entry.span, "cutOffAngle");
            }
            ctx.report(diagnostic);
        }
    }
}
