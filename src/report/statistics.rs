//! `--statistics`: per code, how many findings and in how many files, instead of the
//! findings themselves (a folded diagnostic counts as the findings it stands for, as in the
//! summary). Sorted by count, most frequent first, then by code.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::Serialize;

use super::{FileReport, Summary};
use crate::diagnostic::{find_rule_in, Rule, Severity};

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct CodeCount {
    pub code: &'static str,
    /// The highest severity it was reported with.
    pub severity: Severity,
    pub count: usize,
    pub files: usize,
}

pub fn of(reports: &[FileReport]) -> Vec<CodeCount> {
    let mut by_code: BTreeMap<&'static str, CodeCount> = BTreeMap::new();
    for report in reports {
        let mut seen_here: Vec<&'static str> = Vec::new();
        for d in &report.diagnostics {
            let row = by_code.entry(d.code).or_insert(CodeCount {
                code: d.code,
                severity: d.severity,
                count: 0,
                files: 0,
            });
            row.count += d.count;
            row.severity = row.severity.max(d.severity);
            if !seen_here.contains(&d.code) {
                seen_here.push(d.code);
                row.files += 1;
            }
        }
    }
    let mut rows: Vec<CodeCount> = by_code.into_values().collect();
    rows.sort_by(|a, b| b.count.cmp(&a.count).then(a.code.cmp(b.code)));
    rows
}

/// Summaries longer than this are cut, so that a row fits a wide terminal.
const SUMMARY_CHARS: usize = 72;

/// A table: count, files, severity, code and the rule's summary (of the rule among
/// `rules`, the catalogue).
pub fn render_text(rows: &[CodeCount], rules: &[&'static Rule]) -> String {
    let code_width = rows.iter().map(|r| r.code.len()).max().unwrap_or(4).max(4);
    let mut out = format!(
        "{:>8}  {:>6}  {:<8}  {:<code_width$}  SUMMARY\n",
        "COUNT", "FILES", "SEVERITY", "CODE"
    );
    for row in rows {
        let summary = find_rule_in(rules, row.code)
            .map(|r| r.summary())
            .unwrap_or_default();
        let summary = match summary.char_indices().nth(SUMMARY_CHARS) {
            Some((cut, _)) => format!("{}…", &summary[..cut]),
            None => summary,
        };
        let _ = writeln!(
            out,
            "{:>8}  {:>6}  {:<8}  {:<code_width$}  {summary}",
            row.count,
            row.files,
            row.severity.as_str(),
            row.code
        );
    }
    out
}

#[derive(Serialize)]
struct Report<'a> {
    tool: &'static str,
    version: &'static str,
    statistics: &'a [CodeCount],
    summary: Summary,
}

/// `{ "tool", "version", "statistics": [ { code, severity, count, files } ], "summary" }`.
pub fn render_json(rows: &[CodeCount], reports: &[FileReport]) -> String {
    let report = Report {
        tool: "x3dcheck",
        version: env!("CARGO_PKG_VERSION"),
        statistics: rows,
        summary: Summary::of(reports),
    };
    let mut text = serde_json::to_string_pretty(&report).expect("the statistics serialize");
    text.push('\n');
    text
}
