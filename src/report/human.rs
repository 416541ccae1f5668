//! The human format: per diagnostic a compiler-like block (`error[CODE]: message`, the
//! place, the source line with the span underlined and labelled, help, clause and path),
//! and the summary line the CLI prints last.
//!
//! miette draws the snippets, but it is never given the whole source: it scans from the
//! start of what it gets to the span, and prints whole lines. Each label instead gets an
//! excerpt (its line and one line of context, or a cut window of a long line) placed in a
//! virtual offset space of its own, so an 86 MB single-line file costs what a small one does.

use std::fmt::{self, Write as _};

use miette::{
    GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, MietteSpanContents,
    SourceCode, SourceSpan, SpanContents,
};

use super::line_index::LineIndex;
use super::{FileReport, Resolved, Summary};
use crate::diagnostic::Severity;
use crate::model::Span;
use crate::parse::Progress;

/// Lines longer than this (in bytes) are shown as a window around the span.
const LONG_LINE: usize = 200;
/// Bytes of a long line shown on each side of the span, and at most of the span itself.
const MARGIN: usize = 60;
const MAX_SPAN: usize = 120;
const ELLIPSIS: &str = "…";

/// Fixable findings marked (`[*]`) as a run without `--unsafe-fixes` applies them.
pub fn render(report: &FileReport, source: &[u8], color: bool) -> String {
    render_marked(report, source, &(), color, false)
}

/// [`render`]; `unsafe_fixes`: whether unsafe fixes count as fixable (`--unsafe-fixes`);
/// `progress` is told how far the line index's pass over `source` has got.
pub fn render_marked(
    report: &FileReport,
    source: &[u8],
    progress: &dyn Progress,
    color: bool,
    unsafe_fixes: bool,
) -> String {
    let mut out = String::new();
    if report.diagnostics.is_empty() && !report.truncated {
        return out;
    }
    let theme = if color {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let renderer = Renderer {
        handler: GraphicalReportHandler::new_themed(theme)
            .with_context_lines(1)
            .without_primary_span_start()
            .with_wrap_lines(false)
            .with_links(false),
        path: &report.path,
        source,
        lines: LineIndex::new(source, progress),
        color,
        unsafe_fixes,
    };
    for diagnostic in &report.diagnostics {
        renderer.block(&mut out, diagnostic);
    }
    if report.truncated {
        let path = &report.path;
        let _ = writeln!(
            out,
            "{path}: further diagnostics not shown (--max-diagnostics)\n"
        );
    }
    out
}

/// `Checked 12 files: 3 errors, 1 warning, 0 infos, 0 hints`, and `(2 suppressed)` when
/// inline comments suppressed some.
pub fn summary_line(summary: &Summary) -> String {
    let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
    let suppressed = match summary.suppressed {
        0 => String::new(),
        n => format!(" ({n} suppressed)"),
    };
    format!(
        "Checked {}: {}, {}, {}, {}{suppressed}",
        plural(summary.files, "file"),
        plural(summary.errors, "error"),
        plural(summary.warnings, "warning"),
        plural(summary.infos, "info"),
        plural(summary.hints, "hint"),
    )
}

struct Renderer<'a> {
    handler: GraphicalReportHandler,
    path: &'a str,
    source: &'a [u8],
    lines: LineIndex<'a>,
    color: bool,
    unsafe_fixes: bool,
}

impl Renderer<'_> {
    fn block(&self, out: &mut String, d: &Resolved) {
        let (on, bold, off) = if self.color {
            (severity_colour(d.severity), "\x1b[1m", "\x1b[0m")
        } else {
            ("", "", "")
        };
        let (severity, code, message) = (d.severity, d.code, &d.message);
        let mark = d.fix_mark(self.unsafe_fixes);
        let _ = writeln!(
            out,
            "{on}{bold}{severity}[{code}]{off}{bold}: {mark}{message}{off}"
        );

        let mut labels = vec![Label {
            span: d.span,
            text: None,
            at: (d.line, d.column),
        }];
        labels.extend(d.related.iter().map(|r| Label {
            span: r.span,
            text: Some(r.label.clone()),
            at: (r.line, r.column),
        }));
        let snippet = Snippet::new(self.path, &labels, self.source, &self.lines, d);
        let mut drawn = String::new();
        if snippet.labels.is_empty() || self.handler.render_report(&mut drawn, &snippet).is_err() {
            let _ = writeln!(out, "  ╭─[{}:{}:{}]\n  ╰────", self.path, d.line, d.column);
            if let Some(help) = &d.help {
                let _ = writeln!(out, "  help: {help}");
            }
        } else {
            // The report's message is empty, so miette's first line is empty: drop it.
            out.push_str(drawn.strip_prefix('\n').unwrap_or(&drawn));
        }
        let _ = writeln!(out, "  = clause {}, at {}\n", d.clause, d.path);
    }
}

fn severity_colour(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "\x1b[31m",
        Severity::Warning => "\x1b[33m",
        Severity::Info => "\x1b[34m",
        Severity::Hint => "\x1b[36m",
    }
}

struct Label {
    span: Span,
    text: Option<String>,
    /// The reported 1-based line and column.
    at: (usize, usize),
}

/// What miette renders: no message (the header is ours), the labels, help.
struct Snippet {
    excerpts: Excerpts,
    labels: Vec<LabeledSpan>,
    help: Option<String>,
    severity: miette::Severity,
}

impl Snippet {
    fn new(
        path: &str,
        labels: &[Label],
        source: &[u8],
        lines: &LineIndex,
        d: &Resolved,
    ) -> Snippet {
        let mut placed: Vec<Placed> = labels
            .iter()
            .enumerate()
            .filter(|_| !source.is_empty())
            .map(|(i, label)| Placed::new(label, i == 0, source, lines))
            .collect();
        placed.sort_by_key(|p| (p.line, p.span.start));
        let mut snippet = Snippet {
            excerpts: Excerpts(Vec::new()),
            labels: Vec::new(),
            help: d.help.clone(),
            severity: match d.severity {
                Severity::Error => miette::Severity::Error,
                Severity::Warning => miette::Severity::Warning,
                Severity::Info | Severity::Hint => miette::Severity::Advice,
            },
        };
        let mut groups = Vec::new();
        let mut rest = &placed[..];
        while !rest.is_empty() {
            let (group, tail) = rest.split_at(group_len(rest, lines));
            groups.push(group);
            rest = tail;
        }
        // The primary label's excerpt first: miette draws excerpts in offset order.
        groups.sort_by_key(|g| !g.iter().any(|p| p.primary));
        for group in groups {
            snippet.add_excerpt(path, group, source, lines);
        }
        snippet
    }

    /// One excerpt for a group of labels (see [`group_len`]), in the next free virtual range.
    fn add_excerpt(&mut self, path: &str, group: &[Placed], source: &[u8], lines: &LineIndex) {
        let base = self
            .excerpts
            .0
            .last()
            .map_or(0, |e| e.base + e.text.len() + 1);
        let first = &group[0];
        let (window, prefix, suffix, first_line) = if group.len() == 1 && first.long {
            let line = lines.line_range(first.line);
            let start = floor_boundary(
                source,
                first.span.start.saturating_sub(MARGIN).max(line.start),
            );
            let end = ceil_boundary(source, (first.span.end + MARGIN).min(line.end));
            let prefix = if start > line.start { ELLIPSIS } else { "" };
            let suffix = if end < line.end { ELLIPSIS } else { "" };
            (start..end, prefix, suffix, first.line)
        } else {
            // One line of context on each side, unless it is long (it would be printed whole).
            let last = group[group.len() - 1].line;
            let top = if first.line > 1 && all_short(first.line - 1..first.line, lines) {
                first.line - 1
            } else {
                first.line
            };
            let bottom = if last < lines.line_count() && all_short(last + 1..last + 2, lines) {
                last + 1
            } else {
                last
            };
            let window = lines.line_range(top).start..lines.line_range(bottom).end;
            (window, "", "", top)
        };
        let mut text = String::with_capacity(window.len() + 6);
        text.push_str(prefix);
        text.push_str(&sanitize(&source[window.clone()]));
        text.push_str(suffix);
        let offset = |at: usize| base + prefix.len() + at - window.start;
        for p in group {
            let span = SourceSpan::new(offset(p.span.start).into(), p.span.len());
            self.labels.push(if p.primary {
                LabeledSpan::new_primary_with_span(p.text.clone(), span)
            } else {
                LabeledSpan::new_with_span(p.text.clone(), span)
            });
        }
        let at = group.iter().find(|p| p.primary).unwrap_or(first).at;
        self.excerpts.0.push(Excerpt {
            name: format!("{path}:{}:{}", at.0, at.1),
            base,
            text,
            first_line: first_line - 1,
        });
    }
}

/// A label's span made drawable: within the source, on its first line, at least one char
/// long where the line has one, and no longer than [`MAX_SPAN`] on a long line.
struct Placed {
    span: std::ops::Range<usize>,
    line: usize,
    long: bool,
    primary: bool,
    text: Option<String>,
    at: (usize, usize),
}

impl Placed {
    fn new(label: &Label, primary: bool, source: &[u8], lines: &LineIndex) -> Placed {
        let at = (label.span.start as usize).min(source.len());
        let empty = label.span.end <= label.span.start;
        let mut line = lines.line_of(at);
        if empty && line > 1 && lines.line_range(line).is_empty() {
            // An empty line (the end of the file, say): point at the end of the one before.
            line -= 1;
        }
        let range = lines.line_range(line);
        let mut start = floor_boundary(source, at.clamp(range.start, range.end));
        let mut end = (label.span.end as usize).clamp(start, range.end);
        let long = range.len() > LONG_LINE;
        if long {
            end = end.min(start + MAX_SPAN);
        }
        if end == start {
            if start < range.end {
                end = start + char_len(source, start);
            } else if start > range.start {
                // At the end of the line: point at its last char.
                start = floor_boundary(source, start - 1);
            }
        }
        Placed {
            span: start..ceil_boundary(source, end),
            line,
            long,
            primary,
            text: label.text.clone(),
            at: label.at,
        }
    }
}

/// How many of the (sorted) labels share one excerpt: labels on short lines close enough
/// for their context lines to touch; a label on a long line gets a window of its own.
fn group_len(labels: &[Placed], lines: &LineIndex) -> usize {
    if labels[0].long {
        return 1;
    }
    let mut len = 1;
    while let Some(next) = labels.get(len) {
        let previous = labels[len - 1].line;
        if next.long || next.line > previous + 3 || !all_short(previous + 1..next.line, lines) {
            break;
        }
        len += 1;
    }
    len
}

fn all_short(range: std::ops::Range<usize>, lines: &LineIndex) -> bool {
    range
        .into_iter()
        .all(|l| lines.line_range(l).len() <= LONG_LINE)
}

/// The bytes as UTF-8 of the same length: each byte of an invalid sequence becomes `?`, and
/// a lone `\r` a space (miette would count it as a line break, the line index does not).
fn sanitize(bytes: &[u8]) -> String {
    let mut text = String::with_capacity(bytes.len());
    for chunk in bytes.utf8_chunks() {
        text.push_str(chunk.valid());
        text.extend(std::iter::repeat_n('?', chunk.invalid().len()));
    }
    if !text.contains('\r') {
        return text;
    }
    let mut fixed = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        fixed.push(if c == '\r' && chars.peek() != Some(&'\n') {
            ' '
        } else {
            c
        });
    }
    fixed
}

fn is_continuation(source: &[u8], at: usize) -> bool {
    source.get(at).is_some_and(|b| b & 0xC0 == 0x80)
}

fn floor_boundary(source: &[u8], mut at: usize) -> usize {
    while at > 0 && is_continuation(source, at) {
        at -= 1;
    }
    at
}

fn ceil_boundary(source: &[u8], mut at: usize) -> usize {
    while at < source.len() && is_continuation(source, at) {
        at += 1;
    }
    at
}

fn char_len(source: &[u8], at: usize) -> usize {
    ceil_boundary(source, at + 1) - at
}

impl fmt::Debug for Snippet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Snippet")
    }
}

impl fmt::Display for Snippet {
    fn fmt(&self, _: &mut fmt::Formatter<'_>) -> fmt::Result {
        Ok(())
    }
}

impl std::error::Error for Snippet {}

impl miette::Diagnostic for Snippet {
    fn severity(&self) -> Option<miette::Severity> {
        Some(self.severity)
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.help
            .as_ref()
            .map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        Some(&self.excerpts)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        Some(Box::new(self.labels.iter().cloned()))
    }
}

/// Pieces of the source, each at its own virtual offset, numbered with its real lines.
struct Excerpts(Vec<Excerpt>);

struct Excerpt {
    /// `file:line:col` of the excerpt's main label, shown in its header.
    name: String,
    base: usize,
    text: String,
    /// 0-based line number of the excerpt's first line.
    first_line: usize,
}

impl SourceCode for Excerpts {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let (start, end) = (span.offset(), span.offset() + span.len());
        let excerpt = self
            .0
            .iter()
            .find(|e| e.base <= start && end <= e.base + e.text.len())
            .ok_or(MietteError::OutOfBounds)?;
        let local = SourceSpan::new((start - excerpt.base).into(), span.len());
        let inner = excerpt.text.as_bytes().read_span(&local, before, after)?;
        Ok(Box::new(MietteSpanContents::new_named(
            excerpt.name.clone(),
            inner.data(),
            SourceSpan::new(
                (inner.span().offset() + excerpt.base).into(),
                inner.span().len(),
            ),
            inner.line() + excerpt.first_line,
            inner.column(),
            inner.line_count(),
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Diagnostic;
    use crate::model::rules::DEF_DUPLICATE;
    use crate::report::{resolve, Stats};

    fn render_one(source: &str, diagnostic: Diagnostic) -> String {
        let report = FileReport {
            path: "s.x3d".to_string(),
            encoding: None,
            compressed: false,
            x3d_version: None,
            profile: None,
            diagnostics: resolve(&[diagnostic], source.as_bytes(), &(), None),
            truncated: false,
            suppressed: 0,
            stats: Stats::default(),
        };
        render(&report, source.as_bytes(), false)
    }

    fn span_of(source: &str, text: &str, nth: usize) -> Span {
        let start = source.match_indices(text).nth(nth).unwrap().0;
        Span::new(start, start + text.len())
    }

    #[test]
    fn block_with_related_label() {
        let source = "<X3D>\n<Group DEF='A'/>\n<Group DEF='A'/>\n</X3D>\n";
        let d = Diagnostic::new(&DEF_DUPLICATE, span_of(source, "A", 1), "DEF `A` again")
            .related(span_of(source, "A", 0), "first defined here")
            .help("rename one");
        let out = render_one(source, d);
        assert!(
            out.starts_with("error[DEF_DUPLICATE]: DEF `A` again\n"),
            "{out}"
        );
        assert!(
            out.contains("[s.x3d:3:13]") && out.contains("first defined here"),
            "{out}"
        );
        assert!(
            out.contains("help: rename one") && out.contains("= clause 4.4.3, at /X3D\n"),
            "{out}"
        );
        assert!(!out.contains('\x1b'), "{out}");
    }

    #[test]
    fn long_lines_are_cut_around_the_span() {
        let source = format!("<X3D>{}<Bad/></X3D>", "1 ".repeat(500_000));
        let d = Diagnostic::new(&DEF_DUPLICATE, span_of(&source, "Bad", 0), "bad");
        let out = render_one(&source, d);
        assert!(
            out.len() < 1000 && out.contains("… 1 1 1") && out.contains("<Bad/>"),
            "{out}"
        );
    }

    #[test]
    fn empty_span_at_the_end_points_at_the_last_char() {
        let source = "<X3D>\r\n<Scene>\r\n";
        let d = Diagnostic::new(
            &DEF_DUPLICATE,
            Span::new(source.len(), source.len()),
            "ends",
        );
        let out = render_one(source, d);
        assert!(
            out.contains("[s.x3d:3:1]") && out.contains("2 │ <Scene>\n"),
            "{out}"
        );
        assert!(out.contains("      ─\n"), "{out}");
    }

    #[test]
    fn summary() {
        let summary = Summary {
            files: 1,
            errors: 2,
            warnings: 1,
            infos: 0,
            hints: 1,
            suppressed: 0,
        };
        assert_eq!(
            summary_line(&summary),
            "Checked 1 file: 2 errors, 1 warning, 0 infos, 1 hint"
        );
        let with_suppressed = Summary {
            suppressed: 3,
            ..summary
        };
        assert_eq!(
            summary_line(&with_suppressed),
            "Checked 1 file: 2 errors, 1 warning, 0 infos, 1 hint (3 suppressed)"
        );
    }
}
