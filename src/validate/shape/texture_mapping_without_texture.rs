//! TEXTURE_MAPPING_WITHOUT_TEXTURE: an xxxTextureMapping whose xxxTexture is NULL.

use super::analysis::texture_fields;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a material (any X3DOneSidedMaterialNode) that sets a non-empty
    /// `xxxTextureMapping` while its `xxxTexture` is NULL. Fields connected by `IS` are
    /// not judged.
    ///
    /// ## Why it matters
    /// The mapping selects coordinates and a transformation for the texture (12.2.4); with
    /// no texture it does nothing, which usually means the texture was forgotten or put in
    /// another field.
    ///
    /// ## Example
    /// ```xml
    /// <Material normalTextureMapping='uv0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.4 Texture mapping specified in material nodes.
    pub static TEXTURE_MAPPING_WITHOUT_TEXTURE = {
        severity: Hint,
        level: Standard,
        clause: "12.2.4",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        let Some(def) = node.def().filter(|d| d.is_a("X3DOneSidedMaterialNode")) else {
            continue;
        };
        for (texture, mapping) in texture_fields(def) {
            let Some(entry) = node.entry(mapping) else {
                continue;
            };
            let set = entry
                .value
                .as_strings()
                .and_then(|s| s.first())
                .is_some_and(|s| !s.is_empty());
            if set && node.child(texture).is_none() && !node.is_connected(texture) {
                found.push((id, entry.span, texture, mapping, def.name));
            }
        }
    }
    for (id, span, texture, mapping, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &TEXTURE_MAPPING_WITHOUT_TEXTURE,
                span,
                format!(
                    "{type_name}.{mapping} is set but {texture} is NULL: the mapping does nothing"
                ),
            )
            .node(id),
        );
    }
}
