//! Picking component (clause 38): the geometry each pick sensor picks with.

pub mod picking_geometry_type_invalid;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&picking_geometry_type_invalid::CHECK];
