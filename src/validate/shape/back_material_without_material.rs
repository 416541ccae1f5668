//! BACK_MATERIAL_WITHOUT_MATERIAL: backMaterial set while material is NULL.

use super::analysis::{appearances, back_material};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an Appearance whose `backMaterial` holds a node while its `material` is NULL.
    ///
    /// ## Why it matters
    /// 12.2.3: "The backMaterial field can have a value different than NULL only when the
    /// material field also has a value different than NULL." With no material the shape is
    /// unlit white on both sides, and what browsers make of the back material is undefined.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <Material containerField='backMaterial' diffuseColor='1 0 0'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials; 12.4.2 Appearance.
    /// > "It is only allowed to define a backMaterial if the material is also defined (not NULL)" (19775-1 12.4.2)
    pub static BACK_MATERIAL_WITHOUT_MATERIAL = {
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
    let mut found = Vec::new();
    for (appearance, node) in appearances(ctx.doc) {
        let Some(back) = back_material(ctx.doc, node) else {
            continue;
        };
        if node.child("material").is_none() {
            found.push((appearance, back));
        }
    }
    for (appearance, back) in found {
        ctx.report(
            Diagnostic::new(
                &BACK_MATERIAL_WITHOUT_MATERIAL,
                back.span,
                "Appearance.backMaterial is set but Appearance.material is NULL",
            )
            .node(appearance)
            .help("set a material of the same type, or move this node to `material`"),
        );
    }
}
