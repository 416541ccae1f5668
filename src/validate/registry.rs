//! Every rule, in catalogue order. `x3dcheck rules`, the docs and the checks all read this.

use super::document::*;
use super::Rule;

pub static RULES: &[&Rule] = &[
    // §1 Encoding and document
    &xml_malformed::XML_MALFORMED,
    &json_malformed::JSON_MALFORMED,
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
    &node_type_not_allowed::NODE_TYPE_NOT_ALLOWED,
    &container_field_invalid::CONTAINER_FIELD_INVALID,
    &sfnode_multiple::SFNODE_MULTIPLE,
    &node_deprecated::NODE_DEPRECATED,
    &field_deprecated::FIELD_DEPRECATED,
    &component_level_insufficient::COMPONENT_LEVEL_INSUFFICIENT,
    &validation_incomplete::VALIDATION_INCOMPLETE,
];

pub fn find_rule(code: &str) -> Option<&'static Rule> {
    RULES.iter().copied().find(|r| r.code == code)
}
