//! FIELD_NOT_INITIALIZABLE: a value given for an inputOnly or outputOnly field.

use crate::diagnostic::Diagnostic;
use crate::model::{FieldRef, NodeKind, Origin};
use crate::schema::AccessType;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a value (or child nodes) given in the document for a field whose access
    /// type is `inputOnly` or `outputOnly`, such as `set_index` or `duration_changed`;
    /// also a ProtoInstance `fieldValue` for a prototype field that its ProtoDeclare or
    /// ExternProtoDeclare declares `inputOnly` or `outputOnly` (`set_startpoint`); and an
    /// initial value (a `value`, or child nodes) in a `field` declaration of a Script, a
    /// shader node or a ProtoDeclare's interface whose `accessType` is `inputOnly` or
    /// `outputOnly` (the ClassicVRML grammar gives `eventIn`/`eventOut` no value).
    ///
    /// ## Why it matters
    /// Such fields are events: they only exist at run time, through ROUTEs and scripts.
    /// A value in the file is ignored by browsers.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet set_coordIndex='0 1 2 -1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.2.2 Field semantics (access types). A declaration is the same field
    /// with the same access type: the value it carries is one the field cannot take
    /// (19775-1 3 Definitions: an inputOnly field "may only receive events", an
    /// outputOnly field "may only send events"). 29.4.1 Script and the shader nodes of
    /// clause 31 declare their fields with these access types.
    /// The XML encoding gives such fields no place in a file; the ClassicVRML grammar gives
    /// an `eventIn`/`eventOut` declaration no value.
    /// > "Fields with accessType inputOnly or outputOnly are transient and are not explicitly specified in an .x3d file." (19776-1 V3.0 6.1)
    pub static FIELD_NOT_INITIALIZABLE = {
        severity: Error,
        level: Fast,
        clause: "4.4.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    report_declarations(ctx);
    for (id, node) in ctx.doc.iter() {
        for entry in &node.fields {
            if let (
                NodeKind::ProtoInstance {
                    name,
                    proto: Some(proto),
                },
                Origin::FieldValue,
            ) = (&node.kind, entry.origin)
            {
                let declared = ctx.doc.protos[*proto]
                    .interface
                    .iter()
                    .find(|d| d.name.text == entry.name())
                    .and_then(|d| d.access);
                if let Some(access @ (AccessType::InputOnly | AccessType::OutputOnly)) = declared {
                    ctx.report(
                        Diagnostic::new(
                            &FIELD_NOT_INITIALIZABLE,
                            entry.name_span,
                            format!(
                                "prototype {name} declares field {} {}: a fieldValue cannot give it a value",
                                entry.name(),
                                access.as_str()
                            ),
                        )
                        .node(id),
                    );
                }
                continue;
            }
            let FieldRef::Schema { def, .. } = entry.field else {
                continue;
            };
            if !def.access.is_initializable() {
                ctx.report(
                    Diagnostic::new(
                        &FIELD_NOT_INITIALIZABLE,
                        entry.name_span,
                        format!(
                            "{}.{} is {}: a document cannot give it a value",
                            node.type_name(),
                            def.name,
                            def.access.as_str()
                        ),
                    )
                    .node(id),
                );
            }
        }
    }
}

/// Field declarations (Script, shader nodes, ProtoDeclare interfaces) that give an
/// inputOnly or outputOnly field an initial value: a `value`, or child nodes (a node's
/// declared field keeps those as a field entry, a ProtoDeclare's as the declaration's
/// value). Copies made by instantiating a prototype carry their body node's
/// declarations, reported once at the original.
fn report_declarations(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter().filter(|(_, node)| node.copy_of.is_none()) {
        for decl in &node.declared {
            let nodes = node
                .entry(&decl.name.text)
                .filter(|entry| entry.origin != Origin::Is)
                .map(|entry| entry.span);
            let span = decl.value.as_ref().map(|(_, span)| *span).or(nodes);
            found.push((Some(id), node.type_name(), decl, span));
        }
    }
    for proto in doc.protos.iter().filter(|proto| !proto.external) {
        for decl in &proto.interface {
            let span = decl.value.as_ref().map(|(_, span)| *span);
            found.push((None, "ProtoDeclare", decl, span));
        }
    }
    for (id, owner, decl, span) in found {
        let (Some(access @ (AccessType::InputOnly | AccessType::OutputOnly)), Some(span)) =
            (decl.access, span)
        else {
            continue;
        };
        let mut diagnostic = Diagnostic::new(
            &FIELD_NOT_INITIALIZABLE,
            span,
            format!(
                "{owner} field `{}` is declared {}: its declaration cannot give it a value",
                decl.name.text,
                access.as_str()
            ),
        )
        .help("drop the value, or declare the field initializeOnly or inputOutput if it needs one");
        if let Some(id) = id {
            diagnostic = diagnostic.node(id);
        }
        ctx.report(diagnostic);
    }
}
