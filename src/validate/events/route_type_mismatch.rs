//! ROUTE_TYPE_MISMATCH: a ROUTE connects fields of different types.

use super::endpoint::{route_ends, End, Lookup};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ROUTE whose fromField and toField have different field types (SFFloat to
    /// SFVec3f, SFNode to MFNode, SFTime to SFDouble). Ends that ROUTE_NODE_UNDEFINED or
    /// ROUTE_FIELD_UNKNOWN report, and fields whose type is not known (unknown node types,
    /// declarations with a bad type), are not compared. There is no implicit conversion:
    /// the types must be the same.
    ///
    /// ## Why it matters
    /// Browsers refuse a ROUTE between fields of different types, so nothing is passed
    /// on. An interpolator or a Script converts values where that is what is wanted.
    ///
    /// ## Example
    /// ```xml
    /// <TimeSensor DEF='Clock'/>
    /// <Transform DEF='Box'/>
    /// <ROUTE fromNode='Clock' fromField='fraction_changed' toNode='Box' toField='set_translation'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.8.2 Routes: the destination field's type shall be the same as the
    /// source field's.
    /// > "The types of the eventIn and the eventOut shall match exactly" (14772-1 4.10.2; 19775-1 4.4.8.2 keeps the rule for input and output fields)
    pub static ROUTE_TYPE_MISMATCH = {
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
        let Some((from, to)) = route_ends(ctx, route) else {
            continue;
        };
        let field_type = |end: &End, name: &str| match end.lookup(name) {
            Lookup::Found(field) => field.ty,
            Lookup::Missing { .. } | Lookup::Unchecked => None,
        };
        let (Some(from_type), Some(to_type)) = (
            field_type(&from, &route.from_field.text),
            field_type(&to, &route.to_field.text),
        ) else {
            continue;
        };
        if from_type == to_type {
            continue;
        }
        let message = format!(
            "ROUTE connects `{}.{}` ({}, {from_type}) to `{}.{}` ({}, {to_type}): both ends need the same type",
            route.from_node.text,
            route.from_field.text,
            from.label(),
            route.to_node.text,
            route.to_field.text,
            to.label(),
        );
        let diagnostic = Diagnostic::new(&ROUTE_TYPE_MISMATCH, route.to_field.span, message)
            .value(to_type.as_str())
            .related(
                route.from_field.span,
                format!("{from_type} event from here"),
            );
        found.push(match to.local() {
            Some(node) => diagnostic.node(node),
            None => diagnostic,
        });
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
