//! Encoding and document rules (RULES.md §1): syntax, schema, DEF/USE. All at the fast level.

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
pub mod x3d_version_missing;
pub mod x3d_version_unknown;
pub mod xml_malformed;

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
