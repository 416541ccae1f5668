//! FIELD_NOT_IN_VERSION: a field of the node's type in another X3D version only.

use crate::model::{FieldRef, NodeKind};
use crate::report::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a field that the node's type has in another X3D version but not in the
    /// document's: `backMaterial` in 3.x; `alphaMode`, `alphaCutoff`, `castShadow`,
    /// `markerType`, AcousticProperties `description`/`enabled` in 4.0;
    /// PointProperties `colorMode` in 4.1.
    ///
    /// ## Why it matters
    /// A browser of the declared version ignores the field, so the scene looks different
    /// from what its author saw in a newer browser.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0' profile='Interchange'>
    ///   <Scene><Shape><Appearance alphaMode='BLEND'/><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Clause
    /// The node's interface table in the version that defines the field; 7.2.5.2.
    pub static FIELD_NOT_IN_VERSION = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        // A node of another version is NODE_NOT_IN_VERSION; its fields go with it.
        if matches!(node.kind, NodeKind::Known { version, .. } if version != ctx.version) {
            continue;
        }
        for entry in &node.fields {
            let FieldRef::Schema { def, version } = entry.field else {
                continue;
            };
            if version != ctx.version {
                ctx.report(
                    Diagnostic::new(
                        &FIELD_NOT_IN_VERSION,
                        entry.name_span,
                        format!(
                            "{}.{} is not in X3D {}; X3D {version} has it",
                            node.type_name(),
                            def.name,
                            ctx.version
                        ),
                    )
                    .node(id),
                );
            }
        }
    }
}
