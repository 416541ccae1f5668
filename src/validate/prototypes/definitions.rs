//! Which prototype definition each node belongs to, and the prototypes each definition
//! instantiates.

use crate::model::{Document, NodeId, NodeKind, Place};

/// For each node, the prototype whose definition holds it — its body, or the initial value
/// of one of its interface fields — or None for a node of the scene. A node inside a
/// prototype nested in a body belongs to the nested one.
pub fn owners(doc: &Document) -> Vec<Option<usize>> {
    // The nodes as written: the copies instantiation makes hold no definition.
    let written = doc.written_nodes();
    let mut owners: Vec<Option<usize>> = Vec::with_capacity(written.len());
    for node in written {
        let owner = match node.place {
            Place::Scene | Place::Instance { .. } => None,
            Place::ProtoBody { proto } | Place::ProtoField { proto, .. } => Some(proto),
            // A parent is made before its children, so its owner is known.
            Place::Field { parent, .. } => owners.get(parent.index()).copied().flatten(),
        };
        owners.push(owner);
    }
    owners
}

/// For each prototype, the instances of declared prototypes its definition holds, in
/// document order: (the ProtoInstance node, the prototype it instantiates).
pub fn instances(doc: &Document) -> Vec<Vec<(NodeId, usize)>> {
    let mut by_proto = vec![Vec::new(); doc.protos.len()];
    for ((id, node), owner) in doc.iter().zip(owners(doc)) {
        if let (NodeKind::ProtoInstance { proto: Some(q), .. }, Some(p)) = (&node.kind, owner) {
            if let Some(list) = by_proto.get_mut(p) {
                list.push((id, *q));
            }
        }
    }
    by_proto
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_bodies_and_interface_values_belong_to_their_prototype() {
        let text = "<X3D version='4.0'><Scene>\
            <ProtoDeclare name='A'><ProtoInterface><field name='n' type='SFNode' accessType='initializeOnly'><Group><ProtoInstance name='A'/></Group></field></ProtoInterface>\
            <ProtoBody><ProtoDeclare name='B'><ProtoBody><Transform><ProtoInstance name='A'/></Transform></ProtoBody></ProtoDeclare>\
            <Group><ProtoInstance name='B'/></Group></ProtoBody></ProtoDeclare>\
            <ProtoInstance name='A'/></Scene></X3D>";
        let doc = crate::parse::read(text.as_bytes()).document.unwrap();
        let instances = instances(&doc);
        let targets = |p: usize| instances[p].iter().map(|(_, q)| *q).collect::<Vec<_>>();
        assert_eq!(targets(0), [0, 1], "A: its field's value and its body");
        assert_eq!(targets(1), [0], "B's body");
        let scene_instance = doc.iter().last().unwrap().0;
        assert_eq!(owners(&doc)[scene_instance.index()], None);
    }
}
