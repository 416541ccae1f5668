//! Lighting component (clause 17), RULES.md §4.

use super::Rule;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[];
