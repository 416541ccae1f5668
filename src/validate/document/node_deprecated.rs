//! NODE_DEPRECATED: TwoSidedMaterial in X3D 4.

use crate::model::Value;
use crate::report::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports TwoSidedMaterial in an X3D 4.x scene, with the upgrade path of 12.4.9 for
    /// this node: with `separateBackColor` FALSE, a Material with the same front values
    /// does the same; with TRUE, put a Material in Appearance.material and another in
    /// Appearance.backMaterial.
    ///
    /// ## Why it matters
    /// TwoSidedMaterial is deprecated in X3D 4 and cannot be used with the physical or
    /// unlit material models or with Appearance.backMaterial.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0' profile='Immersive'>
    ///   <Scene><Shape><Appearance><TwoSidedMaterial/></Appearance><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 (4.x) 12.4.9 TwoSidedMaterial.
    pub static NODE_DEPRECATED = {
        severity: Warning,
        level: Fast,
        clause: "12.4.9",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    for id in ctx.doc.nodes_of_type("TwoSidedMaterial") {
        let node = ctx.doc.node(id);
        let separate = matches!(node.value("separateBackColor"), Some(Value::Bools(b)) if b.first() == Some(&true));
        let help = if separate {
            "separateBackColor is TRUE: use a Material in Appearance.material and a second Material in Appearance.backMaterial"
        } else {
            "separateBackColor is FALSE: a Material with the same front values does the same"
        };
        ctx.report(
            Diagnostic::new(
                &NODE_DEPRECATED,
                node.name_span,
                "TwoSidedMaterial is deprecated in X3D 4",
            )
            .node(id)
            .help(help),
        );
    }
}
