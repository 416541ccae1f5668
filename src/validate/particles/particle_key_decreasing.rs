//! PARTICLE_KEY_DECREASING: a ParticleSystem colorKey smaller than the key before it.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, written_entries};
use crate::validate::numbers::first_decrease;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first value of a ParticleSystem's `colorKey` that is smaller than the
    /// one before it. Equal neighbouring keys are allowed, as for interpolators. A
    /// `colorKey` that a ROUTE sends values to, or that takes its value through `IS`, is
    /// left alone, as are keys that are not finite (FIELD_VALUE_NONFINITE's).
    /// `texCoordKey` is not checked: no sentence read says how its keys are ordered or
    /// interpolated.
    ///
    /// ## Why it matters
    /// Each key is a particle age in seconds at which the colour of the same index in the
    /// colour ramp applies, and the colours between keys are interpolated as a
    /// ColorInterpolator interpolates them. Out of order, the keys' intervals overlap:
    /// the particles' colour over their lifetime jumps back and forth, differently in
    /// each browser.
    ///
    /// ## Example
    /// ```xml
    /// <ParticleSystem colorKey='0 3 1'>
    ///   <PointEmitter/>
    ///   <Color containerField='colorRamp' color='1 1 0 1 0 0 0 0 0'/>
    /// </ParticleSystem>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ParticleSystem colorKey='0 1 3'>
    ///   <PointEmitter/>
    ///   <Color containerField='colorRamp' color='1 1 0 0 0 0 1 0 0'/>
    /// </ParticleSystem>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 40.4.5 ParticleSystem, read in H3D's documentation of its ParticleSystem
    /// node, which follows the clause's text (the 4.0 IS page's node section was not
    /// reached): "The colorRamp field holds a series of colour values to be used at the
    /// given colorKey points in time for the particle over its lifetime. Between keys,
    /// colour values are interpreted in a linear HSV space, using the same rules defined
    /// for the ColorInterpolator node." Those rules include 19.2.2's "The keys shall be
    /// monotonically non-decreasing, otherwise the results are undefined". A warning: the
    /// statement reaches colorKey only by that reference, and its outcome is undefined
    /// results.
    pub static PARTICLE_KEY_DECREASING = {
        severity: Warning,
        level: Standard,
        clause: "40.4.5",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, entry) in written_entries(doc, &routed, "ParticleSystem", "colorKey") {
        let Some(keys) = entry.value.as_floats() else {
            continue;
        };
        if let Some(at) = first_decrease(keys) {
            found.push((id, entry, at));
        }
    }
    for (id, entry, at) in found {
        let (span, text) = ctx.scalar_text(entry, at);
        let (_, before) = ctx.scalar_text(entry, at - 1);
        ctx.report(
            Diagnostic::new(
                &PARTICLE_KEY_DECREASING,
                span,
                format!(
                    "ParticleSystem.colorKey[{at}] = {text} is smaller than colorKey[{}] = {before}: the colours between them are undefined",
                    at - 1
                ),
            )
            .node(id)
            .index(at)
            .help("sort the keys, with their colours in the colour ramp, so that each key is at least the one before it"),
        );
    }
}
