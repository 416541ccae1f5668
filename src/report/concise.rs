//! The concise format, one line per diagnostic: `file:line:col: severity[CODE] message`.

use std::fmt::Write as _;

use super::FileReport;

pub fn render(report: &FileReport) -> String {
    let mut out = String::new();
    for d in &report.diagnostics {
        let _ = writeln!(
            out,
            "{}:{}:{}: {}[{}] {}",
            report.path, d.line, d.column, d.severity, d.code, d.message
        );
    }
    out
}
