//! Texturing component (clause 18), RULES.md §5.

use super::Rule;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[];
