//! NODE_UNKNOWN: an element or object names no X3D node or statement.

use crate::diagnostic::{Applicability, Diagnostic, Fix};
use crate::model::NodeKind;
use crate::schema::{self, Version};
use crate::validate::{edits, suggest, Ctx};

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
    /// ## Fix safety
    /// Where the one suggestion is a case slip (`material` → `Material`), renaming the
    /// element or key (and the XML end tag) is a safe fix: no X3D node's name differs from
    /// another only in case, so the node meant is not in doubt, and a browser skips the
    /// misspelt one anyway. A suggestion at an edit distance is only help.
    ///
    /// ## Clause
    /// 19775-1 4.4.1 (node types); 19776-1 4.3 (element names).
    /// A node type of no version is in no component, so the document cannot declare it (the
    /// sentence added to 7.2.5.4 by 19775-1 V3.1, read on the web3d.org V3.1 `core.html`
    /// page).
    /// > "A user shall declare all components and levels for the nodes and/or functionality being used either explicitly through the use of the COMPONENT statement or implicitly through the PROFILE statement" (19775-1 V3.1 7.2.5.4)
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
            let suggestion = suggest::did_you_mean(name, names.clone());
            let mut diagnostic = Diagnostic::new(
                &NODE_UNKNOWN,
                node.name_span,
                format!("`{name}` is not an X3D node"),
            )
            .node(id)
            .value(name.clone())
            .help_opt(suggestion.map(|c| format!("did you mean `{c}`?")));
            if let Some(fix) = suggestion.and_then(|to| case_fix(ctx, id, name, to)) {
                diagnostic = diagnostic.fix(fix);
            }
            ctx.report(diagnostic);
        }
    }
}

/// Renames a node whose name is `to` but for case.
fn case_fix(ctx: &Ctx, id: crate::model::NodeId, from: &str, to: &str) -> Option<Fix> {
    if !to.eq_ignore_ascii_case(from) || !edits::written(ctx.doc, id) {
        return None;
    }
    let edits = edits::rename_node(ctx.source, ctx.doc.encoding, ctx.doc.node(id), from, to)?;
    Some(edits::fix(
        format!("Rename to `{to}`"),
        Applicability::Safe,
        edits,
    ))
}
