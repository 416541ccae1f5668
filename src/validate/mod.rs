//! The rules of `RULES.md`, one per file, grouped by component. [`check`] runs those the
//! configuration enables on a parsed document; rules found while reading are reported by
//! the readers and the model builder and only filtered here.

pub mod document;
mod registry;
mod rule;
pub mod suggest;

pub use registry::{find_rule, RULES};
pub use rule::{Level, Rule, Severity};

use crate::config::CheckConfig;
use crate::model::{Document, FieldEntry, Span};
use crate::report::Diagnostic;
use crate::schema::Version;

/// What a rule's check sees: the document and its source, its version and where to report.
pub struct Ctx<'a> {
    pub doc: &'a Document,
    pub source: &'a [u8],
    /// The version whose rules apply (the document's, or the latest when it names none).
    pub version: Version,
    pub config: &'a CheckConfig,
    diagnostics: Vec<Diagnostic>,
}

impl Ctx<'_> {
    pub fn report(&mut self, diagnostic: Diagnostic) {
        self.diagnostics.push(diagnostic);
    }

    /// The place of the `k`-th number of a field's value (XML attribute text or JSON array),
    /// or the whole value when it cannot be told.
    pub fn scalar_span(&self, entry: &FieldEntry, k: usize) -> Span {
        let range = entry.span.range();
        let Some(text) = self.source.get(range.clone()) else {
            return entry.span;
        };
        let is_separator = |b: u8| b.is_ascii_whitespace() || matches!(b, b',' | b'[' | b']');
        let (mut at, mut seen) = (0, 0);
        while at < text.len() {
            if is_separator(text[at]) {
                at += 1;
                continue;
            }
            let start = at;
            while at < text.len() && !is_separator(text[at]) {
                at += 1;
            }
            if seen == k {
                return Span::new(range.start + start, range.start + at);
            }
            seen += 1;
        }
        entry.span
    }
}

/// Runs every enabled rule with a check on `doc`.
pub fn check(doc: &Document, source: &[u8], config: &CheckConfig) -> Vec<Diagnostic> {
    let mut ctx = Ctx {
        doc,
        source,
        version: doc.schema_version(),
        config,
        diagnostics: Vec::new(),
    };
    for rule in RULES {
        if let Some(check) = rule.check {
            if config.runs(rule) {
                check(&mut ctx);
            }
        }
    }
    ctx.diagnostics
}
