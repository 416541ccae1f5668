//! The concise format, one line per diagnostic: `file:line:col: severity[CODE] message`,
//! the message after `[*] ` when `--fix` (or `--unsafe-fixes`) would fix the finding.

use std::fmt::Write as _;

use super::FileReport;

/// Fixable findings marked as a run without `--unsafe-fixes` applies them.
pub fn render(report: &FileReport) -> String {
    render_marked(report, false)
}

/// `unsafe_fixes`: whether unsafe fixes count as fixable (`--unsafe-fixes`).
pub fn render_marked(report: &FileReport, unsafe_fixes: bool) -> String {
    let mut out = String::new();
    for d in &report.diagnostics {
        let _ = writeln!(
            out,
            "{}:{}:{}: {}[{}] {}{}",
            report.path,
            d.line,
            d.column,
            d.severity,
            d.code,
            d.fix_mark(unsafe_fixes),
            d.message
        );
    }
    out
}
