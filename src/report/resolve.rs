//! Turns diagnostics (byte spans, node handles) into what every emitter prints: line and
//! column, the structural path, and the rule's code and clause. Done once per file while
//! its source is at hand, only for the diagnostics that are reported.

use super::line_index::LineIndex;
use super::path::{NodePaths, ROOT};
use crate::diagnostic::{Applicability, Diagnostic, Severity};
use crate::model::{Document, Encoding, NodeKind, Span};
use crate::parse::rules::vrml_malformed::VRML_MALFORMED;
use crate::parse::Progress;
use crate::schema::clauses;

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
    /// The edits that resolve the finding, with their places.
    pub fix: Option<ResolvedFix>,
}

impl Resolved {
    /// Whether the finding has a fix that a run applies: a safe one, or any with
    /// `--unsafe-fixes` (`unsafe_fixes`).
    pub fn fixable(&self, unsafe_fixes: bool) -> bool {
        self.fix
            .as_ref()
            .is_some_and(|f| unsafe_fixes || f.applicability == Applicability::Safe)
    }

    /// `"[*] "` before the message of a finding [`fixable`](Self::fixable) so, as ruff marks.
    pub fn fix_mark(&self, unsafe_fixes: bool) -> &'static str {
        if self.fixable(unsafe_fixes) {
            "[*] "
        } else {
            ""
        }
    }
}

/// A [`Fix`](crate::diagnostic::Fix) with the line and column of each edit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ResolvedFix {
    pub title: String,
    pub applicability: Applicability,
    pub edits: Vec<ResolvedEdit>,
}

/// One edit: the text between (line, column) and (end_line, end_column) becomes
/// `replacement`. `span` is its byte range (empty in a report read back from JSON).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ResolvedEdit {
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    pub replacement: String,
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

/// The diagnostics as reported; `progress` is told how far the passes over `source` for
/// lines and columns have got.
pub fn resolve(
    diagnostics: &[Diagnostic],
    source: &[u8],
    progress: &dyn Progress,
    doc: Option<&Document>,
) -> Vec<Resolved> {
    if diagnostics.is_empty() {
        return Vec::new();
    }
    // Every offset at once, ascending, so that a long line is scanned once.
    let mut offsets: Vec<usize> = diagnostics
        .iter()
        .flat_map(|d| {
            let related = d.related.iter().map(|(span, _)| span.start as usize);
            let edits = d
                .fix
                .iter()
                .flat_map(|f| &f.edits)
                .flat_map(|e| [e.span.start as usize, e.span.end.max(e.span.start) as usize]);
            [d.span.start as usize, d.span.end.max(d.span.start) as usize]
                .into_iter()
                .chain(related)
                .chain(edits)
        })
        .collect();
    offsets.sort_unstable();
    offsets.dedup();
    let positions = LineIndex::new(source, progress).line_cols(&offsets);
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
                fix: d.fix.as_ref().map(|fix| ResolvedFix {
                    title: fix.title.clone(),
                    applicability: fix.applicability,
                    edits: fix
                        .edits
                        .iter()
                        .map(|e| {
                            let (start, end) = (at(e.span.start), at(e.span.end.max(e.span.start)));
                            ResolvedEdit {
                                line: start.line,
                                column: start.column,
                                end_line: end.line,
                                end_column: end.column,
                                replacement: e.replacement.clone(),
                                span: e.span,
                            }
                        })
                        .collect(),
                }),
            }
        })
        .collect()
}

/// What a VRML97 file's syntax finding cites: the grammar of ISO/IEC 14772-1, Annex A.
pub(crate) const VRML97_GRAMMAR: &str = "14772-1 A";

/// The clause a diagnostic cites: the one it names itself, else its rule's, or, when the
/// rule cites a node type's subclause, the subclause of the node type it concerns (a
/// SpotLight's direction cites SpotLight's, a QuadSet's count CADGeometry's).
fn clause_of(d: &Diagnostic, doc: Option<&Document>) -> &'static str {
    if let Some(clause) = d.clause {
        return clause;
    }
    // A VRML97 file breaks 14772-1's grammar, not the ClassicVRML one of 19776-2.
    if std::ptr::eq(d.rule, &VRML_MALFORMED)
        && doc.is_some_and(|doc| doc.encoding == Encoding::Vrml97)
    {
        return VRML97_GRAMMAR;
    }
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
