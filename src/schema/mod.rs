//! The X3D schema tables: node types, their fields and components, and the profiles, per version.

pub mod profiles;
mod range;
pub mod types;
// Generated and checked for freshness byte for byte, so rustfmt must leave it alone.
#[rustfmt::skip]
pub mod generated;

pub use generated::schema;
pub use range::{in_range_f32, in_range_f64, range_text};
pub use types::*;
