//! APPEARANCE_TEXTURE_IGNORED: Appearance.texture shadowed by the material's main texture.

use super::analysis::appearances;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

/// Each material class's "main" texture, the one Appearance.texture stands in for (12.2.5).
const MAIN_TEXTURES: &[(&str, &str)] = &[
    ("Material", "diffuseTexture"),
    ("PhysicalMaterial", "baseTexture"),
    ("UnlitMaterial", "emissiveTexture"),
];

crate::declare_rule! {
    /// ## What it does
    /// Reports an Appearance whose `texture` is set while its material's main texture
    /// (Material.diffuseTexture, PhysicalMaterial.baseTexture, UnlitMaterial.emissiveTexture)
    /// is set too. Not reported when the Appearance has `shaders` (textures are then shader
    /// inputs, 18.2.5) or `pointProperties` (a PointSet draws Appearance.texture as point
    /// sprites, 12.4.7).
    ///
    /// ## Why it matters
    /// 12.2.5: Appearance.texture affects the diffuse, base or emissive parameter only when
    /// that main texture is NULL; otherwise it has no effect, and the author sees another
    /// texture than the one they may be editing.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <ImageTexture url='"a.png"'/>
    ///   <Material><ImageTexture containerField='diffuseTexture' url='"b.png"'/></Material>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.5 Coexistence of textures specified in material nodes with the
    /// "Appearance.texture" field.
    pub static APPEARANCE_TEXTURE_IGNORED = {
        severity: Warning,
        level: Standard,
        clause: "12.2.5",
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
    for (id, node) in appearances(doc) {
        let Some(&texture) = node.children("texture").first() else {
            continue;
        };
        if !node.children("shaders").is_empty() || node.child("pointProperties").is_some() {
            continue;
        }
        let Some(material) = node.child("material") else {
            continue;
        };
        let m = doc.node(material);
        let Some(&(type_name, field)) = MAIN_TEXTURES.iter().find(|(t, _)| m.is_a(t)) else {
            continue;
        };
        if let Some(&main) = m.children(field).first() {
            found.push((id, texture, main, type_name, field));
        }
    }
    for (id, texture, main, type_name, field) in found {
        ctx.report(
            Diagnostic::new(
                &APPEARANCE_TEXTURE_IGNORED,
                texture.span,
                format!("Appearance.texture has no effect: {type_name}.{field} is set"),
            )
            .node(id)
            .related(main.span, format!("{type_name}.{field}"))
            .help(format!("remove one of the two; {field} is the one used")),
        );
    }
}
