//! What stands at an offset of a checked document (a node's name, a field's name, a USE,
//! a ROUTE's node name), go to definition, and the document's symbols (the DEF tree).

use lsp_types::{DocumentSymbol, SymbolKind};

use super::position::Lines;
use super::Analysis;
use crate::diagnostic::{NodeId, Span};
use crate::model::{ChildRef, Document, FieldEntry, Node, Value};

/// What an offset points at.
pub enum Target<'a> {
    /// The name of a node's type.
    NodeName(&'a Node),
    /// The name of a field a node sets.
    Field(&'a Node, &'a FieldEntry),
    /// A reference to a DEF'd node: a USE (its span) or a ROUTE's node name.
    Reference { span: Span, node: NodeId },
}

fn contains(span: Span, offset: usize) -> bool {
    (span.start as usize) <= offset && offset <= span.end as usize && span.end > span.start
}

/// What stands at `offset` in `doc`.
pub fn target(doc: &Document, offset: usize) -> Option<Target<'_>> {
    for route in &doc.routes {
        for named in [&route.from_node, &route.to_node] {
            if contains(named.span, offset) {
                let node = *doc.defs.get(&(route.scope, named.text.clone()))?;
                return Some(Target::Reference {
                    span: named.span,
                    node,
                });
            }
        }
    }
    let written = doc.written_nodes();
    // The innermost node whose span holds the offset: nodes are in the order their
    // elements start, so the last one that holds it.
    if let Some(node) = written.iter().rev().find(|n| contains(n.span, offset)) {
        if contains(node.name_span, offset) {
            return Some(Target::NodeName(node));
        }
        if let Some(entry) = node.fields.iter().find(|e| contains(e.name_span, offset)) {
            return Some(Target::Field(node, entry));
        }
    }
    // A USE is a reference among a node's children (or the scene's, a body's).
    let uses = |refs: &[ChildRef]| {
        refs.iter()
            .find(|r| r.is_use && contains(r.span, offset))
            .map(|r| Target::Reference {
                span: r.span,
                node: r.node,
            })
    };
    let children = written
        .iter()
        .flat_map(|n| &n.fields)
        .filter_map(|e| match &e.value {
            Value::Nodes(refs) => Some(refs.as_slice()),
            _ => None,
        });
    std::iter::once(doc.scene.as_slice())
        .chain(doc.protos.iter().map(|p| p.body.as_slice()))
        .chain(children)
        .find_map(uses)
}

/// Where the DEF that the reference at `offset` names is.
pub fn definition(analysis: &Analysis, offset: usize) -> Option<Span> {
    let doc = analysis.document.as_ref()?;
    match target(doc, offset)? {
        Target::Reference { node, .. } => {
            let node = doc.nodes.get(node.index())?;
            Some(node.def_name.as_ref().map_or(node.span, |d| d.span))
        }
        _ => None,
    }
}

/// The DEF tree: each node with a DEF name, the named nodes below it nested in it; the
/// prototype declarations with theirs.
pub fn symbols(analysis: &Analysis, lines: &Lines) -> Vec<DocumentSymbol> {
    let Some(doc) = analysis.document.as_ref() else {
        return Vec::new();
    };
    let mut out = named_below(doc, &doc.scene, lines, 0);
    for proto in &doc.protos {
        out.push(symbol(
            proto.name.text.clone(),
            Some(if proto.external {
                "ExternProtoDeclare".into()
            } else {
                "ProtoDeclare".into()
            }),
            SymbolKind::CLASS,
            lines.range(proto.span),
            lines.range(proto.name.span),
            named_below(doc, &proto.body, lines, 0),
        ));
    }
    out
}

/// Deep enough for any scene people write; deeper trees (generated ones) are cut, so that
/// the symbol list stays small and the recursion bounded.
const MAX_DEPTH: usize = 64;

/// The symbols of the named nodes among `refs` and below them (USEs are not followed).
fn named_below(
    doc: &Document,
    refs: &[ChildRef],
    lines: &Lines,
    depth: usize,
) -> Vec<DocumentSymbol> {
    if depth > MAX_DEPTH {
        return Vec::new();
    }
    let mut out = Vec::new();
    for child in refs.iter().filter(|r| !r.is_use) {
        let Some(node) = doc.nodes.get(child.node.index()) else {
            continue;
        };
        let below: Vec<DocumentSymbol> = node
            .fields
            .iter()
            .filter_map(|e| match &e.value {
                Value::Nodes(refs) => Some(refs),
                _ => None,
            })
            .flat_map(|refs| named_below(doc, refs, lines, depth + 1))
            .collect();
        match &node.def_name {
            Some(def) => {
                out.push(symbol(
                    def.text.clone(),
                    Some(node.type_name().to_string()),
                    SymbolKind::OBJECT,
                    lines.range(node.span),
                    lines.range(def.span),
                    below,
                ));
            }
            _ => out.extend(below),
        }
    }
    out
}

fn symbol(
    name: String,
    detail: Option<String>,
    kind: SymbolKind,
    range: lsp_types::Range,
    selection_range: lsp_types::Range,
    children: Vec<DocumentSymbol>,
) -> DocumentSymbol {
    #[allow(deprecated)] // `deprecated` is a field the type still requires
    DocumentSymbol {
        name,
        detail,
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range,
        children: Some(children),
    }
}
