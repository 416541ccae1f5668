//! Instantiates the ProtoInstances of the document's ProtoDeclares (19775-1 4.4.4), so
//! that the rules and the renderer see the nodes a browser builds, with the values each
//! instance passes through `IS`.
//!
//! Not a deep copy per instance: an instantiation copies only the body nodes that take a
//! value through IS and the nodes above them in the body (path copying); every other body
//! node is shared with the body as written, as `USE` shares it. Instances whose values
//! are identical (same prototype, same fieldValues or defaults) share one instantiation,
//! so 100,000 identical instances cost one copy. A body ProtoInstance that a copy holds is
//! instantiated in turn with the values the copy gives it. The copies are appended to the
//! arena after the written nodes (`Document::copies` counts them), each with [`Copied`] naming the
//! body node it copies and the instance it was made for; their top-level nodes are placed
//! in the instance ([`Place::Instance`]), so a finding in one has the instance in its path.
//! Copies keep the body node's spans and DEF names: each instance is its own DEF name scope.
//!
//! Limits ([`MAX_INSTANCE_NODES`], [`MAX_INSTANCE_VALUES`], [`MAX_PROTO_NESTING`]) stop a
//! prototype "billion laughs" with `LIMIT_EXCEEDED`; past one, no more copies are made and
//! the remaining nodes are checked as written.

use std::collections::HashMap;

use super::builder::{Builder, Limit};
use super::*;
use crate::limits::{MAX_INSTANCE_NODES, MAX_INSTANCE_VALUES, MAX_PROTO_NESTING};

/// Instantiates every ProtoInstance of a ProtoDeclare the document holds.
pub(super) fn instantiate_all(builder: &mut Builder) {
    let written = builder.doc().nodes.len();
    let doc = builder.doc();
    let mut instanced = vec![false; doc.protos.len()];
    for node in &doc.nodes {
        if let NodeKind::ProtoInstance { proto: Some(p), .. } = node.kind {
            instanced[p] = true;
        }
    }
    if !instanced.iter().any(|&i| i) {
        return;
    }
    let mut state = State {
        needs: vec![None; written],
        memo: HashMap::new(),
        nodes: 0,
        values: 0,
        open: Vec::new(),
        stopped: false,
    };
    for index in 0..written {
        let id = NodeId(index as u32);
        let node = builder.doc().node(id);
        if !matches!(node.kind, NodeKind::ProtoInstance { proto: Some(_), .. }) {
            continue;
        }
        // A body instance that takes values through IS is instantiated with each copy of
        // it that its own prototype's instances make, not as written.
        if let Scope::Proto(outer) = node.scope {
            if instanced[outer] && state.needs(builder.doc(), id) {
                continue;
            }
        }
        state.instantiate(builder, id, 0);
    }
    let doc = builder.doc_mut();
    doc.copies = doc.nodes.len() - written;
}

struct State {
    /// Per written node: whether it, or a node below it, takes a value through IS.
    needs: Vec<Option<bool>>,
    /// (prototype, the values as a key) → instantiation.
    memo: HashMap<(usize, Vec<Option<String>>), u32>,
    /// Nodes and field values copied so far.
    nodes: usize,
    values: usize,
    /// The prototypes being instantiated, outermost first.
    open: Vec<usize>,
    /// A limit was reached: nothing more is copied.
    stopped: bool,
}

impl State {
    fn needs(&mut self, doc: &Document, id: NodeId) -> bool {
        let Some(&known) = self.needs.get(id.index()) else {
            return false;
        };
        if let Some(known) = known {
            return known;
        }
        let node = doc.node(id);
        let mut needs = !node.connects.is_empty();
        if !needs {
            let children: Vec<NodeId> = node
                .fields
                .iter()
                .filter_map(|f| f.value.as_nodes())
                .flatten()
                .map(|c| c.node)
                .collect();
            needs = children.into_iter().any(|c| self.needs(doc, c));
        }
        self.needs[id.index()] = Some(needs);
        needs
    }

    fn instantiate(&mut self, builder: &mut Builder, instance: NodeId, depth: usize) {
        let doc = builder.doc();
        let node = doc.node(instance);
        let NodeKind::ProtoInstance { proto: Some(p), .. } = node.kind else {
            return;
        };
        let proto = &doc.protos[p];
        // A prototype instantiated inside its own instantiation is a cycle (PROTO_CYCLE):
        // it builds nothing.
        if proto.external || self.stopped || self.open.contains(&p) {
            return;
        }
        if depth >= MAX_PROTO_NESTING {
            let message = format!(
                "prototype instances nest deeper than {MAX_PROTO_NESTING} levels here; deeper ones are checked as written"
            );
            builder.exceeded(Limit::Instances, node.name_span, message);
            return;
        }
        let values: Vec<Option<Value>> = proto
            .interface
            .iter()
            .map(|decl| {
                let given = node.fields.iter().find(|f| {
                    f.name() == decl.name.text && matches!(f.field, FieldRef::Declared { .. })
                });
                given
                    .map(|f| f.value.clone())
                    .or_else(|| decl.value.as_ref().map(|(v, _)| v.clone()))
            })
            .collect();
        let key = (p, values.iter().map(|v| v.as_ref().map(key_of)).collect());
        if let Some(&shared) = self.memo.get(&key) {
            let doc = builder.doc_mut();
            doc.nodes[instance.index()].instantiation = Some(shared);
            let shared = &mut doc.instantiations[shared as usize];
            shared.count = shared.count.saturating_add(1);
            return;
        }
        let body = proto.body.clone();
        self.open.push(p);
        let mut copies = HashMap::new();
        let mut roots = Vec::with_capacity(body.len());
        for root in body {
            let place = Place::Instance { instance };
            let copy = Copier {
                values: &values,
                proto: p,
                instance,
                depth,
            };
            roots.push(copy.child(self, builder, &mut copies, root, place));
        }
        self.open.pop();
        let doc = builder.doc_mut();
        let index = doc.instantiations.len() as u32;
        doc.instantiations.push(Instantiation {
            proto: p,
            roots,
            instance,
            count: 1,
        });
        doc.nodes[instance.index()].instantiation = Some(index);
        self.memo.insert(key, index);
    }
}

/// What identifies a value for sharing instantiations: its nodes by identity (the same
/// node passed twice builds the same), any other value by its contents.
fn key_of(value: &Value) -> String {
    match value {
        Value::Nodes(refs) => refs
            .iter()
            .map(|c| c.node.0.to_string())
            .collect::<Vec<_>>()
            .join(" "),
        other => format!("{other:?}"),
    }
}

/// Copies the body nodes of one instantiation.
struct Copier<'v> {
    /// Per interface field: the instance's value, or the default.
    values: &'v [Option<Value>],
    proto: usize,
    instance: NodeId,
    depth: usize,
}

impl Copier<'_> {
    /// The reference `child` (of the body) becomes in this instantiation: a copy when a
    /// node at or below it takes a value through IS, else the body's node itself.
    fn child(
        &self,
        state: &mut State,
        builder: &mut Builder,
        copies: &mut HashMap<NodeId, NodeId>,
        child: ChildRef,
        place: Place,
    ) -> ChildRef {
        let original = child.node;
        if let Some(&copy) = copies.get(&original) {
            return ChildRef {
                node: copy,
                ..child
            };
        }
        if !state.needs(builder.doc(), original) || state.stopped {
            return child;
        }
        let mut node = builder.doc().node(original).clone();
        let cost: usize = node.fields.iter().map(|f| f.value.len()).sum();
        if state.nodes >= MAX_INSTANCE_NODES || state.values + cost > MAX_INSTANCE_VALUES {
            state.stopped = true;
            let message = format!(
                "instantiating prototypes copies more than {MAX_INSTANCE_NODES} nodes or {MAX_INSTANCE_VALUES} values; the rest are checked as written"
            );
            builder.exceeded(
                Limit::Instances,
                builder.doc().node(self.instance).name_span,
                message,
            );
            return child;
        }
        state.nodes += 1;
        state.values += cost;
        let id = NodeId(builder.doc().nodes.len() as u32);
        copies.insert(original, id);
        node.place = place;
        node.copy_of = Some(Copied {
            original,
            instance: self.instance,
        });
        node.instantiation = None;
        for connect in std::mem::take(&mut node.connects) {
            if let Some(entry) = self.passed(builder, original, &connect) {
                match node.fields.iter().position(|f| f.name() == entry.name()) {
                    Some(at) => node.fields[at] = entry,
                    None => node.fields.push(entry),
                }
            }
        }
        builder.doc_mut().nodes.push(node);
        let field_count = builder.doc().node(id).fields.len();
        for entry in 0..field_count {
            let field = &builder.doc().node(id).fields[entry];
            // A value passed in through IS is the instance's (or the interface's): shared.
            if field.origin == Origin::Is {
                continue;
            }
            let Some(children) = field.value.as_nodes().map(<[ChildRef]>::to_vec) else {
                continue;
            };
            let place = Place::Field {
                parent: id,
                entry: entry as u32,
            };
            let copied: Vec<ChildRef> = children
                .into_iter()
                .map(|c| self.child(state, builder, copies, c, place))
                .collect();
            builder.doc_mut().nodes[id.index()].fields[entry].value = Value::Nodes(copied);
        }
        if matches!(
            builder.doc().node(id).kind,
            NodeKind::ProtoInstance { proto: Some(_), .. }
        ) {
            state.instantiate(builder, id, self.depth + 1);
        }
        ChildRef { node: id, ..child }
    }

    /// The entry a `connect` gives the copy of `original`: the instance's value for the
    /// prototype field, typed as the node's field. None when the node field takes no
    /// initial value (inputOnly, outputOnly) or the prototype field has none to give.
    fn passed(
        &self,
        builder: &Builder,
        original: NodeId,
        connect: &IsConnect,
    ) -> Option<FieldEntry> {
        let doc = builder.doc();
        let interface = &doc.protos[self.proto].interface;
        let at = interface
            .iter()
            .position(|f| f.name.text == connect.proto_field.text)?;
        let value = self.values[at].as_ref()?;
        let field = builder.field_ref(original, &connect.node_field.text);
        // A field the document's version lacks is the connect's own problem (IS_FIELD_UNKNOWN),
        // not one to report again in every instance.
        let initializable = match &field {
            FieldRef::Schema { def, version } => {
                *version == doc.schema_version()
                    && matches!(
                        def.access,
                        AccessType::InitializeOnly | AccessType::InputOutput
                    )
            }
            FieldRef::Declared { .. } => true,
            FieldRef::Unknown { .. } => false,
        };
        if !initializable {
            return None;
        }
        // A value of another type (IS_TYPE_MISMATCH) is not one the node's rules can read.
        let value = if field.field_type().is_some() && field.field_type() == interface[at].ty {
            value.clone()
        } else {
            Value::Unparsed(String::new())
        };
        Some(FieldEntry {
            field,
            name_span: connect.node_field.span,
            span: connect.span,
            origin: Origin::Is,
            value,
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::model::{Document, NodeId, NodeKind, Place};
    use crate::parse;

    fn doc(scene: &str) -> Document {
        let source = format!(
            "<X3D profile='Immersive' version='4.0'><Scene>
            <ProtoDeclare name='Ball'>
              <ProtoInterface>
                <field name='s' type='SFFloat' accessType='inputOutput' value='0.2'/>
              </ProtoInterface>
              <ProtoBody>
                <Shape>
                  <Appearance><Material><IS><connect nodeField='shininess' protoField='s'/></IS></Material></Appearance>
                  <Box/>
                </Shape>
              </ProtoBody>
            </ProtoDeclare>{scene}</Scene></X3D>"
        );
        parse::read(source.as_bytes()).document.unwrap()
    }

    fn instances(doc: &Document) -> Vec<NodeId> {
        doc.node_ids()
            .filter(|&id| matches!(doc.node(id).kind, NodeKind::ProtoInstance { .. }))
            .collect()
    }

    #[test]
    fn copies_the_path_to_connected_fields_and_shares_the_rest() {
        let doc =
            doc("<ProtoInstance name='Ball'><fieldValue name='s' value='0.7'/></ProtoInstance>");
        // Shape, Appearance and Material are copied; the Box is the body's own.
        assert_eq!(doc.copies, 3);
        let instance = instances(&doc)[0];
        let shape = doc.built(instance).unwrap();
        assert!(shape.index() >= doc.written_nodes().len());
        assert_eq!(doc.node(shape).place, Place::Instance { instance });
        let material = doc.child_of(doc.child_of(shape, "appearance").unwrap(), "material");
        let material = material.unwrap();
        assert_eq!(doc.f32_of(material, "shininess"), Some(0.7));
        assert!(doc.node(material).connects.is_empty());
        let body_shape = doc.node(shape).copy_of.unwrap().original;
        assert_eq!(
            doc.child_of(shape, "geometry"),
            doc.child_of(body_shape, "geometry")
        );
    }

    #[test]
    fn identical_instances_share_one_instantiation() {
        let same = "<ProtoInstance name='Ball'><fieldValue name='s' value='0.5'/></ProtoInstance>";
        let doc = doc(&format!(
            "{}<ProtoInstance name='Ball'/><ProtoInstance name='Ball'><fieldValue name='s' value='0.2'/></ProtoInstance>",
            same.repeat(100)
        ));
        // 0.5 a hundred times; the default and an explicit 0.2 are two more values.
        assert_eq!(doc.instantiations.len(), 2);
        assert_eq!(doc.instantiations[0].count, 100);
        assert_eq!(doc.instantiations[1].count, 2);
        assert_eq!(doc.copies, 6);
    }

    #[test]
    fn a_prototype_billion_laughs_stops_at_the_limit() {
        // P_k's body holds ten instances of P_(k-1), each setting its own field k and
        // passing the others on: 10^7 distinct instantiations of P0.
        let n = 8;
        let fields: String = (0..n)
            .map(|i| {
                format!("<field name='f{i}' type='SFFloat' accessType='initializeOnly' value='0'/>")
            })
            .collect();
        let mut scene = format!(
            "<ProtoDeclare name='P0'><ProtoInterface>{fields}</ProtoInterface><ProtoBody><Material><IS><connect nodeField='shininess' protoField='f0'/></IS></Material></ProtoBody></ProtoDeclare>"
        );
        for k in 1..n {
            let connects: String = (0..n)
                .filter(|&i| i != k)
                .map(|i| format!("<connect nodeField='f{i}' protoField='f{i}'/>"))
                .collect();
            let body: String = (0..10)
                .map(|j| format!("<ProtoInstance name='P{}'><fieldValue name='f{k}' value='0.{j}'/><IS>{connects}</IS></ProtoInstance>", k - 1))
                .collect();
            scene += &format!("<ProtoDeclare name='P{k}'><ProtoInterface>{fields}</ProtoInterface><ProtoBody><Group>{body}</Group></ProtoBody></ProtoDeclare>");
        }
        scene += &format!("<ProtoInstance name='P{}'/>", n - 1);
        let source = format!("<X3D profile='Immersive' version='4.0'><Scene>{scene}</Scene></X3D>");
        let parsed = parse::read(source.as_bytes());
        assert!(parsed.document.unwrap().copies <= crate::limits::MAX_INSTANCE_NODES);
        assert!(parsed
            .diagnostics
            .iter()
            .any(|d| d.code() == "LIMIT_EXCEEDED" && d.message.contains("instantiating")));
    }
}
