//! PROTO_FIELD_UNKNOWN: a prototype statement names a field that is not there — a
//! ProtoInstance fieldValue, or either side of an `IS`/`connect`.

use super::endpoint::{did_you_mean, lookup, only_in_text, type_label, Lookup};
use crate::model::{IsConnect, NodeId, NodeKind, Scope};
use crate::report::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a name in a prototype statement that names no field.
    ///
    /// - a ProtoInstance `fieldValue` naming no field of its ProtoDeclare's or
    ///   ExternProtoDeclare's interface;
    /// - an `IS`/`connect` whose `protoField` names no field of the enclosing
    ///   ProtoDeclare's interface (or that stands outside any ProtoBody, where there is no
    ///   interface to name);
    /// - an `IS`/`connect` whose `nodeField` names no field of the node it stands in.
    ///
    /// `connect` is part of the prototype declaration, so both of its names are checked
    /// here; FIELD_UNKNOWN stays about fields given values. Instances of undeclared
    /// prototypes and nodes of unknown types are not checked.
    ///
    /// ## Why it matters
    /// A fieldValue for a field the prototype does not declare is dropped, and an IS that
    /// names a missing field connects nothing: the instance keeps its defaults.
    ///
    /// ## Example
    /// ```xml
    /// <ProtoDeclare name='Ball'>
    ///   <ProtoInterface><field name='radius' type='SFFloat' accessType='initializeOnly' value='1'/></ProtoInterface>
    ///   <ProtoBody><Shape><Sphere><IS><connect nodeField='radius' protoField='radius'/></IS></Sphere></Shape></ProtoBody>
    /// </ProtoDeclare>
    /// <ProtoInstance name='Ball'><fieldValue name='radios' value='2'/></ProtoInstance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.4.3 Prototype scoping rules and IS statements, 4.4.4.4 Prototype
    /// instantiation semantics.
    pub static PROTO_FIELD_UNKNOWN = {
        severity: Error,
        level: Standard,
        clause: "4.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        if let NodeKind::ProtoInstance {
            proto: Some(p),
            name,
        } = &node.kind
        {
            field_values(ctx, id, *p, name);
        }
        for connect in &node.connects {
            proto_field(ctx, id, node.scope, connect);
            node_field(ctx, id, connect);
        }
    }
}

/// Each fieldValue (or other field entry) of an instance against its prototype's interface.
fn field_values(ctx: &mut Ctx, id: NodeId, proto: usize, proto_name: &str) {
    let Some(decl) = ctx.doc.protos.get(proto) else {
        return;
    };
    let names: Vec<String> = decl.interface.iter().map(|f| f.name.text.clone()).collect();
    let kind = if decl.external {
        "ExternProtoDeclare"
    } else {
        "ProtoDeclare"
    };
    for entry in &ctx.doc.node(id).fields {
        let name = entry.name();
        if names.iter().any(|n| n == name) {
            continue;
        }
        let d = Diagnostic::new(
            &PROTO_FIELD_UNKNOWN,
            entry.name_span,
            format!("fieldValue `{name}`: {kind} `{proto_name}` declares no such field"),
        )
        .node(id)
        .value(name)
        .help_opt(did_you_mean(name, &names))
        .related(decl.name.span, format!("`{proto_name}` declared here"));
        ctx.report(d);
    }
}

fn proto_field(ctx: &mut Ctx, id: NodeId, scope: Scope, connect: &IsConnect) {
    let name = &connect.proto_field;
    let message = match scope {
        _ if name.text.is_empty() => "IS connect has no `protoField`".to_string(),
        Scope::Scene => format!(
            "IS connect protoField `{}` stands outside any ProtoBody: there is no prototype interface to name",
            name.text
        ),
        Scope::Proto(p) => {
            let Some(decl) = ctx.doc.protos.get(p) else {
                return;
            };
            if decl.interface.iter().any(|f| f.name.text == name.text) {
                return;
            }
            let names: Vec<String> = decl.interface.iter().map(|f| f.name.text.clone()).collect();
            let d = Diagnostic::new(
                &PROTO_FIELD_UNKNOWN,
                name.span,
                format!(
                    "IS connect protoField `{}`: ProtoDeclare `{}` declares no such field",
                    name.text, decl.name.text
                ),
            )
            .node(id)
            .value(name.text.clone())
            .help_opt(did_you_mean(&name.text, &names))
            .related(decl.name.span, format!("`{}` declared here", decl.name.text));
            ctx.report(d);
            return;
        }
    };
    ctx.report(Diagnostic::new(&PROTO_FIELD_UNKNOWN, name.span, message).node(id));
}

fn node_field(ctx: &mut Ctx, id: NodeId, connect: &IsConnect) {
    let name = &connect.node_field;
    if name.text.is_empty() {
        let d = Diagnostic::new(
            &PROTO_FIELD_UNKNOWN,
            name.span,
            "IS connect has no `nodeField`",
        );
        ctx.report(d.node(id));
        return;
    }
    let Lookup::Missing {
        candidates,
        only_in,
        ..
    } = lookup(ctx.doc, ctx.version, id, &name.text)
    else {
        return;
    };
    let d = Diagnostic::new(
        &PROTO_FIELD_UNKNOWN,
        name.span,
        format!(
            "IS connect nodeField `{}`: {} has no such field{}",
            name.text,
            type_label(ctx.doc, id),
            only_in_text(&only_in)
        ),
    )
    .node(id)
    .value(name.text.clone())
    .help_opt(did_you_mean(&name.text, &candidates));
    ctx.report(d);
}
