//! Hover: a node type (component and level, clause, default containerField), a field (type,
//! access type, default, range, enumeration, accepted node types), a USE or ROUTE name (the
//! DEF it names and where), and the rule docs of the findings at the place.
//!
//! Node and field descriptions are the X3D Unified Object Model's, generated into
//! `schema::descriptions` at the newest version's wording.

use std::fmt::Write as _;

use super::convert::rule_markdown;
use super::navigate::{target, Target};
use super::position::Lines;
use super::Analysis;
use crate::diagnostic::Span;
use crate::model::{Document, FieldRef, Node, NodeKind};
use crate::schema::{
    clauses, field_description, node_description, range_text, FieldDef, NodeDef, Version,
};
use crate::validate::find_rule;

/// The hover at `offset`: the span it concerns and its Markdown.
pub fn hover(analysis: &Analysis, offset: usize) -> Option<(Span, String)> {
    let mut parts = Vec::new();
    let mut span = None;
    if let Some(doc) = &analysis.document {
        if let Some((at, text)) = model_hover(doc, &analysis.text, offset) {
            span = Some(at);
            parts.push(text);
        }
    }
    for d in &analysis.report.diagnostics {
        let (start, end) = (d.span.start as usize, d.span.end as usize);
        if start <= offset && offset <= end.max(start + 1) {
            if let Some(rule) = find_rule(d.code) {
                span.get_or_insert(d.span);
                parts.push(format!(
                    "**{}**: {}\n\n{}",
                    d.code,
                    d.message,
                    rule_markdown(rule)
                ));
            }
        }
    }
    (!parts.is_empty()).then(|| (span.unwrap_or_default(), parts.join("\n\n---\n\n")))
}

fn model_hover(doc: &Document, text: &[u8], offset: usize) -> Option<(Span, String)> {
    Some(match target(doc, offset)? {
        Target::NodeName(node) => (node.name_span, node_hover(node)?),
        Target::Field(node, entry) => {
            let markdown = match &entry.field {
                FieldRef::Schema { def, .. } => field_hover(def, node.type_name()),
                FieldRef::Declared { name, ty } => format!(
                    "**{name}**: {}\n\ndeclared by the prototype",
                    ty.map_or("(type unknown)", |t| t.as_str())
                ),
                FieldRef::Unknown { name } => {
                    format!("**{name}**: no field of {}", node.type_name())
                }
            };
            (entry.name_span, markdown)
        }
        Target::Reference { span, node } => {
            let node = doc.nodes.get(node.index())?;
            let def = node.def_name.as_ref()?;
            let line = Lines::new(text, super::position::Units::Utf8)
                .position(def.span.start as usize)
                .line
                + 1;
            (
                span,
                format!(
                    "`DEF {}` — **{}**, defined on line {line}",
                    def.text,
                    node.type_name()
                ),
            )
        }
    })
}

fn node_hover(node: &Node) -> Option<String> {
    let NodeKind::Known { def, version } = &node.kind else {
        return match &node.kind {
            NodeKind::ProtoInstance { name, .. } => {
                Some(format!("instance of prototype **{name}**"))
            }
            _ => None,
        };
    };
    Some(node_type_markdown(def, *version))
}

/// A node type as hover and completion documentation show it.
pub fn node_type_markdown(def: &NodeDef, version: Version) -> String {
    let mut out = format!(
        "**{}** (X3D {})\n\ncomponent {}, level {}",
        def.name,
        version.as_str(),
        def.component.component,
        def.component.level
    );
    if let Some(clause) = clauses::node_subclause(version, def.name) {
        let _ = write!(out, " · ISO/IEC 19775-1 {clause}");
    }
    if let Some(text) = node_description(def.name) {
        let _ = write!(out, "\n\n{}", escape_markdown(text));
    }
    let _ = write!(
        out,
        "\n\ndefault containerField `{}` · {} fields",
        def.container_field,
        def.fields.len()
    );
    if !def.ancestors.is_empty() {
        let _ = write!(out, "\n\nis a {}", def.ancestors.join(", "));
    }
    out.push_str("\n\n| field | type | access | default |\n|---|---|---|---|");
    for field in def.fields {
        let _ = write!(
            out,
            "\n| {} | {} | {} | {} |",
            field.name,
            field.ty.as_str(),
            field.access.as_str(),
            table_default(field.default)
        );
    }
    out
}

/// A default as a table cell: code, cut to a line's worth (an MF default may be long), and
/// `|` escaped, which would end the cell.
fn table_default(default: &str) -> String {
    const LONGEST: usize = 32;
    if default.is_empty() {
        return String::new();
    }
    let mut text: String = default.chars().take(LONGEST).collect();
    if text.len() < default.len() {
        text.push('…');
    }
    format!("`{}`", text.replace('|', "\\|"))
}

/// A field as hover and completion documentation show it.
pub fn field_hover(def: &FieldDef, node: &str) -> String {
    let mut out = format!(
        "**{}**: {} ({}) — field of {node}",
        def.name,
        def.ty.as_str(),
        def.access.as_str()
    );
    if let Some(text) = field_description(node, def.name) {
        let _ = write!(out, "\n\n{}", escape_markdown(text));
    }
    if !def.default.is_empty() {
        let _ = write!(out, "\n\ndefault `{}`", def.default);
    }
    if def.min.is_some() || def.max.is_some() {
        let _ = write!(out, "\n\nrange {}", range_text(def));
    }
    if !def.enumeration.is_empty() {
        let _ = write!(
            out,
            "\n\n{}: {}",
            if def.enumeration_strict {
                "one of"
            } else {
                "for example"
            },
            def.enumeration
                .iter()
                .map(|v| format!("`{v}`"))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    if !def.acceptable.is_empty() {
        let _ = write!(out, "\n\naccepts {}", def.acceptable.join(", "));
    }
    if let Some(level) = def.component {
        let _ = write!(
            out,
            "\n\nneeds component {} level {}",
            level.component, level.level
        );
    }
    out
}

/// UOM prose as Markdown text: the characters Markdown would read as emphasis, code, links
/// or HTML are escaped (descriptions say `x*y`, `<Shape>` and `[0,1]`).
pub fn escape_markdown(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if matches!(
            c,
            '\\' | '*' | '_' | '`' | '<' | '>' | '[' | ']' | '#' | '|'
        ) {
            out.push('\\');
        }
        out.push(c);
    }
    out
}
