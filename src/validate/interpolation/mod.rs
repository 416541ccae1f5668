//! Interpolation component (clause 19), and the interpolators of other components built on
//! X3DInterpolatorNode (GeoPositionInterpolator, 25).

pub mod key_decreasing;
pub mod key_value_count_mismatch;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&key_value_count_mismatch::CHECK, &key_decreasing::CHECK];
