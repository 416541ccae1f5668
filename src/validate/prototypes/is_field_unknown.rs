//! IS_FIELD_UNKNOWN: an `IS`/`connect` names a field that is not there.

use crate::diagnostic::Diagnostic;
use crate::model::{IsConnect, NodeId, Scope};
use crate::validate::events::endpoint::{did_you_mean, lookup, only_in_text, type_label, Lookup};
use crate::validate::terms::Terms;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an `IS` inside a ProtoBody that names a field that does not exist.
    ///
    /// - a `protoField` (ClassicVRML: the name after `IS`) that is no field of the enclosing
    ///   prototype's interface;
    /// - a `nodeField` (ClassicVRML: the name before `IS`) that is no field of the node it
    ///   stands in: a field of the node's type (an inputOutput field `x` may be named
    ///   `set_x` or `x_changed`, 4.4.2.2), a field the node declares itself (Script,
    ///   shaders), or, for a ProtoInstance, a field of its prototype's interface;
    /// - a `connect` missing either name.
    ///
    /// Nodes of unknown types and instances of undeclared prototypes are not checked; an IS
    /// outside any ProtoBody is IS_OUTSIDE_PROTO. Earlier versions of x3dcheck reported
    /// these as PROTO_FIELD_UNKNOWN, which now keeps only fieldValues that name no field.
    ///
    /// ## Why it matters
    /// 4.4.4.3: an IS statement refers to a field of the interface of the prototype it is
    /// in. One that names a missing field connects nothing: the instance's value never
    /// reaches the node, and browsers report the prototype as broken or drop the IS.
    ///
    /// ## Example
    /// ```xml
    /// <ProtoDeclare name='Ball'>
    ///   <ProtoInterface><field name='radius' type='SFFloat' accessType='initializeOnly' value='1'/></ProtoInterface>
    ///   <ProtoBody><Shape><Sphere><IS><connect nodeField='radius' protoField='radios'/></IS></Sphere></Shape></ProtoBody>
    /// </ProtoDeclare>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.4.3 Prototype scoping rules: "An IS statement refers to a field in the
    /// interface of the same prototype".
    /// > "It is an error for an IS statement to refer to a non-existent declaration" (14772-1 4.8.3)
    ///
    /// The IS names an interface field the prototype does not declare, or a node field the
    /// node does not have (the quoted paragraph also says "IS statements shall refer to
    /// fields or events defined in the prototype declaration"; wording read in a copy of
    /// the 1997 text).
    pub static IS_FIELD_UNKNOWN = {
        severity: Error,
        level: Standard,
        clause: "4.4.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        let Scope::Proto(proto) = node.scope else {
            continue;
        };
        for connect in &node.connects {
            proto_field(ctx, id, proto, connect);
            node_field(ctx, id, connect);
        }
    }
}

fn proto_field(ctx: &mut Ctx, id: NodeId, proto: usize, connect: &IsConnect) {
    let name = &connect.proto_field;
    if name.text.is_empty() {
        ctx.report(
            Diagnostic::new(
                &IS_FIELD_UNKNOWN,
                name.span,
                "IS connect has no `protoField`",
            )
            .node(id),
        );
        return;
    }
    let Some(decl) = ctx.doc.protos.get(proto) else {
        return;
    };
    if decl.interface.iter().any(|f| f.name.text == name.text) {
        return;
    }
    let names: Vec<String> = decl.interface.iter().map(|f| f.name.text.clone()).collect();
    let terms = Terms::of(ctx.doc.encoding);
    let message = if terms.statements() {
        format!(
            "{}: {} `{}` declares no field `{}`",
            Terms::is_statement(&connect.node_field.text, &name.text),
            terms.proto(),
            decl.name.text,
            name.text
        )
    } else {
        format!(
            "IS connect protoField `{}`: ProtoDeclare `{}` declares no such field",
            name.text, decl.name.text
        )
    };
    let d = Diagnostic::new(&IS_FIELD_UNKNOWN, name.span, message)
        .node(id)
        .value(name.text.clone())
        .help_opt(did_you_mean(&name.text, &names))
        .related(
            decl.name.span,
            format!("`{}` declared here", decl.name.text),
        );
    ctx.report(d);
}

fn node_field(ctx: &mut Ctx, id: NodeId, connect: &IsConnect) {
    let name = &connect.node_field;
    if name.text.is_empty() {
        let d = Diagnostic::new(
            &IS_FIELD_UNKNOWN,
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
    let message = if Terms::of(ctx.doc.encoding).statements() {
        format!(
            "{}: {} has no field `{}`{}",
            Terms::is_statement(&name.text, &connect.proto_field.text),
            type_label(ctx.doc, id),
            name.text,
            only_in_text(&only_in)
        )
    } else {
        format!(
            "IS connect nodeField `{}`: {} has no such field{}",
            name.text,
            type_label(ctx.doc, id),
            only_in_text(&only_in)
        )
    };
    let d = Diagnostic::new(&IS_FIELD_UNKNOWN, name.span, message)
        .node(id)
        .value(name.text.clone())
        .help_opt(did_you_mean(&name.text, &candidates));
    ctx.report(d);
}
