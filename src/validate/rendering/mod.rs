//! Rendering component (clause 11), RULES.md §3.

use super::Rule;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[];
