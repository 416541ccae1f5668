//! TEXTURE_REPEAT_IGNORED: repeatS/repeatT on a texture whose TextureProperties override them.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports `repeatS`, `repeatT` (and, for 3D textures, `repeatR`) set explicitly on a
    /// texture that also has a `textureProperties` node, one diagnostic per field.
    ///
    /// ## Why it matters
    /// 18.2.3: "Texture nodes with a provided TextureProperties node shall ignore the
    /// settings of repeatS and repeatT and shall use the provided values in the
    /// boundaryMode fields." The value written has no effect; the wrapping comes from
    /// boundaryModeS/T (default REPEAT).
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture url='"a.png"' repeatS='false'><TextureProperties/></ImageTexture>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.2.3 Texture map formats; 18.4.9 TextureProperties.
    pub static TEXTURE_REPEAT_IGNORED = {
        severity: Info,
        level: Standard,
        clause: "18.2.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        let Some(properties) = node.child("textureProperties") else {
            continue;
        };
        for (field, boundary) in [
            ("repeatS", "boundaryModeS"),
            ("repeatT", "boundaryModeT"),
            ("repeatR", "boundaryModeR"),
        ] {
            if let Some(entry) = node.entry(field) {
                let mode = doc.string_of(properties, boundary).unwrap_or_default();
                found.push((
                    id,
                    entry.span,
                    node.type_name().to_string(),
                    field,
                    boundary,
                    mode,
                ));
            }
        }
    }
    for (id, span, type_name, field, boundary, mode) in found {
        ctx.report(
            Diagnostic::new(
                &TEXTURE_REPEAT_IGNORED,
                span,
                format!(
                    "{type_name}.{field} is ignored: the texture has textureProperties, whose {boundary} (\"{mode}\") applies"
                ),
            )
            .node(id)
            .help(format!("remove {field}, or set {boundary} on the TextureProperties")),
        );
    }
}
