//! Humanoid animation (clause 26, and ISO/IEC 19774 HAnim 1.0 / 19774-1 HAnim 2.0): the
//! skin weights of the joints, the humanoid's lists of its joints, segments and sites, and
//! the names that identify them.

pub mod hanim_list_mismatch;
pub mod hanim_name_duplicate;
pub mod hanim_name_not_standard;
pub mod hanim_skin_coord_index_out_of_range;
pub mod hanim_skin_weight_count_mismatch;
pub mod hanim_skin_weight_out_of_range;
#[rustfmt::skip]
pub mod names;

use std::collections::HashSet;

use super::events::wiring::{routed_fields, set_elsewhere};
use super::Check;
use crate::model::{Document, NodeId, NodeKind};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &hanim_skin_weight_count_mismatch::CHECK,
    &hanim_skin_coord_index_out_of_range::CHECK,
    &hanim_skin_weight_out_of_range::CHECK,
    &hanim_list_mismatch::CHECK,
    &hanim_name_duplicate::CHECK,
    &hanim_name_not_standard::CHECK,
];

/// One HAnimHumanoid and what its skeleton holds.
pub(crate) struct Humanoid {
    pub id: NodeId,
    /// The HAnimJoint, HAnimSegment and HAnimSite nodes reached from `skeleton` through
    /// `children` fields (each once, however often USE repeats it), in document order of
    /// the walk; a nested HAnimHumanoid is not entered.
    pub joints: Vec<NodeId>,
    pub segments: Vec<NodeId>,
    pub sites: Vec<NodeId>,
    /// Whether the skeleton is not all known: it holds a prototype instance or a node of
    /// unknown type, or a `skeleton` or `children` field on the way takes its value from
    /// elsewhere (IS, ROUTE). Rules that need the whole skeleton stay silent then.
    pub opaque: bool,
}

impl Humanoid {
    /// The nodes of the skeleton of one HAnim type: `HAnimJoint`, `HAnimSegment` or
    /// `HAnimSite`.
    pub fn of_type(&self, type_name: &str) -> &[NodeId] {
        match type_name {
            "HAnimJoint" => &self.joints,
            "HAnimSegment" => &self.segments,
            _ => &self.sites,
        }
    }
}

/// Every HAnimHumanoid of the document with its skeleton.
pub(crate) fn humanoids(doc: &Document) -> Vec<Humanoid> {
    let routed = routed_fields(doc);
    doc.nodes_of_type("HAnimHumanoid")
        .map(|id| walk(doc, &routed, id))
        .collect()
}

fn walk(doc: &Document, routed: &HashSet<(NodeId, String)>, id: NodeId) -> Humanoid {
    let mut humanoid = Humanoid {
        id,
        joints: Vec::new(),
        segments: Vec::new(),
        sites: Vec::new(),
        opaque: set_elsewhere(doc, routed, id, "skeleton"),
    };
    let mut seen = HashSet::new();
    let mut stack: Vec<NodeId> = doc
        .node(id)
        .children("skeleton")
        .iter()
        .rev()
        .map(|c| c.node)
        .collect();
    while let Some(next) = stack.pop() {
        if !seen.insert(next) {
            continue;
        }
        let node = doc.node(next);
        match &node.kind {
            NodeKind::Known { .. } => {}
            _ => {
                humanoid.opaque = true;
                continue;
            }
        }
        match node.type_name() {
            "HAnimHumanoid" => continue,
            "HAnimJoint" => humanoid.joints.push(next),
            "HAnimSegment" => humanoid.segments.push(next),
            "HAnimSite" => humanoid.sites.push(next),
            _ => {}
        }
        if set_elsewhere(doc, routed, next, "children") {
            humanoid.opaque = true;
        }
        stack.extend(node.children("children").iter().rev().map(|c| c.node));
    }
    humanoid
}

/// The `name` of a node as written, when it is written, not empty and not set elsewhere.
pub(crate) fn written_name(doc: &Document, id: NodeId) -> Option<&str> {
    let node = doc.node(id);
    if node.is_connected("name") {
        return None;
    }
    let name = node.value("name")?.as_strings()?.first()?;
    (!name.is_empty()).then_some(name.as_str())
}

/// The node's written name as a message puts it after the node type (" `l_elbow`"), or
/// nothing when it has none.
pub(crate) fn name_suffix(doc: &Document, id: NodeId) -> String {
    written_name(doc, id).map_or(String::new(), |n| format!(" `{n}`"))
}

/// How a node is named in a message: `HAnimJoint "l_elbow"` (with its DEF when it has no
/// name).
pub(crate) fn describe(doc: &Document, id: NodeId) -> String {
    let node = doc.node(id);
    match (written_name(doc, id), &node.def_name) {
        (Some(name), _) => format!("{} `{name}`", node.type_name()),
        (None, Some(def)) => format!("{} DEF `{}`", node.type_name(), def.text),
        (None, None) => node.type_name().to_string(),
    }
}
