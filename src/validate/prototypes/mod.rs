//! Prototypes, RULES.md §8: IS statements (names, types, access types, place) and
//! prototypes that instantiate themselves, at the standard level; at the deep level,
//! external prototypes resolved from local files ([`externs`]) and compared with the
//! ProtoDeclares they name.

use super::Check;

pub mod definitions;
pub mod externproto_interface_mismatch;
pub mod externproto_not_found;
pub mod externs;
pub mod is_field_unknown;
pub mod is_outside_proto;
pub mod is_type_mismatch;
pub mod proto_cycle;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &proto_cycle::CHECK,
    &is_field_unknown::CHECK,
    &is_type_mismatch::CHECK,
    &is_outside_proto::CHECK,
    &externproto_not_found::CHECK,
    &externproto_interface_mismatch::CHECK,
];
