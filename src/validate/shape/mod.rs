//! Shape component (clause 12), RULES.md §2. Rules that depend on how an Appearance meets
//! a geometry (texture mappings, backMaterial with `solid`, unlit normals) judge each
//! Appearance × geometry pair the scene forms, since both are shared by USE
//! ([`analysis::shape_pairs`]); the 12.2.4 resolution itself is
//! [`crate::model::texture_mapping`], shared with the renderer.

use super::Rule;

mod analysis;
mod back_textures;

pub mod alpha_cutoff_unused;
pub mod appearance_texture_ignored;
pub mod back_material_class_mismatch;
pub mod back_material_mapping_mismatch;
pub mod back_material_no_effect;
pub mod back_material_texture_mismatch;
pub mod back_material_texture_not_shared;
pub mod back_material_with_two_sided;
pub mod back_material_without_material;
pub mod bbox_too_small;
pub mod color_ignored_by_texture;
pub mod hatch_style_unsupported;
pub mod lines_emissive_black;
pub mod linetype_unsupported;
pub mod marker_type_unsupported;
pub mod point_size_min_exceeds_max;
pub mod shaders_replace_lighting;
pub mod shape_geometry_missing;
pub mod texcoord_mapping_duplicate;
pub mod texture_mapping_unresolved;
pub mod texture_mapping_without_texture;
pub mod texture_transform_mapping_duplicate;
pub mod texture_transform_mapping_unresolved;
pub mod unlit_normals_unused;

/// This group's rules, in catalogue order (BBOX_TOO_SMALL, also §2, is not here yet).
pub static RULES: &[&Rule] = &[
    &back_material_without_material::BACK_MATERIAL_WITHOUT_MATERIAL,
    &back_material_with_two_sided::BACK_MATERIAL_WITH_TWO_SIDED,
    &back_material_class_mismatch::BACK_MATERIAL_CLASS_MISMATCH,
    &back_material_texture_mismatch::BACK_MATERIAL_TEXTURE_MISMATCH,
    &back_material_texture_not_shared::BACK_MATERIAL_TEXTURE_NOT_SHARED,
    &back_material_mapping_mismatch::BACK_MATERIAL_MAPPING_MISMATCH,
    &back_material_no_effect::BACK_MATERIAL_NO_EFFECT,
    &texcoord_mapping_duplicate::TEXCOORD_MAPPING_DUPLICATE,
    &texture_mapping_unresolved::TEXTURE_MAPPING_UNRESOLVED,
    &texture_transform_mapping_unresolved::TEXTURE_TRANSFORM_MAPPING_UNRESOLVED,
    &texture_transform_mapping_duplicate::TEXTURE_TRANSFORM_MAPPING_DUPLICATE,
    &texture_mapping_without_texture::TEXTURE_MAPPING_WITHOUT_TEXTURE,
    &appearance_texture_ignored::APPEARANCE_TEXTURE_IGNORED,
    &point_size_min_exceeds_max::POINT_SIZE_MIN_EXCEEDS_MAX,
    &hatch_style_unsupported::HATCH_STYLE_UNSUPPORTED,
    &linetype_unsupported::LINETYPE_UNSUPPORTED,
    &marker_type_unsupported::MARKER_TYPE_UNSUPPORTED,
    &shape_geometry_missing::SHAPE_GEOMETRY_MISSING,
    &shaders_replace_lighting::SHADERS_REPLACE_LIGHTING,
    &alpha_cutoff_unused::ALPHA_CUTOFF_UNUSED,
    &unlit_normals_unused::UNLIT_NORMALS_UNUSED,
    &lines_emissive_black::LINES_EMISSIVE_BLACK,
    &bbox_too_small::BBOX_TOO_SMALL,
    &color_ignored_by_texture::COLOR_IGNORED_BY_TEXTURE,
];
