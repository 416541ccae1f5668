//! Inline suppression: an `x3dcheck: ignore CODE[, CODE]` comment drops the findings of
//! those codes in what it applies to (the readers place each comment: see
//! [`Directive`]). A CODE is read as `--ignore` reads it: a code, a prefix of whole words
//! of codes, or `ALL`, in any case ([`select`]). A code that suppresses nothing there, or
//! names no rule, is SUPPRESSION_UNUSED.
//!
//! Applied where a file's findings are gathered ([`crate::check`]), after the
//! configuration's filters and before `--max-diagnostics`, so that the command line and
//! the language server report the same.

use std::collections::HashSet;

use crate::config::CheckConfig;
use crate::config_file::select;
use crate::diagnostic::Diagnostic;
use crate::limits::MAX_DIRECTIVES;
use crate::model::rules::LIMIT_EXCEEDED;
use crate::model::{Directive, Document, Encoding, Span};
use crate::validate::document::suppression_unused::SUPPRESSION_UNUSED;

/// One CODE of a comment: its place and the codes it stands for.
struct Selector {
    written: String,
    span: Span,
    codes: HashSet<&'static str>,
    /// Whether any of its codes' rules runs with this configuration: one that does not
    /// cannot be found unused.
    runs: bool,
    used: bool,
}

/// A comment read: where it applies, its codes, and what is wrong with it.
struct Suppression {
    directive: Directive,
    selectors: Vec<Selector>,
    /// Findings about the comment itself (not a suppression, an unknown code).
    problems: Vec<(Span, String)>,
}

/// Drops from `diagnostics` those the document's comments suppress, adds the
/// SUPPRESSION_UNUSED findings (when that rule runs) and says how many findings were
/// suppressed (a folded finding counts as those it stands for).
pub fn apply(
    doc: &Document,
    text: &[u8],
    config: &CheckConfig,
    diagnostics: &mut Vec<Diagnostic>,
) -> usize {
    if doc.directives.is_empty() {
        return 0;
    }
    let honoured = &doc.directives[..doc.directives.len().min(MAX_DIRECTIVES)];
    let mut suppressions: Vec<Suppression> =
        honoured.iter().map(|d| read(*d, text, config)).collect();
    let mut suppressed = 0;
    diagnostics.retain(|d| {
        let mut hit = false;
        for s in suppressions
            .iter_mut()
            .filter(|s| covers(s.directive.scope, d.span))
        {
            for selector in &mut s.selectors {
                if selector.codes.contains(d.rule.code) {
                    selector.used = true;
                    hit = true;
                }
            }
        }
        if hit {
            suppressed += d.count;
        }
        !hit
    });
    if let Some(first) = doc.directives.get(MAX_DIRECTIVES) {
        diagnostics.push(Diagnostic::new(
            &LIMIT_EXCEEDED,
            first.span,
            format!("more than {MAX_DIRECTIVES} `x3dcheck:` comments in this document; the rest are not read"),
        ));
    }
    suppressed + report_unused(doc.encoding, &mut suppressions, config, diagnostics)
}

/// Whether a finding at `span` lies in `scope` (None: the whole file).
fn covers(scope: Option<Span>, span: Span) -> bool {
    scope.is_none_or(|scope| scope.start <= span.start && span.end <= scope.end)
}

/// Reads the text after `x3dcheck:`: `ignore` and codes separated by commas or spaces.
fn read(directive: Directive, text: &[u8], config: &CheckConfig) -> Suppression {
    let mut suppression = Suppression {
        directive,
        selectors: Vec::new(),
        problems: Vec::new(),
    };
    let words = words(text, directive.text);
    match words.split_first() {
        Some(((first, _), codes)) if first == "ignore" => {
            if codes.is_empty() {
                suppression.problems.push((
                    directive.span,
                    "`x3dcheck: ignore` names no code: write `x3dcheck: ignore CODE[, CODE]`"
                        .into(),
                ));
            }
            for (written, span) in codes {
                match select(written) {
                    Ok(rules) => suppression.selectors.push(Selector {
                        written: written.clone(),
                        span: *span,
                        codes: rules.iter().map(|r| r.code).collect(),
                        runs: rules.iter().any(|r| config.runs(r)),
                        used: false,
                    }),
                    Err(message) => suppression.problems.push((*span, message)),
                }
            }
        }
        _ => suppression.problems.push((
            directive.span,
            "an `x3dcheck:` comment that is not a suppression: write `x3dcheck: ignore CODE[, CODE]`".into(),
        )),
    }
    suppression
}

/// The words of `text[at]` (separated by whitespace and commas), with their places.
fn words(text: &[u8], at: Span) -> Vec<(String, Span)> {
    let bytes = text.get(at.range()).unwrap_or_default();
    let is_separator = |b: u8| b.is_ascii_whitespace() || b == b',';
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if is_separator(bytes[i]) {
            i += 1;
            continue;
        }
        let start = i;
        while i < bytes.len() && !is_separator(bytes[i]) {
            i += 1;
        }
        let word = String::from_utf8_lossy(&bytes[start..i]).into_owned();
        let offset = at.start as usize;
        out.push((word, Span::new(offset + start, offset + i)));
    }
    out
}

/// Adds a SUPPRESSION_UNUSED finding for each unused code and each problem of a comment,
/// unless a whole-file suppression in another comment covers SUPPRESSION_UNUSED; returns
/// how many that suppressed.
fn report_unused(
    encoding: Encoding,
    suppressions: &mut [Suppression],
    config: &CheckConfig,
    diagnostics: &mut Vec<Diagnostic>,
) -> usize {
    if !config.runs(&SUPPRESSION_UNUSED) {
        return 0;
    }
    // (comment, its unused selector if that is the finding, place, message)
    let mut findings = Vec::new();
    for (k, s) in suppressions.iter().enumerate() {
        let place = applies_to(encoding, s.directive.scope);
        for (i, selector) in s.selectors.iter().enumerate() {
            if selector.runs && !selector.used {
                let message = format!(
                    "`x3dcheck: ignore {}` suppresses nothing: no finding of {} in {place}",
                    selector.written,
                    if selector.codes.len() == 1 {
                        "that code"
                    } else {
                        "those codes"
                    },
                );
                findings.push((k, Some(i), selector.span, message));
            }
        }
        for (span, message) in &s.problems {
            findings.push((k, None, *span, message.clone()));
        }
    }
    // First which findings a whole-file suppression of another comment takes (using it),
    // then the rest, but for codes that became used so.
    let mut kept = Vec::new();
    let mut suppressed = 0;
    for (k, selector, span, message) in findings {
        let mut hit = false;
        for (j, other) in suppressions.iter_mut().enumerate() {
            if j == k || other.directive.scope.is_some() {
                continue;
            }
            for other_selector in &mut other.selectors {
                if other_selector.codes.contains(SUPPRESSION_UNUSED.code) {
                    other_selector.used = true;
                    hit = true;
                }
            }
        }
        if hit {
            suppressed += 1;
        } else {
            kept.push((k, selector, span, message));
        }
    }
    for (k, selector, span, message) in kept {
        if selector.is_some_and(|i| suppressions[k].selectors[i].used) {
            continue;
        }
        diagnostics.push(
            Diagnostic::new(&SUPPRESSION_UNUSED, span, message)
                .help("remove it, or move the comment to where the finding is"),
        );
    }
    suppressed
}

/// What a comment applies to, in words.
fn applies_to(encoding: Encoding, scope: Option<Span>) -> &'static str {
    match scope {
        None => "this file",
        Some(scope) if scope.start == scope.end => {
            "what follows this comment (nothing does, in its parent)"
        }
        Some(_) => match encoding {
            Encoding::Xml => "the element that follows this comment",
            Encoding::Json => "the object this comment applies to",
            _ => "the node, statement or field that follows this comment",
        },
    }
}
