//! Events and prototypes, RULES.md §6: ROUTE ends (node, field, access type, field type)
//! and the names prototype statements use, at the standard level; empty prototype bodies,
//! at the fast level.

use super::Check;

pub(crate) mod endpoint;
pub mod proto_body_empty;
pub mod proto_field_unknown;
pub mod route_field_unknown;
pub mod route_node_undefined;
pub mod route_type_mismatch;
pub(crate) mod wiring;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &route_node_undefined::CHECK,
    &route_field_unknown::CHECK,
    &route_type_mismatch::CHECK,
    &proto_field_unknown::CHECK,
    &proto_body_empty::CHECK,
];
