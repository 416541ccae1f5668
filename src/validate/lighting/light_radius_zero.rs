//! LIGHT_RADIUS_ZERO: a PointLight or SpotLight with radius 0.

use super::{is_positional_light, lights_setting};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a PointLight or SpotLight whose `radius` is 0 (or -0).
    ///
    /// ## Why it matters
    /// 17.4.3, 17.4.4: the light "illuminates geometry within radius length base units of
    /// its location" and "does not emit light outside this radius". With radius 0 it lights
    /// nothing; usually `radius` was confused with the size of a lamp.
    ///
    /// ## Example
    /// ```xml
    /// <PointLight location='0 2 0' radius='0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 17.4.3 PointLight, 17.4.4 SpotLight.
    pub static LIGHT_RADIUS_ZERO = {
        severity: Warning,
        level: Standard,
        clause: "17.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let found = lights_setting(ctx.doc, is_positional_light, "radius", |v| {
        v.first() == Some(&0.0)
    });
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &LIGHT_RADIUS_ZERO,
                span,
                format!("{type_name}.radius is 0: the light reaches no geometry"),
            )
            .node(id),
        );
    }
}
