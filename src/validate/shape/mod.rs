//! Shape component (clause 12), RULES.md §2. Rules that depend on how an Appearance meets
//! a geometry (texture mappings, backMaterial with `solid`, unlit normals) judge each
//! Appearance × geometry pair the scene forms, since both are shared by USE
//! (`analysis::shape_pairs`); the 12.2.4 resolution itself is
//! [`crate::model::texture_mapping`], shared with the renderer.

use super::Check;

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
pub static RULES: &[&Check] = &[
    &back_material_without_material::CHECK,
    &back_material_with_two_sided::CHECK,
    &back_material_class_mismatch::CHECK,
    &back_material_texture_mismatch::CHECK,
    &back_material_texture_not_shared::CHECK,
    &back_material_mapping_mismatch::CHECK,
    &back_material_no_effect::CHECK,
    &texcoord_mapping_duplicate::CHECK,
    &texture_mapping_unresolved::CHECK,
    &texture_transform_mapping_unresolved::CHECK,
    &texture_transform_mapping_duplicate::CHECK,
    &texture_mapping_without_texture::CHECK,
    &appearance_texture_ignored::CHECK,
    &point_size_min_exceeds_max::CHECK,
    &hatch_style_unsupported::CHECK,
    &linetype_unsupported::CHECK,
    &marker_type_unsupported::CHECK,
    &shape_geometry_missing::CHECK,
    &shaders_replace_lighting::CHECK,
    &alpha_cutoff_unused::CHECK,
    &unlit_normals_unused::CHECK,
    &lines_emissive_black::CHECK,
    &bbox_too_small::CHECK,
    &color_ignored_by_texture::CHECK,
];
