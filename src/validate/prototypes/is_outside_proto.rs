//! IS_OUTSIDE_PROTO: an `IS`/`connect` outside any ProtoBody.

use crate::diagnostic::Diagnostic;
use crate::model::Scope;
use crate::validate::terms::Terms;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an `IS` (XML and JSON: its `connect` statements; ClassicVRML and VRML97:
    /// `field IS protoField`) on a node that is not inside a ProtoBody (PROTO body), where
    /// there is no prototype interface for it to name. An IS in the initial value of a
    /// prototype's interface field is outside the body too.
    ///
    /// Earlier versions of x3dcheck reported this as PROTO_FIELD_UNKNOWN, which now keeps
    /// only fieldValues that name no field.
    ///
    /// ## Why it matters
    /// 4.4.4.3: an IS statement refers to a field of the interface of the prototype it is
    /// in. Outside a prototype it connects nothing; XML Schema validation rejects it, and
    /// browsers drop it, so the field keeps the value written beside it.
    ///
    /// ## Example
    /// ```xml
    /// <Scene>
    ///   <Material><IS><connect nodeField='diffuseColor' protoField='color'/></IS></Material>
    /// </Scene>
    /// ```
    ///
    /// ## Use instead
    /// Move the node into the ProtoBody of the prototype whose field it should follow, or
    /// drop the IS and set the field's value.
    ///
    /// ## Clause
    /// 19775-1 4.4.4.3 Prototype scoping rules (IS statements refer to the interface of the
    /// prototype they are in).
    /// > "IS statements shall refer to fields or events defined in the prototype declaration" (14772-1 4.8.3)
    ///
    /// Outside any prototype body there is no prototype declaration for the IS to refer
    /// to ("IS statements may appear inside the prototype definition wherever fields may
    /// appear", the same paragraph; wording read in a copy of the 1997 text).
    pub static IS_OUTSIDE_PROTO = {
        severity: Error,
        level: Standard,
        clause: "4.4.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        if node.scope != Scope::Scene {
            continue;
        }
        for connect in &node.connects {
            let (node_field, proto_field) = (&connect.node_field.text, &connect.proto_field.text);
            let message = if Terms::of(doc.encoding).statements() {
                format!(
                    "{} outside any PROTO body: there is no prototype interface to name",
                    Terms::is_statement(node_field, proto_field)
                )
            } else {
                format!(
                    "IS connects `{node_field}` to `{proto_field}` outside any ProtoBody: there is no prototype interface to name"
                )
            };
            ctx.report(Diagnostic::new(&IS_OUTSIDE_PROTO, connect.span, message).node(id));
        }
    }
}
