//! Documents around one node or field, in both encodings, and what the checker says of them.

use x3dcheck::config::CheckConfig;
use x3dcheck::model::{Document, Value};
use x3dcheck::report::{FileReport, Resolved};
use x3dcheck::schema::Version;
use x3dcheck::validate::Level;

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Encoding {
    Xml,
    Json,
}

pub const ENCODINGS: [Encoding; 2] = [Encoding::Xml, Encoding::Json];

/// A scene node of type `node` with field values already written in the encoding's
/// syntax: `(name, text)`, the text an XML attribute value or a JSON value.
pub struct NodeText<'a> {
    pub node: &'a str,
    pub fields: &'a [(&'a str, String)],
}

/// A whole document holding `node` at the top of the Scene.
pub fn document(encoding: Encoding, version: Version, node: &NodeText) -> String {
    match encoding {
        Encoding::Xml => {
            let attributes: String = node
                .fields
                .iter()
                .map(|(name, text)| format!(" {name}='{text}'"))
                .collect();
            format!(
                "<X3D profile='Full' version='{version}'><Scene><{}{attributes}/></Scene></X3D>",
                node.node
            )
        }
        Encoding::Json => {
            let members: Vec<String> = node
                .fields
                .iter()
                .map(|(name, text)| format!("\"@{name}\": {text}"))
                .collect();
            format!(
                "{{\"X3D\": {{\"@profile\": \"Full\", \"@version\": \"{version}\", \"Scene\": {{\"-children\": [{{\"{}\": {{{}}}}}]}}}}}}",
                node.node,
                members.join(", ")
            )
        }
    }
}

/// A value of numbers as the encoding writes it: space-separated in XML, an array in
/// JSON unless it is a single value of an SF type of arity 1 (`scalar`).
pub fn numbers(encoding: Encoding, tokens: &[String], scalar: bool) -> String {
    match encoding {
        Encoding::Xml => tokens.join(" "),
        Encoding::Json if scalar => tokens[0].clone(),
        Encoding::Json => format!("[{}]", tokens.join(", ")),
    }
}

pub fn config(level: Level) -> CheckConfig {
    CheckConfig {
        level,
        ..CheckConfig::default()
    }
}

pub fn check(source: &str, level: Level) -> FileReport {
    x3dcheck::check_source("extreme.x3d", source.as_bytes(), &config(level))
}

/// The diagnostics of one code.
pub fn of<'r>(report: &'r FileReport, code: &str) -> Vec<&'r Resolved> {
    report
        .diagnostics
        .iter()
        .filter(|d| d.code == code)
        .collect()
}

/// The document a source reads into; panics when it is not one.
pub fn read(source: &str) -> Document {
    x3dcheck::parse::read(source.as_bytes())
        .document
        .unwrap_or_else(|| panic!("not a document: {source}"))
}

/// The value the first node of type `node` holds for `field`.
pub fn value_of<'d>(doc: &'d Document, node: &str, field: &str) -> &'d Value {
    let id = doc
        .nodes_of_type(node)
        .next()
        .unwrap_or_else(|| panic!("no {node}"));
    doc.node(id)
        .value(field)
        .unwrap_or_else(|| panic!("{node}.{field} is not set"))
}

/// Words of a text (letters and digits), to look for `NaN` and `inf` as words.
pub fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
}

/// Whether a text spells a non-finite number the way Rust, C or JSON tools print one.
pub fn has_non_finite_word(text: &str) -> bool {
    words(text).any(|w| {
        ["nan", "inf", "infinity"]
            .iter()
            .any(|bad| w.eq_ignore_ascii_case(bad))
    })
}
