//! Scenes written in both encodings, and what the checker says of them.

use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;
use x3dcheck::model::{Document, Value};
use x3dcheck::report::{FileReport, Resolved};
use x3dcheck::schema::{schema, Version};

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Encoding {
    Xml,
    Json,
}

pub const ENCODINGS: [Encoding; 2] = [Encoding::Xml, Encoding::Json];

/// A node to write: its fields as number (or boolean) tokens, and its child nodes by
/// field name. Tokens go in as written, so a test controls every character of a number.
#[derive(Clone, Debug)]
pub struct El {
    pub name: &'static str,
    pub fields: Vec<(&'static str, Vec<String>)>,
    pub children: Vec<(&'static str, El)>,
}

impl El {
    pub fn new(name: &'static str) -> El {
        El {
            name,
            fields: Vec::new(),
            children: Vec::new(),
        }
    }

    pub fn field<S: ToString>(
        mut self,
        name: &'static str,
        tokens: impl IntoIterator<Item = S>,
    ) -> El {
        self.fields
            .push((name, tokens.into_iter().map(|t| t.to_string()).collect()));
        self
    }

    pub fn child(mut self, field: &'static str, child: El) -> El {
        self.children.push((field, child));
        self
    }

    fn xml(&self, out: &mut String) {
        out.push('<');
        out.push_str(self.name);
        for (name, tokens) in &self.fields {
            out.push_str(&format!(" {name}='{}'", tokens.join(" ")));
        }
        if self.children.is_empty() {
            out.push_str("/>");
            return;
        }
        out.push('>');
        for (_, child) in &self.children {
            child.xml(out);
        }
        out.push_str(&format!("</{}>", self.name));
    }

    /// The JSON object of the node. Whether a value is an array, and whether a node field
    /// holds one node or a list, comes from the schema of `version`.
    fn json(&self, version: Version, out: &mut String) {
        let def = schema(version)
            .node(self.name)
            .unwrap_or_else(|| panic!("no {} in X3D {version}", self.name));
        let mut members = Vec::new();
        for (name, tokens) in &self.fields {
            let ty = def
                .field(name)
                .unwrap_or_else(|| panic!("no {}.{name} in X3D {version}", self.name))
                .ty;
            let value = if !ty.is_mf() && ty.arity() == 1 {
                tokens.join(" ")
            } else {
                format!("[{}]", tokens.join(", "))
            };
            members.push(format!("\"@{name}\": {value}"));
        }
        let mut fields: Vec<&str> = Vec::new();
        for (field, _) in &self.children {
            if !fields.contains(field) {
                fields.push(field);
            }
        }
        for field in fields {
            let many = def.field(field).is_some_and(|f| f.ty.is_mf());
            let nodes: Vec<String> = self
                .children
                .iter()
                .filter(|(f, _)| *f == field)
                .map(|(_, child)| {
                    let mut text = String::new();
                    child.json(version, &mut text);
                    text
                })
                .collect();
            let value = if many {
                format!("[{}]", nodes.join(", "))
            } else {
                nodes.join(", ")
            };
            members.push(format!("\"-{field}\": {value}"));
        }
        out.push_str(&format!(
            "{{\"{}\": {{{}}}}}",
            self.name,
            members.join(", ")
        ));
    }
}

/// A whole document with `nodes` at the top of its Scene.
pub fn document(encoding: Encoding, version: Version, nodes: &[El]) -> String {
    match encoding {
        Encoding::Xml => {
            let mut scene = String::new();
            for node in nodes {
                node.xml(&mut scene);
            }
            format!("<X3D profile='Full' version='{version}'><Scene>{scene}</Scene></X3D>")
        }
        Encoding::Json => {
            let children: Vec<String> = nodes
                .iter()
                .map(|node| {
                    let mut text = String::new();
                    node.json(version, &mut text);
                    text
                })
                .collect();
            format!(
                "{{\"X3D\": {{\"@profile\": \"Full\", \"@version\": \"{version}\", \"Scene\": {{\"-children\": [{}]}}}}}}",
                children.join(", ")
            )
        }
    }
}

pub fn config(level: Level) -> CheckConfig {
    CheckConfig {
        level,
        ..CheckConfig::default()
    }
}

pub fn check_with(source: &str, config: &CheckConfig) -> FileReport {
    x3dcheck::check_source("extreme.x3d", source.as_bytes(), config)
}

pub fn check(source: &str, level: Level) -> FileReport {
    check_with(source, &config(level))
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

/// The value the first node of type `node` holds for `field`, if it holds one.
pub fn value_of<'d>(doc: &'d Document, node: &str, field: &str) -> Option<&'d Value> {
    let id = doc.nodes_of_type(node).next()?;
    doc.node(id).value(field)
}

/// Whether `text` is a JSON number (RFC 8259 grammar); the others are XML-only tokens.
pub fn is_json_number(text: &str) -> bool {
    let s = text.strip_prefix('-').unwrap_or(text);
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(at) => (&s[..at], Some(&s[at + 1..])),
        None => (s, None),
    };
    let (int, fraction) = match mantissa.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (mantissa, None),
    };
    let digits = |d: &str| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit());
    digits(int)
        && (int == "0" || !int.starts_with('0'))
        && fraction.is_none_or(digits)
        && exponent.is_none_or(|e| digits(e.strip_prefix(['+', '-']).unwrap_or(e)))
}

/// Whether a text spells a non-finite number the way Rust, C or JSON tools print one
/// (`NaN`, `inf`, `-inf`, `Infinity`), as a word of its own.
pub fn has_non_finite_word(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphanumeric()).any(|w| {
        ["nan", "inf", "infinity"]
            .iter()
            .any(|bad| w.eq_ignore_ascii_case(bad))
    })
}
