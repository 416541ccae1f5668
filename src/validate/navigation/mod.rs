//! Navigation component (clause 23), and GeoViewpoint (25), an X3DViewpointNode.

pub mod viewpoint_orientation_axis_zero;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&viewpoint_orientation_axis_zero::CHECK];
