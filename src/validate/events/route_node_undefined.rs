//! ROUTE_NODE_UNDEFINED: a ROUTE end names no DEF in the ROUTE's name scope.

use crate::diagnostic::Diagnostic;
use crate::model::{Document, Named, Route, RouteEnd};
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a ROUTE whose `fromNode` or `toNode` is missing or names no node DEF'd in
    /// the ROUTE's own name scope: the Scene for ROUTEs in the Scene, the ProtoBody for
    /// ROUTEs inside a ProtoDeclare (a ROUTE cannot reach across that boundary). The DEF
    /// may come before or after the ROUTE. A name an IMPORT statement of the scope brings
    /// in (its `AS`, else its `importedDEF`; 19775-1 4.9.2) is a node name too: whether the
    /// inlined file exports it is IMPORT_UNRESOLVED's finding, at the deep level, where the
    /// inlined file is read.
    ///
    /// ## Why it matters
    /// Browsers drop a ROUTE whose node they cannot find, so the animation or interaction
    /// it was meant to wire up silently does nothing.
    ///
    /// ## Example
    /// ```xml
    /// <TimeSensor DEF='Clock' loop='true'/>
    /// <ROUTE fromNode='Clok' fromField='fraction_changed' toNode='Mover' toField='set_fraction'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.8.2 Routes, 4.4.7 Run-time name scope.
    /// > "Nodes referenced in a ROUTE statement shall be defined before the ROUTE statement" (14772-1 4.10.2; the order is not checked, only that the node is defined)
    pub static ROUTE_NODE_UNDEFINED = {
        severity: Error,
        level: Standard,
        clause: "4.4.8.2",
        versions: "all",
        check: Some(check),
    }
}

/// Suggestions compare a name with every DEF name in scope; a file with hundreds of bad
/// ROUTEs and thousands of DEFs gets suggestions for the first ones only.
const MAX_SUGGESTIONS: usize = 100;

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut reported = 0;
    for route in &doc.routes {
        for (attribute, end) in [("fromNode", RouteEnd::From), ("toNode", RouteEnd::To)] {
            let name = route.node_name(end);
            if route.node_id(doc, end).is_none() && !imported(ctx, route, &name.text) {
                let suggest = reported < MAX_SUGGESTIONS;
                ctx.report(diagnostic(doc, route, attribute, name, suggest));
                reported += 1;
            }
        }
    }
}

fn diagnostic(
    doc: &Document,
    route: &Route,
    attribute: &str,
    name: &Named,
    suggest: bool,
) -> Diagnostic {
    if name.text.is_empty() {
        return Diagnostic::new(
            &ROUTE_NODE_UNDEFINED,
            name.span,
            format!("ROUTE has no `{attribute}`"),
        );
    }
    let in_scope = doc
        .defs
        .keys()
        .filter(|(scope, _)| *scope == route.scope)
        .map(|(_, n)| n.as_str());
    let in_other_scope = doc
        .defs
        .keys()
        .any(|(scope, n)| *scope != route.scope && *n == name.text);
    let help = if !suggest {
        None
    } else if in_other_scope {
        Some("a node of that name is DEF'd in another name scope (Scene or ProtoBody), which a ROUTE cannot reach".to_string())
    } else {
        let mut names: Vec<&str> = in_scope.collect();
        names.sort_unstable();
        suggest::did_you_mean(&name.text, names).map(|c| format!("did you mean `{c}`?"))
    };
    Diagnostic::new(
        &ROUTE_NODE_UNDEFINED,
        name.span,
        format!(
            "ROUTE {attribute} `{}` names no DEF in its scope",
            name.text
        ),
    )
    .value(name.text.clone())
    .help_opt(help)
}

/// Whether an IMPORT statement of the ROUTE's scope brings the name in (its `AS`, else its
/// `importedDEF`). Whether the inlined file exports it is IMPORT_UNRESOLVED's finding (deep).
fn imported(ctx: &Ctx, route: &Route, name: &str) -> bool {
    !name.is_empty()
        && ctx
            .doc
            .imports
            .iter()
            .any(|i| i.scope == route.scope && i.local_name().text == name)
}
