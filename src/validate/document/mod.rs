//! Encoding and document rules (RULES.md §1): syntax, schema, DEF/USE. All at the fast level.

use super::Rule;

pub mod component_level_insufficient;
pub mod component_unknown;
pub mod container_field_invalid;
pub mod def_duplicate;
pub mod encoding_unsupported;
pub mod field_deprecated;
pub mod field_duplicate;
pub mod field_enum_invalid;
pub mod field_not_in_version;
pub mod field_not_initializable;
pub mod field_out_of_range;
pub mod field_unknown;
pub mod field_value_nonfinite;
pub mod field_value_syntax;
pub mod json_malformed;
pub mod limit_exceeded;
pub mod node_deprecated;
pub mod node_not_in_version;
pub mod node_type_not_allowed;
pub mod node_unknown;
pub mod profile_missing;
pub mod profile_unknown;
pub mod root_not_x3d;
pub mod sfnode_multiple;
pub mod use_cycle;
pub mod use_type_mismatch;
pub mod use_undefined;
pub mod use_with_fields;
pub mod validation_incomplete;
pub mod vrml_malformed;
pub mod x3d_version_missing;
pub mod x3d_version_unknown;
pub mod xml_malformed;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[
    &xml_malformed::XML_MALFORMED,
    &json_malformed::JSON_MALFORMED,
    &vrml_malformed::VRML_MALFORMED,
    &encoding_unsupported::ENCODING_UNSUPPORTED,
    &root_not_x3d::ROOT_NOT_X3D,
    &x3d_version_missing::X3D_VERSION_MISSING,
    &x3d_version_unknown::X3D_VERSION_UNKNOWN,
    &profile_missing::PROFILE_MISSING,
    &profile_unknown::PROFILE_UNKNOWN,
    &component_unknown::COMPONENT_UNKNOWN,
    &node_unknown::NODE_UNKNOWN,
    &node_not_in_version::NODE_NOT_IN_VERSION,
    &field_unknown::FIELD_UNKNOWN,
    &field_not_in_version::FIELD_NOT_IN_VERSION,
    &field_not_initializable::FIELD_NOT_INITIALIZABLE,
    &field_duplicate::FIELD_DUPLICATE,
    &field_value_syntax::FIELD_VALUE_SYNTAX,
    &field_value_nonfinite::FIELD_VALUE_NONFINITE,
    &field_out_of_range::FIELD_OUT_OF_RANGE,
    &field_enum_invalid::FIELD_ENUM_INVALID,
    &def_duplicate::DEF_DUPLICATE,
    &use_undefined::USE_UNDEFINED,
    &use_with_fields::USE_WITH_FIELDS,
    &use_cycle::USE_CYCLE,
    &use_type_mismatch::USE_TYPE_MISMATCH,
    &limit_exceeded::LIMIT_EXCEEDED,
    &node_type_not_allowed::NODE_TYPE_NOT_ALLOWED,
    &container_field_invalid::CONTAINER_FIELD_INVALID,
    &sfnode_multiple::SFNODE_MULTIPLE,
    &node_deprecated::NODE_DEPRECATED,
    &field_deprecated::FIELD_DEPRECATED,
    &component_level_insufficient::COMPONENT_LEVEL_INSUFFICIENT,
    &validation_incomplete::VALIDATION_INCOMPLETE,
];

/// The index of the first element that fails a test and how many fail, for rules that
/// fold every failure of one field into one diagnostic.
pub(crate) fn failures(ok: impl Iterator<Item = bool>) -> Option<(usize, usize)> {
    ok.enumerate()
        .filter(|(_, ok)| !ok)
        .fold(None, |found, (i, _)| match found {
            None => Some((i, 1)),
            Some((first, count)) => Some((first, count + 1)),
        })
}
