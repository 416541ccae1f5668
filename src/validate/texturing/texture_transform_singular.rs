//! TEXTURE_TRANSFORM_SINGULAR: a texture transform scale of 0.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a TextureTransform (or TextureTransform3D) whose `scale` has a component
    /// equal to 0 (-0 included), one diagnostic per component.
    ///
    /// ## Why it matters
    /// 18.4.10: the scale multiplies the texture coordinates about the centre. A zero
    /// component collapses every coordinate along that axis to one value, so the shape
    /// shows a single row or column of texels stretched across it.
    ///
    /// ## Example
    /// ```xml
    /// <TextureTransform scale='0 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.10 TextureTransform.
    pub static TEXTURE_TRANSFORM_SINGULAR = {
        severity: Warning,
        level: Standard,
        clause: "18.4.10",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !matches!(node.type_name(), "TextureTransform" | "TextureTransform3D")
            || node.is_connected("scale")
        {
            continue;
        }
        let Some(entry) = node.entry("scale") else {
            continue;
        };
        let Some(scale) = entry.value.as_floats() else {
            continue;
        };
        for (k, value) in scale.iter().enumerate() {
            if *value == 0.0 {
                found.push((
                    id,
                    ctx.scalar_span(entry, k),
                    node.type_name().to_string(),
                    k,
                ));
            }
        }
    }
    for (id, span, type_name, k) in found {
        let axis = ["S", "T", "R"][k.min(2)];
        ctx.report(
            Diagnostic::new(
                &TEXTURE_TRANSFORM_SINGULAR,
                span,
                format!("{type_name}.scale is 0 along {axis}: every texture coordinate collapses to one value"),
            )
            .node(id)
            .index(k),
        );
    }
}
