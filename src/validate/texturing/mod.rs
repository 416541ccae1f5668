//! Texturing component (clause 18), RULES.md §5.

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

use super::Rule;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[
    &multitexture_extra_modes::MULTITEXTURE_EXTRA_MODES,
    &multitexture_coords_short::MULTITEXTURE_COORDS_SHORT,
    &texgen_parameter_count::TEXGEN_PARAMETER_COUNT,
    &texture_mipmap_required::TEXTURE_MIPMAP_REQUIRED,
    &texture_repeat_ignored::TEXTURE_REPEAT_IGNORED,
    &texture_transform_singular::TEXTURE_TRANSFORM_SINGULAR,
    &pixel_texture_size_mismatch::PIXEL_TEXTURE_SIZE_MISMATCH,
    &image_url_empty::IMAGE_URL_EMPTY,
    &url_unresolved::URL_UNRESOLVED,
    &image_unreadable::IMAGE_UNREADABLE,
    &image_format_unsupported::IMAGE_FORMAT_UNSUPPORTED,
    &movie_format_unsupported::MOVIE_FORMAT_UNSUPPORTED,
];
