//! Events and prototypes, RULES.md §6: ROUTE ends (node, field, access type, field type)
//! and the names prototype statements use. All at the standard level.

use super::Rule;

mod endpoint;
pub mod proto_field_unknown;
pub mod route_field_unknown;
pub mod route_node_undefined;
pub mod route_type_mismatch;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[
    &route_node_undefined::ROUTE_NODE_UNDEFINED,
    &route_field_unknown::ROUTE_FIELD_UNKNOWN,
    &route_type_mismatch::ROUTE_TYPE_MISMATCH,
    &proto_field_unknown::PROTO_FIELD_UNKNOWN,
];
