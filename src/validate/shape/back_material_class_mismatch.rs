//! BACK_MATERIAL_CLASS_MISMATCH: material and backMaterial of different node types.

use super::analysis::front_and_back;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an Appearance whose `material` and `backMaterial` are of different node
    /// types (Material with PhysicalMaterial, …). A USE counts as the type of the node it
    /// refers to, whatever element name it was written with. A TwoSidedMaterial in
    /// `material` is BACK_MATERIAL_WITH_TWO_SIDED instead; prototype instances are not
    /// judged.
    ///
    /// ## Why it matters
    /// 12.2.3 requires both to "specify the same node class" and 12.4.2 says the type given
    /// to backMaterial "must match" the one given to material: front and back may differ
    /// only in their numeric fields, not in the lighting model.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <Material/>
    ///   <PhysicalMaterial containerField='backMaterial'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials; 12.4.2 Appearance.
    /// > "The node type provided to backMaterial (if any) must match the node type provided to material" (19775-1 12.4.2)
    pub static BACK_MATERIAL_CLASS_MISMATCH = {
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
        let (Some(front_def), Some(back_def)) =
            (doc.node(material.node).def(), doc.node(back.node).def())
        else {
            continue;
        };
        if front_def.name != back_def.name && !front_def.is_a("TwoSidedMaterial") {
            found.push((appearance, back, material, front_def.name, back_def.name));
        }
    }
    for (appearance, back, material, front, back_name) in found {
        ctx.report(
            Diagnostic::new(
                &BACK_MATERIAL_CLASS_MISMATCH,
                back.span,
                format!(
                    "Appearance.backMaterial is a {back_name} but Appearance.material is a {front}"
                ),
            )
            .node(appearance)
            .related(material.span, format!("the {front}"))
            .help(format!("use a {front} for backMaterial too")),
        );
    }
}
