//! Turns diagnostics (byte spans, node handles) into what every emitter prints: line and
//! column, the structural path, and the rule's code and clause. Done once per file while
//! its source is at hand, only for the diagnostics that are reported.

use super::line_index::LineIndex;
use super::path::{node_path, ROOT};
use super::Diagnostic;
use crate::model::{Document, Span};
use crate::validate::Severity;

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Resolved {
    pub code: &'static str,
    pub severity: Severity,
    pub message: String,
    /// 1-based; columns count Unicode scalar values.
    pub line: usize,
    pub column: usize,
    /// Where the span ends (exclusive).
    pub end_line: usize,
    pub end_column: usize,
    pub path: String,
    pub clause: &'static str,
    pub index: Option<usize>,
    pub value: Option<String>,
    pub help: Option<String>,
    pub related: Vec<Related>,
    pub count: usize,
    pub span: Span,
}

/// Another place that explains a diagnostic ("first defined here").
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Related {
    pub line: usize,
    pub column: usize,
    pub label: String,
    pub span: Span,
}

pub fn resolve(diagnostics: &[Diagnostic], source: &[u8], doc: Option<&Document>) -> Vec<Resolved> {
    if diagnostics.is_empty() {
        return Vec::new();
    }
    let lines = LineIndex::new(source);
    diagnostics
        .iter()
        .map(|d| {
            let start = lines.line_col(d.span.start as usize);
            let end = lines.line_col(d.span.end.max(d.span.start) as usize);
            let path = match (doc, d.node) {
                (Some(doc), Some(node)) => node_path(doc, node),
                _ => ROOT.to_string(),
            };
            Resolved {
                code: d.rule.code,
                severity: d.severity,
                message: d.message.clone(),
                line: start.line,
                column: start.column,
                end_line: end.line,
                end_column: end.column,
                path,
                clause: d.rule.clause,
                index: d.index,
                value: d.value.clone(),
                help: d.help.clone(),
                related: d
                    .related
                    .iter()
                    .map(|(span, label)| {
                        let at = lines.line_col(span.start as usize);
                        Related {
                            line: at.line,
                            column: at.column,
                            label: label.clone(),
                            span: *span,
                        }
                    })
                    .collect(),
                count: d.count,
                span: d.span,
            }
        })
        .collect()
}
