//! Encoding and document rules (RULES.md §1): syntax, schema, DEF/USE. All at the fast level.

use super::Check;

pub mod component_level_insufficient;
pub mod component_unknown;
pub mod container_field_invalid;
pub mod field_deprecated;
pub mod field_enum_invalid;
pub mod field_not_in_version;
pub mod field_not_initializable;
pub mod field_out_of_range;
pub mod field_unknown;
pub mod field_value_nonfinite;
pub mod node_deprecated;
pub mod node_not_in_version;
pub mod node_type_not_allowed;
pub mod node_unknown;
pub mod profile_missing;
pub mod profile_unknown;
pub mod root_content_ignored;
pub mod sfnode_multiple;
pub mod suppression_unused;
pub mod unit_category_duplicate;
pub mod validation_incomplete;
pub mod x3d_version_missing;
pub mod x3d_version_unknown;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &Check::reported(&crate::parse::rules::XML_MALFORMED),
    &Check::reported(&crate::parse::rules::JSON_MALFORMED),
    &Check::reported(&crate::parse::rules::VRML_MALFORMED),
    &Check::reported(&crate::parse::rules::ENCODING_UNSUPPORTED),
    &Check::reported(&crate::parse::rules::ROOT_NOT_X3D),
    &Check::reported(&crate::parse::rules::HTML_SCENE_MISSING),
    &Check::reported(&crate::parse::rules::HTML_SELF_CLOSED),
    &Check::reported(&crate::parse::rules::X3DOM_EXTENSION),
    &Check::reported(&crate::parse::rules::X3DOM_VALUE_SYNTAX),
    &x3d_version_missing::CHECK,
    &x3d_version_unknown::CHECK,
    &profile_missing::CHECK,
    &profile_unknown::CHECK,
    &component_unknown::CHECK,
    &node_unknown::CHECK,
    &node_not_in_version::CHECK,
    &field_unknown::CHECK,
    &field_not_in_version::CHECK,
    &field_not_initializable::CHECK,
    &Check::reported(&crate::model::rules::FIELD_DUPLICATE),
    &Check::reported(&crate::parse::rules::FIELD_VALUE_SYNTAX),
    &field_value_nonfinite::CHECK,
    &field_out_of_range::CHECK,
    &field_enum_invalid::CHECK,
    &Check::reported(&crate::model::rules::DEF_DUPLICATE),
    &Check::reported(&crate::model::rules::USE_UNDEFINED),
    &Check::reported(&crate::parse::rules::USE_WITH_FIELDS),
    &Check::reported(&crate::model::rules::USE_CYCLE),
    &Check::reported(&crate::model::rules::USE_TYPE_MISMATCH),
    &Check::reported(&crate::model::rules::LIMIT_EXCEEDED),
    &node_type_not_allowed::CHECK,
    &container_field_invalid::CHECK,
    &sfnode_multiple::CHECK,
    &node_deprecated::CHECK,
    &field_deprecated::CHECK,
    &component_level_insufficient::CHECK,
    &validation_incomplete::CHECK,
    &root_content_ignored::CHECK,
    &unit_category_duplicate::CHECK,
    &Check::reported(&crate::parse::rules::GZIP_CORRUPT),
    &Check::reported(&crate::parse::rules::XML_ENCODING_UNSUPPORTED),
    &Check::reported(&suppression_unused::SUPPRESSION_UNUSED),
];

/// The index of the first element that fails a test and how many fail, for rules that
/// fold every failure of one field into one diagnostic.
pub(crate) fn failures<T: Copy>(values: &[T], ok: impl Fn(T) -> bool) -> Option<(usize, usize)> {
    // Nearly every field passes: a first pass without branches (which the compiler turns
    // into vector code) settles that for a tenth of the counting loop's cost.
    if values.iter().fold(true, |all, &x| all & ok(x)) {
        return None;
    }
    values
        .iter()
        .enumerate()
        .filter(|&(_, &x)| !ok(x))
        .fold(None, |found, (i, _)| match found {
            None => Some((i, 1)),
            Some((first, count)) => Some((first, count + 1)),
        })
}
