//! GitHub Actions workflow commands, one per diagnostic, which the runner turns into
//! annotations on the pull request:
//! `::error file=a.x3d,line=3,col=5,endLine=3,endColumn=9,title=CODE::message`.
//! Info and hint become `notice`. Escaping follows the runner's rules: `%`, CR and LF in
//! the message, and additionally `:` and `,` in property values, are percent-encoded.

use std::fmt::Write as _;

use super::FileReport;
use crate::diagnostic::Severity;

pub fn render(report: &FileReport) -> String {
    let mut out = String::new();
    for d in &report.diagnostics {
        let command = match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info | Severity::Hint => "notice",
        };
        let mut message = format!("{} [{}]", d.message, d.path);
        if let Some(help) = &d.help {
            message.push_str("\nhelp: ");
            message.push_str(help);
        }
        let _ = writeln!(
            out,
            "::{command} file={},line={},col={},endLine={},endColumn={},title={}::{}",
            property(&report.path),
            d.line,
            d.column,
            d.end_line,
            d.end_column,
            property(d.code),
            data(&message),
        );
    }
    out
}

/// A command's message.
fn data(text: &str) -> String {
    text.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// A command property's value.
fn property(text: &str) -> String {
    data(text).replace(':', "%3A").replace(',', "%2C")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escaping() {
        assert_eq!(data("50% a\r\nb: c, d"), "50%25 a%0D%0Ab: c, d");
        assert_eq!(property("C:\\a,b%.x3d"), "C%3A\\a%2Cb%25.x3d");
    }
}
