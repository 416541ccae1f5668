//! POINTING_SENSOR_NO_GEOMETRY: a pointing-device sensor with no geometry to pick.

use std::collections::{HashMap, HashSet};

use crate::diagnostic::Diagnostic;
use crate::model::{Document, Node, NodeId, NodeKind, Place};
use crate::schema::FieldType;
use crate::validate::events::wiring::Wiring;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a pointing-device sensor (TouchSensor, PlaneSensor, CylinderSensor,
    /// SphereSensor, GeoTouchSensor) none of whose parent groups holds any geometry
    /// among its descendants: no Shape anywhere below the group (the sensor's siblings
    /// and their children, through every node field). A sensor at the top of the scene
    /// has the scene for its parent group. Nothing is reported where geometry may be
    /// there after all: an Inline, a prototype instance that is not built, a node of an
    /// unknown type, a node field passed in through `IS`, a group that a ROUTE adds
    /// children to or that a Script may change, a sensor at the top of a prototype body
    /// (its parent is wherever the instance goes), and the top of a scene with Scripts
    /// (which may add root nodes).
    ///
    /// ## Why it matters
    /// 20.2.1: "A pointing device sensor is activated when the user locates the pointing
    /// device over geometry that is influenced by that specific pointing device sensor.
    /// Pointing device sensors have influence over all geometry that is descended from
    /// the sensor's parent groups." With no geometry below its parent the sensor can
    /// never be activated, so its ROUTEs never fire. It usually sits one group too deep
    /// (a Transform of its own instead of beside the Shape it should make clickable).
    ///
    /// ## Example
    /// ```xml
    /// <Transform>
    ///   <Transform><TouchSensor DEF='Button'/></Transform>
    ///   <Shape><Box/></Shape>
    /// </Transform>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Transform>
    ///   <TouchSensor DEF='Button'/>
    ///   <Shape><Box/></Shape>
    /// </Transform>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 20.2.1 Overview of pointing device sensors. Reading: the sensor cannot be
    /// activated, which the clause implies rather than forbids; information.
    pub static POINTING_SENSOR_NO_GEOMETRY = {
        severity: Info,
        level: Standard,
        clause: "20.2.1",
        versions: "all",
        check: Some(check),
    }
}

/// A group a sensor is a child of: the scene itself, or a node.
#[derive(Copy, Clone, PartialEq, Eq, Hash)]
enum Parent {
    Scene,
    Node(NodeId),
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let written = doc.written_nodes().len();
    let sensors: Vec<NodeId> = doc
        .iter()
        .take(written)
        .filter(|(_, node)| is_pointing_sensor(node))
        .map(|(id, _)| id)
        .collect();
    if sensors.is_empty() {
        return;
    }
    let parents = parents(doc);
    let wiring = Wiring::new(ctx);
    let scripted = doc.written_nodes().iter().any(|n| n.is_a("Script"));
    let mut search = Search {
        doc,
        wiring: &wiring,
        verdicts: HashMap::new(),
    };
    let mut found = Vec::new();
    for id in sensors {
        let Some(of_sensor) = parents.get(&id) else {
            continue;
        };
        let blind = of_sensor.iter().all(|parent| match parent {
            Parent::Scene => !scripted && !doc.scene.iter().any(|c| search.may_hold(c.node)),
            Parent::Node(group) => !search.is_opaque_parent(*group) && !search.may_hold(*group),
        });
        if blind {
            found.push((id, of_sensor[0]));
        }
    }
    for (id, parent) in found {
        let node = doc.node(id);
        let place = match parent {
            Parent::Scene => "the scene holds".to_string(),
            Parent::Node(group) => format!("its parent {} holds", doc.node(group).type_name()),
        };
        ctx.report(
            Diagnostic::new(
                &POINTING_SENSOR_NO_GEOMETRY,
                node.name_span,
                format!(
                    "{} senses nothing: {place} no geometry for the pointer to touch",
                    node.type_name()
                ),
            )
            .node(id)
            .help("put the sensor in the same group as the Shape it should make interactive"),
        );
    }
}

fn is_pointing_sensor(node: &Node) -> bool {
    node.is_a("X3DPointingDeviceSensorNode")
        || matches!(
            node.type_name(),
            "TouchSensor" | "PlaneSensor" | "CylinderSensor" | "SphereSensor" | "GeoTouchSensor"
        )
}

/// Every group each written node is a child of (by DEF or USE). A node at the top of a
/// prototype body has no entry: its parent is not in the body.
fn parents(doc: &Document) -> HashMap<NodeId, Vec<Parent>> {
    let mut parents: HashMap<NodeId, Vec<Parent>> = HashMap::new();
    for child in &doc.scene {
        parents.entry(child.node).or_default().push(Parent::Scene);
    }
    for (id, node) in doc.iter().take(doc.written_nodes().len()) {
        for entry in &node.fields {
            for child in entry.value.as_nodes().unwrap_or(&[]) {
                parents
                    .entry(child.node)
                    .or_default()
                    .push(Parent::Node(id));
            }
        }
    }
    parents.retain(|id, _| !matches!(doc.node(*id).place, Place::ProtoBody { .. }));
    parents
}

/// Whether each subtree may hold geometry, remembered so that shared (USE) subtrees
/// are walked once.
struct Search<'a> {
    doc: &'a Document,
    wiring: &'a Wiring,
    verdicts: HashMap<NodeId, bool>,
}

impl Search<'_> {
    /// A parent whose children are not all written here: a Script or prototype instance
    /// holding the sensor in a field (the sensor goes wherever they put it).
    fn is_opaque_parent(&self, group: NodeId) -> bool {
        let node = self.doc.node(group);
        node.is_a("Script") || !matches!(node.kind, NodeKind::Known { .. })
    }

    /// Whether `id` or a node below it is, or may become, geometry.
    fn may_hold(&mut self, id: NodeId) -> bool {
        let mut on_path = HashSet::new();
        self.walk(id, &mut on_path)
    }

    fn walk(&mut self, id: NodeId, on_path: &mut HashSet<NodeId>) -> bool {
        if let Some(&verdict) = self.verdicts.get(&id) {
            return verdict;
        }
        if !on_path.insert(id) {
            return false;
        }
        let verdict = self.holds_itself(id) || self.children_hold(id, on_path);
        on_path.remove(&id);
        self.verdicts.insert(id, verdict);
        verdict
    }

    /// Geometry, or a node whose content is not known here or may change.
    fn holds_itself(&self, id: NodeId) -> bool {
        let node = self.doc.node(id);
        let Some(def) = node.def() else {
            // A prototype instance is looked into through what it builds.
            return self.doc.instantiation_of(id).is_none();
        };
        node.is_a("X3DShapeNode")
            || node.is_a("X3DGeometryNode")
            || matches!(node.type_name(), "Inline" | "GeoLOD")
            || node.connects.iter().any(|c| {
                def.field(&c.node_field.text)
                    .is_some_and(|f| matches!(f.ty, FieldType::SFNode | FieldType::MFNode))
            })
            || ["children", "addChildren"]
                .iter()
                .any(|field| self.wiring.is_routed_into_field(id, field))
            || node.is_a("X3DGroupingNode") && self.wiring.is_reachable_by_code(self.doc, id)
    }

    fn children_hold(&mut self, id: NodeId, on_path: &mut HashSet<NodeId>) -> bool {
        let doc = self.doc;
        let node = doc.node(id);
        let built = doc.instantiation_of(id).map(|i| i.roots.as_slice());
        let children = node
            .fields
            .iter()
            .filter_map(|entry| entry.value.as_nodes())
            .chain(built)
            .flatten();
        for child in children {
            if self.walk(child.node, on_path) {
                return true;
            }
        }
        false
    }
}
