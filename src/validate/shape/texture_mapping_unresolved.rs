//! TEXTURE_MAPPING_UNRESOLVED: a material's texture mapping names no texture coordinate.

use super::analysis::{one_sided_materials, shape_pairs, texture_fields};
use crate::diagnostic::{Diagnostic, Severity};
use crate::model::texture_mapping::{texture_coordinates, Resolution};
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports, per Shape, a non-empty `xxxTextureMapping` of the Appearance's material or
    /// backMaterial, whose `xxxTexture` is not NULL, that names the `mapping` of no node on
    /// the geometry's list of texture coordinates (12.2.4.1; see
    /// [`crate::model::texture_mapping`]): the geometry's `texCoord` node, or the children
    /// of its MultiTextureCoordinate; geometries without a `texCoord` field (Box, Sphere…)
    /// have an empty list, where every non-empty mapping fails. Names match exactly; an
    /// empty mapping never fails (it takes the first entry). One Appearance may serve
    /// several geometries: each Appearance × geometry pair is reported at the first Shape
    /// forming it. Lists holding prototype instances are not judged.
    ///
    /// An error in X3D 4.0 ("it must refer to a corresponding X3DSingleTextureCoordinateNode
    /// node"), a warning in 4.1 ("should", with browsers falling back to the first entry).
    ///
    /// ## Why it matters
    /// The texture is then mapped with other coordinates than the author meant (4.1), or the
    /// scene is invalid (4.0).
    ///
    /// ## Example
    /// ```xml
    /// <Shape>
    ///   <Appearance><Material diffuseTextureMapping='uv1'>
    ///     <ImageTexture containerField='diffuseTexture' url='"a.png"'/>
    ///   </Material></Appearance>
    ///   <IndexedFaceSet coordIndex='0 1 2'>
    ///     <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    ///     <TextureCoordinate mapping='uv0' point='0 0 1 0 0 1'/>
    ///   </IndexedFaceSet>
    /// </Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.4.1 Texture coordinates.
    /// > "it must refer to a corresponding X3DSingleTextureCoordinateNode node" (19775-1 V4.0 12.2.4.1; 4.1 says "should", hence a warning there)
    pub static TEXTURE_MAPPING_UNRESOLVED = {
        severity: Error,
        level: Standard,
        clause: "12.2.4.1",
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
    for pair in shape_pairs(doc) {
        let Some(appearance) = pair.appearance else {
            continue;
        };
        let list = texture_coordinates(doc, pair.geometry);
        if list.opaque {
            continue;
        }
        let geometry_type = doc.node(pair.geometry).type_name().to_string();
        for material in one_sided_materials(doc, appearance) {
            let node = doc.node(material.child.node);
            for (texture, mapping) in texture_fields(material.def) {
                if node.child(texture).is_none()
                    || node.is_connected(texture)
                    || node.is_connected(mapping)
                {
                    continue;
                }
                let Some(name) = doc.string_of(material.child.node, mapping) else {
                    continue;
                };
                if !matches!(list.resolve(doc, &name), Resolution::Unresolved { .. }) {
                    continue;
                }
                let known: Vec<String> = list
                    .items
                    .iter()
                    .filter_map(|c| crate::model::texture_mapping::mapping_of(doc, c.node))
                    .map(|m| format!("{m:?}"))
                    .collect();
                let listed = if known.is_empty() {
                    format!("its {geometry_type} has no texture coordinates")
                } else {
                    format!(
                        "the mappings of its {geometry_type}'s texture coordinates are {}",
                        known.join(", ")
                    )
                };
                let mut diagnostic = Diagnostic::new(
                    &TEXTURE_MAPPING_UNRESOLVED,
                    pair.geometry_ref.span,
                    format!(
                        "{}.{mapping} {name:?} names no texture coordinate of this Shape: {listed}",
                        material.field
                    ),
                )
                .node(pair.shape)
                .severity(severity)
                .value(name.clone());
                if let Some(entry) = node.entry(mapping) {
                    diagnostic =
                        diagnostic.related(entry.span, format!("{}.{mapping}", material.def.name));
                }
                ctx.report(diagnostic.help(
                    "give a texture coordinate node of this geometry that mapping, or fix the name; \
                 meanwhile browsers use the first texture coordinates (the 4.1 fallback) or the defaults",
                ));
            }
        }
    }
}
