//! Readers: decode the input ([`decode`](mod@decode): gzip, character encodings), detect the encoding
//! from the content (not the file name) and read XML, JSON, ClassicVRML or VRML97 into the
//! one scene model. The readers read the decoded UTF-8 text.

pub mod behind;
pub mod classic;
pub mod decode;
mod detect;
mod directive;
pub mod html;
pub mod json;
pub mod rules;
pub mod xml;
mod xml_entities;

pub use behind::Progress;
pub use decode::{decode, Decoded};
pub use detect::{detect, Detected};

use crate::diagnostic::Diagnostic;
use crate::model::{Document, Encoding, Span};

/// What a reader keeps of the numeric MF values of schema fields.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum KeepValues {
    /// Every number (what the standard and deep levels and the renderer read).
    All,
    /// A [`Summary`](crate::model::Summary) of each: what the fast level reads.
    Summaries,
}

/// Reads an input of any supported encoding, keeping every value.
pub fn read(source: &[u8]) -> Parsed {
    read_with(source, KeepValues::All)
}

/// Reads an input of any supported encoding, keeping numeric MF values as `keep` says.
pub fn read_with(source: &[u8], keep: KeepValues) -> Parsed {
    read_with_progress(source, keep, &())
}

/// [`read_with`], telling `progress` how far the reader has got (see [`behind`]).
pub fn read_with_progress(source: &[u8], keep: KeepValues, progress: &dyn Progress) -> Parsed {
    match detect(source) {
        Detected::Xml => xml::read_with(source, keep, progress),
        Detected::Json => json::read_with(source, keep, progress),
        Detected::Classic => classic::read_with(source, keep, progress),
        Detected::Html { xhtml } => html::read_with(source, xhtml, keep, progress),
        Detected::Unsupported(diagnostic) => Parsed {
            encoding: None,
            document: None,
            diagnostics: vec![diagnostic],
        },
    }
}

/// Reads an input as [`read_with_progress`] does, every X3D island of an HTML page apart
/// (an input of another encoding is one document), each with where it starts.
pub fn read_islands(
    source: &[u8],
    keep: KeepValues,
    progress: &dyn Progress,
) -> Vec<(Parsed, Option<Span>)> {
    let Detected::Html { xhtml } = detect(source) else {
        return vec![(read_with_progress(source, keep, progress), None)];
    };
    match html::read_islands(source, xhtml, keep, progress) {
        Ok(islands) if islands.is_empty() => vec![(
            Parsed {
                encoding: Some(Encoding::Xml),
                document: None,
                diagnostics: vec![html::no_island()],
            },
            None,
        )],
        Ok(islands) => islands
            .into_iter()
            .map(|island| (island.parsed, Some(island.span)))
            .collect(),
        Err(diagnostic) => vec![(
            Parsed {
                encoding: None,
                document: None,
                diagnostics: vec![*diagnostic],
            },
            None,
        )],
    }
}

/// The result of reading an input, whatever its encoding.
pub struct Parsed {
    pub encoding: Option<Encoding>,
    pub document: Option<Document>,
    pub diagnostics: Vec<Diagnostic>,
}
