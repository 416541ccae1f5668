//! SFNODE_MULTIPLE: more than one node in a single-node field.

use crate::diagnostic::Diagnostic;
use crate::model::Value;
use crate::schema::FieldType;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an SFNode field given more than one node, such as two materials in one
    /// Appearance or two geometries in one Shape. The diagnostic points at the second.
    ///
    /// ## Why it matters
    /// An SFNode field holds one node. Browsers keep the first or the last, differently,
    /// so what is drawn depends on the browser.
    ///
    /// ## Example
    /// ```xml
    /// <Shape><Box/><Sphere/></Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 5.3.12 SFNode and MFNode.
    /// > "SFxxxx fields may only contain a single value of the type indicated by the name of the field type" (19775-1 5.2.3)
    pub static SFNODE_MULTIPLE = {
        severity: Error,
        level: Fast,
        clause: "5.3.12",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        for entry in &node.fields {
            let (Some(FieldType::SFNode), Value::Nodes(children)) =
                (entry.field_type(), &entry.value)
            else {
                continue;
            };
            if let [first, second, ..] = children.as_slice() {
                ctx.report(
                    Diagnostic::new(
                        &SFNODE_MULTIPLE,
                        second.span,
                        format!(
                            "{}.{} holds one node, but {} are given",
                            node.type_name(),
                            entry.name(),
                            children.len()
                        ),
                    )
                    .node(id)
                    .related(first.span, "the first node"),
                );
            }
        }
    }
}
