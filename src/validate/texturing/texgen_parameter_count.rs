//! TEXGEN_PARAMETER_COUNT: TextureCoordinateGenerator parameter count wrong for its mode.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a TextureCoordinateGenerator whose `parameter` count does not fit its
    /// `mode` (Table 18.6): NOISE and NOISE-EYE take 6 values (scale and translation),
    /// SPHERE-REFLECT-LOCAL 4 (index of refraction and eye point), SPHERE-REFLECT an
    /// "optional index of refraction", so 0 or 1. Other modes take none and are not
    /// checked.
    ///
    /// ## Why it matters
    /// Missing values leave the generator without the scale, translation or eye point it
    /// needs, which browsers fill in differently; extra values are ignored.
    ///
    /// ## Example
    /// ```xml
    /// <TextureCoordinateGenerator mode='NOISE' parameter='1 1 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.8 TextureCoordinateGenerator, Table 18.6.
    pub static TEXGEN_PARAMETER_COUNT = {
        severity: Warning,
        level: Standard,
        clause: "18.4.8",
        versions: "all",
        check: Some(check),
    }
}

/// The parameter counts a mode accepts, and how to say so.
fn expected(mode: &str) -> Option<(&'static [usize], &'static str)> {
    Some(match mode {
        "NOISE" | "NOISE-EYE" => (&[6], "6 values (scale x y z, translation x y z)"),
        "SPHERE-REFLECT" => (&[0, 1], "at most 1 value (the index of refraction)"),
        "SPHERE-REFLECT-LOCAL" => (&[4], "4 values (index of refraction, eye point x y z)"),
        _ => return None,
    })
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("TextureCoordinateGenerator") {
        let node = doc.node(id);
        if node.is_connected("mode") || node.is_connected("parameter") {
            continue;
        }
        let Some(mode) = doc.string_of(id, "mode") else {
            continue;
        };
        let Some((counts, wanted)) = expected(&mode) else {
            continue;
        };
        let Some(given) = doc.value_of(id, "parameter").map(|v| v.len()) else {
            continue;
        };
        if !counts.contains(&given) {
            let span = node
                .entry("parameter")
                .or(node.entry("mode"))
                .map_or(node.name_span, |e| e.span);
            found.push((id, span, mode, given, wanted));
        }
    }
    for (id, span, mode, given, wanted) in found {
        ctx.report(
            Diagnostic::new(
                &TEXGEN_PARAMETER_COUNT,
                span,
                format!("TextureCoordinateGenerator mode \"{mode}\" takes {wanted}, not {given}"),
            )
            .node(id),
        );
    }
}
