//! Rendering component (clause 11), RULES.md §3, with the Geometry3D (13.3) and
//! CADGeometry (32.4) polygonal nodes that share its index and attribute rules.

use super::Rule;

pub mod geometry;

pub mod attribute_count_insufficient;
pub mod color_per_vertex_ignored;
pub mod coord_missing;
pub mod count_exceeds_coords;
pub mod count_leaves_coords;
pub mod degenerate_triangle;
pub mod height_count_mismatch;
pub mod index_negative;
pub mod index_out_of_range;
pub mod normal_not_unit;
pub mod normal_zero;
pub mod normals_contradict_ccw;
pub mod polyline_too_short;
pub mod strip_fan_too_short;
pub mod triangle_count_not_multiple;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[
    &index_out_of_range::INDEX_OUT_OF_RANGE,
    &index_negative::INDEX_NEGATIVE,
    &triangle_count_not_multiple::TRIANGLE_COUNT_NOT_MULTIPLE,
    &strip_fan_too_short::STRIP_FAN_TOO_SHORT,
    &polyline_too_short::POLYLINE_TOO_SHORT,
    &count_exceeds_coords::COUNT_EXCEEDS_COORDS,
    &count_leaves_coords::COUNT_LEAVES_COORDS,
    &attribute_count_insufficient::ATTRIBUTE_COUNT_INSUFFICIENT,
    &coord_missing::COORD_MISSING,
    &color_per_vertex_ignored::COLOR_PER_VERTEX_IGNORED,
    &normal_zero::NORMAL_ZERO,
    &normal_not_unit::NORMAL_NOT_UNIT,
    &normals_contradict_ccw::NORMALS_CONTRADICT_CCW,
    &degenerate_triangle::DEGENERATE_TRIANGLE,
    &height_count_mismatch::HEIGHT_COUNT_MISMATCH,
];
