//! TEXTURE_TRANSFORM_MAPPING_UNRESOLVED: a material's texture mapping names no texture transform.

use super::analysis::{appearances, one_sided_materials, texture_fields};
use crate::model::texture_mapping::{texture_transforms, Resolution};
use crate::report::Diagnostic;
use crate::schema::Version;
use crate::validate::{Ctx, Severity};

crate::declare_rule! {
    /// ## What it does
    /// Reports a non-empty `xxxTextureMapping` of an Appearance's material or backMaterial,
    /// whose `xxxTexture` is not NULL, that names the `mapping` of no node on the
    /// Appearance's list of texture transformations (12.2.4.2: `textureTransform`'s node, or
    /// the children of its MultiTextureTransform). The list depends only on the
    /// Appearance, so this is judged once per Appearance and material.
    ///
    /// An Appearance without `textureTransform` (an empty list) is no exception. The 4.0
    /// text reads: "If the xxxTextureMapping field is not empty, it must refer to a
    /// corresponding X3DSingleTextureTransformNode node within the list of texture
    /// transformations"; it names no case in which a non-empty mapping may refer to
    /// nothing, and "If the list is empty, no texture transformation is used" is said of
    /// an *empty* xxxTextureMapping only. 4.1 keeps the sentence with "should" and adds
    /// that a browser then proceeds "as if xxxTextureMapping would be empty", which for an
    /// empty list means no transformation. So a mapping name used only to pick texture
    /// coordinates (12.2.4.1) still needs a texture transformation of that name: without
    /// one it is reported, as an error in 4.0 and a warning in 4.1.
    ///
    /// An error in X3D 4.0 ("must refer to"), a warning in 4.1 ("should", with browsers
    /// falling back to the first transformation).
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
        if list.opaque {
            continue;
        }
        let transform = node.children("textureTransform").first().copied();
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
        let (what, help) = match transform {
            Some(_) => (
                "names no texture transformation of its Appearance",
                "give a texture transformation that mapping, or fix the name; \
                 meanwhile browsers use the first transformation (the 4.1 fallback)",
            ),
            None => (
                "names a texture transformation, but its Appearance has none",
                "add a TextureTransform with that mapping to the Appearance, or empty the \
                 mapping if no texture coordinates are chosen by it",
            ),
        };
        let mut diagnostic = Diagnostic::new(
            &TEXTURE_TRANSFORM_MAPPING_UNRESOLVED,
            span,
            format!("{field}.{mapping} {name:?} {what}"),
        )
        .node(material)
        .severity(severity)
        .value(name)
        .help(help);
        if let Some(transform) = transform {
            diagnostic =
                diagnostic.related(transform.span, "the Appearance's texture transformations");
        }
        ctx.report(diagnostic);
    }
}
