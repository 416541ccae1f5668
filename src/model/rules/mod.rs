//! The rules the model builder reports while a reader drives it (RULES.md §1): DEF/USE
//! and name scopes, a field given twice, and the limits that keep hostile input bounded.
//! One rule per file, as under [`crate::validate`].

pub mod def_duplicate;
pub mod field_duplicate;
pub mod limit_exceeded;
pub mod use_cycle;
pub mod use_type_mismatch;
pub mod use_undefined;

pub use def_duplicate::DEF_DUPLICATE;
pub use field_duplicate::FIELD_DUPLICATE;
pub use limit_exceeded::LIMIT_EXCEEDED;
pub use use_cycle::USE_CYCLE;
pub use use_type_mismatch::USE_TYPE_MISMATCH;
pub use use_undefined::USE_UNDEFINED;
