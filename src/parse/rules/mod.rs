//! The rules the readers report while reading (RULES.md §1 and §7): an input in no
//! encoding x3dcheck reads, text that does not parse, values that do not parse as their
//! field's type. One rule per file, as under [`crate::validate`].

pub mod encoding_unsupported;
pub mod field_value_syntax;
pub mod gzip_corrupt;
pub mod html_scene_missing;
pub mod html_self_closed;
pub mod json_malformed;
pub mod root_not_x3d;
pub mod use_with_fields;
pub mod vrml_malformed;
pub mod x3dom_extension;
pub mod x3dom_value_syntax;
pub mod xml_encoding_unsupported;
pub mod xml_malformed;

pub use encoding_unsupported::ENCODING_UNSUPPORTED;
pub use field_value_syntax::FIELD_VALUE_SYNTAX;
pub use gzip_corrupt::GZIP_CORRUPT;
pub use html_scene_missing::HTML_SCENE_MISSING;
pub use html_self_closed::HTML_SELF_CLOSED;
pub use json_malformed::JSON_MALFORMED;
pub use root_not_x3d::ROOT_NOT_X3D;
pub use use_with_fields::USE_WITH_FIELDS;
pub use vrml_malformed::VRML_MALFORMED;
pub use x3dom_extension::X3DOM_EXTENSION;
pub use x3dom_value_syntax::X3DOM_VALUE_SYNTAX;
pub use xml_encoding_unsupported::XML_ENCODING_UNSUPPORTED;
pub use xml_malformed::XML_MALFORMED;
