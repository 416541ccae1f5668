//! The same scene in XML and in JSON gives the same model: every `.x3d`/`.json` pair with
//! one stem in `../shared/corpus/pythonSAI` and `../shared/corpus/x3dschema` is read with
//! `x3dcheck::parse::read` and compared through a canonical summary (node types, DEF/USE
//! structure, routes, protos, and every node's field values), then through the `stats`
//! of `x3dcheck --format json`.
//!
//! The pairs come from different tools (the XML is the source, the JSON was produced from
//! it by the X3dToJson stylesheet), and the comparison ignores what that conversion is
//! documented to change:
//! - values equal to the field's default are dropped by X3dToJson (`scale='1 1 1'`), and
//!   so are zero rotations about any axis (`orientation='0 1 0 0'`): a field set to its
//!   default (or an SFRotation to a zero angle) counts as not set, on both sides;
//! - comments, source code text (CDATA vs an array of lines), `containerField` (the JSON
//!   key is the field) and the order of a node's fields: node fields are walked in name
//!   order, fields are compared as a sorted list;
//! - numbers are re-printed by the stylesheet: floats compare equal within 1 ulp of their
//!   precision;
//! - the raw text of values the model keeps unparsed (unknown fields, values that do not
//!   parse) differs by encoding: only their presence is compared.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use common::summary::{first_difference, Summary};

/// Pairs whose XML and JSON really describe different scenes, with the reason.
const KNOWN_DIFFERENCES: &[(&str, &str)] = &[
    (
        "pythonSAI/JohnJoint",
        "the XML has an HAnimHumanoid in the Scene with containerField='skeleton'; the JSON left it out",
    ),
    (
        "pythonSAI/t4",
        "X3dToJson mangled the MFString url `\"a\", \"b\"`: the JSON has [\", \", \"a');b\"]",
    ),
    (
        "pythonSAI/Json",
        "a MetadataString in a Shape without containerField is the Shape's metadata in the XML (x3d-4.0.xsd); the JSON converter wrote it to `-value`, which Shape has not",
    ),
    ("x3dschema/examples/mirror", "the XML has `component Shape 4` that the JSON lacks"),
    ("x3dschema/examples/mirror2", "the XML has `component Shape 4` that the JSON lacks"),
    ("x3dschema/examples/rubik", "the XML says version 4.0, the JSON 3.3"),
    (
        "x3dschema/examples/sphereflowers",
        "the XML has a Sound, AudioClip and ROUTE commented out; the JSON has them",
    ),
    (
        "x3dschema/examples/plainflowers",
        "the ExternProtoDeclare url is ../data/… in the XML and ../personal/… in the JSON",
    ),
    (
        "x3dschema/examples/x3domflowers",
        "the ExternProtoDeclare url is ../data/… in the XML and ../personal/… in the JSON",
    ),
];

/// Pairs whose reader findings differ because their files do (beyond KNOWN_DIFFERENCES).
const KNOWN_FINDING_DIFFERENCES: &[(&str, &str)] = &[(
    "pythonSAI/Trebuchet",
    "the XML sets whichChoice='-1' on three USE nodes (USE_WITH_FIELDS); X3dToJson dropped the default value",
)];

fn pairs() -> Vec<(String, PathBuf, PathBuf)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    assert!(
        root.is_dir(),
        "../shared/corpus is missing: {}",
        root.display()
    );
    let mut pairs = Vec::new();
    for folder in ["pythonSAI", "x3dschema"] {
        let mut dirs = vec![root.join(folder)];
        while let Some(dir) = dirs.pop() {
            for entry in std::fs::read_dir(&dir).unwrap().flatten() {
                let path = entry.path();
                if entry.file_type().unwrap().is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|e| e == "json") {
                    let xml = path.with_extension("x3d");
                    if xml.is_file() {
                        let name = path
                            .strip_prefix(&root)
                            .unwrap()
                            .with_extension("")
                            .display()
                            .to_string();
                        pairs.push((name, xml, path));
                    }
                }
            }
        }
    }
    pairs.sort();
    pairs
}

#[test]
fn xml_and_json_give_the_same_model() {
    let pairs = pairs();
    assert!(
        pairs.len() >= 100,
        "expected the corpus pairs, found {}",
        pairs.len()
    );
    let mut mismatches = Vec::new();
    let mut equal = 0;
    for (name, xml_path, json_path) in &pairs {
        let xml = x3dcheck::parse::read(&std::fs::read(xml_path).unwrap());
        let json = x3dcheck::parse::read(&std::fs::read(json_path).unwrap());
        let known = KNOWN_DIFFERENCES.iter().find(|(n, _)| n == name);
        let (Some(xml_doc), Some(json_doc)) = (&xml.document, &json.document) else {
            mismatches.push(format!(
                "{name}: a side did not read (xml: {:?}, json: {:?})",
                xml.diagnostics.first().map(|d| &d.message),
                json.diagnostics.first().map(|d| &d.message)
            ));
            continue;
        };
        let difference = first_difference(
            ("xml", &Summary::of(xml_doc)),
            ("json", &Summary::of(json_doc)),
        );
        match (difference, known) {
            (None, None) => equal += 1,
            (None, Some(_)) => mismatches.push(format!(
                "{name}: listed as a known difference but now equal"
            )),
            (Some(_), Some(_)) => {}
            (Some(difference), None) => mismatches.push(format!("{name}:\n{difference}")),
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} of {} pairs differ ({equal} equal):\n{}",
        mismatches.len(),
        pairs.len(),
        mismatches.join("\n")
    );
}

/// The reader diagnostics of both sides agree (same codes, same counts) where the scene
/// is the same.
#[test]
fn xml_and_json_report_the_same_reader_findings() {
    let mut mismatches = Vec::new();
    for (name, xml_path, json_path) in &pairs() {
        if KNOWN_DIFFERENCES
            .iter()
            .chain(KNOWN_FINDING_DIFFERENCES)
            .any(|(n, _)| n == name)
        {
            continue;
        }
        let codes = |path: &Path| {
            let parsed = x3dcheck::parse::read(&std::fs::read(path).unwrap());
            let mut codes: BTreeMap<&'static str, usize> = BTreeMap::new();
            // XML-only spellings (an MFString element without quotes, 19776-1 5.15; a
            // comma inside one value, 5.1.2) have no JSON form: JSON writes arrays.
            let xml_only = |message: &str| {
                message.contains("is not in quotes") || message.contains("a comma ")
            };
            for d in parsed.diagnostics.iter().filter(|d| !xml_only(&d.message)) {
                *codes.entry(d.rule.code).or_default() += 1;
            }
            codes
        };
        let (xml, json) = (codes(xml_path), codes(json_path));
        if xml != json {
            mismatches.push(format!("{name}: xml {xml:?}, json {json:?}"));
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} pairs differ:\n{}",
        mismatches.len(),
        mismatches.join("\n")
    );
}

/// `x3dcheck --format json` gives the same `stats` for both members of every pair.
#[test]
fn cli_stats_agree() {
    let binary = env!("CARGO_BIN_EXE_x3dcheck");
    let pairs = pairs();
    let stats = |path: &Path| -> serde_json::Value {
        let output = std::process::Command::new(binary)
            .args(["--format", "json"])
            .arg(path)
            .output()
            .expect("run x3dcheck");
        let report: serde_json::Value = serde_json::from_slice(&output.stdout)
            .unwrap_or_else(|e| panic!("{}: the JSON report does not parse: {e}", path.display()));
        report["files"][0]["stats"].clone()
    };
    let mut mismatches = Vec::new();
    for (name, xml_path, json_path) in &pairs {
        if KNOWN_DIFFERENCES.iter().any(|(n, _)| n == name) {
            continue;
        }
        let (xml, json) = (stats(xml_path), stats(json_path));
        if xml.is_null() || xml != json {
            mismatches.push(format!("{name}:\n      xml:  {xml}\n      json: {json}"));
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} of {} pairs differ in stats:\n{}",
        mismatches.len(),
        pairs.len(),
        mismatches.join("\n")
    );
}
