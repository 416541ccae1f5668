//! Geometry3D component (clause 13): what the 3D geometry nodes' fields shall satisfy
//! together.

pub mod extrusion_count_mismatch;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&extrusion_count_mismatch::CHECK];
