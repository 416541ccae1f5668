//! A file's report as LSP diagnostics, and its fixes as code actions.

use std::collections::HashMap;
use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::Mutex;

use lsp_types::{
    CodeAction, CodeActionKind, CodeActionOrCommand, CodeDescription, Diagnostic,
    DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Range, TextEdit,
    Uri, WorkspaceEdit,
};

use super::position::Lines;
use crate::diagnostic::{Applicability, Rule, Severity};
use crate::report::Resolved;
use crate::validate::find_rule;

/// Where a rule's documentation is linked from a diagnostic (`codeDescription.href`).
/// By default each rule's doc (the text `x3dcheck rules CODE` prints) is written once to
/// `<temp>/x3dcheck-VERSION-rules/CODE.md` and linked as a `file:` URI, so the link works
/// offline and matches the binary; `rulesDocUrl` (an initialization option, `{code}`
/// standing for the code) links elsewhere instead.
pub struct DocLinks {
    template: Option<String>,
    dir: PathBuf,
    written: Mutex<HashSet<&'static str>>,
}

impl DocLinks {
    pub fn new(template: Option<String>) -> DocLinks {
        DocLinks {
            template,
            dir: std::env::temp_dir().join(format!("x3dcheck-{}-rules", env!("CARGO_PKG_VERSION"))),
            written: Mutex::new(HashSet::new()),
        }
    }

    /// The link to `rule`'s documentation, None when it cannot be made.
    pub fn href(&self, rule: &'static Rule) -> Option<Uri> {
        if let Some(template) = &self.template {
            return template.replace("{code}", rule.code).parse().ok();
        }
        let path = self.dir.join(format!("{}.md", rule.code));
        let mut written = self.written.lock().unwrap_or_else(|e| e.into_inner());
        if !written.contains(rule.code) {
            std::fs::create_dir_all(&self.dir).ok()?;
            std::fs::write(&path, rule_markdown(rule)).ok()?;
            written.insert(rule.code);
        }
        super::uri::from_path(&path)
    }
}

/// A rule's documentation as Markdown: its code, what it is, and its doc.
pub fn rule_markdown(rule: &Rule) -> String {
    let mut out = format!(
        "# {}\n\nseverity: {} · level: {} · versions: {} · clause: {}\n\n",
        rule.code,
        rule.severity,
        rule.level.as_str(),
        rule.versions,
        rule.clause
    );
    for line in rule.doc.lines() {
        out.push_str(line.strip_prefix(' ').unwrap_or(line));
        out.push('\n');
    }
    out
}

pub fn severity(severity: Severity) -> DiagnosticSeverity {
    match severity {
        Severity::Error => DiagnosticSeverity::ERROR,
        Severity::Warning => DiagnosticSeverity::WARNING,
        Severity::Info => DiagnosticSeverity::INFORMATION,
        Severity::Hint => DiagnosticSeverity::HINT,
    }
}

/// One reported finding as an LSP diagnostic of the document `uri`, whose checked text
/// `lines` indexes.
pub fn diagnostic(d: &Resolved, uri: &Uri, lines: &Lines, links: &DocLinks) -> Diagnostic {
    let mut message = d.message.clone();
    if let Some(help) = &d.help {
        message.push_str(&format!("\nhelp: {help}"));
    }
    if d.count > 1 {
        message.push_str(&format!(" ({} occurrences)", d.count));
    }
    let related: Vec<DiagnosticRelatedInformation> = d
        .related
        .iter()
        .map(|r| DiagnosticRelatedInformation {
            location: Location::new(uri.clone(), lines.range(r.span)),
            message: r.label.clone(),
        })
        .collect();
    Diagnostic {
        range: lines.range(d.span),
        severity: Some(severity(d.severity)),
        code: Some(NumberOrString::String(d.code.to_string())),
        code_description: find_rule(d.code)
            .and_then(|rule| links.href(rule))
            .map(|href| CodeDescription { href }),
        source: Some("x3dcheck".to_string()),
        message: format!("{message} [{}]", clause_text(d.clause)),
        related_information: (!related.is_empty()).then_some(related),
        tags: None,
        data: None,
    }
}

fn clause_text(clause: &str) -> String {
    if clause.is_empty() {
        String::new()
    } else {
        format!("clause {clause}")
    }
}

/// Whether two ranges share a position (touching counts: a cursor at a finding's end
/// still offers its fix).
pub fn touches(a: &Range, b: &Range) -> bool {
    a.start <= b.end && b.start <= a.end
}

/// The quick fixes of the findings whose range touches `range`: one code action per
/// finding with a fix, safe fixes preferred.
pub fn code_actions(
    report: &[Resolved],
    uri: &Uri,
    lines: &Lines,
    range: &Range,
    links: &DocLinks,
) -> Vec<CodeActionOrCommand> {
    report
        .iter()
        .filter(|d| touches(&lines.range(d.span), range))
        .filter_map(|d| {
            let fix = d.fix.as_ref()?;
            let edits: Vec<TextEdit> = fix
                .edits
                .iter()
                .map(|e| TextEdit::new(lines.range(e.span), e.replacement.clone()))
                .collect();
            let safe = fix.applicability == Applicability::Safe;
            Some(CodeActionOrCommand::CodeAction(CodeAction {
                title: if safe {
                    fix.title.clone()
                } else {
                    format!("{} (unsafe fix)", fix.title)
                },
                kind: Some(CodeActionKind::QUICKFIX),
                diagnostics: Some(vec![diagnostic(d, uri, lines, links)]),
                edit: Some(WorkspaceEdit {
                    changes: Some(HashMap::from([(uri.clone(), edits)])),
                    ..WorkspaceEdit::default()
                }),
                is_preferred: Some(safe),
                ..CodeAction::default()
            }))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::position::Units;
    use super::*;
    use crate::diagnostic::{Edit, Fix, Span};
    use crate::report::resolve;

    fn finding(code: &str, span: Span, fix: Option<Fix>) -> crate::diagnostic::Diagnostic {
        let mut d = crate::diagnostic::Diagnostic::new(find_rule(code).unwrap(), span, "m");
        d.fix = fix.map(Box::new);
        d
    }

    #[test]
    fn fixes_become_quickfixes_safe_ones_preferred() {
        let text = "<Material diffusecolor='1 0 0'/>\n<Box sizé='1 1 1'/>";
        let safe = Fix {
            title: "Rename to `diffuseColor`".into(),
            applicability: Applicability::Safe,
            edits: vec![Edit {
                span: Span::new(10, 22),
                replacement: "diffuseColor".into(),
            }],
        };
        let unsafe_fix = Fix {
            title: "Rename to `size`".into(),
            applicability: Applicability::Unsafe,
            edits: vec![Edit {
                span: Span::new(38, 43),
                replacement: "size".into(),
            }],
        };
        let diagnostics = vec![
            finding("FIELD_UNKNOWN", Span::new(10, 22), Some(safe)),
            finding("FIELD_UNKNOWN", Span::new(38, 43), Some(unsafe_fix)),
            finding("FIELD_UNKNOWN", Span::new(0, 9), None),
        ];
        let report = resolve(&diagnostics, text.as_bytes(), &(), None);
        let uri: Uri = "file:///s.x3d".parse().unwrap();
        let lines = Lines::new(text.as_bytes(), Units::Utf16);
        let links = DocLinks::new(Some("https://example.org/{code}".into()));
        let whole = lines.range(Span::new(0, text.len()));
        let actions = code_actions(&report, &uri, &lines, &whole, &links);
        assert_eq!(actions.len(), 2, "the finding without a fix offers none");
        let CodeActionOrCommand::CodeAction(first) = &actions[0] else {
            panic!("a command")
        };
        assert_eq!(first.title, "Rename to `diffuseColor`");
        assert_eq!(first.kind, Some(CodeActionKind::QUICKFIX));
        assert_eq!(first.is_preferred, Some(true));
        let edits = &first.edit.as_ref().unwrap().changes.as_ref().unwrap()[&uri];
        assert_eq!(edits[0].new_text, "diffuseColor");
        assert_eq!(edits[0].range, lines.range(Span::new(10, 22)));
        let CodeActionOrCommand::CodeAction(second) = &actions[1] else {
            panic!("a command")
        };
        assert_eq!(second.is_preferred, Some(false));
        // "sizé": é is one UTF-16 unit, so the edit ends at character 9 of line 1.
        let edits = &second.edit.as_ref().unwrap().changes.as_ref().unwrap()[&uri];
        assert_eq!(edits[0].range.end, lsp_types::Position::new(1, 9));
        // Only the findings at the requested range.
        let at_second = lines.range(Span::new(40, 40));
        assert_eq!(
            code_actions(&report, &uri, &lines, &at_second, &links).len(),
            1
        );
        assert_eq!(
            first.diagnostics.as_ref().unwrap()[0]
                .code_description
                .as_ref()
                .unwrap()
                .href
                .as_str(),
            "https://example.org/FIELD_UNKNOWN"
        );
    }
}
