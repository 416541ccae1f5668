//! Interpolation component (clause 19), and the interpolators of other components built on
//! X3DInterpolatorNode (GeoPositionInterpolator, 25), and the sequencers of the event
//! utilities (30), whose keys follow the same rules.

pub mod ease_in_ease_out_count_mismatch;
pub mod key_decreasing;
pub mod key_value_count_mismatch;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &key_value_count_mismatch::CHECK,
    &key_decreasing::CHECK,
    &ease_in_ease_out_count_mismatch::CHECK,
];
