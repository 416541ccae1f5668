//! The structural path of a node, XPath-like: `/X3D/Scene/Transform[2]/Shape/Appearance`.
//!
//! Each step names the node's type, then
//! - `[@DEF='name']` when the node has a DEF name;
//! - `[n]` when it stands in an MF field (or the Scene, a ProtoBody): its 1-based position
//!   among the references of the same type in that field (USEs included, as XPath counts
//!   USE elements);
//! - nothing in an SF field.
//!
//! Nodes in a ProtoBody start at `/X3D/Scene/ProtoDeclare[@name='P']/ProtoBody`; initial
//! values of a ProtoInterface field at `…/ProtoInterface/field[@name='f']`. A body node
//! as an instance builds it (a copy holding the instance's values) is under the instance:
//! `/X3D/Scene/ProtoInstance[2]/Shape/Appearance/Material`. The walk follows
//! `Node::place` upward, done only for reported diagnostics. Positions among siblings are
//! counted for the whole document in one pass, the first time one is needed, so that many
//! diagnostics on the nodes of one long list cost O(nodes), not O(nodes × siblings).

use std::cell::OnceCell;
use std::collections::HashMap;

use crate::model::{Document, NodeId, Place, Span, Value};

/// The path of diagnostics that concern no node.
pub const ROOT: &str = "/X3D";

/// The paths of one document's nodes.
pub struct NodePaths<'d> {
    doc: &'d Document,
    /// Per node: its 1-based position among the same-type references of its parent field.
    positions: OnceCell<Vec<u32>>,
}

impl<'d> NodePaths<'d> {
    pub fn new(doc: &'d Document) -> NodePaths<'d> {
        NodePaths {
            doc,
            positions: OnceCell::new(),
        }
    }

    pub fn path(&self, id: NodeId) -> String {
        node_path(self.doc, id, |id| self.position(id))
    }

    /// The path of a place that no node was recorded for (a value that did not parse, a
    /// USE of an undefined name, a ROUTE): the innermost node whose element holds it, or
    /// else the ProtoDeclare or Scene that does, or else [`ROOT`].
    pub fn path_at(&self, span: Span) -> String {
        if let Some(node) = node_at(self.doc, span) {
            return self.path(node);
        }
        let holds = |outer: Span| outer.start <= span.start && span.end <= outer.end;
        if let Some(proto) = self.doc.protos.iter().rposition(|p| holds(p.span)) {
            let decl = proto_declare(self.doc, proto);
            return if self.doc.protos[proto].external {
                decl.replacen("ProtoDeclare", "ExternProtoDeclare", 1)
            } else {
                format!("{decl}/ProtoBody")
            };
        }
        // The Scene is the root's last child, and an XML reader records only its start
        // tag: whatever starts after that start is inside it.
        match self.doc.scene_span {
            Some(scene) if scene.start <= span.start => "/X3D/Scene".to_string(),
            _ => ROOT.to_string(),
        }
    }

    fn position(&self, id: NodeId) -> u32 {
        let positions = self.positions.get_or_init(|| positions(self.doc));
        positions.get(id.index()).copied().unwrap_or(1).max(1)
    }
}

/// The innermost node whose span holds `span`. Readers number nodes in the order their
/// elements start, so the candidates are the last node that starts at or before `span`
/// and its ancestors.
fn node_at(doc: &Document, span: Span) -> Option<NodeId> {
    let holds = |id: NodeId| {
        let outer = doc.node(id).span;
        outer.start <= span.start && span.end <= outer.end
    };
    // Only the written nodes are in document order (instantiation's copies follow them).
    let started = doc
        .written_nodes()
        .partition_point(|n| n.span.start <= span.start);
    let mut current = NodeId(started.checked_sub(1)? as u32);
    // Bounded by the depth of the tree; the count guards a model that is not a tree.
    for _ in 0..=doc.nodes.len() {
        if holds(current) {
            return Some(current);
        }
        match doc.node(current).place {
            Place::Field { parent, .. } => current = parent,
            _ => return None,
        }
    }
    None
}

/// Every node's position among the references of the same type in its sibling list.
fn positions(doc: &Document) -> Vec<u32> {
    let mut positions = vec![0u32; doc.nodes.len()];
    let lists = doc
        .nodes
        .iter()
        .flat_map(|n| n.fields.iter().filter_map(|f| f.value.as_nodes()))
        .chain(doc.protos.iter().flat_map(|p| {
            let interface = p.interface.iter();
            let values = interface.filter_map(|f| f.value.as_ref().and_then(|(v, _)| v.as_nodes()));
            values.chain(std::iter::once(&p.body[..]))
        }))
        .chain(doc.instantiations.iter().map(|i| &i.roots[..]))
        .chain(std::iter::once(&doc.scene[..]));
    for siblings in lists {
        let mut seen: HashMap<&str, u32> = HashMap::new();
        for sibling in siblings {
            let Some(node) = doc.nodes.get(sibling.node.index()) else {
                continue;
            };
            let count = seen.entry(node.type_name()).or_default();
            *count += 1;
            if !sibling.is_use {
                positions[sibling.node.index()] = *count;
            }
        }
    }
    positions
}

fn node_path(doc: &Document, id: NodeId, position: impl Fn(NodeId) -> u32) -> String {
    let mut steps = Vec::new();
    let mut current = id;
    let root = loop {
        let Some(node) = doc.nodes.get(current.index()) else {
            break ROOT.to_string();
        };
        // A well-formed model is a tree by `place`; this bounds the walk if it is not.
        if steps.len() > doc.nodes.len() {
            break ROOT.to_string();
        }
        match node.place {
            Place::Scene => {
                steps.push(step(doc, current, true, &position));
                break "/X3D/Scene".to_string();
            }
            Place::ProtoBody { proto } => {
                steps.push(step(doc, current, true, &position));
                break format!("{}/ProtoBody", proto_declare(doc, proto));
            }
            Place::ProtoField { proto, field } => {
                let decl = doc
                    .protos
                    .get(proto)
                    .and_then(|p| p.interface.get(field as usize));
                let siblings = decl
                    .and_then(|f| f.value.as_ref())
                    .and_then(|(v, _)| v.as_nodes())
                    .unwrap_or(&[]);
                let multiple = decl
                    .and_then(|f| f.ty)
                    .map_or(siblings.len() > 1, |t| t.is_mf());
                steps.push(step(doc, current, multiple, &position));
                let name = decl.map_or("", |f| f.name.text.as_str());
                break format!(
                    "{}/ProtoInterface/field[@name={}]",
                    proto_declare(doc, proto),
                    quote(name)
                );
            }
            Place::Instance { instance } => {
                let roots = doc
                    .instantiation_of(instance)
                    .map_or(&[][..], |i| &i.roots[..]);
                steps.push(step(doc, current, roots.len() > 1, &position));
                current = instance;
            }
            Place::Field { parent, entry } => {
                let entry = doc
                    .nodes
                    .get(parent.index())
                    .and_then(|p| p.fields.get(entry as usize));
                let siblings = entry
                    .and_then(|e| match &e.value {
                        Value::Nodes(refs) => Some(&refs[..]),
                        _ => None,
                    })
                    .unwrap_or(&[]);
                let multiple = entry
                    .and_then(|e| e.field_type())
                    .map_or(siblings.len() > 1, |t| t.is_mf());
                steps.push(step(doc, current, multiple, &position));
                current = parent;
            }
        }
    };
    let mut path = root;
    for step in steps.iter().rev() {
        path.push('/');
        path.push_str(step);
    }
    path
}

fn step(doc: &Document, id: NodeId, multiple: bool, position: impl Fn(NodeId) -> u32) -> String {
    let node = doc.node(id);
    let ty = node.type_name();
    if let Some(def) = &node.def_name {
        return format!("{ty}[@DEF={}]", quote(&def.text));
    }
    if !multiple {
        return ty.to_string();
    }
    format!("{ty}[{}]", position(id))
}

fn proto_declare(doc: &Document, proto: usize) -> String {
    let name = doc.protos.get(proto).map_or("", |p| p.name.text.as_str());
    format!("/X3D/Scene/ProtoDeclare[@name={}]", quote(name))
}

/// An XPath string literal: single quotes unless the text holds one.
fn quote(text: &str) -> String {
    if text.contains('\'') {
        format!("\"{text}\"")
    } else {
        format!("'{text}'")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::builder::testing::{named, parent_of};
    use crate::model::{Builder, Encoding, ProtoDecl, Scope, Span};

    /// Builds nodes as a reader would: open, optionally DEF, close later.
    struct Scene(Builder);

    impl Scene {
        fn new() -> Scene {
            Scene(Builder::new(Encoding::Xml))
        }

        fn open(&mut self, ty: &str, parent: Option<(NodeId, &str)>, def: Option<&str>) -> NodeId {
            let kind = self.0.node_kind(ty);
            let id = self
                .0
                .begin_node(kind, Span::default(), parent_of(parent))
                .expect("shallow test scene");
            if let Some(name) = def {
                self.0.define(id, named(name));
            }
            id
        }

        fn leaf(&mut self, ty: &str, parent: Option<(NodeId, &str)>, def: Option<&str>) -> NodeId {
            let id = self.open(ty, parent, def);
            self.0.end_node(id, Span::default());
            id
        }

        fn reuse(&mut self, ty: &str, name: &str, parent: Option<(NodeId, &str)>) {
            self.0
                .use_node(&named(name), Some(ty), Span::default(), parent_of(parent));
        }

        fn path(&self, id: NodeId) -> String {
            NodePaths::new(self.0.doc()).path(id)
        }
    }

    #[test]
    fn positions_among_same_type_siblings() {
        let mut s = Scene::new();
        s.leaf("Transform", None, None);
        s.leaf("Group", None, None);
        let t = s.open("Transform", None, None);
        s.leaf("Shape", Some((t, "children")), None);
        let shape = s.open("Shape", Some((t, "children")), None);
        let appearance = s.open("Appearance", Some((shape, "appearance")), None);
        let material = s.leaf("Material", Some((appearance, "material")), None);
        s.0.end_node(appearance, Span::default());
        s.0.end_node(shape, Span::default());
        s.0.end_node(t, Span::default());
        assert_eq!(s.path(t), "/X3D/Scene/Transform[2]");
        assert_eq!(
            s.path(material),
            "/X3D/Scene/Transform[2]/Shape[2]/Appearance/Material"
        );
    }

    #[test]
    fn def_names_and_uses() {
        let mut s = Scene::new();
        let t = s.open("Transform", None, Some("T"));
        let first = s.leaf("Shape", Some((t, "children")), Some("S"));
        s.reuse("Shape", "S", Some((t, "children")));
        let third = s.leaf("Shape", Some((t, "children")), None);
        s.0.end_node(t, Span::default());
        assert_eq!(
            s.path(first),
            "/X3D/Scene/Transform[@DEF='T']/Shape[@DEF='S']"
        );
        // The USE element counts, as XPath counts it.
        assert_eq!(s.path(third), "/X3D/Scene/Transform[@DEF='T']/Shape[3]");
    }

    #[test]
    fn proto_body() {
        let mut s = Scene::new();
        let proto = s.0.declare_proto(ProtoDecl {
            name: named("Wheel"),
            span: Span::default(),
            external: false,
            scope: Scope::Scene,
            interface: Vec::new(),
            body: Vec::new(),
            url: Vec::new(),
        });
        s.0.begin_proto_body(proto);
        let group = s.open("Group", None, None);
        let shape = s.leaf("Shape", Some((group, "children")), Some("it's"));
        s.0.end_node(group, Span::default());
        s.0.end_proto_body();
        assert_eq!(
            s.path(shape),
            "/X3D/Scene/ProtoDeclare[@name='Wheel']/ProtoBody/Group[1]/Shape[@DEF=\"it's\"]"
        );
    }
}
