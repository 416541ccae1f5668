//! NODE_NOT_IN_VERSION: a node type of another X3D version.

use crate::model::NodeKind;
use crate::report::Diagnostic;
use crate::schema::versions;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a node type that does not exist in the document's version but does in
    /// another, such as PhysicalMaterial or UnlitMaterial in a 3.3 scene.
    ///
    /// ## Why it matters
    /// A browser of the declared version does not know the node and skips it.
    /// Raising the document's version (and checking what else that changes) fixes it.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='3.3' profile='Immersive'>
    ///   <Scene><Shape><Appearance><PhysicalMaterial/></Appearance><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 the node's clause in the version that defines it; 7.2.5.2 (version).
    pub static NODE_NOT_IN_VERSION = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        if let NodeKind::Known { def, version } = node.kind {
            if version != ctx.version {
                ctx.report(
                    Diagnostic::new(
                        &NODE_NOT_IN_VERSION,
                        node.name_span,
                        format!(
                            "{} is not in X3D {}; it is in {}",
                            def.name,
                            ctx.version,
                            versions::describe(&versions::with_node(def.name))
                        ),
                    )
                    .node(id),
                );
            }
        }
    }
}
