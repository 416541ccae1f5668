//! How a node's events can reach other nodes, or other nodes' events reach it, after the
//! scene loads: the ROUTEs that name it, a prototype's `IS` on its fields, a Script or
//! prototype instance that holds it in a field (a Script with `directOutput` may send it
//! events and add routes), an EXPORT (an importing scene may route to it), and Script code
//! that may look it up by its DEF name. The rules that say a node's events go nowhere, or
//! that it never receives one, ask here, and stay silent wherever one of these may
//! connect it. The rules of every component that judge a field's written value ask
//! [`set_elsewhere`] whether a ROUTE or `IS` replaces it.

use std::collections::{HashMap, HashSet};

use super::endpoint::route_node;
use crate::model::{Document, Encoding, FieldEntry, NodeId, NodeKind, RouteEnd, Scope, Value};
use crate::parse::behind::{Pass, Progress};
use crate::validate::Ctx;

pub(crate) struct Wiring {
    /// Per node: the fields ROUTEs read from it.
    routed_from: HashMap<NodeId, Vec<String>>,
    /// Per node: the fields ROUTEs write to it, without `set_` (`set_bind` → `bind`).
    routed_into: HashMap<NodeId, Vec<String>>,
    /// Nodes a Script field or a ProtoInstance fieldValue holds.
    held: HashSet<NodeId>,
    /// Nodes an EXPORT of this file names.
    exported: HashSet<NodeId>,
    /// What Script code may name a node by its DEF name.
    scripts: ScriptText,
}

/// The Script code of the document, for DEF names it may look nodes up by.
enum ScriptText {
    /// Every Script's running code was read (or there are no Scripts).
    Known(Vec<String>),
    /// Some Script runs code that was not read (a `.js` file below the deep level, a
    /// network URL, another language): it may name any node.
    Unknown,
}

impl Wiring {
    pub(crate) fn new(ctx: &Ctx) -> Wiring {
        let doc = ctx.doc;
        let mut routed_from: HashMap<NodeId, Vec<String>> = HashMap::new();
        let mut routed_into: HashMap<NodeId, Vec<String>> = HashMap::new();
        for route in &doc.routes {
            if let Some(node) = route.node_id(doc, RouteEnd::From) {
                let field = route.from_field.text.as_str();
                let field = field.strip_suffix("_changed").unwrap_or(field);
                routed_from.entry(node).or_default().push(field.to_string());
            }
            if let Some(node) = route.node_id(doc, RouteEnd::To) {
                let field = route.to_field.text.as_str();
                let field = field.strip_prefix("set_").unwrap_or(field);
                routed_into.entry(node).or_default().push(field.to_string());
            }
        }
        let mut exported: HashSet<NodeId> = doc
            .exports
            .iter()
            .filter_map(|export| route_node(doc, export.scope, &export.local_def.text))
            .collect();
        if doc.encoding == Encoding::Vrml97 {
            exported.extend(vrml97_exports(doc, ctx.source, ctx.progress));
        }
        Wiring {
            routed_from,
            routed_into,
            held: held_nodes(doc),
            exported,
            scripts: script_text(ctx),
        }
    }

    /// Whether a ROUTE reads any field of `id`.
    pub(crate) fn is_routed_from(&self, id: NodeId) -> bool {
        self.routed_from.contains_key(&id)
    }

    /// Whether a ROUTE writes any field of `id`.
    pub(crate) fn is_routed_into(&self, id: NodeId) -> bool {
        self.routed_into.contains_key(&id)
    }

    /// Whether a ROUTE writes field `field` of `id` (named `field` or `set_field`).
    pub(crate) fn is_routed_into_field(&self, id: NodeId, field: &str) -> bool {
        self.routed_into
            .get(&id)
            .is_some_and(|fields| fields.iter().any(|f| f == field))
    }

    /// The entries of `candidates` whose node's `field` keeps the file's value: no ROUTE
    /// sends to it and no Script code can reach the node.
    pub(crate) fn keep_unset<T>(
        &self,
        doc: &Document,
        candidates: Vec<(NodeId, T)>,
        field: &str,
    ) -> Vec<(NodeId, T)> {
        candidates
            .into_iter()
            .filter(|(id, _)| {
                !self.is_routed_into_field(*id, field) && !self.is_reachable_by_code(doc, *id)
            })
            .collect()
    }

    /// Whether something other than a ROUTE may send `id` events or read its events: a
    /// Script or prototype instance holding it, an EXPORT, or Script code that may name
    /// its DEF name (with `Browser.currentScene.getNamedNode`, `addRoute`).
    pub(crate) fn is_reachable_by_code(&self, doc: &Document, id: NodeId) -> bool {
        if self.held.contains(&id) || self.exported.contains(&id) {
            return true;
        }
        let Some(name) = &doc.node(id).def_name else {
            return false;
        };
        match &self.scripts {
            ScriptText::Unknown => true,
            ScriptText::Known(codes) => codes.iter().any(|code| code.contains(&name.text)),
        }
    }
}

/// The nodes that Script fields and ProtoInstance fieldValues hold (by DEF or USE).
fn held_nodes(doc: &Document) -> HashSet<NodeId> {
    let mut held = HashSet::new();
    for (_, node) in doc.iter() {
        let holder = node.is_a("Script") || matches!(node.kind, NodeKind::ProtoInstance { .. });
        if !holder {
            continue;
        }
        let declared = node.declared.iter().filter_map(|d| d.value.as_ref());
        let values = declared
            .map(|(value, _)| value)
            .chain(node.fields.iter().map(|entry| &entry.value));
        for value in values {
            if let Value::Nodes(children) = value {
                held.extend(children.iter().map(|child| child.node));
            }
        }
    }
    held
}

/// The nodes a VRML97 file names in EXPORT statements. VRML97 has none (the reader reports
/// them as VRML_MALFORMED and drops them), but browsers that read X3D's statements in
/// VRML97 files too (Castle Game Engine) export the node, so it may be routed from outside.
fn vrml97_exports(doc: &Document, source: &[u8], progress: &dyn Progress) -> Vec<NodeId> {
    let mut pass = Pass::new(source, progress);
    let mut line_start = 0;
    let mut exported = Vec::new();
    for line in source.split(|byte| *byte == b'\n') {
        // The lines before this one have been read.
        pass.reached(line_start);
        line_start += line.len() + 1;
        let Ok(line) = std::str::from_utf8(line) else {
            continue;
        };
        let mut words = line.split_whitespace();
        if words.next() == Some("EXPORT") {
            exported.extend(
                words
                    .next()
                    .and_then(|name| route_node(doc, Scope::Scene, name)),
            );
        }
    }
    exported
}

fn script_text(ctx: &Ctx) -> ScriptText {
    if !ctx.doc.written_nodes().iter().any(|n| n.is_a("Script")) {
        return ScriptText::Known(Vec::new());
    }
    let scripts = &ctx.scripts().scripts;
    if scripts.iter().any(|script| script.unchecked.is_some()) {
        return ScriptText::Unknown;
    }
    let codes = scripts
        .iter()
        .flat_map(|script| script.parsed.iter().map(|code| code.code().to_string()))
        .collect();
    ScriptText::Known(codes)
}

/// The fields of nodes that a ROUTE sends events to, by field name without `set_` or
/// `_changed`: their values in the file are only the initial ones, which the scene replaces.
pub(crate) fn routed_fields(doc: &Document) -> HashSet<(NodeId, String)> {
    doc.routes
        .iter()
        .filter_map(|route| {
            let node = route.node_id(doc, RouteEnd::To)?;
            let field = route.to_field.text.as_str();
            let field = field.strip_prefix("set_").unwrap_or(field);
            let field = field.strip_suffix("_changed").unwrap_or(field);
            Some((node, field.to_string()))
        })
        .collect()
}

/// Whether the scene may change `field` of `id` after loading (a ROUTE to it) or takes it
/// from a prototype instance (`IS`): the written value is then not what the node uses.
pub(crate) fn set_elsewhere(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    id: NodeId,
    field: &str,
) -> bool {
    doc.node(id).is_connected(field) || routed.contains(&(id, field.to_string()))
}

/// Each `type_name` node with a written `field` whose value is the one the node uses (not
/// set by a ROUTE or IS), with that entry.
pub(crate) fn written_entries<'d>(
    doc: &'d Document,
    routed: &'d HashSet<(NodeId, String)>,
    type_name: &'d str,
    field: &'d str,
) -> impl Iterator<Item = (NodeId, &'d FieldEntry)> + 'd {
    doc.nodes_of_type(type_name)
        .filter(move |&id| !set_elsewhere(doc, routed, id, field))
        .filter_map(move |id| Some((id, doc.node(id).entry(field)?)))
}

/// Whether any of `fields` of node `id` is set other than by its written value.
pub(crate) fn any_set_elsewhere(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    id: NodeId,
    fields: &[&str],
) -> bool {
    fields
        .iter()
        .any(|field| set_elsewhere(doc, routed, id, field))
}
