//! ATTENUATION_ZERO: attenuation 0 0 0, which means 1 0 0.

use super::{all_zero, is_positional_light, lights_setting};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a PointLight or SpotLight whose `attenuation` is `0 0 0` (-0 included).
    ///
    /// ## Why it matters
    /// 17.4.3, 17.4.4: "An attenuation value of (0, 0, 0) is identical to (1, 0, 0)": the
    /// light does not fall off with distance. Authors who wrote zeros usually meant some
    /// fall-off, or none and should write the default.
    ///
    /// ## Example
    /// ```xml
    /// <PointLight attenuation='0 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 17.4.3 PointLight, 17.4.4 SpotLight.
    pub static ATTENUATION_ZERO = {
        severity: Info,
        level: Standard,
        clause: "17.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let found = lights_setting(ctx.doc, is_positional_light, "attenuation", all_zero);
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &ATTENUATION_ZERO,
                span,
                format!(
                    "{type_name}.attenuation 0 0 0 is read as 1 0 0 (no fall-off with distance)"
                ),
            )
            .node(id)
            .help("write `1 0 0` to say \"no fall-off\", or give the fall-off wanted"),
        );
    }
}
