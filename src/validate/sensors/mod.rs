//! Time and sensors (clauses 8, 20–22, 25, 27, 30): sensor nodes whose events can go
//! nowhere, that are never enabled, whose box can never be entered, or that have no
//! geometry to sense.

pub mod pointing_sensor_no_geometry;
pub mod sensor_never_enabled;
pub mod sensor_size_zero;
pub mod sensor_unrouted;

use super::Check;
use crate::model::{Document, Node, NodeId, Place, Span};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &sensor_unrouted::CHECK,
    &sensor_never_enabled::CHECK,
    &sensor_size_zero::CHECK,
    &pointing_sensor_no_geometry::CHECK,
];

/// A sensor whose only effect is the events it sends (X3DSensorNode, 7.3.7). Collision
/// (a grouping node that also stops the viewer) and the DIS nodes (which talk to the
/// network and move their children) do more, so they are left out.
fn is_sensor(node: &Node) -> bool {
    node.is_a("X3DSensorNode")
        && !matches!(
            node.type_name(),
            "Collision" | "EspduTransform" | "ReceiverPdu" | "SignalPdu" | "TransmitterPdu"
        )
}

/// The place of `enabled FALSE` when the node writes it itself (not through `IS`).
fn written_disabled(node: &Node) -> Option<Span> {
    if node.is_connected("enabled") {
        return None;
    }
    let entry = node.entry("enabled")?;
    (entry.value.as_bools()? == [false]).then_some(entry.span)
}

/// The nodes this file writes (not prototype copies) that the scene holds as written
/// (see [`is_replaced`]).
fn written_in_scene(doc: &Document) -> impl Iterator<Item = (NodeId, &Node)> {
    doc.iter()
        .take(doc.written_nodes().len())
        .filter(move |(_, node)| !is_replaced(doc, node))
}

/// Whether what the document writes for the node is not what the scene holds: it is the
/// value of a node field that takes the instance's value through `IS`, or a prototype
/// interface's default (placed wherever the prototype puts it).
fn is_replaced(doc: &Document, node: &Node) -> bool {
    match node.place {
        Place::Field { parent, entry } => {
            let parent = doc.node(parent);
            let field = parent.fields.get(entry as usize).map(|e| e.name());
            field.is_some_and(|name| parent.is_connected(name))
        }
        Place::ProtoField { .. } => true,
        _ => false,
    }
}
