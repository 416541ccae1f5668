//! Shape component (clause 12), RULES.md §2.

use super::Rule;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[];
