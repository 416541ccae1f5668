//! Turns diagnostics (byte spans, node handles) into what every emitter prints: line and
//! column, the structural path, and the rule's code and clause. Done once per file while
//! its source is at hand, only for the diagnostics that are reported.

use super::line_index::LineIndex;
use super::path::{NodePaths, ROOT};
use super::Diagnostic;
use crate::diagnostic::Fix;
use crate::model::{Document, NodeKind, Span};
use crate::schema::clauses;
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
    /// For a folded diagnostic, the first indices it stands for.
    pub indices: Vec<usize>,
    pub value: Option<String>,
    pub help: Option<String>,
    pub related: Vec<Related>,
    pub count: usize,
    pub span: Span,
    /// The edits that resolve the finding, where its rule knows them (for `--fix` and the
    /// language server's code actions; not part of the JSON report).
    pub fix: Option<Box<Fix>>,
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
    // Every offset at once, ascending, so that a long line is scanned once.
    let mut offsets: Vec<usize> = diagnostics
        .iter()
        .flat_map(|d| {
            let related = d.related.iter().map(|(span, _)| span.start as usize);
            [d.span.start as usize, d.span.end.max(d.span.start) as usize]
                .into_iter()
                .chain(related)
        })
        .collect();
    offsets.sort_unstable();
    offsets.dedup();
    let positions = LineIndex::new(source).line_cols(&offsets);
    let at = |offset: u32| positions[offsets.binary_search(&(offset as usize)).unwrap_or(0)];
    let paths = doc.map(NodePaths::new);
    diagnostics
        .iter()
        .map(|d| {
            let start = at(d.span.start);
            let end = at(d.span.end.max(d.span.start));
            let path = match (&paths, d.node) {
                (Some(paths), Some(node)) => paths.path(node),
                (Some(paths), None) => paths.path_at(d.span),
                (None, _) => ROOT.to_string(),
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
                clause: clause_of(d, doc),
                index: d.index,
                indices: d.indices.clone(),
                value: d.value.clone(),
                help: d.help.clone(),
                related: d
                    .related
                    .iter()
                    .map(|(span, label)| {
                        let place = at(span.start);
                        Related {
                            line: place.line,
                            column: place.column,
                            label: label.clone(),
                            span: *span,
                        }
                    })
                    .collect(),
                count: d.count,
                span: d.span,
                fix: d.fix.clone(),
            }
        })
        .collect()
}

/// The clause a diagnostic cites: its rule's, or, when the rule cites a node type's
/// subclause, the subclause of the node type it concerns (a SpotLight's direction cites
/// SpotLight's, a QuadSet's count CADGeometry's).
fn clause_of(d: &Diagnostic, doc: Option<&Document>) -> &'static str {
    if !clauses::is_node_subclause(d.rule.clause) {
        return d.rule.clause;
    }
    let node = doc
        .zip(d.node)
        .and_then(|(doc, id)| doc.nodes.get(id.index()));
    match node.map(|n| &n.kind) {
        Some(NodeKind::Known { def, version }) => {
            clauses::node_subclause(*version, def.name).unwrap_or(d.rule.clause)
        }
        _ => d.rule.clause,
    }
}
