//! Text component (clause 15): how many values FontStyle.justify and Text.length hold.
//! ScreenFontStyle (36.4.4), an X3DFontStyleNode, shares FontStyle's justify.

pub mod justify_extra_values;
pub mod text_length_extra_values;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &justify_extra_values::CHECK,
    &text_length_extra_values::CHECK,
];
