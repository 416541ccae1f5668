//! NODE_TYPE_NOT_ALLOWED: a node given to a field that does not accept its type.

use crate::model::{ChildRef, Document, FieldRef, NodeKind};
use crate::report::Diagnostic;
use crate::schema::NodeDef;
use crate::validate::Ctx;

/// What the Scene's top level accepts: children nodes, metadata, and LayerSet (35.4.2:
/// a LayerSet is a root node).
const SCENE_ACCEPTS: &[&str] = &["X3DChildNode", "X3DMetadataObject", "LayerSet"];

/// Prototype instances nest; this many levels are followed to find an instance's type.
const MAX_PROTO_DEPTH: usize = 32;

crate::declare_rule! {
    /// ## What it does
    /// Reports a node given to a node field that does not accept its type, per the
    /// `[X3D…Node]` annotation of the field in the interface table: an ImageTexture in
    /// `material`, a TwoSidedMaterial in `backMaterial` (which takes
    /// X3DOneSidedMaterialNode, 12.4.2), a MultiTexture in a material's `xxxTexture` field,
    /// a non-geometry in Shape.geometry, a Material at the Scene's top level. A
    /// ProtoInstance counts as the type of the first node of its ProtoBody. A field that
    /// is not in the document's version is FIELD_NOT_IN_VERSION and its nodes are not
    /// judged here.
    ///
    /// ## Why it matters
    /// Browsers ignore a node of the wrong type (or fail to load the scene), so what it
    /// was meant to do silently does not happen.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <ImageTexture containerField='material' url='"wood.png"'/>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.2.2 (SFNode/MFNode fields name the node types they accept) and the
    /// field's interface table.
    pub static NODE_TYPE_NOT_ALLOWED = {
        severity: Error,
        level: Fast,
        clause: "4.4.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for &child in &ctx.doc.scene {
        check_child(ctx, child, "Scene", "children", SCENE_ACCEPTS);
    }
    for (_, node) in ctx.doc.iter() {
        let NodeKind::Known { def, .. } = node.kind else {
            continue;
        };
        for entry in &node.fields {
            // A field of another version is FIELD_NOT_IN_VERSION: its acceptable types
            // come from a hierarchy the document's version lacks, so judging its nodes
            // would report the same cause twice.
            let FieldRef::Schema {
                def: field,
                version,
            } = entry.field
            else {
                continue;
            };
            if version != ctx.version {
                continue;
            }
            if field.acceptable.is_empty() {
                continue;
            }
            for &child in entry.value.as_nodes().unwrap_or_default() {
                check_child(ctx, child, def.name, field.name, field.acceptable);
            }
        }
    }
}

fn check_child(ctx: &mut Ctx, child: ChildRef, parent: &str, field: &str, acceptable: &[&str]) {
    let Some(def) = node_type(ctx.doc, child, 0) else {
        return;
    };
    if acceptable.iter().any(|a| def.is_a(a)) {
        return;
    }
    ctx.report(
        Diagnostic::new(
            &NODE_TYPE_NOT_ALLOWED,
            child.span,
            format!("{parent}.{field} does not accept {} nodes", def.name),
        )
        .node(child.node)
        .help(format!(
            "{parent}.{field} takes {}",
            acceptable.join(" or ")
        )),
    );
}

/// The node type a child counts as: its own, or for a ProtoInstance the type of the first
/// node of its ProtoBody (for an external prototype, as instantiated from the library file
/// at the deep level). None when it cannot be told (unknown names, external prototypes not
/// resolved).
fn node_type(doc: &Document, child: ChildRef, depth: usize) -> Option<&'static NodeDef> {
    match &doc.node(child.node).kind {
        NodeKind::Known { def, .. } => Some(def),
        NodeKind::ProtoInstance { .. } if doc.instantiation_of(child.node).is_some() => doc
            .built(child.node)
            .and_then(|built| doc.node(built).def()),
        NodeKind::ProtoInstance { proto: Some(p), .. } if depth < MAX_PROTO_DEPTH => {
            let first = *doc.protos[*p].body.first()?;
            node_type(doc, first, depth + 1)
        }
        _ => None,
    }
}
