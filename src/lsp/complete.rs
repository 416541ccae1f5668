//! Completion: node types the enclosing field accepts, a node's field names (attribute
//! names in XML, `@`/`-` keys in JSON), enumeration values, and the DEF names a USE there
//! may name.

use lsp_types::{CompletionItem, CompletionItemKind, Documentation, MarkupContent, MarkupKind};

use super::context::{context, Context, Syntax};
use super::hover::{escape_markdown, field_hover, node_type_markdown};
use super::Analysis;
use crate::model::{Document, Scope};
use crate::schema::{
    schema, value_description, FieldDef, FieldType, NodeDef, Version, VersionSchema,
};

/// A completion's label, kind, detail and Markdown documentation.
pub struct Candidate {
    pub label: String,
    /// What the completion inserts, when it is not the label.
    pub insert: Option<String>,
    pub kind: CompletionItemKind,
    pub detail: Option<String>,
    pub doc: Option<String>,
}

impl Candidate {
    pub fn item(self, edit_range: lsp_types::Range) -> CompletionItem {
        CompletionItem {
            text_edit: Some(lsp_types::CompletionTextEdit::Edit(
                lsp_types::TextEdit::new(
                    edit_range,
                    self.insert.unwrap_or_else(|| self.label.clone()),
                ),
            )),
            label: self.label,
            kind: Some(self.kind),
            detail: self.detail,
            documentation: self.doc.map(|value| {
                Documentation::MarkupContent(MarkupContent {
                    kind: MarkupKind::Markdown,
                    value,
                })
            }),
            ..CompletionItem::default()
        }
    }
}

/// The completions at `offset` of `text` (the newest text); `analysis`, the last check
/// (or, if its reader stopped, the last that read a document), gives the version and the
/// DEF names.
pub fn complete(text: &[u8], offset: usize, analysis: Option<&Analysis>) -> Vec<Candidate> {
    let syntax = Syntax::of(text);
    let doc = analysis
        .and_then(Analysis::with_document)
        .and_then(|a| a.document.as_ref());
    let version = doc.and_then(|d| d.version).unwrap_or(Version::V4_0);
    let schema = schema(version);
    match context(syntax, text, offset) {
        Some(Context::NodeName { parent, field }) => {
            node_names(schema, syntax, parent.as_deref(), field.as_deref())
        }
        Some(Context::ElementContent { parent }) => {
            let mut names = node_names(schema, syntax, Some(&parent), None);
            for name in &mut names {
                name.insert = Some(format!("<{}", name.label));
            }
            names
        }
        Some(Context::FieldName { node, written }) => match schema.node(&node) {
            Some(def) => field_names(def, syntax, &written),
            None => Vec::new(),
        },
        Some(Context::Value { node, field }) => schema
            .node(&node)
            .and_then(|def| def.field(&field))
            .map(|field| {
                field
                    .enumeration
                    .iter()
                    .map(|value| Candidate {
                        insert: None,
                        label: value.to_string(),
                        kind: CompletionItemKind::ENUM_MEMBER,
                        detail: Some(format!("{} of {node}", field.name)),
                        doc: value_description(&node, field.name, value).map(escape_markdown),
                    })
                    .collect()
            })
            .unwrap_or_default(),
        Some(Context::DefName) => {
            let Some(doc) = doc else {
                return Vec::new();
            };
            let scope = scope_at(doc, offset);
            let mut names: Vec<Candidate> = doc
                .defs
                .iter()
                .filter(|((def_scope, _), _)| *def_scope == scope)
                .map(|((_, name), node)| Candidate {
                    insert: None,
                    label: name.clone(),
                    kind: CompletionItemKind::REFERENCE,
                    detail: doc
                        .nodes
                        .get(node.index())
                        .map(|n| n.type_name().to_string()),
                    doc: None,
                })
                .collect();
            names.sort_by(|a, b| a.label.cmp(&b.label));
            names
        }
        None => Vec::new(),
    }
}

/// The scope whose DEF names a USE at `offset` may name: the body of the innermost
/// prototype whose body (from its first node or ROUTE to its last) holds the offset, else
/// the scene. The document may be an older check's (while the newest text does not parse),
/// whose places are then near, not exact.
fn scope_at(doc: &Document, offset: usize) -> Scope {
    let body_extent = |index: usize| {
        let nodes = doc.protos[index].body.iter().map(|child| child.span);
        let routes = doc
            .routes
            .iter()
            .filter(|route| route.scope == Scope::Proto(index))
            .map(|route| route.span);
        nodes
            .chain(routes)
            .fold(None, |extent: Option<(usize, usize)>, span| {
                let (start, end) = (span.start as usize, span.end as usize);
                Some(extent.map_or((start, end), |(s, e)| (s.min(start), e.max(end))))
            })
    };
    (0..doc.protos.len())
        .filter_map(|index| Some((index, body_extent(index)?)))
        .filter(|(_, (start, end))| *start < offset && offset < *end)
        .min_by_key(|(_, (start, end))| end - start)
        .map_or(Scope::Scene, |(index, _)| Scope::Proto(index))
}

/// Whether node field `field` accepts a node of type `node`.
fn accepts(field: &FieldDef, node: &NodeDef) -> bool {
    field.acceptable.iter().any(|a| node.is_a(a))
}

fn is_node_field(field: &FieldDef) -> bool {
    matches!(field.ty, FieldType::SFNode | FieldType::MFNode)
}

/// The node types that may go into `field` of a `parent` (XML: into the field each type's
/// default containerField names); at the top of a scene, the child node types.
fn node_names(
    schema: &VersionSchema,
    syntax: Syntax,
    parent: Option<&str>,
    field: Option<&str>,
) -> Vec<Candidate> {
    let parent_def = parent.and_then(|p| schema.node(p));
    let fits = |node: &NodeDef| match (parent_def, field) {
        (Some(parent), Some(field)) => parent
            .field(field)
            .is_some_and(|f| is_node_field(f) && accepts(f, node)),
        (Some(parent), None) => parent
            .field(node.container_field)
            .is_some_and(|f| is_node_field(f) && accepts(f, node)),
        (None, _) => node.is_a("X3DChildNode"),
    };
    let mut out: Vec<Candidate> = schema
        .nodes
        .iter()
        .filter(|n| fits(n))
        .map(|n| Candidate {
            insert: None,
            label: n.name.to_string(),
            kind: CompletionItemKind::CLASS,
            detail: Some(format!("{} {}", n.component.component, n.component.level)),
            doc: Some(node_type_markdown(n, schema.version)),
        })
        .collect();
    let statements: &[&str] = match (syntax, parent) {
        (Syntax::Xml, Some("X3D")) => &["head", "Scene"],
        (Syntax::Xml, Some("head")) => &["component", "unit", "meta"],
        (Syntax::Xml, Some("Scene" | "ProtoBody") | None) => &[
            "ROUTE",
            "ProtoDeclare",
            "ExternProtoDeclare",
            "ProtoInstance",
            "IMPORT",
            "EXPORT",
        ],
        _ => &[],
    };
    if matches!(parent, Some("X3D" | "head")) {
        out.clear();
    }
    out.extend(statements.iter().map(|s| Candidate {
        insert: None,
        label: s.to_string(),
        kind: CompletionItemKind::KEYWORD,
        detail: None,
        doc: None,
    }));
    out
}

/// The fields a node may set where it is written (initializable ones), not set yet; in
/// XML the node fields are child elements, not attributes.
fn field_names(def: &NodeDef, syntax: Syntax, written: &[String]) -> Vec<Candidate> {
    let mut out: Vec<Candidate> = def
        .fields
        .iter()
        .filter(|f| f.access.is_initializable())
        .filter(|f| !(syntax == Syntax::Xml && is_node_field(f)))
        .map(|f| {
            let label = match syntax {
                Syntax::Json if is_node_field(f) => format!("-{}", f.name),
                Syntax::Json => format!("@{}", f.name),
                _ => f.name.to_string(),
            };
            Candidate {
                insert: None,
                label,
                kind: CompletionItemKind::FIELD,
                detail: Some(format!("{} ({})", f.ty.as_str(), f.access.as_str())),
                doc: Some(field_hover(f, def.name)),
            }
        })
        .collect();
    let extra: &[&str] = match syntax {
        Syntax::Xml => &["DEF", "USE", "containerField", "class"],
        Syntax::Json => &["@DEF", "@USE", "@containerField", "@class"],
        Syntax::Classic => &[],
    };
    out.extend(extra.iter().map(|name| Candidate {
        insert: None,
        label: name.to_string(),
        kind: CompletionItemKind::KEYWORD,
        detail: None,
        doc: None,
    }));
    out.retain(|c| !written.contains(&c.label));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(text: &str) -> Vec<String> {
        let offset = text.find('|').unwrap();
        let text = text.replace('|', "");
        complete(text.as_bytes(), offset, None)
            .into_iter()
            .map(|c| c.label)
            .collect()
    }

    #[test]
    fn node_names_follow_the_enclosing_field() {
        let in_shape = labels("<X3D><Scene><Shape><|");
        assert!(in_shape.contains(&"Box".to_string()), "{in_shape:?}");
        assert!(in_shape.contains(&"Appearance".to_string()));
        assert!(!in_shape.contains(&"Transform".to_string()));
        let in_scene = labels("<X3D><Scene><|");
        assert!(in_scene.contains(&"Transform".to_string()));
        assert!(in_scene.contains(&"ROUTE".to_string()));
        assert!(!in_scene.contains(&"Box".to_string()));
    }

    #[test]
    fn element_content_offers_child_elements_with_their_angle_bracket() {
        let text = "<X3D><Scene><Shape>\n  Ap";
        let items = complete(text.as_bytes(), text.len(), None);
        let appearance = items.iter().find(|c| c.label == "Appearance").unwrap();
        assert_eq!(appearance.insert.as_deref(), Some("<Appearance"));
        assert!(!items.iter().any(|c| c.label == "Transform"));
        let hover = appearance.doc.as_deref().unwrap_or_default();
        assert!(
            hover.contains("| material | SFNode | inputOutput |"),
            "the fields, with their types: {hover}"
        );
        let in_head = labels("<X3D version='4.0'><head>\n|");
        assert_eq!(in_head, ["component", "unit", "meta"]);
    }

    #[test]
    fn attributes_and_enumerations() {
        let attrs = labels("<X3D><Scene><Material diffuseColor='1 0 0' |");
        assert!(attrs.contains(&"shininess".to_string()));
        assert!(attrs.contains(&"DEF".to_string()));
        assert!(
            !attrs.contains(&"diffuseColor".to_string()),
            "written already"
        );
        assert!(!attrs.contains(&"metadata".to_string()), "a node field");
        let json = labels(r#"{"X3D": {"Scene": {"-children": [{"Shape": {"|"#);
        assert!(json.contains(&"-geometry".to_string()), "{json:?}");
        assert!(json.contains(&"@bboxSize".to_string()));
        let fog = labels("<X3D><Scene><Fog fogType='|");
        assert_eq!(fog, ["LINEAR", "EXPONENTIAL"].map(String::from).to_vec());
        let offset = "<X3D><Scene><Fog fogType='".len();
        let linear = complete(b"<X3D><Scene><Fog fogType='", offset, None)
            .into_iter()
            .next()
            .and_then(|c| c.doc)
            .unwrap_or_default();
        assert!(linear.contains("linear blending"), "{linear}");
    }
}
