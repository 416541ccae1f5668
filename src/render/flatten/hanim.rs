//! The H-Anim component (19775-1 clause 26): what a browser shows of a humanoid before
//! any animation runs. HAnimHumanoid transforms like a Transform (26.3.2); its `skeleton`
//! holds the root joints (and sites), each HAnimJoint again transforms like a Transform
//! (26.3.3) and holds joints, segments and sites, and HAnimSegment's children are its
//! shapes (26.3.4). The `skin` shapes are drawn in the humanoid's coordinates as written
//! (the rest pose): where joints weight skin coordinates (skinCoordIndex, skinCoordWeight)
//! the skin is not deformed by them, and a note says so.
//! `joints`, `segments`, `sites` and `viewpoints` only list nodes of the skeleton, and the
//! HAnimMotion of `motions` animates; neither draws anything.

use glam::DMat4;

use super::{child_ids, Context, Scope, Walker};
use crate::model::NodeId;
use crate::render::fields::ints;

impl Walker<'_> {
    /// HAnimHumanoid: the skeleton, then the skin, in the humanoid's transform.
    pub(super) fn humanoid(
        &mut self,
        context: Context,
        id: NodeId,
        world: DMat4,
        scope: &Scope,
        depth: usize,
    ) {
        let Some(local) = self.local_transform(context, id) else {
            return;
        };
        let world = world * local;
        let node = context.doc.node(id);
        let (skeleton, skin) = (child_ids(node, "skeleton"), child_ids(node, "skin"));
        if !skin.is_empty() && weights_skin(context, &skeleton) {
            self.note(
                context,
                id,
                "HAnimHumanoid skin: drawn as written (the rest pose), not deformed by the \
                 joints that weight it (26.3.2)"
                    .into(),
            );
        }
        self.walk_children(context, &skeleton, world, scope, depth);
        self.walk_children(context, &skin, world, scope, depth);
    }

    /// HAnimJoint: its children (joints, segments, sites) in its transform.
    pub(super) fn joint(
        &mut self,
        context: Context,
        id: NodeId,
        world: DMat4,
        scope: &Scope,
        depth: usize,
    ) {
        if let Some(local) = self.local_transform(context, id) {
            let kids = child_ids(context.doc.node(id), "children");
            self.walk_children(context, &kids, world * local, scope, depth);
        }
    }
}

/// Whether a joint below these roots weights skin coordinates.
fn weights_skin(context: Context, roots: &[NodeId]) -> bool {
    let doc = context.doc;
    let mut stack = roots.to_vec();
    let mut visited: u64 = 0;
    while let Some(id) = stack.pop() {
        visited += 1;
        if visited > super::MAX_NODE_INSTANCES {
            return true;
        }
        let node = doc.node(id);
        if node.type_name() != "HAnimJoint" {
            continue;
        }
        if !ints(doc, id, "skinCoordIndex").is_empty() {
            return true;
        }
        stack.extend(node.children("children").iter().map(|c| c.node));
    }
    false
}
