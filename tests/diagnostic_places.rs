//! Where a finding points and what it cites, over every rule fixture: a finding about a
//! node has that node's structural path (never the bare `/X3D`), and a rule that cites a
//! node type's subclause cites the subclause of the node type it reports on, derived from
//! the schema ([`x3dcheck::schema::clauses`]) — one table, not a clause per rule. Also: one
//! cause gives one diagnostic, for the cases that used to give two or three.

mod common;

use std::collections::BTreeSet;
use std::path::Path;

use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;
use x3dcheck::report::FileReport;
use x3dcheck::schema::clauses::SEQUENCER_KEYS;
use x3dcheck::schema::{clauses, Version};
use x3dcheck::validate::find_rule;

/// Codes whose findings always concern a node or a statement inside the Scene.
const NODE_LEVEL: &[&str] = &[
    "FIELD_VALUE_SYNTAX",
    "USE_WITH_FIELDS",
    "USE_UNDEFINED",
    "FIELD_DUPLICATE",
    "ROUTE_NODE_UNDEFINED",
];

fn check(path: &Path) -> FileReport {
    let source = std::fs::read(path).unwrap();
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    x3dcheck::check_source(&path.to_string_lossy(), &source, &config)
}

fn check_text(text: &str) -> Vec<String> {
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let report = x3dcheck::check_source("<stdin>", text.as_bytes(), &config);
    report
        .diagnostics
        .iter()
        .map(|d| d.code.to_string())
        .collect()
}

fn fixtures() -> Vec<std::path::PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/rules");
    common::files_under(&root, &["x3d", "x3dj", "json"])
}

/// The node type a path ends in: `…/Shape/IndexedFaceSet[@DEF='x']` → IndexedFaceSet.
fn last_type(path: &str) -> &str {
    let step = path.rsplit('/').next().unwrap_or("");
    step.split('[').next().unwrap_or(step)
}

#[test]
fn node_level_findings_have_the_nodes_path() {
    let mut seen = BTreeSet::new();
    let mut problems = Vec::new();
    for path in fixtures() {
        for d in check(&path).diagnostics {
            if !NODE_LEVEL.contains(&d.code) {
                continue;
            }
            seen.insert(d.code);
            if d.path == "/X3D" {
                problems.push(format!("{}:{}: {} at /X3D", path.display(), d.line, d.code));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert_eq!(seen.len(), NODE_LEVEL.len(), "fixtures reach only {seen:?}");
}

#[test]
fn findings_cite_the_subclause_of_their_node_type() {
    let mut pairs = BTreeSet::new();
    let mut problems = Vec::new();
    for path in fixtures() {
        let report = check(&path);
        let version = report
            .x3d_version
            .as_deref()
            .and_then(Version::parse)
            .unwrap_or(Version::LATEST);
        for d in &report.diagnostics {
            let rule = find_rule(d.code).unwrap();
            if !clauses::is_node_subclause(rule.clause) {
                // A sequencer's decreasing key cites 30.3.1 (tests/cited_clauses.rs).
                let own = d.code == "KEY_DECREASING" && d.clause == SEQUENCER_KEYS;
                if !own {
                    assert_eq!(d.clause, rule.clause, "{}: {}", path.display(), d.code);
                }
                continue;
            }
            let node_type = last_type(&d.path);
            let Some(expected) = clauses::node_subclause(version, node_type) else {
                continue;
            };
            pairs.insert((d.code, node_type.to_string(), d.clause));
            if d.clause != expected {
                problems.push(format!(
                    "{}:{}: {} on {node_type} cites {}, its node's subclause is {expected}",
                    path.display(),
                    d.line,
                    d.code,
                    d.clause
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // The cases the clause table was made for.
    for expected in [
        ("TRIANGLE_COUNT_NOT_MULTIPLE", "QuadSet", "32.4.6"),
        ("TRIANGLE_COUNT_NOT_MULTIPLE", "IndexedQuadSet", "32.4.5"),
        ("POLYLINE_TOO_SHORT", "IndexedLineSet", "11.4.6"),
        ("LIGHT_DIRECTION_ZERO", "SpotLight", "17.4.3"),
        ("LIGHT_RADIUS_ZERO", "SpotLight", "17.4.4"),
        ("LIGHT_REACHES_NOTHING", "SpotLight", "17.4.3"),
        ("INDEX_COUNT_MISMATCH", "IndexedLineSet", "11.4.6"),
        ("INDEX_COUNT_MISMATCH", "IndexedFaceSet", "13.3.6"),
    ] {
        let (code, node, clause) = expected;
        assert!(
            pairs.contains(&(code, node.to_string(), clause)),
            "{code} on {node} citing {clause} not among {pairs:#?}"
        );
    }
}

/// A scene in `version` with `body` in its Scene.
fn scene(version: &str, body: &str) -> String {
    format!(
        "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Full' version='{version}'><Scene>{body}</Scene></X3D>"
    )
}

#[test]
fn one_cause_gives_one_diagnostic() {
    // A field of another version: FIELD_NOT_IN_VERSION, not also NODE_TYPE_NOT_ALLOWED.
    let codes = check_text(&scene(
        "3.0",
        "<Shape><Appearance><Material><ImageTexture containerField='normalTexture' url='\"bumps.png\"'/></Material></Appearance><Box/></Shape>",
    ));
    // (The url of a document with no directory is VALIDATION_INCOMPLETE: not at issue.)
    assert_eq!(
        codes,
        ["FIELD_NOT_IN_VERSION", "VALIDATION_INCOMPLETE"],
        "{codes:?}"
    );
    // A TwoSidedMaterial USE'd as backMaterial: NODE_TYPE_NOT_ALLOWED alone.
    let codes = check_text(&scene(
        "4.0",
        "<Shape><Appearance><TwoSidedMaterial DEF='T'/></Appearance><Box/></Shape>\
         <Shape><Appearance><Material/><TwoSidedMaterial USE='T' containerField='backMaterial'/></Appearance><Box/></Shape>",
    ));
    let codes: Vec<&str> = codes
        .iter()
        .map(String::as_str)
        .filter(|c| *c != "NODE_DEPRECATED")
        .collect();
    assert_eq!(codes, ["NODE_TYPE_NOT_ALLOWED"]);
    // An index of -2 that cuts a strip: INDEX_NEGATIVE, not also STRIP_FAN_TOO_SHORT.
    let codes = check_text(&scene(
        "4.0",
        "<Shape><IndexedTriangleStripSet index='0 1 -2 2 3 4'><Coordinate point='0 0 0 1 0 0 0 1 0 1 1 0 2 0 0'/></IndexedTriangleStripSet></Shape>",
    ));
    assert_eq!(codes, ["INDEX_NEGATIVE"]);
}

/// The findings of a ClassicVRML or VRML97 text that are about its syntax.
fn syntax_codes(text: &str) -> Vec<String> {
    check_text(text)
        .into_iter()
        .filter(|c| {
            matches!(
                c.as_str(),
                "VRML_MALFORMED" | "FIELD_UNKNOWN" | "FIELD_VALUE_SYNTAX" | "NODE_UNKNOWN"
            )
        })
        .collect()
}

#[test]
fn one_classic_syntax_error_gives_one_diagnostic() {
    // A PROTO in a node list: read where it stands, its instance known.
    let codes = syntax_codes(
        "#VRML V2.0 utf8\nTransform { children [ Shape { } PROTO P [ field SFFloat s 1 ] { Group { } } Group { } ] translation 1 0 0 }\nP { s 2 }\n",
    );
    assert_eq!(codes, ["VRML_MALFORMED"]);
    // A ROUTE in a node list.
    let codes = syntax_codes(
        "#X3D V3.3 utf8\nPROFILE Interchange\nDEF T TimeSensor { }\nDEF G Group { children [ DEF I ScalarInterpolator { } ROUTE T.fraction_changed TO I.set_fraction Shape { } ] }\n",
    );
    assert_eq!(codes, ["VRML_MALFORMED"]);
    // A name that is neither a node nor a field of the enclosing node, with a value.
    let codes = syntax_codes(
        "#VRML V2.0 utf8\nTransform { children [ Shape { } Bogus [ 1 2 3 ] Shape { } ] translation 1 0 0 }\n",
    );
    assert_eq!(codes, ["VRML_MALFORMED"]);
    // A string that never ends swallows the rest of the file, braces included.
    let codes = syntax_codes("#VRML V2.0 utf8\nGroup { children [ WorldInfo { title \"abc } ] }\n");
    assert_eq!(codes, ["VRML_MALFORMED"]);
    let codes = syntax_codes("#VRML V2.0 utf8\nGroup { children [ Anchor { url [ \"abc ] } ] }\n");
    assert_eq!(codes, ["VRML_MALFORMED"]);
}
