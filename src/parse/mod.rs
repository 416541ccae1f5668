//! Readers: detect the encoding from the content (not the file name) and read XML or JSON
//! into the one scene model.

mod detect;
pub mod json;
pub mod number;
pub mod xml;
mod xml_entities;
pub mod xml_value;

pub use crate::check::Parsed;
pub use detect::{detect, Detected};

/// Reads an input of any supported encoding.
pub fn read(source: &[u8]) -> Parsed {
    match detect(source) {
        Detected::Xml => xml::read(source),
        Detected::Json => json::read(source),
        Detected::Unsupported(diagnostic) => Parsed {
            encoding: None,
            document: None,
            diagnostics: vec![diagnostic],
        },
    }
}
