//! PARTICLE_KEY_DECREASING: a ParticleSystem colorKey or texCoordKey smaller than the key
//! before it.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, written_entries};
use crate::validate::numbers::first_decrease;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first value of a ParticleSystem's `colorKey`, and of its
    /// `texCoordKey`, that is smaller than the one before it. Equal neighbouring keys are
    /// allowed, as for interpolators. A key field that a ROUTE sends values to, or that
    /// takes its value through `IS`, is left alone, as are keys that are not finite
    /// (FIELD_VALUE_NONFINITE's).
    ///
    /// ## Why it matters
    /// Each key is a particle age in seconds at which the colour of the same index in the
    /// colour ramp applies, and the colours between keys are interpolated as a
    /// ColorInterpolator interpolates them. Out of order, the keys' intervals overlap:
    /// the particles' colour over their lifetime jumps back and forth, differently in
    /// each browser. The texture-coordinate keys are time stamps a particle reaches one
    /// after the other; out of order, a particle's texture coordinates skip sets or never
    /// reach them.
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
    ///
    /// texCoordKey (issue 33): no "shall" orders it; the same text (H3D's copy) describes
    /// its keys as a sequence reached in turn: "When a particle reaches the next time
    /// stamp it moves to the next set of texture coordinates. There is no interpolation of
    /// the texture coordinates, just sequenced according to the times defined by
    /// texCoordKey." A warning, as for colorKey.
    pub static PARTICLE_KEY_DECREASING = {
        severity: Warning,
        level: Standard,
        clause: "40.4.5",
        versions: "all",
        check: Some(check),
    }
}

/// A key field of ParticleSystem and what its disorder means to the reader.
struct KeyField {
    field: &'static str,
    consequence: &'static str,
    help: &'static str,
}

static KEYS: [KeyField; 2] = [
    KeyField {
        field: "colorKey",
        consequence: "the colours between them are undefined",
        help: "sort the keys, with their colours in the colour ramp, so that each key is at least the one before it",
    },
    KeyField {
        field: "texCoordKey",
        consequence: "the texture coordinates are sequenced by these times, so the sets between them are skipped or never reached",
        help: "sort the keys, with their sets of texture coordinates in the ramp, so that each key is at least the one before it",
    },
];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for key in &KEYS {
        for (id, entry) in written_entries(doc, &routed, "ParticleSystem", key.field) {
            let Some(keys) = entry.value.as_floats() else {
                continue;
            };
            if let Some(at) = first_decrease(keys) {
                found.push((key, id, entry, at));
            }
        }
    }
    for (key, id, entry, at) in found {
        let (span, text) = ctx.scalar_text(entry, at);
        let (_, before) = ctx.scalar_text(entry, at - 1);
        let field = key.field;
        ctx.report(
            Diagnostic::new(
                &PARTICLE_KEY_DECREASING,
                span,
                format!(
                    "ParticleSystem.{field}[{at}] = {text} is smaller than {field}[{}] = {before}: {}",
                    at - 1,
                    key.consequence
                ),
            )
            .node(id)
            .index(at)
            .help(key.help),
        );
    }
}
