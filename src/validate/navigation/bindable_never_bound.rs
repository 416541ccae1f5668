//! BINDABLE_NEVER_BOUND: a second NavigationInfo, Background or Fog that nothing binds.

use std::collections::{HashMap, HashSet};

use crate::diagnostic::Diagnostic;
use crate::model::{Document, NodeId, NodeKind};
use crate::validate::events::wiring::Wiring;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a NavigationInfo, Background, TextureBackground or Fog of the scene that
    /// comes after another of its binding stack in the same layer, when nothing can bind
    /// it: no ROUTE sends it `set_bind`, no Script field or prototype instance holds it,
    /// no EXPORT names it, and no Script code of the file names its DEF (where a Script
    /// runs code that was not read, nothing is reported). Background and
    /// TextureBackground share one stack (X3DBackgroundNode). The first of a stack is
    /// the first met in document order outside Switch, LOD and GeoLOD (which may not
    /// show their children); the nodes after it are checked. Each Layer has stacks of its
    /// own; nodes in prototype bodies, in prototype instances' fields and in Inlines are
    /// not counted. Viewpoints are left alone: users pick them from the browser's list,
    /// and so is a NavigationInfo that a viewpoint names in its `navigationInfo` field
    /// (X3D 4.0): "The navigationInfo field defines a dedicated NavigationInfo node for this
    /// X3DViewpointNode", which is bound whenever that viewpoint is (23.3.1, 23.4.4).
    ///
    /// ## Why it matters
    /// 7.2.2: bindable nodes "have the unique behaviour that only one of each type can be
    /// bound (i.e., affect the user's experience) at any instant in time. The browser
    /// shall maintain an independent, separate stack for each type of bindable node."
    /// When the scene loads, the first node of each stack is bound; another only takes
    /// effect when it receives `set_bind TRUE`. A later NavigationInfo, Background or
    /// Fog that receives none never affects what the user sees or how they move: its
    /// settings are silently lost (often a copy-pasted scene brought its own).
    ///
    /// ## Example
    /// ```xml
    /// <NavigationInfo type='"EXAMINE" "ANY"'/>
    /// <NavigationInfo DEF='Walking' type='"WALK"'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NavigationInfo type='"EXAMINE" "ANY"'/>
    /// <NavigationInfo DEF='Walking' type='"WALK"'/>
    /// <ROUTE fromNode='Door' fromField='enterTime' toNode='Walking' toField='set_bind'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.2.2 Bindable children nodes. Reading: a node no event can bind keeps
    /// off the stack's top for the life of the scene; information. ROUTE's toField
    /// `set_bind` (or `bind`) is what binds it.
    pub static BINDABLE_NEVER_BOUND = {
        severity: Info,
        level: Standard,
        clause: "7.2.2",
        versions: "all",
        check: Some(check),
    }
}

/// The binding stack a node is on: X3DBackgroundNode, Fog, NavigationInfo. The 3.x
/// object models do not derive Fog and NavigationInfo from an abstract type of their
/// own, so the types are named.
fn stack(node: &crate::model::Node) -> Option<&'static str> {
    match node.type_name() {
        "Background" | "TextureBackground" => Some("Background"),
        "Fog" => Some("Fog"),
        "NavigationInfo" => Some("NavigationInfo"),
        _ => None,
    }
}

/// A bindable node as the walk meets it: its layer, its stack, and whether it sits
/// under a Switch or LOD (a browser may not bind it first).
struct Met {
    node: NodeId,
    layer: Option<NodeId>,
    stack: &'static str,
    selective: bool,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut met = Vec::new();
    let mut seen = HashSet::new();
    for child in &doc.scene {
        walk(doc, child.node, None, false, &mut seen, &mut met);
    }
    let mut firsts: HashMap<(Option<NodeId>, &str), NodeId> = HashMap::new();
    let mut later = Vec::new();
    for m in &met {
        match firsts.get(&(m.layer, m.stack)) {
            Some(&first) => later.push((m.node, (first, m.layer.is_some()))),
            None if !m.selective => {
                firsts.insert((m.layer, m.stack), m.node);
            }
            None => {}
        }
    }
    // A viewpoint's `navigationInfo` binds its NavigationInfo whenever the viewpoint is
    // bound, and users bind viewpoints from the browser's list.
    let dedicated = dedicated_navigation_infos(doc);
    later.retain(|(id, _)| !dedicated.contains(id));
    if later.is_empty() {
        return;
    }
    let wiring = Wiring::new(ctx);
    let found = wiring.keep_unset(doc, later, "bind");
    for (id, (first, in_layer)) in found {
        let node = doc.node(id);
        let type_name = node.type_name();
        let first_node = doc.node(first);
        // Name the one bound: the first of its stack, which need not be the nearest before.
        let named = first_node
            .def_name
            .as_ref()
            .map_or(String::new(), |name| format!(" `{}`", name.text));
        let scope = if in_layer { "its layer" } else { "the scene" };
        ctx.report(
            Diagnostic::new(
                &BINDABLE_NEVER_BOUND,
                node.name_span,
                format!(
                    "{type_name} is never bound: the first {}{named} of {scope} is bound when the scene loads, and nothing sends this one `set_bind`",
                    first_node.type_name()
                ),
            )
            .node(id)
            .related(first_node.name_span, "bound when the scene loads")
            .help(
                "remove it, merge its settings into the first, or ROUTE a TRUE event to its `set_bind` to switch to it",
            ),
        );
    }
}

/// The NavigationInfo nodes that some X3DViewpointNode names in its `navigationInfo`
/// field (4.0, 23.3.1), USE included.
fn dedicated_navigation_infos(doc: &Document) -> HashSet<NodeId> {
    doc.iter()
        .filter(|(_, node)| node.is_a("X3DViewpointNode"))
        .filter_map(|(_, node)| node.child("navigationInfo"))
        .collect()
}

/// Visits `id` and the nodes below it in document order, once each, collecting the
/// bindable nodes with their layer. Prototype instances and Inlines are not entered.
fn walk(
    doc: &Document,
    id: NodeId,
    layer: Option<NodeId>,
    selective: bool,
    seen: &mut HashSet<NodeId>,
    met: &mut Vec<Met>,
) {
    if !seen.insert(id) {
        return;
    }
    let node = doc.node(id);
    if !matches!(node.kind, NodeKind::Known { .. }) {
        return;
    }
    if let Some(stack) = stack(node) {
        met.push(Met {
            node: id,
            layer,
            stack,
            selective,
        });
    }
    let layer = if node.is_a("X3DLayerNode") || matches!(node.type_name(), "Layer" | "LayoutLayer")
    {
        Some(id)
    } else {
        layer
    };
    let selective = selective || matches!(node.type_name(), "Switch" | "LOD" | "GeoLOD");
    for entry in &node.fields {
        for child in entry.value.as_nodes().unwrap_or(&[]) {
            walk(doc, child.node, layer, selective, seen, met);
        }
    }
}
