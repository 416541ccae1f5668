//! FIELD_UNKNOWN: a field no version of the node's type has.

use crate::model::{FieldRef, NodeKind, Origin};
use crate::report::Diagnostic;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a field (XML attribute, JSON `@` member) that the node's type does not
    /// have in any X3D version, and suggests the nearest field name (`diffusecolor` →
    /// `diffuseColor`). Fields of unknown node types are not reported again, and node
    /// children placed by `containerField` are CONTAINER_FIELD_INVALID's business.
    ///
    /// ## Why it matters
    /// Browsers ignore unknown fields, so a misspelt field silently keeps its default.
    ///
    /// ## Example
    /// ```xml
    /// <Material diffusecolor='1 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.2 (field semantics) and the node's interface table.
    pub static FIELD_UNKNOWN = {
        severity: Error,
        level: Fast,
        clause: "4.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        let NodeKind::Known { def, .. } = node.kind else {
            continue;
        };
        for entry in &node.fields {
            let FieldRef::Unknown { name } = &entry.field else {
                continue;
            };
            if entry.origin == Origin::Children {
                continue;
            }
            if ctx.is_full() {
                return;
            }
            let names = def.fields.iter().map(|f| f.name);
            ctx.report(
                Diagnostic::new(
                    &FIELD_UNKNOWN,
                    entry.name_span,
                    format!("{} has no field `{name}`", def.name),
                )
                .node(id)
                .value(name.clone())
                .help_opt(suggest::help(name, names)),
            );
        }
    }
}
