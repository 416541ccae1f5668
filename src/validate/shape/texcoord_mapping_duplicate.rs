//! TEXCOORD_MAPPING_DUPLICATE: two texture coordinate nodes of one list share a mapping.

use super::analysis::{repeated_mappings, RepeatedMapping};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a node of a MultiTextureCoordinate's `texCoord` list (a geometry's list of
    /// texture coordinates, 12.2.4.1) whose non-empty `mapping` repeats that of an earlier
    /// node. Empty mappings may repeat. A node listed twice (USE) with a non-empty mapping
    /// repeats itself. A single `texCoord` node is a list of one and cannot repeat.
    ///
    /// ## Why it matters
    /// 12.2.4.1: "All the X3DSingleTextureCoordinateNode nodes on the list of texture
    /// coordinates … must have a different mapping value. An exception is the empty
    /// mapping value, which may occur many times." A material naming the mapping cannot
    /// tell which coordinates it means (4.1 browsers take the first).
    ///
    /// ## Example
    /// ```xml
    /// <MultiTextureCoordinate>
    ///   <TextureCoordinate mapping='uv' point='0 0 1 0 1 1'/>
    ///   <TextureCoordinate mapping='uv' point='0 0 2 0 2 2'/>
    /// </MultiTextureCoordinate>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.4.1 Texture coordinates.
    /// > "All the X3DSingleTextureCoordinateNode nodes on the list of texture coordinates defined above must have a different mapping value" (19775-1 12.2.4.1)
    pub static TEXCOORD_MAPPING_DUPLICATE = {
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
    for RepeatedMapping {
        list: id,
        first,
        repeat,
        index,
        mapping,
    } in repeated_mappings(ctx.doc, "MultiTextureCoordinate", "texCoord")
    {
        ctx.report(
            Diagnostic::new(
                &TEXCOORD_MAPPING_DUPLICATE,
                repeat.span,
                format!("MultiTextureCoordinate.texCoord[{index}] repeats mapping {mapping:?}"),
            )
            .node(id)
            .index(index)
            .value(mapping)
            .related(first.span, "the first with this mapping")
            .help("give each texture coordinate node of the list its own mapping"),
        );
    }
}
