//! Layering component (clause 35): where the LayerSet stands, which layers its `order`
//! and `activeLayer` name, and the four sides of a Viewport's clip boundary.

pub mod layerset_duplicate;
pub mod layerset_layer_past_end;
pub mod layerset_not_root;
pub mod viewport_clip_boundary_count;

use super::Check;
use crate::model::{Document, NodeId};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &layerset_not_root::CHECK,
    &layerset_duplicate::CHECK,
    &layerset_layer_past_end::CHECK,
    &viewport_clip_boundary_count::CHECK,
];

/// Whether the node a reference stands for (a prototype instance's built node included)
/// is a LayerSet.
fn is_layer_set(doc: &Document, id: NodeId) -> bool {
    doc.built(id)
        .is_some_and(|built| doc.node(built).type_name() == "LayerSet")
}
