//! Rendering component (clause 11), RULES.md §3, with the Geometry3D (13.3) and
//! CADGeometry (32.4) polygonal nodes that share its index and attribute rules.

use super::Check;

pub mod face_crossing;
pub mod face_survey;
pub mod geometry;

pub mod attribute_count_insufficient;
pub mod color_per_vertex_ignored;
pub mod coord_missing;
pub mod count_exceeds_coords;
pub mod count_leaves_coords;
pub mod degenerate_triangle;
pub mod face_not_convex;
pub mod face_not_planar;
pub mod face_self_intersecting;
pub mod height_count_mismatch;
pub mod index_count_mismatch;
pub mod index_negative;
pub mod index_out_of_range;
pub mod normal_not_unit;
pub mod normal_zero;
pub mod normals_contradict_ccw;
pub mod polyline_too_short;
pub mod strip_fan_too_short;
pub mod triangle_count_not_multiple;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &index_out_of_range::CHECK,
    &index_negative::CHECK,
    &triangle_count_not_multiple::CHECK,
    &strip_fan_too_short::CHECK,
    &polyline_too_short::CHECK,
    &count_exceeds_coords::CHECK,
    &count_leaves_coords::CHECK,
    &attribute_count_insufficient::CHECK,
    &coord_missing::CHECK,
    &color_per_vertex_ignored::CHECK,
    &normal_zero::CHECK,
    &normal_not_unit::CHECK,
    &normals_contradict_ccw::CHECK,
    &degenerate_triangle::CHECK,
    &index_count_mismatch::CHECK,
    &face_not_convex::CHECK,
    &face_not_planar::CHECK,
    &face_self_intersecting::CHECK,
    &height_count_mismatch::CHECK,
];
