//! Layout component (clause 36): how many values a Layout's fields hold.

pub mod layout_value_count;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&layout_value_count::CHECK];
