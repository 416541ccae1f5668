//! JUnit XML for CI test dashboards (GitLab merge-request widgets, Jenkins): one
//! `testsuite` per checked file; in it one failing `testcase` per diagnostic at or above
//! the file's fail level (named `CODE at line:column`, so each finding is its own row with
//! its place), or one passing `testcase` for a file without such diagnostics, so clean files
//! count as passed. Diagnostics below the fail level are listed in the suite's
//! `system-out`. Dashboards count and list test cases, not suites, so one case per finding
//! shows what failed without opening a log. Deterministic: no timestamps, report order.

use std::fmt::Write as _;

use super::{FileReport, Resolved};
use crate::diagnostic::Severity;

/// `fail_levels[i]` is the fail level of `reports[i]` (each file may have its own config).
pub fn render(reports: &[FileReport], fail_levels: &[Severity]) -> String {
    let mut suites = String::new();
    let (mut all_tests, mut all_failures) = (0, 0);
    for (report, &fail_level) in reports.iter().zip(fail_levels) {
        let (failing, below): (Vec<&Resolved>, Vec<&Resolved>) = report
            .diagnostics
            .iter()
            .partition(|d| d.severity >= fail_level);
        let tests = failing.len().max(1);
        all_tests += tests;
        all_failures += failing.len();
        let path = escape(&report.path);
        let _ = writeln!(
            suites,
            "  <testsuite name=\"{path}\" tests=\"{tests}\" failures=\"{}\" errors=\"0\" skipped=\"0\">",
            failing.len()
        );
        if failing.is_empty() {
            let _ = writeln!(
                suites,
                "    <testcase name=\"{path}\" classname=\"x3dcheck\"/>"
            );
        }
        for d in &failing {
            let _ = writeln!(
                suites,
                "    <testcase name=\"{} at {}:{}\" classname=\"x3dcheck.{}\" file=\"{path}\" line=\"{}\">",
                d.code, d.line, d.column, d.code, d.line
            );
            let _ = writeln!(
                suites,
                "      <failure type=\"{}\" message=\"{}\">{}</failure>",
                d.code,
                escape(&d.message),
                escape(&details(&report.path, d))
            );
            suites.push_str("    </testcase>\n");
        }
        if !below.is_empty() || report.truncated {
            let mut text = String::new();
            for d in &below {
                let _ = writeln!(
                    text,
                    "{}:{}:{}: {}[{}] {}",
                    report.path, d.line, d.column, d.severity, d.code, d.message
                );
            }
            if report.truncated {
                text.push_str("further diagnostics not shown (--max-diagnostics)\n");
            }
            let _ = writeln!(suites, "    <system-out>{}</system-out>", escape(&text));
        }
        suites.push_str("  </testsuite>\n");
    }
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"x3dcheck\" tests=\"{all_tests}\" failures=\"{all_failures}\" errors=\"0\">\n{suites}</testsuites>\n"
    )
}

/// The failure's body: place, path, clause and help.
fn details(path: &str, d: &Resolved) -> String {
    let mut text = format!(
        "{}[{}] {}\nat {path}:{}:{} ({})\nclause {}",
        d.severity, d.code, d.message, d.line, d.column, d.path, d.clause
    );
    if let Some(help) = &d.help {
        text.push_str("\nhelp: ");
        text.push_str(help);
    }
    text
}

/// Text for XML attribute values and content. Characters XML 1.0 cannot carry at all
/// (most C0 controls) become U+FFFD.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' => out.push_str("&#9;"),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::escape;

    #[test]
    fn escapes_markup_and_controls() {
        assert_eq!(
            escape("a<b & \"c\"\n\u{1}"),
            "a&lt;b &amp; &quot;c&quot;&#10;\u{FFFD}"
        );
    }
}
