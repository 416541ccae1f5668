//! Sound component (clause 16): what the Sound node's fields shall satisfy together.

pub mod sound_min_exceeds_max;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&sound_min_exceeds_max::CHECK];
