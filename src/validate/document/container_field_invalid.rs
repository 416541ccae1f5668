//! CONTAINER_FIELD_INVALID: a child node placed in a field its parent does not have as a
//! node field.

use crate::diagnostic::Diagnostic;
use crate::model::{FieldRef, NodeKind, Origin};
use crate::schema::Scalar;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a child node whose `containerField` (given, or the default of its type)
    /// names no SFNode/MFNode field of its parent, and suggests the node field it most
    /// likely meant.
    ///
    /// ## Why it matters
    /// The XML encoding places every child node by its containerField. A wrong one means
    /// the child is dropped by browsers, or lands somewhere else than intended.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <ImageTexture containerField='diffuseTexture' url='"a.png"'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 (XML encoding) 5.1.2 containerField; 19775-1 the parent's interface table.
    /// A containerField names the parent's field that holds the child; a name that is no
    /// SFNode or MFNode field of the parent is no container field by the definition of the
    /// term (read in the 19776-1 V3.0 text at x3d.m2osw.com, Part01/definitions.html).
    /// X3D 4 changed the default of the Metadata nodes from `metadata` to `value`;
    /// x3d-4.0.xsd says the default is read as `metadata` under a node that is not a
    /// MetadataSet ("Default containerField='metadata' when providing information about the
    /// parent element itself, otherwise apply containerField='value' when this element contains
    /// payload metadata inside a parent/ancestor MetadataSet element"), so a MetadataSet child
    /// of a Group without containerField is the Group's metadata, not a finding.
    /// > "container field: field name for contained SFNode/MFNode content" (19776-1 3.2)
    pub static CONTAINER_FIELD_INVALID = {
        severity: Error,
        level: Fast,
        clause: "19776-1 5.1.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        let NodeKind::Known { def, .. } = node.kind else {
            continue;
        };
        for entry in node.fields.iter().filter(|e| e.origin == Origin::Children) {
            let is_node_field = match &entry.field {
                FieldRef::Schema { def, .. } => def.ty.scalar() == Scalar::Node,
                FieldRef::Declared { ty, .. } => ty.is_none_or(|t| t.scalar() == Scalar::Node),
                FieldRef::Unknown { .. } => false,
            };
            // Unknown child nodes get NODE_UNKNOWN; their default placement is a guess.
            let children = entry.value.as_nodes().unwrap_or_default();
            let any_known = children
                .iter()
                .any(|c| ctx.doc.node(c.node).def().is_some());
            if is_node_field || !any_known {
                continue;
            }
            let node_fields = def
                .fields
                .iter()
                .filter(|f| f.ty.scalar() == Scalar::Node)
                .map(|f| f.name);
            // Without a containerField attribute the place is the child's element name:
            // the value is then the child type's default, which the author never wrote.
            let written = ctx.source.get(entry.name_span.range()) == Some(entry.name().as_bytes());
            let message = match children.first() {
                Some(child) if !written => format!(
                    "the default containerField of {}, `{}`, names no node field of {}",
                    ctx.doc.node(child.node).type_name(),
                    entry.name(),
                    def.name
                ),
                _ => format!(
                    "containerField `{}` names no node field of {}",
                    entry.name(),
                    def.name
                ),
            };
            let mut diagnostic =
                Diagnostic::new(&CONTAINER_FIELD_INVALID, entry.name_span, message)
                    .node(id)
                    .value(entry.name().to_string())
                    .help_opt(suggest::help(entry.name(), node_fields.clone()));
            if diagnostic.help.is_none() {
                let all: Vec<&str> = node_fields.collect();
                if !all.is_empty() {
                    diagnostic =
                        diagnostic.help(format!("{}'s node fields: {}", def.name, all.join(", ")));
                }
            }
            ctx.report(diagnostic);
        }
    }
}
