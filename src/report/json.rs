//! The JSON report of DESIGN.md: pretty-printed, deterministic (same input, same bytes).

use serde::Serialize;

use super::{FileReport, Resolved, Stats, Summary};
use crate::model::Encoding;
use crate::validate::Severity;

#[derive(Serialize)]
struct Report<'a> {
    tool: &'static str,
    version: &'static str,
    files: Vec<File<'a>>,
    summary: Summary,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct File<'a> {
    path: &'a str,
    encoding: Option<Encoding>,
    x3d_version: Option<&'a str>,
    profile: Option<&'a str>,
    diagnostics: Vec<Diagnostic<'a>>,
    truncated: bool,
    stats: &'a Stats,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Diagnostic<'a> {
    code: &'static str,
    severity: Severity,
    message: &'a str,
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    path: &'a str,
    clause: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    index: Option<usize>,
    #[serde(skip_serializing_if = "<[usize]>::is_empty")]
    indices: &'a [usize],
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    help: Option<&'a str>,
    #[serde(skip_serializing_if = "is_one")]
    count: usize,
}

fn is_one(count: &usize) -> bool {
    *count == 1
}

impl<'a> From<&'a Resolved> for Diagnostic<'a> {
    fn from(d: &'a Resolved) -> Diagnostic<'a> {
        Diagnostic {
            code: d.code,
            severity: d.severity,
            message: &d.message,
            line: d.line,
            column: d.column,
            end_line: d.end_line,
            end_column: d.end_column,
            path: &d.path,
            clause: d.clause,
            index: d.index,
            indices: &d.indices,
            value: d.value.as_deref(),
            help: d.help.as_deref(),
            count: d.count,
        }
    }
}

/// The whole report, with a trailing newline.
pub fn render(reports: &[FileReport]) -> String {
    let report = Report {
        tool: "x3dcheck",
        version: env!("CARGO_PKG_VERSION"),
        files: reports
            .iter()
            .map(|r| File {
                path: &r.path,
                encoding: r.encoding,
                x3d_version: r.x3d_version.as_deref(),
                profile: r.profile.as_deref(),
                diagnostics: r.diagnostics.iter().map(Diagnostic::from).collect(),
                truncated: r.truncated,
                stats: &r.stats,
            })
            .collect(),
        summary: Summary::of(reports),
    };
    // Plain structs with string keys: serializing cannot fail.
    let mut text = serde_json::to_string_pretty(&report).expect("the report serializes");
    text.push('\n');
    text
}
