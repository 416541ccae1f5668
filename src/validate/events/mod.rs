//! Events and prototypes, RULES.md §6.

use super::Rule;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[];
