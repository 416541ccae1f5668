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

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use x3dcheck::model::{ChildRef, Document, FieldEntry, FieldRef, Node, NodeKind, Value};
use x3dcheck::parse::xml_value;
use x3dcheck::schema::{FieldType, Scalar};

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

/// A field value for comparison: numbers at their precision, the rest as text.
#[derive(Debug, Clone)]
enum V {
    F32(Vec<f32>),
    F64(Vec<f64>),
    Text(String),
}

fn within_ulp_f32(a: f32, b: f32) -> bool {
    a == b
        || (a.is_nan() && b.is_nan())
        || (a.signum() == b.signum() && a.to_bits().abs_diff(b.to_bits()) <= 1)
}

fn within_ulp_f64(a: f64, b: f64) -> bool {
    a == b
        || (a.is_nan() && b.is_nan())
        || (a.signum() == b.signum() && a.to_bits().abs_diff(b.to_bits()) <= 1)
}

impl PartialEq for V {
    fn eq(&self, other: &V) -> bool {
        match (self, other) {
            (V::F32(a), V::F32(b)) => {
                a.len() == b.len() && a.iter().zip(b).all(|(x, y)| within_ulp_f32(*x, *y))
            }
            (V::F64(a), V::F64(b)) => {
                a.len() == b.len() && a.iter().zip(b).all(|(x, y)| within_ulp_f64(*x, *y))
            }
            (V::Text(a), V::Text(b)) => a == b,
            _ => false,
        }
    }
}

fn v(value: &Value) -> V {
    match value {
        Value::Floats(f) => V::F32(f.clone()),
        Value::Doubles(d) => V::F64(d.clone()),
        Value::Bools(b) => V::Text(format!("{b:?}")),
        Value::Int32s(i) => V::Text(format!("{i:?}")),
        Value::Strings(s) => V::Text(format!("{s:?}")),
        Value::Images(i) => V::Text(format!("{i:?}")),
        Value::Nodes(n) => V::Text(format!("{} nodes", n.len())),
        Value::Unparsed(_) => V::Text("<unparsed>".to_string()),
        Value::Summary(s) => V::Text(format!("{s:?}")),
    }
}

/// One line of the canonical summary: text, and the values it carries.
#[derive(Debug, Clone, PartialEq)]
struct Line {
    text: String,
    value: Option<V>,
}

fn line(out: &mut Vec<Line>, depth: usize, text: String, value: Option<V>) {
    out.push(Line {
        text: format!("{}{text}", "  ".repeat(depth)),
        value,
    });
}

/// Whether an entry holds its field's default (X3dToJson leaves those out).
fn is_default(entry: &FieldEntry) -> bool {
    let FieldRef::Schema { def, .. } = &entry.field else {
        return false;
    };
    if matches!(def.ty.scalar(), Scalar::Node) {
        return false;
    }
    if let (FieldType::SFRotation, Value::Floats(r)) = (def.ty, &entry.value) {
        if r.len() == 4 && r[3] == 0.0 {
            return true;
        }
    }
    match xml_value::parse_value(def.ty, def.default) {
        Ok(default) => v(&default) == v(&entry.value),
        Err(_) => false,
    }
}

struct Summary<'d> {
    doc: &'d Document,
    lines: Vec<Line>,
}

impl Summary<'_> {
    fn of(doc: &Document) -> Vec<Line> {
        let mut s = Summary {
            doc,
            lines: Vec::new(),
        };
        let mut types: BTreeMap<&str, usize> = BTreeMap::new();
        for node in &doc.nodes {
            *types.entry(node.type_name()).or_default() += 1;
        }
        line(
            &mut s.lines,
            0,
            format!(
                "version {:?} profile {:?}",
                doc.version,
                doc.profile.as_ref().map(|p| &p.text)
            ),
            None,
        );
        let components: Vec<_> = doc
            .head
            .components
            .iter()
            .map(|c| (c.name.text.clone(), c.level.map(|l| l.0)))
            .collect();
        line(
            &mut s.lines,
            0,
            format!("components {components:?} units {}", doc.head.units),
            None,
        );
        line(
            &mut s.lines,
            0,
            format!("{} nodes: {types:?}", doc.nodes.len()),
            None,
        );
        let defs = doc.nodes.iter().filter(|n| n.def_name.is_some()).count();
        line(&mut s.lines, 0, format!("{defs} DEFs"), None);
        let mut routes: Vec<String> = doc
            .routes
            .iter()
            .map(|r| {
                format!(
                    "ROUTE {}.{} TO {}.{} in {:?}",
                    r.from_node.text, r.from_field.text, r.to_node.text, r.to_field.text, r.scope
                )
            })
            .collect();
        routes.sort();
        for route in routes {
            line(&mut s.lines, 0, route, None);
        }
        for proto in &doc.protos {
            line(
                &mut s.lines,
                0,
                format!(
                    "PROTO {} external={} url={:?}",
                    proto.name.text, proto.external, proto.url
                ),
                None,
            );
            for decl in &proto.interface {
                s.decl(1, decl);
            }
            for child in &proto.body {
                s.child(1, child);
            }
        }
        line(&mut s.lines, 0, "Scene".to_string(), None);
        for child in &doc.scene {
            s.child(1, child);
        }
        s.lines
    }

    fn decl(&mut self, depth: usize, decl: &x3dcheck::model::FieldDecl) {
        let value = decl.value.as_ref().map(|(value, _)| value);
        let text = format!("field {} {:?} {:?}", decl.name.text, decl.ty, decl.access);
        match value {
            Some(Value::Nodes(children)) => {
                line(&mut self.lines, depth, text, None);
                for child in children {
                    self.child(depth + 1, child);
                }
            }
            Some(value) => line(&mut self.lines, depth, text, Some(v(value))),
            None => line(&mut self.lines, depth, text, None),
        }
    }

    fn child(&mut self, depth: usize, child: &ChildRef) {
        let node = self.doc.node(child.node);
        if child.is_use {
            let name = node.def_name.as_ref().map_or("?", |d| d.text.as_str());
            line(
                &mut self.lines,
                depth,
                format!("USE {} {name}", node.type_name()),
                None,
            );
            return;
        }
        self.node(depth, node);
    }

    fn node(&mut self, depth: usize, node: &Node) {
        let kind = match &node.kind {
            NodeKind::ProtoInstance { name, .. } => format!("ProtoInstance {name}"),
            _ => node.type_name().to_string(),
        };
        let def = node
            .def_name
            .as_ref()
            .map_or(String::new(), |d| format!(" DEF {}", d.text));
        line(&mut self.lines, depth, format!("{kind}{def}"), None);
        let mut values: Vec<&FieldEntry> = node
            .fields
            .iter()
            .filter(|e| !matches!(e.value, Value::Nodes(_)) && !is_default(e))
            .collect();
        values.sort_by_key(|e| e.name().to_string());
        for entry in values {
            line(
                &mut self.lines,
                depth + 1,
                format!("@{}", entry.name()),
                Some(v(&entry.value)),
            );
        }
        for decl in &node.declared {
            self.decl(depth + 1, decl);
        }
        for connect in &node.connects {
            line(
                &mut self.lines,
                depth + 1,
                format!(
                    "IS {} {}",
                    connect.node_field.text, connect.proto_field.text
                ),
                None,
            );
        }
        let mut node_fields: Vec<&FieldEntry> = node
            .fields
            .iter()
            .filter(|e| matches!(&e.value, Value::Nodes(c) if !c.is_empty()))
            .collect();
        node_fields.sort_by_key(|e| e.name().to_string());
        for entry in node_fields {
            line(
                &mut self.lines,
                depth + 1,
                format!("-{}", entry.name()),
                None,
            );
            if let Value::Nodes(children) = &entry.value {
                for child in children {
                    self.child(depth + 2, child);
                }
            }
        }
    }
}

fn show(line: Option<&Line>) -> String {
    match line {
        None => "(nothing)".to_string(),
        Some(Line { text, value: None }) => text.trim().to_string(),
        Some(Line {
            text,
            value: Some(value),
        }) => {
            let mut shown = format!("{value:?}");
            if shown.len() > 160 {
                let cut = (0..=160)
                    .rev()
                    .find(|&i| shown.is_char_boundary(i))
                    .unwrap_or(0);
                shown.truncate(cut);
                shown.push('…');
            }
            format!("{} = {shown}", text.trim())
        }
    }
}

/// The first difference between two summaries, with the lines around it.
fn first_difference(xml: &[Line], json: &[Line]) -> Option<String> {
    let at = (0..xml.len().max(json.len())).find(|&i| xml.get(i) != json.get(i))?;
    let mut out = String::new();
    if let Some(context) = at.checked_sub(1).and_then(|i| xml.get(i)) {
        let _ = writeln!(out, "      after: {}", show(Some(context)));
    }
    let _ = writeln!(out, "      xml:   {}", show(xml.get(at)));
    let _ = write!(out, "      json:  {}", show(json.get(at)));
    Some(out)
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
        let difference = first_difference(&Summary::of(xml_doc), &Summary::of(json_doc));
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
            for d in &parsed.diagnostics {
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
