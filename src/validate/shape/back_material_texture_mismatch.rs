//! BACK_MATERIAL_TEXTURE_MISMATCH: material and backMaterial use different textures.

use super::back_textures::{equal_content, material_pairs};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// For an Appearance whose material and backMaterial are of the same class, reports
    /// each `xxxTexture` field of that class (read from the schema: every field ending in
    /// `Texture` with a matching `TextureMapping` field) where the two refer to different
    /// nodes, or one is NULL and the other not. Two separate texture nodes with equal
    /// content are BACK_MATERIAL_TEXTURE_NOT_SHARED instead (see there for "equal").
    ///
    /// ## Why it matters
    /// 12.2.3 item 2: the values of the xxxTexture fields "shall be equal for both front and
    /// back materials"; front and back may differ only in scalar and vector values, so a
    /// browser is free to bind one set of textures for both sides.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <Material><ImageTexture containerField='diffuseTexture' url='"a.png"'/></Material>
    ///   <Material containerField='backMaterial'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials, item 2; 12.2.4.
    /// > "the values of the fields xxxTexture and xxxTextureMapping … shall be equal for both front and back materials" (19775-1 12.2.3)
    pub static BACK_MATERIAL_TEXTURE_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "12.2.3",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let doc = ctx.doc;
    for pair in material_pairs(doc) {
        let (front, back) = (doc.node(pair.front.node), doc.node(pair.back.node));
        for &(field, _) in &pair.fields {
            let (f, b) = (front.children(field).first(), back.children(field).first());
            let diagnostic = match (f, b) {
                (Some(f), Some(b)) if f.node == b.node || equal_content(doc, f.node, b.node) => {
                    continue
                }
                (None, None) => continue,
                (Some(f), Some(b)) => Diagnostic::new(
                    &BACK_MATERIAL_TEXTURE_MISMATCH,
                    b.span,
                    format!("backMaterial.{field} is another texture than material.{field}"),
                )
                .related(f.span, format!("material.{field}")),
                (Some(f), None) => Diagnostic::new(
                    &BACK_MATERIAL_TEXTURE_MISMATCH,
                    pair.back.span,
                    format!("material.{field} is set but backMaterial.{field} is NULL"),
                )
                .related(f.span, format!("material.{field}")),
                (None, Some(b)) => Diagnostic::new(
                    &BACK_MATERIAL_TEXTURE_MISMATCH,
                    b.span,
                    format!("backMaterial.{field} is set but material.{field} is NULL"),
                )
                .related(pair.front.span, "material"),
            };
            ctx.report(
                diagnostic
                    .node(pair.back.node)
                    .help("give both materials the same texture node (DEF it once, USE it in the other), or none"),
            );
        }
    }
}
