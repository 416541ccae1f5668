//! FIELD_NOT_IN_VERSION: a field of the node's type in another X3D version only.

use crate::model::{FieldRef, NodeKind};
use crate::report::Diagnostic;
use crate::schema::versions;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a field that the node's type has in another X3D version but not in the
    /// document's: `backMaterial` in 3.x; `alphaMode`, `alphaCutoff`, `castShadow`,
    /// `markerType`, AcousticProperties `description`/`enabled` in 4.0;
    /// PointProperties `colorMode` in 4.1. A node field holding only nodes that are not in
    /// the document's version either (Appearance.shaders with a ComposedShader in 3.0) is
    /// left to NODE_NOT_IN_VERSION, which reports those nodes at the same place. The
    /// message names the versions that have the field: the first, and every run of
    /// versions where it is not contiguous.
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
            // A node field whose nodes are all of another version (ComposedShader in
            // Appearance.shaders of a 3.0 file) is NODE_NOT_IN_VERSION's finding, at the
            // same place: the field came with the nodes.
            let nodes = entry.value.as_nodes().unwrap_or_default();
            let nodes_of_other_version = !nodes.is_empty()
                && nodes.iter().all(|child| {
                    matches!(ctx.doc.node(child.node).kind,
                        NodeKind::Known { version, .. } if version != ctx.version)
                });
            if version != ctx.version && !nodes_of_other_version {
                ctx.report(
                    Diagnostic::new(
                        &FIELD_NOT_IN_VERSION,
                        entry.name_span,
                        format!(
                            "{}.{} is not in X3D {}; it is in {}",
                            node.type_name(),
                            def.name,
                            ctx.version,
                            versions::describe(&versions::with_field(node.type_name(), def.name))
                        ),
                    )
                    .node(id),
                );
            }
        }
    }
}
