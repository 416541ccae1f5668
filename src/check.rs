//! Checking one input: decode it (gzip, character encodings), detect the encoding, read it into the model, run the rules, and
//! resolve what is reported (line, column, path) while the source is at hand.

use std::borrow::Cow;
use std::path::Path;

use crate::config::CheckConfig;
use crate::diagnostic::{Diagnostic, Level};
use crate::library::Library;
use crate::model::{Document, Encoding};
use crate::parse;
pub use crate::parse::Parsed;
use crate::parse::Progress;
use crate::report::{resolve, FileReport, Stats};
use crate::validate;
use crate::validate::prototypes::externs::{self, Externs};

/// The name standard input is reported under; such a document has no directory.
pub const STDIN_NAME: &str = "<stdin>";

/// Checks one input. `path` names the file in the report, and its directory is where the
/// deep level resolves relative URLs (none for [`STDIN_NAME`]).
pub fn check_source(path: &str, source: &[u8], config: &CheckConfig) -> FileReport {
    check_document(path, source, config).report
}

/// What [`check_document`] hands back.
pub struct Checked<'a> {
    pub report: FileReport,
    /// The document read (None when the input is not a document). At the fast level its
    /// numeric MF values are [`Summary`](crate::model::Summary)s unless `config.render` is
    /// set ([`CheckConfig::keep_values`]).
    pub document: Option<Document>,
    /// The decoded text (decompressed, UTF-8: see [`parse::decode()`]) that the report's
    /// positions and the document's spans are offsets into; what to show as the source.
    pub text: Cow<'a, [u8]>,
}

/// [`check_source`], also handing back the document it read, so that a caller such as the
/// renderer need not parse it again, and the text it read.
pub fn check_document<'a>(path: &str, source: &'a [u8], config: &CheckConfig) -> Checked<'a> {
    check_document_with_progress(path, source, config, &())
}

/// [`check_document`], telling `progress` how far each pass over the whole text has got
/// (see [`parse::behind`]): a mapped file gives back what they have read.
pub fn check_document_with_progress<'a>(
    path: &str,
    source: &'a [u8],
    config: &CheckConfig,
    progress: &dyn Progress,
) -> Checked<'a> {
    let decoded = parse::decode::decode_with_progress(source, progress);
    check_decoded(path, decoded, config, progress)
}

/// The report of an input not read because it is larger than
/// [`MAX_INPUT_BYTES`](crate::limits::MAX_INPUT_BYTES): LIMIT_EXCEEDED. For callers that
/// stop reading at the limit, as the command line does, rather than hold more.
pub fn check_too_large(path: &str, config: &CheckConfig) -> FileReport {
    check_decoded(path, parse::decode::too_large_input(), config, &()).report
}

fn check_decoded<'a>(
    path: &str,
    decoded: parse::Decoded<'a>,
    config: &CheckConfig,
    progress: &dyn Progress,
) -> Checked<'a> {
    let text = decoded.text;
    let islands = match decoded.failure {
        Some(failure) => vec![(
            Parsed {
                encoding: None,
                document: None,
                diagnostics: vec![failure],
            },
            None,
        )],
        None => parse::read_islands(&text, config.keep_values(), progress),
    };
    // Each island of an HTML page is a scene of its own; the report holds them all, each
    // finding named by its island when there are several.
    let count = islands.len();
    let mut report: Option<FileReport> = None;
    let mut document = None;
    for (index, (parsed, start)) in islands.into_iter().enumerate() {
        let (mut island_report, island_document) =
            check_parsed(path, parsed, decoded.compressed, &text, config, progress);
        if index + 1 == config.island.max(1) || count == 1 {
            document = island_document;
        }
        if count > 1 {
            let line = start.map_or(1, |s| {
                1 + memchr::memchr_iter(b'\n', &text[..s.start as usize]).count()
            });
            for d in &mut island_report.diagnostics {
                d.message = format!(
                    "island {} of {count} (line {line}): {}",
                    index + 1,
                    d.message
                );
            }
        }
        match &mut report {
            None => report = Some(island_report),
            Some(first) => {
                first.diagnostics.extend(island_report.diagnostics);
                first.truncated |= island_report.truncated;
                first.suppressed += island_report.suppressed;
            }
        }
    }
    let mut report = report.expect("reading gives at least one document or finding");
    if count > 1 {
        report
            .diagnostics
            .sort_by(|a, b| (a.line, a.column, a.code).cmp(&(b.line, b.column, b.code)));
    }
    Checked {
        report,
        document,
        text,
    }
}

/// Checks one document read from `text` (a file, or one island of a page): the report, and
/// the document for the caller.
fn check_parsed(
    path: &str,
    parsed: Parsed,
    compressed: bool,
    text: &[u8],
    config: &CheckConfig,
    progress: &dyn Progress,
) -> (FileReport, Option<Document>) {
    let mut diagnostics = parsed.diagnostics;
    let file = (path != STDIN_NAME).then(|| Path::new(path));
    let deep = config.level >= Level::Deep;
    // External prototypes are resolved at the deep level, and for the renderer (after the
    // check, so that --render does not change the report).
    let mut externs = Externs::default();
    let mut document = parsed.document.map(|doc| {
        if !(deep || config.render) {
            return doc;
        }
        externs = Externs::resolve(&doc, file, config);
        if deep {
            instantiate_externals(doc, file, config, &externs, &mut diagnostics)
        } else {
            doc
        }
    });
    let externs_for_rules = if deep {
        externs.clone()
    } else {
        Externs::default()
    };
    let report = report_of(
        path,
        diagnostics,
        parsed.encoding,
        compressed,
        document.as_ref(),
        text,
        progress,
        config,
        externs_for_rules,
    );
    if !deep && config.render {
        if let Some(doc) = document.take() {
            let mut limits = Vec::new();
            document = Some(instantiate_externals(
                doc,
                file,
                config,
                &externs,
                &mut limits,
            ));
        }
    }
    (report, document)
}

/// The report of a file an Inline loads, from the file as the batch read and parsed it
/// (once, in [`Libraries`](crate::library::Libraries)), checked as a scene of its own:
/// with its own version, profile and directory. `path` names it in the report.
pub fn check_library(path: &str, library: &Library, config: &CheckConfig) -> FileReport {
    report_of(
        path,
        library.read_findings.clone(),
        library.encoding,
        library.compressed,
        library.document.as_ref(),
        &library.text,
        &(),
        config,
        match &library.document {
            Some(doc) if config.level >= Level::Deep => {
                Externs::resolve(doc, Some(Path::new(path)), config)
            }
            _ => Externs::default(),
        },
    )
}

/// Runs the rules on a document read from `text`, after the findings of reading it, and
/// resolves what is reported (telling `progress` how far the line index has got).
#[allow(clippy::too_many_arguments)] // what reading gave, and what the rules need
fn report_of(
    path: &str,
    mut diagnostics: Vec<Diagnostic>,
    encoding: Option<Encoding>,
    compressed: bool,
    doc: Option<&Document>,
    text: &[u8],
    progress: &dyn Progress,
    config: &CheckConfig,
    externs: Externs,
) -> FileReport {
    let file = (path != STDIN_NAME).then(|| Path::new(path));
    if let Some(doc) = doc {
        diagnostics.extend(validate::check_with(
            doc, text, progress, file, config, externs,
        ));
    }

    diagnostics.retain(|d| config.enabled(d.rule.code) && d.rule.level <= config.level);
    let suppressed = doc.map_or(0, |doc| {
        crate::suppress::apply(doc, text, config, &mut diagnostics)
    });
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
    FileReport {
        path: path.to_string(),
        encoding,
        compressed,
        x3d_version: doc.and_then(|d| d.version_text.as_ref().map(|v| v.text.clone())),
        profile: doc.and_then(|d| d.profile.as_ref().map(|p| p.text.clone())),
        diagnostics: resolve(&diagnostics, text, progress, doc),
        truncated,
        suppressed,
        stats: doc.map(Stats::of).unwrap_or_default(),
    }
}

/// `doc` with its external prototypes instantiated (when one resolves); the findings of
/// the instantiation made when it was read give way to those of this one.
fn instantiate_externals(
    doc: Document,
    file: Option<&Path>,
    config: &CheckConfig,
    externs: &Externs,
    diagnostics: &mut Vec<crate::diagnostic::Diagnostic>,
) -> Document {
    let (doc, found) = externs::instantiate(doc, file, config, externs);
    if let Some(found) = found {
        diagnostics.retain(|d| !crate::model::is_instantiation_limit(d));
        diagnostics.extend(found);
    }
    doc
}
