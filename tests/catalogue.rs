//! The registry matches the catalogue `../shared/RULES.md`: every code there is
//! implemented, with the catalogue's default severity and level. Codes are API, so a
//! missing or renamed one fails here.

use std::path::Path;

use x3dcheck::validate::{find_rule, Level, Severity};

struct Entry {
    code: String,
    severity: Severity,
    level: Level,
}

/// The table rows of RULES.md: `| CODE | sev | …`. Sections "(all levels)" (§1, §7) are
/// the fast level; the others are
/// standard unless the severity says "(deep)". For a severity that depends on version or
/// value ("error in 4.0, warning in 4.1", "info (7–19), warning (>19)") the first is the
/// rule's default.
fn catalogue() -> Vec<Entry> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/RULES.md");
    let text = std::fs::read_to_string(&path).expect("../shared/RULES.md");
    let mut entries = Vec::new();
    let mut fast_section = false;
    for line in text.lines() {
        if line.starts_with("## ") {
            // §1 and §7 (encodings and inputs) apply at every level: fast.
            fast_section = line.contains("(all levels)");
        }
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let (Some(code), Some(severity)) = (cells.get(1), cells.get(2)) else {
            continue;
        };
        if code.is_empty()
            || !code
                .chars()
                .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
        {
            continue;
        }
        let first_word = severity
            .split(|c: char| !c.is_ascii_alphabetic())
            .next()
            .unwrap_or("");
        let severity_value =
            Severity::parse(first_word).unwrap_or_else(|| panic!("{code}: severity `{severity}`"));
        let level = if fast_section {
            Level::Fast
        } else if severity.contains("deep") {
            Level::Deep
        } else {
            Level::Standard
        };
        entries.push(Entry {
            code: code.to_string(),
            severity: severity_value,
            level,
        });
    }
    entries
}

#[test]
fn every_catalogue_code_is_implemented_as_catalogued() {
    let entries = catalogue();
    assert!(
        entries.len() >= 89,
        "read only {} codes from RULES.md",
        entries.len()
    );
    let mut problems = Vec::new();
    for entry in &entries {
        match find_rule(&entry.code) {
            None => problems.push(format!("{}: not implemented", entry.code)),
            Some(rule) => {
                if rule.severity != entry.severity {
                    problems.push(format!(
                        "{}: severity {} (catalogue: {})",
                        entry.code, rule.severity, entry.severity
                    ));
                }
                if rule.level != entry.level {
                    problems.push(format!(
                        "{}: level {:?} (catalogue: {:?})",
                        entry.code, rule.level, entry.level
                    ));
                }
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} of {} codes:\n{}",
        problems.len(),
        entries.len(),
        problems.join("\n")
    );
}
