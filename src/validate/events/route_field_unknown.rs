//! ROUTE_FIELD_UNKNOWN: a ROUTE end names no field of its node, or a field that cannot
//! send (fromField) or receive (toField) events.

use super::endpoint::{
    did_you_mean, not_input_output_text, only_in_text, route_end, Direction, End, Lookup,
};
use crate::diagnostic::Diagnostic;
use crate::model::{Named, RouteEnd};
use crate::validate::terms::Terms;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ROUTE whose `fromField` or `toField` is missing, is no field of the node
    /// it names, or has the wrong access type: events are read from an outputOnly or
    /// inputOutput field and written to an inputOnly or inputOutput field; initializeOnly
    /// fields take no events. A node's fields are those of its type in the document's
    /// version, the `field` declarations of a Script or shader node, or a ProtoInstance's
    /// ProtoDeclare/ExternProtoDeclare interface. An inputOutput field `x` may be named
    /// `set_x` as a toField and `x_changed` as a fromField, and not the other way round.
    /// Nodes of unknown types and instances of undeclared prototypes are not checked.
    ///
    /// ## Why it matters
    /// Browsers reject or ignore a ROUTE to a field that does not exist or cannot carry
    /// the event that way, so the scene does not move or react as intended.
    ///
    /// ## Example
    /// ```xml
    /// <TimeSensor DEF='Clock'/>
    /// <PositionInterpolator DEF='Path' key='0 1' keyValue='0 0 0 1 0 0'/>
    /// <ROUTE fromNode='Clock' fromField='set_fraction' toNode='Path' toField='set_fraction'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.8.2 Routes, 4.4.2.2 Field semantics (access types, `set_`/`_changed`).
    /// > "Routes may be established only from eventOuts to eventIns" (14772-1 4.10.2)
    ///
    /// A route whose field the node does not have (with or without the optional `set_` or
    /// `_changed`) runs from or to no event at all (wording read in a copy of the 1997
    /// text).
    pub static ROUTE_FIELD_UNKNOWN = {
        severity: Error,
        level: Standard,
        clause: "4.4.8.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for route in &doc.routes {
        let ends = [
            (RouteEnd::From, &route.from_field, Direction::Out),
            (RouteEnd::To, &route.to_field, Direction::In),
        ];
        for (which, field, direction) in ends {
            // An undefined node is ROUTE_NODE_UNDEFINED's finding.
            if let Some(end) = route_end(ctx, route, which) {
                found.extend(problem(&end, field, direction, Terms::of(doc.encoding)));
            }
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

fn problem(end: &End, field: &Named, direction: Direction, terms: Terms) -> Option<Diagnostic> {
    let attribute = terms.route_end(direction == Direction::Out);
    let diagnostic = |message: String| {
        let diagnostic =
            Diagnostic::new(&ROUTE_FIELD_UNKNOWN, field.span, message).value(field.text.clone());
        match end.local() {
            Some(node) => diagnostic.node(node),
            None => diagnostic,
        }
    };
    if field.text.is_empty() {
        return Some(diagnostic(format!("ROUTE has no `{attribute}`")));
    }
    let label = end.label();
    match end.lookup(&field.text) {
        Lookup::Unchecked => None,
        Lookup::Missing {
            candidates,
            only_in,
            not_input_output,
        } => Some(
            diagnostic(format!(
                "ROUTE {attribute} `{}`: {label} has no such field{}{}",
                field.text,
                only_in_text(&only_in),
                not_input_output_text(&not_input_output)
            ))
            .help_opt(did_you_mean(&field.text, &candidates)),
        ),
        Lookup::Found(found) if !found.allows(direction) => {
            let (verb, wanted) = match direction {
                Direction::Out => ("sends", "outputOnly or inputOutput"),
                Direction::In => ("receives", "inputOnly or inputOutput"),
            };
            let access = found.access_text();
            Some(
                diagnostic(format!(
                    "ROUTE {attribute} `{}` of {label} is {access}: a ROUTE {verb} events through an {wanted} field",
                    field.text
                ))
                .help_opt(alias_help(&found, direction)),
            )
        }
        Lookup::Found(_) => None,
    }
}

/// For an inputOutput field named by the other direction's alias, the right name.
fn alias_help(found: &super::endpoint::Field, direction: Direction) -> Option<String> {
    found.alias?;
    let name = &found.name;
    Some(match direction {
        Direction::Out => format!("use `{name}` or `{name}_changed`"),
        Direction::In => format!("use `{name}` or `set_{name}`"),
    })
}
