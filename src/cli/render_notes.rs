//! `--render` of a file frees its source before the scene is flattened (with the document
//! and the draw list, it made the peak of a large scene's memory); the renderer's notes,
//! when there are any, are placed in the file read again.

use std::hash::{DefaultHasher, Hasher};
use std::path::Path;

use crate::model::Document;
use crate::parse::behind::{Pass, Progress, STEP};
use crate::render::{Preview, Unresolved};
use crate::report::FileReport;

use super::{read_file, render_text, Presentation};

/// What tells the file read again from the one checked: the decoded text's length and hash.
#[derive(PartialEq, Eq)]
pub struct Fingerprint(usize, u64);

impl Fingerprint {
    /// Hashed a [`STEP`] at a time, telling `progress` (a mapped file gives back what was
    /// hashed).
    pub fn of(text: &[u8], progress: &dyn Progress) -> Fingerprint {
        let mut hasher = DefaultHasher::new();
        let mut pass = Pass::new(text, progress);
        for (k, step) in text.chunks(STEP).enumerate() {
            hasher.write(step);
            pass.reached(k * STEP + step.len());
        }
        Fingerprint(text.len(), hasher.finish())
    }
}

/// Adds the renderer's notes to `report`, placed in the file at `path` read again, and
/// draws `text` (the report's text) again with them; without notes nothing is read. Err:
/// the file cannot be read again, or is no longer the text that was checked.
// Without the renderer `Unresolved` has no values, so everything after its first use is
// unreachable; the function is kept so that callers need no feature gates.
#[cfg_attr(not(feature = "render"), allow(unreachable_code, unused_variables))]
pub fn place(
    unresolved: Unresolved,
    path: &Path,
    checked: &Fingerprint,
    doc: &Document,
    report: &mut FileReport,
    text: &mut String,
    shown: Presentation,
) -> Result<Preview, String> {
    if !unresolved.has_notes() {
        return Ok(unresolved.resolve(&[], doc, report));
    }
    let bytes = read_file(path)?;
    let source = crate::parse::decode(&bytes).text;
    if Fingerprint::of(&source, &()) != *checked {
        return Err(format!(
            "{} changed while it was being drawn; run again",
            path.display()
        ));
    }
    let preview = unresolved.resolve(&source, doc, report);
    *text = render_text(report, &source, &(), shown);
    Ok(preview)
}
