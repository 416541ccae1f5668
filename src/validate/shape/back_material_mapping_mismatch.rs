//! BACK_MATERIAL_MAPPING_MISMATCH: material and backMaterial use different texture mappings.

use super::back_textures::material_pairs;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// For an Appearance whose material and backMaterial are of the same class, reports
    /// each `xxxTextureMapping` field (of every xxxTexture/xxxTextureMapping pair of that
    /// class) whose effective values differ, defaults (`""`) included. The comparison is
    /// exact, as mapping names are matched exactly (12.2.4).
    ///
    /// ## Why it matters
    /// 12.2.3 item 2: the values of the xxxTexture **and xxxTextureMapping** fields "shall
    /// be equal for both front and back materials": both sides use the same texture
    /// coordinates and transformations.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <Material diffuseTextureMapping='uv0'/>
    ///   <Material containerField='backMaterial' diffuseTextureMapping='uv1'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials, item 2; 12.2.4.
    /// > "the values of the fields xxxTexture and xxxTextureMapping … shall be equal for both front and back materials" (19775-1 12.2.3)
    pub static BACK_MATERIAL_MAPPING_MISMATCH = {
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
        for &(_, mapping) in &pair.fields {
            let front = doc.string_of(pair.front.node, mapping);
            let back = doc.string_of(pair.back.node, mapping);
            let (Some(front), Some(back)) = (front, back) else {
                continue;
            };
            if front == back {
                continue;
            }
            let back_entry = doc.node(pair.back.node).entry(mapping);
            let front_entry = doc.node(pair.front.node).entry(mapping);
            let span = back_entry.map_or(pair.back.span, |e| e.span);
            let related = front_entry.map_or(pair.front.span, |e| e.span);
            ctx.report(
                Diagnostic::new(
                    &BACK_MATERIAL_MAPPING_MISMATCH,
                    span,
                    format!(
                        "backMaterial.{mapping} is {back:?} but material.{mapping} is {front:?}"
                    ),
                )
                .node(pair.back.node)
                .related(related, format!("material.{mapping}"))
                .help("front and back materials must use the same texture mappings"),
            );
        }
    }
}
