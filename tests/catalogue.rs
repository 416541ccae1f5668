//! The registry matches the catalogue `../shared/RULES.md`: every code there is
//! implemented, with the catalogue's default severity and level, except the codes still
//! [`PENDING`] on an open issue. Codes are API, so a missing or renamed one fails here.

use std::path::Path;

use x3dcheck::diagnostic::{Level, Severity};
use x3dcheck::validate::find_rule;

struct Entry {
    code: String,
    severity: Severity,
    level: Level,
}

/// Codes the catalogue lists whose rules are not built yet, with the issue that builds
/// them. A code leaves this list when its rule lands (the test fails until it does).
const PENDING: &[(&str, u32)] = &[];

/// Codes whose severity departs on purpose from the catalogue's, with the severity they
/// have and why. A code leaves this list when the catalogue agrees (the test fails until
/// it does), so the list cannot go stale.
const LOWERED: &[(&str, Severity, &str)] = &[
    (
        "LIGHT_DIRECTION_ZERO",
        Severity::Warning,
        "issue 32: no 'shall' on the file; 17.4.1 gives direction the range (-∞,∞)",
    ),
    (
        "COUNT_EXCEEDS_COORDS",
        Severity::Warning,
        "issue 32: 11.4.5/11.4.12/11.4.14 constrain each count, not their sum against the coordinates",
    ),
    (
        "IMAGE_UNREADABLE",
        Severity::Warning,
        "issue 32: an image that does not decode is the browser's run-time matter (url fallback), not a 'shall' of the X3D file",
    ),
    (
        "ENCODING_UNSUPPORTED",
        Severity::Warning,
        "issue 32: x3dcheck cannot read the file (VRML 1.0, binary, …); no X3D 'shall' applies to a file in none of its encodings",
    ),
    (
        "IMPORT_UNRESOLVED",
        Severity::Warning,
        "issue 32: what an IMPORT finds depends on the inlined file, loaded at run time like any url (URL_UNRESOLVED is a warning)",
    ),
    (
        "EXTERNPROTO_NOT_FOUND",
        Severity::Warning,
        "issue 32: whether the url's file declares the prototype depends on that file, loaded at run time like any url",
    ),
    (
        "FIELD_DUPLICATE",
        Severity::Warning,
        "issue 32: JSON only says member names SHOULD be unique (RFC 8259 4); no 'shall' found against two fieldValue statements of one name (duplicate Script and shader field declarations are errors per finding, issue 33)",
    ),
    (
        "PROTO_FIELD_UNKNOWN",
        Severity::Warning,
        "issue 32: 14772-1 4.8.3 makes an IS to an undeclared field an error, but no sentence was found for a field set on an instance",
    ),
    (
        "SHADER_FIELD_TYPE_MISMATCH",
        Severity::Warning,
        "issue 32: Annex I maps field types to GLSL types without a 'shall' on the file; OpenGL refusing the uniform is run-time",
    ),
    (
        "USE_TYPE_MISMATCH",
        Severity::Warning,
        "issue 32: USE is an xs:IDREF; no sentence was found that the USE element's name shall be the DEF node's type",
    ),
];

/// The table rows of RULES.md: `| CODE | sev | …`. §1 and §7 are the fast level; a
/// table with a `lvl` column says the level in it; elsewhere a rule is standard unless
/// the severity says "(deep)". For a severity that depends on version or
/// value ("error in 4.0, warning in 4.1", "info (7–19), warning (>19)") the first is the
/// rule's default.
fn catalogue() -> Vec<Entry> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/RULES.md");
    let text = std::fs::read_to_string(&path).expect("../shared/RULES.md");
    let mut entries = Vec::new();
    let mut fast_section = false;
    let mut level_column = None;
    for line in text.lines() {
        if line.starts_with("## ") {
            fast_section = line.starts_with("## 1.") || line.starts_with("## 7.");
            level_column = None;
        }
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        if cells.get(1) == Some(&"code") {
            level_column = cells.iter().position(|c| *c == "lvl");
        }
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
        let level = if let Some(column) = level_column {
            match cells[column] {
                "fast" => Level::Fast,
                "standard" => Level::Standard,
                "deep" => Level::Deep,
                other => panic!("{code}: level `{other}`"),
            }
        } else if fast_section {
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
        let pending = PENDING.iter().find(|(code, _)| *code == entry.code);
        match (find_rule(&entry.code), pending) {
            (None, Some(_)) => {}
            (None, None) => problems.push(format!("{}: not implemented", entry.code)),
            (Some(_), Some((_, issue))) => problems.push(format!(
                "{}: implemented, so no longer pending on issue {issue}: take it off PENDING",
                entry.code
            )),
            (Some(rule), None) => {
                let lowered = LOWERED.iter().find(|(code, ..)| *code == entry.code);
                if let Some((_, severity, why)) = lowered {
                    if rule.severity != *severity || entry.severity == *severity {
                        problems.push(format!(
                            "{}: severity {} (catalogue: {}; LOWERED says {severity}: {why})",
                            entry.code, rule.severity, entry.severity
                        ));
                    }
                } else if rule.severity != entry.severity {
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
    for (code, ..) in LOWERED {
        if !entries.iter().any(|entry| entry.code == *code) {
            problems.push(format!("{code}: on LOWERED but not in the catalogue"));
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

/// Listings show each rule's first sentence: whole, never cut inside brackets or after an
/// abbreviation.
#[test]
fn every_summary_is_a_whole_sentence() {
    let mut problems = Vec::new();
    for rule in x3dcheck::validate::RULES.iter() {
        let summary = rule.summary();
        let opened = summary.matches(['(', '[']).count();
        let closed = summary.matches([')', ']']).count();
        let cut = summary.ends_with("e.g.") || summary.ends_with("i.e.");
        if !summary.ends_with('.') || opened != closed || cut {
            problems.push(format!("{}: {summary}", rule.code));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
