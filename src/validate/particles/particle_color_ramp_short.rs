//! PARTICLE_COLOR_RAMP_SHORT: a ParticleSystem with fewer ramp colours than colour keys.

use super::ramps;
use crate::diagnostic::Diagnostic;
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ParticleSystem whose colour ramp (the Color or ColorRGBA node in
    /// `colorRamp`, named `color` in X3D 4) holds fewer colours than `colorKey` holds
    /// keys. A system without a colour ramp or without keys is left alone, as are fields
    /// a ROUTE sends values to or that take their value through `IS`.
    ///
    /// ## Why it matters
    /// Each key is the particle age (in seconds) at which the colour of the same index in
    /// the ramp applies; between keys the colour is interpolated as a ColorInterpolator
    /// does. Keys beyond the last colour have no colour to apply, so the particles'
    /// colour over their lifetime is not what the keys describe and differs between
    /// browsers. Usually a key was added without its colour.
    ///
    /// ## Example
    /// ```xml
    /// <ParticleSystem colorKey='0 2 4'>
    ///   <PointEmitter/>
    ///   <Color containerField='colorRamp' color='1 1 0 1 0 0'/>
    /// </ParticleSystem>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ParticleSystem colorKey='0 2 4'>
    ///   <PointEmitter/>
    ///   <Color containerField='colorRamp' color='1 1 0 1 0 0 0.2 0.2 0.2'/>
    /// </ParticleSystem>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 40.4.5 ParticleSystem: "The colorKey field represents the time of the
    /// particle in seconds, while the colorRamp field holds a series of colour values to be
    /// used at the given key points in time." The clause states no count as a "shall"; a
    /// key without a colour cannot work as written, so this is a warning.
    pub static PARTICLE_COLOR_RAMP_SHORT = {
        severity: Warning,
        level: Standard,
        clause: "40.4.5",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let found: Vec<_> = ramps(
        ctx.doc,
        "colorKey",
        ["colorRamp", "color"],
        &["Color", "ColorRGBA"],
        "color",
    )
    .into_iter()
    .filter(|r| r.keys > 0 && r.values < r.keys)
    .collect();
    for ramp in found {
        let message = format!(
            "ParticleSystem.{} has {} but its {} {} holds {}",
            ramp.key_field,
            plural(ramp.keys, "key"),
            ramp.ramp_field,
            ramp.ramp_type,
            plural(ramp.values, "colour"),
        );
        ctx.report(
            Diagnostic::new(&PARTICLE_COLOR_RAMP_SHORT, ramp.span, message)
                .node(ramp.system)
                .help("give the ramp one colour per colorKey value, in the order of the keys"),
        );
    }
}
