//! Grouping component (clause 10): what a Switch's choice names. LOD, a grouping node of
//! the Navigation component, is in `navigation`.

pub mod switch_choice_past_end;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&switch_choice_past_end::CHECK];
