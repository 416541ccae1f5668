//! Interpolation component (clause 19), and the interpolators of other components built on
//! X3DInterpolatorNode (GeoPositionInterpolator, 25).

pub mod key_decreasing;
pub mod key_value_count_mismatch;

use std::collections::HashSet;

use super::events::endpoint::route_node;
use super::Check;
use crate::model::{Document, NodeId};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&key_value_count_mismatch::CHECK, &key_decreasing::CHECK];

/// The fields of nodes that a ROUTE sends events to, by field name without `set_` or
/// `_changed`: their values in the file are only the initial ones, which the scene replaces.
pub(crate) fn routed_fields(doc: &Document) -> HashSet<(NodeId, String)> {
    doc.routes
        .iter()
        .filter_map(|route| {
            let node = route_node(doc, route.scope, &route.to_node.text)?;
            let field = route.to_field.text.as_str();
            let field = field.strip_prefix("set_").unwrap_or(field);
            let field = field.strip_suffix("_changed").unwrap_or(field);
            Some((node, field.to_string()))
        })
        .collect()
}

/// Whether the scene may change `field` of `id` after loading (a ROUTE to it) or takes it
/// from a prototype instance (`IS`): the written value is then not what the node uses.
pub(crate) fn set_elsewhere(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    id: NodeId,
    field: &str,
) -> bool {
    doc.node(id).is_connected(field) || routed.contains(&(id, field.to_string()))
}
