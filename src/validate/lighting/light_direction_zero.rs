//! LIGHT_DIRECTION_ZERO: a DirectionalLight or SpotLight pointing nowhere.

use super::{all_zero, lights_setting};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a DirectionalLight or SpotLight whose `direction` is `0 0 0` (either zero
    /// counts, -0 included).
    ///
    /// ## Why it matters
    /// The direction is the light's axis (17.4.1, 17.4.4); the lighting equations normalize
    /// it (17.2.2), which a zero vector cannot be. Browsers then light nothing, light
    /// everything, or produce NaN colours.
    ///
    /// ## Example
    /// ```xml
    /// <DirectionalLight direction='0 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 17.4.1 DirectionalLight, 17.4.4 SpotLight, 17.2.2 Lighting model.
    /// A warning, not an error: no sentence forbids the zero vector. The interface
    /// tables give `direction` the range `(-∞,∞)`, and the text only says that it
    /// "specifies the direction vector of the illumination" (17.4.1); what a zero vector
    /// lights is left undefined, not made wrong (issue 32).
    pub static LIGHT_DIRECTION_ZERO = {
        severity: Warning,
        level: Standard,
        clause: "17.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let found = lights_setting(
        ctx.doc,
        |node| matches!(node.type_name(), "DirectionalLight" | "SpotLight"),
        "direction",
        all_zero,
    );
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &LIGHT_DIRECTION_ZERO,
                span,
                format!("{type_name}.direction is 0 0 0: the light has no direction"),
            )
            .node(id)
            .help("give the direction the light shines in, e.g. `0 0 -1` (the default)"),
        );
    }
}
