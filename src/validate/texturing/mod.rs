//! Texturing component (clause 18), RULES.md §5.

pub mod composed_texture3d_count_not_power_of_two;
pub mod cube_map_face_size;
pub(crate) mod files;
pub mod image_format_unsupported;
pub mod image_unreadable;
pub mod image_url_empty;
pub mod movie_format_unsupported;
pub mod multitexture_coords_short;
pub mod multitexture_extra_modes;
pub mod pixel_texture_size_mismatch;
pub mod texgen_parameter_count;
pub mod texture_mipmap_required;
pub mod texture_repeat_ignored;
pub mod texture_transform_singular;
pub mod url_unresolved;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &multitexture_extra_modes::CHECK,
    &multitexture_coords_short::CHECK,
    &texgen_parameter_count::CHECK,
    &texture_mipmap_required::CHECK,
    &texture_repeat_ignored::CHECK,
    &texture_transform_singular::CHECK,
    &pixel_texture_size_mismatch::CHECK,
    &composed_texture3d_count_not_power_of_two::CHECK,
    &cube_map_face_size::CHECK,
    &image_url_empty::CHECK,
    &url_unresolved::CHECK,
    &image_unreadable::CHECK,
    &image_format_unsupported::CHECK,
    &movie_format_unsupported::CHECK,
];
