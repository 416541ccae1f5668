//! Navigation component (clause 23), and GeoViewpoint (25), an X3DViewpointNode; the
//! binding stacks of NavigationInfo, Background and Fog (7.2.2).

pub mod bindable_never_bound;
pub mod lod_level_count_mismatch;
pub mod lod_range_not_increasing;
pub mod navigation_type_malformed;
pub mod ortho_field_of_view_invalid;
pub mod viewpoint_orientation_axis_zero;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &viewpoint_orientation_axis_zero::CHECK,
    &bindable_never_bound::CHECK,
    &navigation_type_malformed::CHECK,
    &lod_range_not_increasing::CHECK,
    &lod_level_count_mismatch::CHECK,
    &ortho_field_of_view_invalid::CHECK,
];
