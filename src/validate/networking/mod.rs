//! Inline and IMPORT/EXPORT, RULES.md §8: EXPORT statements and the Inline an IMPORT names
//! at the standard level; at the deep level, the scenes local Inlines load ([`inlines`]),
//! files that load themselves, and IMPORT statements resolved against the exports of the
//! inlined files ([`imports`]). Also Anchor's parameter strings (9.4.1).

use super::Check;

pub mod anchor_parameter_malformed;
pub mod export_undefined;
pub mod import_inline_undefined;
pub mod import_unresolved;
pub mod imports;
pub mod inline_components_exceed;
pub mod inline_cycle;
pub mod inlines;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &inline_cycle::CHECK,
    &inline_components_exceed::CHECK,
    &export_undefined::CHECK,
    &import_inline_undefined::CHECK,
    &import_unresolved::CHECK,
    &anchor_parameter_malformed::CHECK,
];
