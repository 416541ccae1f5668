//! BACKGROUND_ANGLE_DECREASING: a background's sky or ground angle smaller than the one
//! before it.

use super::{is_background, GRADIENTS};
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::first_decrease;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports the first `skyAngle` or `groundAngle` value of a Background or
    /// TextureBackground that is smaller than the angle before it. Equal neighbours are
    /// allowed. Angles a ROUTE sends values to or that take their value through `IS` are
    /// left alone, as are NaN and infinities (FIELD_VALUE_NONFINITE's); whether each angle
    /// lies in its range ([0, π] for the sky, [0, π/2] for the ground) is
    /// FIELD_OUT_OF_RANGE's.
    ///
    /// ## Why it matters
    /// The angles mark the circles, from the zenith (sky) or the nadir (ground), at which
    /// each next colour is reached, and the colour is interpolated between them. An angle
    /// below the one before it folds a band back over itself: browsers paint it
    /// differently, or skip colours.
    ///
    /// ## Example
    /// ```xml
    /// <Background skyAngle='1.2 0.8' skyColor='0 0 1 0.5 0.5 1 1 1 1'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Background skyAngle='0.8 1.2' skyColor='0 0 1 0.5 0.5 1 1 1 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 24.2.1 Backgrounds (X3D 3.x; 24.3.1 X3DBackgroundNode in 4.0): "skyAngle is
    /// restricted to non-decreasing values in the range [0.0, π]" and "groundAngle is
    /// restricted to non-decreasing values in the range [0.0, π/2]"; ISO/IEC 14772-1 6.5
    /// Background for VRML97, in the same words. Range and order are one restriction;
    /// the order is a rule between a field's values, as KEY_DECREASING's keys.
    /// > "skyAngle is restricted to non-decreasing values in the range [0.0, π]" (19775-1 24.2.1)
    pub static BACKGROUND_ANGLE_DECREASING = {
        severity: Error,
        level: Standard,
        clause: "24.2.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter().filter(|(_, node)| is_background(node)) {
        for gradient in &GRADIENTS {
            if set_elsewhere(doc, &routed, id, gradient.angles) {
                continue;
            }
            let Some(entry) = node.entry(gradient.angles) else {
                continue;
            };
            let Some(at) = entry.value.as_floats().and_then(first_decrease) else {
                continue;
            };
            found.push((id, node.type_name(), entry, gradient.angles, at));
        }
    }
    for (id, type_name, entry, field, at) in found {
        let (span, text) = ctx.scalar_text(entry, at);
        let (_, before) = ctx.scalar_text(entry, at - 1);
        ctx.report(
            Diagnostic::new(
                &BACKGROUND_ANGLE_DECREASING,
                span,
                format!(
                    "{type_name}.{field}[{at}] = {text} is smaller than {field}[{}] = {before}: the angles shall not decrease",
                    at - 1
                ),
            )
            .node(id)
            .help("list the angles in increasing order, each with its colour"),
        );
    }
}
