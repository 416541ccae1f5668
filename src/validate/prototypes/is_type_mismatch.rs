//! IS_TYPE_MISMATCH: an `IS`/`connect` joins fields of different types, or access types
//! that may not be connected.

use crate::diagnostic::Diagnostic;
use crate::model::{FieldDecl, IsConnect, NodeId, Scope};
use crate::schema::AccessType;
use crate::validate::events::endpoint::{lookup, type_label, Direction, Field, Lookup};
use crate::validate::terms::Terms;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an `IS` inside a ProtoBody whose two fields do not fit together.
    ///
    /// - their field types differ (SFColor and SFVec3f, SFFloat and MFFloat, SFTime and
    ///   SFDouble): there is no conversion;
    /// - their access types are a pair Table 4.4 of 19775-1 does not allow. A node's
    ///   inputOutput field may be connected to an interface field of any access type; a
    ///   node's initializeOnly, inputOnly or outputOnly field only to an interface field of
    ///   the same access type. So an inputOutput interface field connects only to inputOutput
    ///   node fields, and an initializeOnly interface field to initializeOnly or inputOutput
    ///   ones. A node field named `set_x` is the inputOnly side of inputOutput `x`, and
    ///   `x_changed` its outputOnly side.
    ///
    /// Names that IS_FIELD_UNKNOWN reports, and fields whose type or access type is not
    /// known (unknown node types, declarations without a valid type or accessType), are not
    /// compared.
    ///
    /// ## Why it matters
    /// Browsers refuse such an IS (X_ITE: "are incompatible as an IS mapping", "have
    /// different types"): the instance's value or events never reach the node. An
    /// inputOutput interface field joined to an initializeOnly node field promises events
    /// that the node cannot take after it is created.
    ///
    /// ## Example
    /// ```xml
    /// <ProtoDeclare name='Ball'>
    ///   <ProtoInterface><field name='radius' type='SFFloat' accessType='inputOutput' value='1'/></ProtoInterface>
    ///   <ProtoBody><Shape><Sphere><IS><connect nodeField='radius' protoField='radius'/></IS></Sphere></Shape></ProtoBody>
    /// </ProtoDeclare>
    /// ```
    /// Sphere's radius is initializeOnly: the interface field must be initializeOnly too.
    ///
    /// ## Clause
    /// 19775-1 4.4.4.3 Prototype scoping rules, Table 4.4 Rules for mapping PROTOTYPE
    /// declarations to node instances (read as X_ITE's `X3DField.isReference` implements
    /// it: the node field's access type equals the interface field's, or is inputOutput);
    /// the types of IS-connected fields are the same (as for ROUTEs, 4.4.8.2).
    /// > "It is an error if the type of the field or event being associated does not match the type declared in the prototype's interface declaration" (14772-1 4.8.3)
    ///
    /// For the access types the same paragraph goes on: "It is illegal for an eventIn to
    /// be associated with a field or an eventOut, an eventOut to be associated with a
    /// field or eventIn, or a field to be associated with an eventIn or eventOut", with
    /// Table 4.4 ("no denotes an error"); wording read in a copy of the 1997 text.
    pub static IS_TYPE_MISMATCH = {
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
        let Scope::Proto(proto) = node.scope else {
            continue;
        };
        let Some(decl) = doc.protos.get(proto) else {
            continue;
        };
        for connect in &node.connects {
            let Some(interface) = decl
                .interface
                .iter()
                .find(|f| f.name.text == connect.proto_field.text)
            else {
                continue;
            };
            let Lookup::Found(field) = lookup(doc, ctx.version, id, &connect.node_field.text)
            else {
                continue;
            };
            if let Some(d) = mismatch(ctx, id, connect, &decl.name.text, interface, &field) {
                ctx.report(d);
            }
        }
    }
}

/// The access a node field has as named: `set_x` and `x_changed` are the input and output
/// sides of inputOutput `x`.
fn named_access(field: &Field) -> Option<AccessType> {
    match field.alias {
        Some(Direction::In) => Some(AccessType::InputOnly),
        Some(Direction::Out) => Some(AccessType::OutputOnly),
        None => field.access,
    }
}

/// Table 4.4: whether a node field of access `node` may be IS-connected to an interface
/// field of access `interface`.
pub fn may_connect(node: AccessType, interface: AccessType) -> bool {
    node == AccessType::InputOutput || node == interface
}

fn mismatch(
    ctx: &Ctx,
    id: NodeId,
    connect: &IsConnect,
    proto_name: &str,
    interface: &FieldDecl,
    field: &Field,
) -> Option<Diagnostic> {
    let node_label = format!("{}.{}", type_label(ctx.doc, id), connect.node_field.text);
    let terms = Terms::of(ctx.doc.encoding);
    let proto_label = format!(
        "`{}` of {} `{proto_name}`",
        interface.name.text,
        terms.proto()
    );
    let related = |what: String| (interface.name.span, what);
    if let (Some(node_type), Some(proto_type)) = (field.ty, interface.ty) {
        if node_type != proto_type {
            let (span, what) = related(format!("declared {proto_type} here"));
            return Some(
                Diagnostic::new(
                    &IS_TYPE_MISMATCH,
                    connect.node_field.span,
                    format!(
                        "IS connects `{node_label}` ({node_type}) to {proto_label} ({proto_type}): both need the same type"
                    ),
                )
                .node(id)
                .value(node_type.as_str())
                .related(span, what),
            );
        }
    }
    let (node_access, proto_access) = (named_access(field)?, interface.access?);
    if may_connect(node_access, proto_access) {
        return None;
    }
    let input_output = terms.access(AccessType::InputOutput);
    let allowed = match proto_access {
        AccessType::InputOutput => format!("only to {input_output} node fields"),
        other => format!(
            "only to {} or {input_output} node fields",
            terms.access(other)
        ),
    };
    let (span, what) = related(format!("declared {} here", terms.access(proto_access)));
    Some(
        Diagnostic::new(
            &IS_TYPE_MISMATCH,
            connect.node_field.span,
            format!(
                "IS connects `{node_label}` ({}) to {proto_label} ({}): {} interface field connects {allowed} ({} Table 4.4)",
                terms.access(node_access),
                terms.access(proto_access),
                terms.an_access(proto_access),
                terms.standard(),
            ),
        )
        .node(id)
        .value(node_access.as_str())
        .related(span, what),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use AccessType::*;

    #[test]
    fn table_4_4() {
        let all = [InitializeOnly, InputOnly, OutputOnly, InputOutput];
        for interface in all {
            assert!(
                may_connect(InputOutput, interface),
                "inputOutput node field takes any"
            );
            for node in [InitializeOnly, InputOnly, OutputOnly] {
                assert_eq!(may_connect(node, interface), node == interface);
            }
        }
    }
}
