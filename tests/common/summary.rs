//! A canonical summary of a scene model for comparing encodings: node types, DEF/USE
//! structure, routes, protos, and every node's field values (node fields in name order,
//! fields as a sorted list, floats equal within 1 ulp, fields at their default left out,
//! unparsed text compared by presence only). Used by tests/json_xml_equivalence.rs and
//! tests/encoding_equivalence.rs.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use x3dcheck::model::text::xml_value;
use x3dcheck::model::{ChildRef, Document, FieldEntry, FieldRef, Node, NodeKind, Value};
use x3dcheck::schema::{FieldType, Scalar};

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
pub struct Line {
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

pub struct Summary<'d> {
    doc: &'d Document,
    lines: Vec<Line>,
}

impl Summary<'_> {
    pub fn of(doc: &Document) -> Vec<Line> {
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
        let units: Vec<_> = doc
            .head
            .units
            .iter()
            .map(|u| {
                let text = |n: &Option<x3dcheck::model::Named>| n.as_ref().map(|n| n.text.clone());
                (
                    text(&u.category),
                    text(&u.name),
                    u.conversion_factor.map(|(factor, _)| factor),
                )
            })
            .collect();
        line(
            &mut s.lines,
            0,
            format!("components {components:?} units {units:?}"),
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

/// The first difference between two labelled summaries, with the line before it.
pub fn first_difference(a: (&str, &[Line]), b: (&str, &[Line])) -> Option<String> {
    let ((a_name, a), (b_name, b)) = (a, b);
    let at = (0..a.len().max(b.len())).find(|&i| a.get(i) != b.get(i))?;
    let mut out = String::new();
    if let Some(context) = at.checked_sub(1).and_then(|i| a.get(i)) {
        let _ = writeln!(out, "      after: {}", show(Some(context)));
    }
    let _ = writeln!(out, "      {:<6} {}", format!("{a_name}:"), show(a.get(at)));
    let _ = write!(out, "      {:<6} {}", format!("{b_name}:"), show(b.get(at)));
    Some(out)
}
