//! NODE_NOT_IN_VERSION: a node type of another X3D version.

use crate::model::NodeKind;
use crate::report::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a node type that does not exist in the document's version but does in
    /// another, such as PhysicalMaterial or UnlitMaterial in a 3.3 scene; and a `unit`
    /// statement in a version before 3.3, which introduced it (7.2.5.5).
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
    units_before_3_3(ctx);
    for (id, node) in ctx.doc.iter() {
        if let NodeKind::Known { def, version } = node.kind {
            if version != ctx.version {
                ctx.report(
                    Diagnostic::new(
                        &NODE_NOT_IN_VERSION,
                        node.name_span,
                        format!(
                            "{} is not in X3D {}; X3D {version} has it",
                            def.name, ctx.version
                        ),
                    )
                    .node(id),
                );
            }
        }
    }
}

/// The `unit` statement came with X3D 3.3 (19775-1 7.2.5.5: "UNIT statements may only be
/// contained in X3D worlds created for X3D version 3.3 or later"; a browser shall fail on
/// one in an earlier version). A statement is judged like a node here: NODE_UNKNOWN
/// covers unknown statements too.
fn units_before_3_3(ctx: &mut Ctx) {
    if ctx.version >= Version::V3_3 {
        return;
    }
    for unit in &ctx.doc.head.units {
        ctx.report(
            Diagnostic::new(
                &NODE_NOT_IN_VERSION,
                unit.span,
                format!(
                    "the unit statement is not in X3D {}; X3D 3.3 introduced it",
                    ctx.version
                ),
            )
            .help("declare version='3.3' or later, or remove the unit statement"),
        );
    }
}
