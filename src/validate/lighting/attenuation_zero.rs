//! ATTENUATION_ZERO: attenuation 0 0 0, which means 1 0 0.

use super::is_positional_light;
use crate::report::Diagnostic;
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
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !is_positional_light(node) || node.is_connected("attenuation") {
            continue;
        }
        let Some(entry) = node.entry("attenuation") else {
            continue;
        };
        if entry
            .value
            .as_floats()
            .is_some_and(|v| v.len() == 3 && v.iter().all(|c| *c == 0.0))
        {
            found.push((id, entry.span, node.type_name().to_string()));
        }
    }
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
