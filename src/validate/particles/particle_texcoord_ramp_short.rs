//! PARTICLE_TEXCOORD_RAMP_SHORT: a ParticleSystem whose texture coordinate ramp has fewer
//! points than its keys need for the particles' geometry type.

use super::ramps;
use crate::diagnostic::Diagnostic;
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ParticleSystem whose TextureCoordinate in `texCoordRamp` (named
    /// `texCoord` in X3D 4) holds fewer points than `texCoordKey` has keys times the
    /// points each key takes for its `geometryType`: 2 for `LINE` (one per end of the
    /// line), 4 for `QUAD` and `TRIANGLE` (the four corners of the quad). `POINT`,
    /// `SPRITE` and `GEOMETRY` ignore the ramp and are left alone, as are a system without
    /// keys, other texture coordinate nodes, and fields a ROUTE sends values to or that
    /// take their value through `IS`.
    ///
    /// ## Why it matters
    /// When a particle reaches the next key it moves on to the next set of texture
    /// coordinates in the ramp (no interpolation). A ramp too short for its keys leaves
    /// the later keys without coordinates, so the texture animation over the particle's
    /// life stops or reads past the end, depending on the browser.
    ///
    /// ## Example
    /// ```xml
    /// <ParticleSystem geometryType='QUAD' texCoordKey='0 1'>
    ///   <PointEmitter/>
    ///   <TextureCoordinate containerField='texCoordRamp' point='0 0 0.5 0 0.5 1 0 1'/>
    /// </ParticleSystem>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ParticleSystem geometryType='QUAD' texCoordKey='0 1'>
    ///   <PointEmitter/>
    ///   <TextureCoordinate containerField='texCoordRamp'
    ///     point='0 0 0.5 0 0.5 1 0 1 0.5 0 1 0 1 1 0.5 1'/>
    /// </ParticleSystem>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 40.4.5 ParticleSystem: "The node placed in texCoordRamp shall have enough
    /// values to work with the numbers required by geometryType", with the rules that
    /// follow it: for `LINE` "Each timestamp increases the index into the ramp by two",
    /// `QUAD` gives the four corners counter-clockwise, `TRIANGLE` "only four coordinates
    /// are supplied, representing the four corners of the quad"; `POINT`, `SPRITE` and
    /// `GEOMETRY` ignore the ramp.
    /// > "The node placed in texCoordRamp shall have enough values to work with the numbers required by geometryType" (19775-1 40.4.5)
    pub static PARTICLE_TEXCOORD_RAMP_SHORT = {
        severity: Error,
        level: Standard,
        clause: "40.4.5",
        versions: "all",
        check: Some(check),
    }
}

/// The texture coordinates one key takes for a geometry type; None where the ramp is
/// ignored (or the type is no standard one).
fn points_per_key(geometry_type: &str) -> Option<usize> {
    match geometry_type {
        "LINE" => Some(2),
        "QUAD" | "TRIANGLE" => Some(4),
        _ => None,
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for ramp in ramps(
        doc,
        "texCoordKey",
        ["texCoordRamp", "texCoord"],
        &["TextureCoordinate"],
        "point",
    ) {
        let Some(geometry_type) = doc.string_of(ramp.system, "geometryType") else {
            continue;
        };
        let Some(per_key) = points_per_key(&geometry_type) else {
            continue;
        };
        let needed = ramp.keys * per_key;
        if ramp.values >= needed {
            continue;
        }
        let message = format!(
            "ParticleSystem.{} has {} but its {} TextureCoordinate holds {}; geometryType {geometry_type} needs {per_key} per key, {needed} in all",
            ramp.key_field,
            plural(ramp.keys, "key"),
            ramp.ramp_field,
            plural(ramp.values, "point"),
        );
        found.push((ramp.system, ramp.span, message));
    }
    for (system, span, message) in found {
        ctx.report(
            Diagnostic::new(&PARTICLE_TEXCOORD_RAMP_SHORT, span, message)
                .node(system)
                .help(
                    "give the ramp the texture coordinates of every key, in the order of the keys",
                ),
        );
    }
}
