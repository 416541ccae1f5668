//! Geometry2D component (clause 14): what the 2D geometry nodes' fields shall satisfy
//! together. TriangleSet2D's vertex count is TRIANGLE_COUNT_NOT_MULTIPLE's, with the other
//! triangle sets.

pub mod disk2d_radii_inverted;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&disk2d_radii_inverted::CHECK];
