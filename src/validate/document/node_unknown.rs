//! NODE_UNKNOWN: an element or object names no X3D node or statement.

use crate::model::NodeKind;
use crate::report::Diagnostic;
use crate::schema::{self, Version};
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports an element (XML) or object key (JSON) that names no node type of any X3D
    /// version, and suggests the nearest name (case slips such as `material` first).
    ///
    /// ## Why it matters
    /// Browsers skip unknown nodes, and everything inside them, silently.
    ///
    /// ## Example
    /// ```xml
    /// <Shape><appearance><material/></appearance><Box/></Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.1 (node types); 19776-1 4.3 (element names).
    pub static NODE_UNKNOWN = {
        severity: Error,
        level: Fast,
        clause: "4.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let names = schema::schema(Version::LATEST).nodes.iter().map(|n| n.name);
    for (id, node) in ctx.doc.iter() {
        if let NodeKind::Unknown { name } = &node.kind {
            if ctx.is_full() {
                return;
            }
            ctx.report(
                Diagnostic::new(
                    &NODE_UNKNOWN,
                    node.name_span,
                    format!("`{name}` is not an X3D node"),
                )
                .node(id)
                .value(name.clone())
                .help_opt(suggest::help(name, names.clone())),
            );
        }
    }
}
