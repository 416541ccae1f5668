//! Checking one input: detect the encoding, read it into the model, run the rules, and
//! resolve what is reported (line, column, path) while the source is at hand.

use std::path::Path;

use crate::config::CheckConfig;
use crate::model::Document;
use crate::parse;
pub use crate::parse::Parsed;
use crate::report::{resolve, FileReport, Stats};
use crate::validate;

/// The name standard input is reported under; such a document has no directory.
pub const STDIN_NAME: &str = "<stdin>";

/// Checks one input. `path` names the file in the report, and its directory is where the
/// deep level resolves relative URLs (none for [`STDIN_NAME`]).
pub fn check_source(path: &str, source: &[u8], config: &CheckConfig) -> FileReport {
    check_document(path, source, config).0
}

/// [`check_source`], also handing back the document it read (None when the input is not
/// a document), so that a caller such as the renderer need not parse it again. At the
/// fast level its numeric MF values are [`Summary`](crate::model::Summary)s unless
/// `config.render` is set ([`CheckConfig::keep_values`]).
pub fn check_document(
    path: &str,
    source: &[u8],
    config: &CheckConfig,
) -> (FileReport, Option<Document>) {
    let parsed = parse::read_with(source, config.keep_values());
    let mut diagnostics = parsed.diagnostics;
    let base = (path != STDIN_NAME).then(|| match Path::new(path).parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    });
    if let Some(doc) = &parsed.document {
        diagnostics.extend(validate::check(doc, source, base, config));
    }
    diagnostics.retain(|d| config.enabled(d.rule.code) && d.rule.level <= config.level);
    for d in &mut diagnostics {
        d.severity = config.severity_of(d.rule.code, d.severity);
    }
    diagnostics.sort_by(|a, b| (a.span.start, a.rule.code).cmp(&(b.span.start, b.rule.code)));
    let truncated = config
        .max_diagnostics
        .is_some_and(|max| diagnostics.len() > max);
    if let Some(max) = config.max_diagnostics {
        diagnostics.truncate(max);
    }
    let doc: Option<&Document> = parsed.document.as_ref();
    let report = FileReport {
        path: path.to_string(),
        encoding: parsed.encoding,
        x3d_version: doc.and_then(|d| d.version_text.as_ref().map(|v| v.text.clone())),
        profile: doc.and_then(|d| d.profile.as_ref().map(|p| p.text.clone())),
        diagnostics: resolve(&diagnostics, source, doc),
        truncated,
        stats: doc.map(Stats::of).unwrap_or_default(),
    };
    (report, parsed.document)
}
