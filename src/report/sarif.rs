//! SARIF 2.1.0 (OASIS), the format code-scanning services read: one run whose driver lists
//! each reported rule (summary, its "What it does" text, the whole doc as help, default
//! level, clause) and one result per diagnostic, located by file, 1-based line and column
//! (counted in Unicode code points: `columnKind`), and by the node's structural path as a
//! logical location. Deterministic: rules in catalogue order, results in report order.

use serde_json::{json, Map, Value};

use super::{FileReport, Resolved};
use crate::diagnostic::{Rule, Severity};

const SCHEMA: &str =
    "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";

/// The whole log, pretty-printed, with a trailing newline. `rules`: every rule, in
/// catalogue order (the registry's `RULES`).
pub fn render(reports: &[FileReport], rules: &[&'static Rule]) -> String {
    let reported: Vec<&'static Rule> = rules
        .iter()
        .copied()
        .filter(|r| {
            reports
                .iter()
                .flat_map(|f| &f.diagnostics)
                .any(|d| d.code == r.code)
        })
        .collect();
    let rule_index = |code: &str| reported.iter().position(|r| r.code == code);
    let results: Vec<Value> = reports
        .iter()
        .flat_map(|file| {
            file.diagnostics
                .iter()
                .map(move |d| result(file, d, rule_index(d.code)))
        })
        .collect();
    let log = json!({
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": { "driver": {
                "name": "x3dcheck",
                "version": env!("CARGO_PKG_VERSION"),
                "semanticVersion": env!("CARGO_PKG_VERSION"),
                "rules": reported.iter().map(|r| rule(r)).collect::<Vec<_>>(),
            }},
            "columnKind": "unicodeCodePoints",
            "results": results,
        }],
    });
    // Plain JSON values: serializing cannot fail.
    let mut text = serde_json::to_string_pretty(&log).expect("the log serializes");
    text.push('\n');
    text
}

fn rule(rule: &Rule) -> Value {
    let doc = unindent(rule.doc);
    json!({
        "id": rule.code,
        "shortDescription": { "text": rule.summary() },
        "fullDescription": { "text": section(&doc, "## What it does") },
        "help": { "text": doc, "markdown": doc },
        "defaultConfiguration": { "level": level(rule.severity) },
        "properties": {
            "clause": rule.clause,
            "versions": rule.versions,
            "checkLevel": rule.level.as_str(),
        },
    })
}

fn result(file: &FileReport, d: &Resolved, rule_index: Option<usize>) -> Value {
    let mut message = d.message.clone();
    if let Some(help) = &d.help {
        message = format!("{message} ({help})");
    }
    let mut result = Map::new();
    result.insert("ruleId".into(), json!(d.code));
    if let Some(index) = rule_index {
        result.insert("ruleIndex".into(), json!(index));
    }
    result.insert("level".into(), json!(level(d.severity)));
    result.insert("message".into(), json!({ "text": message }));
    result.insert(
        "locations".into(),
        json!([{
            "physicalLocation": {
                "artifactLocation": { "uri": uri(&file.path) },
                "region": {
                    "startLine": d.line,
                    "startColumn": d.column,
                    "endLine": d.end_line.max(d.line),
                    "endColumn": end_column(d),
                },
            },
            "logicalLocations": [{ "fullyQualifiedName": d.path, "kind": "element" }],
        }]),
    );
    if !d.related.is_empty() {
        let related: Vec<Value> = d
            .related
            .iter()
            .enumerate()
            .map(|(i, r)| {
                json!({
                    "id": i,
                    "physicalLocation": {
                        "artifactLocation": { "uri": uri(&file.path) },
                        "region": { "startLine": r.line, "startColumn": r.column },
                    },
                    "message": { "text": r.label },
                })
            })
            .collect();
        result.insert("relatedLocations".into(), Value::Array(related));
    }
    if let Some(fix) = &d.fix {
        result.insert("fixes".into(), json!([sarif_fix(file, fix)]));
    }
    let mut properties = Map::new();
    properties.insert("clause".into(), json!(d.clause));
    if let Some(index) = d.index {
        properties.insert("index".into(), json!(index));
    }
    if d.count > 1 {
        properties.insert("count".into(), json!(d.count));
        properties.insert("indices".into(), json!(d.indices));
    }
    if let Some(value) = &d.value {
        properties.insert("value".into(), json!(value));
    }
    result.insert("properties".into(), Value::Object(properties));
    Value::Object(result)
}

/// A SARIF `fix` (3.55): one artifact change replacing each edit's region (an empty region
/// is an insertion point); whether `--fix` applies it is in its properties.
fn sarif_fix(file: &FileReport, fix: &crate::report::ResolvedFix) -> Value {
    let replacements: Vec<Value> = fix
        .edits
        .iter()
        .map(|e| {
            json!({
                "deletedRegion": {
                    "startLine": e.line,
                    "startColumn": e.column,
                    "endLine": e.end_line,
                    "endColumn": e.end_column,
                },
                "insertedContent": { "text": e.replacement },
            })
        })
        .collect();
    json!({
        "description": { "text": fix.title },
        "artifactChanges": [{
            "artifactLocation": { "uri": uri(&file.path) },
            "replacements": replacements,
        }],
        "properties": { "applicability": fix.applicability },
    })
}

/// SARIF's end column is exclusive and may not precede the start on the same line.
fn end_column(d: &Resolved) -> usize {
    if d.end_line <= d.line {
        d.end_column.max(d.column)
    } else {
        d.end_column
    }
}

/// SARIF levels: hint and info are both "note".
pub fn level(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info | Severity::Hint => "note",
    }
}

/// A URI reference for a report path: relative paths stay relative (resolved against the
/// directory the tool ran in), absolute ones become `file://` URIs; characters outside
/// RFC 3986's unreserved set and `/` are percent-encoded.
pub fn uri(path: &str) -> String {
    let path = path.replace('\\', "/");
    let mut out = String::new();
    let (prefix, rest) = if path.starts_with('/') {
        ("file://", path.as_str())
    } else if path.as_bytes().get(1) == Some(&b':') {
        // A Windows drive path, `C:/…`.
        ("file:///", path.as_str())
    } else {
        ("", path.as_str())
    };
    out.push_str(prefix);
    for byte in rest.bytes() {
        match byte {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                out.push(byte as char)
            }
            b':' if !prefix.is_empty() => out.push(':'),
            _ => out.push_str(&format!("%{byte:02X}")),
        }
    }
    out
}

/// A rule doc without the one-space indent doc comments leave.
fn unindent(doc: &str) -> String {
    let lines: Vec<&str> = doc
        .lines()
        .map(|l| l.strip_prefix(' ').unwrap_or(l))
        .collect();
    lines.join("\n").trim().to_string()
}

/// The text under a `## ` heading, up to the next heading.
fn section(doc: &str, heading: &str) -> String {
    let Some(start) = doc.find(heading) else {
        return String::new();
    };
    let body = &doc[start + heading.len()..];
    let end = body.find("\n## ").unwrap_or(body.len());
    body[..end].trim().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_are_encoded() {
        assert_eq!(uri("scenes/a b.x3d"), "scenes/a%20b.x3d");
        assert_eq!(uri("/work/x%.x3d"), "file:///work/x%25.x3d");
        assert_eq!(uri("C:\\s\\a.x3d"), "file:///C:/s/a.x3d");
        assert_eq!(uri("<stdin>"), "%3Cstdin%3E");
        assert_eq!(uri("ü.x3d"), "%C3%BC.x3d");
    }

    #[test]
    fn sections_of_a_rule_doc() {
        let doc = "## What it does\nChecks.\nMore.\n\n## Why it matters\nBecause.";
        assert_eq!(section(doc, "## What it does"), "Checks.\nMore.");
        assert_eq!(section(doc, "## Why it matters"), "Because.");
        assert_eq!(section(doc, "## Clause"), "");
    }
}
