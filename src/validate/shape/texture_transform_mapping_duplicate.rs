//! TEXTURE_TRANSFORM_MAPPING_DUPLICATE: two texture transformations share a mapping.

use super::analysis::{repeated_mappings, RepeatedMapping};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a node of a MultiTextureTransform's `textureTransform` list (an Appearance's
    /// list of texture transformations, 12.2.4.2) whose non-empty `mapping` repeats that of
    /// an earlier node. Empty mappings may repeat: they never match anything. A node listed
    /// twice (USE) with a non-empty mapping repeats itself.
    ///
    /// ## Why it matters
    /// Only the first transformation with a mapping can ever be selected by it (4.1: "the
    /// one that is first found on the list … is used"); the later one is reachable only by
    /// its position in a MultiTexture, which is rarely what was meant.
    ///
    /// ## Example
    /// ```xml
    /// <MultiTextureTransform>
    ///   <TextureTransform mapping='uv' scale='2 2'/>
    ///   <TextureTransform mapping='uv' rotation='0.5'/>
    /// </MultiTextureTransform>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.4.2 Texture coordinates transformation.
    pub static TEXTURE_TRANSFORM_MAPPING_DUPLICATE = {
        severity: Warning,
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
    for RepeatedMapping {
        list: id,
        first,
        repeat,
        index,
        mapping,
    } in repeated_mappings(ctx.doc, "MultiTextureTransform", "textureTransform")
    {
        ctx.report(
            Diagnostic::new(
                &TEXTURE_TRANSFORM_MAPPING_DUPLICATE,
                repeat.span,
                format!("MultiTextureTransform.textureTransform[{index}] repeats mapping {mapping:?}: the first with it wins"),
            )
            .node(id)
            .index(index)
            .value(mapping)
            .related(first.span, "the first with this mapping"),
        );
    }
}
