//! The X3D schema tables: node types, their fields and components, and the profiles, per version.

pub mod clauses;
pub mod profiles;
pub mod types;
pub mod versions;
// Generated and checked for freshness byte for byte, so rustfmt must leave it alone.
#[rustfmt::skip]
pub mod generated;

pub use generated::schema;
pub use types::*;
