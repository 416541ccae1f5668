//! Time and sensors (clauses 8, 20–22, 25, 27, 30): sensor nodes whose events can go
//! nowhere, that are never enabled, whose box can never be entered, or that have no
//! geometry to sense.

pub mod pointing_sensor_no_geometry;
pub mod sensor_never_enabled;
pub mod sensor_size_zero;
pub mod sensor_unrouted;

use super::Check;
use crate::model::{Node, Span};

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
