//! TEXTURE_TRANSFORM_MAPPING_UNRESOLVED: a material's texture mapping names no texture transform.

use super::analysis::{appearances, one_sided_materials, texture_fields};
use crate::diagnostic::{Diagnostic, Severity};
use crate::model::texture_mapping::{texture_transforms, Resolution};
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a non-empty `xxxTextureMapping` of an Appearance's material or backMaterial,
    /// whose `xxxTexture` is not NULL, that names the `mapping` of no node on the
    /// Appearance's list of texture transformations (12.2.4.2: `textureTransform`'s node, or
    /// the children of its MultiTextureTransform). The list depends only on the
    /// Appearance, so this is judged once per Appearance and material.
    ///
    /// An Appearance without `textureTransform` (an empty list of texture
    /// transformations) is not reported: the mapping name then only picks texture
    /// coordinates (12.2.4.1), and the texture gets no transformation, which is what the
    /// author meant and what every browser does. The 4.0 sentence ("If the
    /// xxxTextureMapping field is not empty, it must refer to a corresponding
    /// X3DSingleTextureTransformNode node within the list of texture transformations")
    /// read to the letter would also demand a transformation of that name where the
    /// Appearance has none; 4.1 settles the intent: a browser proceeds "as if
    /// xxxTextureMapping would be empty", and for an empty mapping "If the list is empty,
    /// no texture transformation is used". RULES.md likewise checks the rule "when that
    /// list is not empty". So only a non-empty list with no entry of that mapping is
    /// reported: an error in X3D 4.0 ("must refer to"), a warning in 4.1 ("should", with
    /// browsers falling back to the first transformation).
    ///
    /// ## Why it matters
    /// The texture gets another transformation than the author meant, or none.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <Material diffuseTextureMapping='uv1'>
    ///     <ImageTexture containerField='diffuseTexture' url='"a.png"'/>
    ///   </Material>
    ///   <TextureTransform mapping='uv0' scale='2 2'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.4.2 Texture coordinates transformation.
    /// > "it must refer to a corresponding X3DSingleTextureTransformNode node within the list of texture transformations" (19775-1 V4.0 12.2.4.2; 4.1 says "should", hence a warning there)
    pub static TEXTURE_TRANSFORM_MAPPING_UNRESOLVED = {
        severity: Error,
        level: Standard,
        clause: "12.2.4.2",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let severity = if ctx.version >= Version::V4_1 {
        Severity::Warning
    } else {
        Severity::Error
    };
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (appearance, node) in appearances(doc) {
        let list = texture_transforms(doc, Some(appearance));
        // An empty list means no transformation, whatever the mapping (see the docs).
        if list.opaque || list.items.is_empty() {
            continue;
        }
        let Some(transform) = node.children("textureTransform").first().copied() else {
            continue;
        };
        for material in one_sided_materials(doc, appearance) {
            let m = doc.node(material.child.node);
            for (texture, mapping) in texture_fields(material.def) {
                if m.child(texture).is_none() || m.is_connected(texture) || m.is_connected(mapping)
                {
                    continue;
                }
                let (Some(name), Some(entry)) = (
                    doc.string_of(material.child.node, mapping),
                    m.entry(mapping),
                ) else {
                    continue;
                };
                if matches!(list.resolve(doc, &name), Resolution::Unresolved { .. }) {
                    found.push((
                        material.child.node,
                        material.field,
                        mapping,
                        name,
                        entry.span,
                        transform,
                    ));
                }
            }
        }
    }
    for (material, field, mapping, name, span, transform) in found {
        ctx.report(
            Diagnostic::new(
                &TEXTURE_TRANSFORM_MAPPING_UNRESOLVED,
                span,
                format!(
                    "{field}.{mapping} {name:?} names no texture transformation of its \
                     Appearance"
                ),
            )
            .node(material)
            .severity(severity)
            .value(name)
            .help(
                "give a texture transformation that mapping, or fix the name; meanwhile \
                 browsers use the first transformation (the 4.1 fallback)",
            )
            .related(transform.span, "the Appearance's texture transformations"),
        );
    }
}
