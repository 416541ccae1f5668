//! BACK_MATERIAL_TEXTURE_NOT_SHARED: equal copies of one texture in material and backMaterial.

use super::back_textures::{equal_content, material_pairs};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// For an Appearance whose material and backMaterial are of the same class, reports
    /// each `xxxTexture` field where the two give two separate texture nodes with equal
    /// content, instead of one node shared with DEF/USE. Equal content: the same node type,
    /// and every field except `metadata` with the same effective value, defaults included
    /// (so an unset `repeatS` equals `repeatS='true'`); `url` lists equal element by
    /// element; node fields (TextureProperties, cube map faces) compared the same way,
    /// recursively; numbers compared as numbers (`2` equals `2.0`, NaN equals nothing).
    /// Textures that differ in any other way are BACK_MATERIAL_TEXTURE_MISMATCH.
    ///
    /// ## Why it matters
    /// 12.2.3 item 2 asks for the same textures on both sides and "the author should use
    /// the DEF / USE mechanism to have the same references to texture nodes". Copies look
    /// the same, but a browser may load and bind them twice, and an edit to one silently
    /// breaks the rule.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <Material><ImageTexture containerField='diffuseTexture' url='"a.png"'/></Material>
    ///   <Material containerField='backMaterial'>
    ///     <ImageTexture containerField='diffuseTexture' url='"a.png"'/>
    ///   </Material>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials, item 2.
    pub static BACK_MATERIAL_TEXTURE_NOT_SHARED = {
        severity: Warning,
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
            let (Some(&f), Some(&b)) =
                (front.children(field).first(), back.children(field).first())
            else {
                continue;
            };
            if f.node == b.node || !equal_content(doc, f.node, b.node) {
                continue;
            }
            let type_name = doc.node(b.node).type_name().to_string();
            ctx.report(
                Diagnostic::new(
                    &BACK_MATERIAL_TEXTURE_NOT_SHARED,
                    b.span,
                    format!(
                        "backMaterial.{field} is a copy of material.{field} ({type_name}) \
                         instead of the same node"
                    ),
                )
                .node(pair.back.node)
                .related(f.span, format!("material.{field}"))
                .help(format!(
                    "DEF the {type_name} in material and USE it in backMaterial"
                )),
            );
        }
    }
}
