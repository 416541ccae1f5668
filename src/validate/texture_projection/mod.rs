//! Texture projection component (clause 42): the projectors' direction.

pub mod texture_projector_direction_zero;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&texture_projector_direction_zero::CHECK];
