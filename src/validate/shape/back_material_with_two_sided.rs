//! BACK_MATERIAL_WITH_TWO_SIDED: backMaterial set while material is a TwoSidedMaterial.

use super::analysis::front_and_back;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an Appearance whose `material` is a TwoSidedMaterial (deprecated) while its
    /// `backMaterial` also holds a node. A USE counts as the type of the node it refers to.
    ///
    /// ## Why it matters
    /// 12.2.3: "It is not allowed to provide a backMaterial when the material specifies a
    /// TwoSidedMaterial." The two mechanisms both define the back faces; which one a
    /// browser follows is undefined.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <TwoSidedMaterial separateBackColor='true'/>
    ///   <Material containerField='backMaterial'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials.
    /// > "It is not allowed to provide a backMaterial when the material specifies a TwoSidedMaterial" (19775-1 12.2.3)
    pub static BACK_MATERIAL_WITH_TWO_SIDED = {
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
    let mut found = Vec::new();
    for (appearance, material, back) in front_and_back(doc) {
        if doc.node(material.node).is_a("TwoSidedMaterial") {
            found.push((appearance, back, material));
        }
    }
    for (appearance, back, material) in found {
        ctx.report(
            Diagnostic::new(
                &BACK_MATERIAL_WITH_TWO_SIDED,
                back.span,
                "Appearance.backMaterial is set while Appearance.material is a TwoSidedMaterial",
            )
            .node(appearance)
            .related(material.span, "the TwoSidedMaterial")
            .help(
                "replace the TwoSidedMaterial by a Material and keep the backMaterial (12.4.9), \
                 or remove the backMaterial",
            ),
        );
    }
}
