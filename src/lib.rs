//! x3dcheck: checks X3D scene documents (XML and JSON encodings) against ISO/IEC 19775-1
//! and reports like a compiler.
//!
//! bytes ─parse→ [`model::Document`] ─validate→ [`diagnostic::Diagnostic`]s ─report→ formats
//!
//! Programs (and the Python and Node.js packages in `bindings/`) call [`api`]: a scene in
//! memory or a file, checked as the command line checks it, into the command line's JSON
//! report as a typed value. [`cli::main`] is the command line itself.

pub mod api;
mod batch;
pub mod check;
pub mod cli;
pub mod config;
pub mod config_file;
pub mod diagnostic;
pub mod fix;
pub mod library;
pub mod limits;
pub mod lsp;
pub mod model;
pub mod parse;
pub mod read;
pub mod render;
pub mod report;
pub mod schema;
pub mod shard;
pub mod suppress;
pub mod validate;

pub use check::check_source;
