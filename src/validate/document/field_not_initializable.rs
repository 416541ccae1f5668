//! FIELD_NOT_INITIALIZABLE: a value given for an inputOnly or outputOnly field.

use crate::model::{FieldRef, NodeKind, Origin};
use crate::report::Diagnostic;
use crate::schema::AccessType;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a value (or child nodes) given in the document for a field whose access
    /// type is `inputOnly` or `outputOnly`, such as `set_index` or `duration_changed`;
    /// also a ProtoInstance `fieldValue` for a prototype field that its ProtoDeclare or
    /// ExternProtoDeclare declares `inputOnly` or `outputOnly` (`set_startpoint`).
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
    /// 19775-1 4.4.2.2 Field semantics (access types).
    pub static FIELD_NOT_INITIALIZABLE = {
        severity: Error,
        level: Fast,
        clause: "4.4.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
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
