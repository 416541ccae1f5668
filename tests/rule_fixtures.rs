//! Every rule code has a failing and a passing scene in `corpus/rules/CODE/` and complete
//! docs. The failing scene's report is pinned by an insta snapshot, so that a changed
//! message or position shows in review. To accept changed snapshots:
//! `INSTA_UPDATE=always cargo test --test rule_fixtures`, then review the diff.

use std::fs;
use std::path::{Path, PathBuf};

use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::{Level, Severity};
use x3dcheck::validate::RULES;

const DOC_SECTIONS: [&str; 4] = [
    "## What it does",
    "## Why it matters",
    "## Example",
    "## Clause",
];

fn fixture_dir(code: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("corpus/rules")
        .join(code)
}

/// The scenes in a rule's fixture folder whose name starts with `stem` (`fail`, `pass`).
fn scenes(code: &str, stem: &str) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(fixture_dir(code)) else {
        return Vec::new();
    };
    let mut found: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with(stem))
        })
        .collect();
    found.sort();
    found
}

/// The concise report of one scene, with its path relative to the crate.
fn report(path: &Path) -> (Vec<String>, String) {
    let source = fs::read(path).unwrap();
    let relative = path
        .strip_prefix(env!("CARGO_MANIFEST_DIR"))
        .unwrap()
        .to_string_lossy()
        .into_owned();
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let file = x3dcheck::check_source(&relative, &source, &config);
    let codes = file
        .diagnostics
        .iter()
        .map(|d| d.code.to_string())
        .collect();
    (codes, x3dcheck::report::concise::render(&file))
}

#[test]
fn every_rule_has_docs() {
    let mut missing = Vec::new();
    for rule in RULES.iter() {
        for section in DOC_SECTIONS {
            if !rule.doc.contains(section) {
                missing.push(format!("{}: no `{section}`", rule.code));
            }
        }
        if rule.summary().is_empty() {
            missing.push(format!("{}: empty summary", rule.code));
        }
    }
    assert!(
        missing.is_empty(),
        "rule docs incomplete:\n{}",
        missing.join("\n")
    );
}

/// An error says which "shall" it enforces: the `## Clause` section of every rule whose
/// default severity is Error quotes the sentence, as a line `> "…" (document clause)`
/// (issue 32).
#[test]
fn every_error_quotes_its_clause() {
    let mut problems = Vec::new();
    for rule in RULES.iter() {
        let clause = rule
            .doc
            .split_once("## Clause")
            .map_or("", |(_, rest)| rest.split("\n ##").next().unwrap_or(rest));
        let quoted = clause
            .lines()
            .any(|line| line.trim_start().starts_with("> \""));
        if rule.severity == Severity::Error && !quoted {
            problems.push(format!("{}: no `> \"…\"` line in `## Clause`", rule.code));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn every_rule_has_a_failing_and_a_passing_scene() {
    let mut problems = Vec::new();
    for rule in RULES.iter() {
        let failing = scenes(rule.code, "fail");
        let passing = scenes(rule.code, "pass");
        if failing.is_empty() {
            problems.push(format!(
                "{}: no corpus/rules/{}/fail.* scene",
                rule.code, rule.code
            ));
        }
        if passing.is_empty() {
            problems.push(format!(
                "{}: no corpus/rules/{}/pass.* scene",
                rule.code, rule.code
            ));
        }
        for path in &failing {
            let (codes, text) = report(path);
            if !codes.iter().any(|c| c == rule.code) {
                problems.push(format!(
                    "{}: {} does not trigger it; it reports:\n{text}",
                    rule.code,
                    path.display()
                ));
            }
        }
        for path in &passing {
            let (codes, text) = report(path);
            if codes.iter().any(|c| c == rule.code) {
                problems.push(format!(
                    "{}: {} triggers it:\n{text}",
                    rule.code,
                    path.display()
                ));
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} fixture problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn failing_scene_reports_are_pinned() {
    for rule in RULES.iter() {
        for path in scenes(rule.code, "fail") {
            let (_, text) = report(&path);
            let name = format!(
                "{}__{}",
                rule.code,
                path.file_name()
                    .unwrap()
                    .to_string_lossy()
                    .replace('.', "_")
            );
            insta::assert_snapshot!(name, text);
        }
    }
}
