//! PROTO_FIELD_UNKNOWN: a ProtoInstance fieldValue names no field of its prototype.

use super::endpoint::did_you_mean;
use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, NodeKind};
use crate::validate::terms::Terms;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ProtoInstance `fieldValue` (ClassicVRML and VRML97: a field given in a
    /// prototype instance's body) naming no field of its ProtoDeclare's or
    /// ExternProtoDeclare's interface. Instances of undeclared prototypes are not checked.
    ///
    /// The names an `IS`/`connect` uses were reported here by earlier versions of
    /// x3dcheck; they are now IS_FIELD_UNKNOWN (a name that is no field) and
    /// IS_OUTSIDE_PROTO (an IS outside any ProtoBody).
    ///
    /// ## Why it matters
    /// A fieldValue for a field the prototype does not declare is dropped: the instance
    /// keeps its default.
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
    /// 19775-1 4.4.4.4 Prototype instantiation semantics (an instance sets the fields its
    /// prototype declares).
    ///
    /// A warning (issue 32): 14772-1 4.8.3 makes an IS to an undeclared field an error
    /// (IS_FIELD_UNKNOWN), but no sentence was found that says the same of a field set
    /// on an instance, and the X3D XML Schema types a `fieldValue` name as any string.
    pub static PROTO_FIELD_UNKNOWN = {
        severity: Warning,
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
    }
}

/// Each fieldValue (or other field entry) of an instance against its prototype's interface.
fn field_values(ctx: &mut Ctx, id: NodeId, proto: usize, proto_name: &str) {
    let Some(decl) = ctx.doc.protos.get(proto) else {
        return;
    };
    let names: Vec<String> = decl.interface.iter().map(|f| f.name.text.clone()).collect();
    let terms = Terms::of(ctx.doc.encoding);
    let kind = if decl.external {
        terms.extern_proto()
    } else {
        terms.proto()
    };
    let setting = terms.field_value();
    for entry in &ctx.doc.node(id).fields {
        let name = entry.name();
        if names.iter().any(|n| n == name) {
            continue;
        }
        let d = Diagnostic::new(
            &PROTO_FIELD_UNKNOWN,
            entry.name_span,
            format!("{setting} `{name}`: {kind} `{proto_name}` declares no such field"),
        )
        .node(id)
        .value(name)
        .help_opt(did_you_mean(name, &names))
        .related(decl.name.span, format!("`{proto_name}` declared here"));
        ctx.report(d);
    }
}
