//! What a document holds, for the report's `stats`. Both encodings build the same model, so
//! the same scene gives the same numbers in XML and JSON.
//!
//! - `nodes`: distinct nodes (a USE'd node counts once), ProtoBodies included;
//!   `nodeTypes`: the same, by type name as written (`ProtoInstance` for instances).
//! - `shapes`, `lights`, `textures`: nodes that are an `X3DShapeNode`, `X3DLightNode`,
//!   `X3DTextureNode` (MultiTexture and 3D textures included).
//! - `defs`: nodes with a DEF name; `uses`: USE references anywhere (node fields, the Scene,
//!   ProtoBodies, initial values of declared fields); `routes`: ROUTE statements.
//! - `triangles`, `lines`, `points`: the primitives each distinct geometry node's data
//!   defines, counted once however often it is USE'd: IndexedFaceSet n−2 per polygon of
//!   n ≥ 3 indices (runs ended by −1 or the end); IndexedTriangleSet index/3; TriangleSet
//!   coordinates/3; Indexed{TriangleStrip,TriangleFan}Set n−2 per index run of n ≥ 3;
//!   TriangleStripSet, TriangleFanSet n−2 per stripCount/fanCount of n ≥ 3; ElevationGrid
//!   (x−1)(z−1)·2; IndexedLineSet n−1 per index run of n ≥ 2; LineSet n−1 per vertexCount
//!   of n ≥ 2; PointSet its coordinates. Other geometry (Box, Sphere, Extrusion, NURBS, …)
//!   counts 0: how finely it is tessellated is the browser's choice.
//!
//! At the fast level a numeric MF value may be a [`Summary`], which holds these lengths
//! and run sums, so the numbers are the same.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::model::{ChildRef, Document, Node, Summary, Value};
use crate::schema::Scalar;

#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct Stats {
    pub nodes: usize,
    pub node_types: BTreeMap<String, usize>,
    pub shapes: usize,
    pub triangles: u64,
    pub lines: u64,
    pub points: u64,
    pub lights: usize,
    pub textures: usize,
    pub defs: usize,
    pub uses: usize,
    pub routes: usize,
}

impl Stats {
    pub fn of(doc: &Document) -> Stats {
        let mut stats = Stats {
            nodes: doc.written_nodes().len(),
            routes: doc.routes.len(),
            uses: uses(&doc.scene),
            ..Stats::default()
        };
        for proto in &doc.protos {
            stats.uses += uses(&proto.body);
            stats.uses += proto
                .interface
                .iter()
                .map(|f| declared_uses(&f.value))
                .sum::<usize>();
        }
        // The nodes as written: the copies prototype instances build are not counted.
        for node in doc.written_nodes() {
            *stats
                .node_types
                .entry(node.type_name().to_string())
                .or_default() += 1;
            stats.shapes += usize::from(node.is_a("X3DShapeNode"));
            stats.lights += usize::from(node.is_a("X3DLightNode"));
            stats.textures += usize::from(node.is_a("X3DTextureNode"));
            stats.defs += usize::from(node.def_name.is_some());
            stats.uses += node
                .fields
                .iter()
                .filter_map(|f| f.value.as_nodes())
                .map(uses)
                .sum::<usize>();
            stats.uses += node
                .declared
                .iter()
                .map(|f| declared_uses(&f.value))
                .sum::<usize>();
            let primitives = primitives(doc, node);
            stats.triangles = stats.triangles.saturating_add(primitives.triangles);
            stats.lines = stats.lines.saturating_add(primitives.lines);
            stats.points = stats.points.saturating_add(primitives.points);
        }
        stats
    }
}

fn uses(refs: &[ChildRef]) -> usize {
    refs.iter().filter(|r| r.is_use).count()
}

fn declared_uses(value: &Option<(Value, crate::model::Span)>) -> usize {
    value
        .as_ref()
        .and_then(|(v, _)| v.as_nodes())
        .map_or(0, uses)
}

#[derive(Default)]
struct Primitives {
    triangles: u64,
    lines: u64,
    points: u64,
}

fn primitives(doc: &Document, node: &Node) -> Primitives {
    let ints = |name| Ints::of(node.value(name));
    let triangles = |triangles| Primitives {
        triangles,
        ..Primitives::default()
    };
    let Some(def) = node.def() else {
        return Primitives::default();
    };
    match def.name {
        "IndexedFaceSet" | "IndexedTriangleStripSet" | "IndexedTriangleFanSet" => {
            let field = if def.name == "IndexedFaceSet" {
                "coordIndex"
            } else {
                "index"
            };
            triangles(ints(field).index_runs(2))
        }
        "IndexedTriangleSet" => triangles(ints("index").len() / 3),
        "TriangleSet" => triangles(coordinates(doc, node) / 3),
        "TriangleStripSet" | "TriangleFanSet" => {
            let field = if def.name == "TriangleStripSet" {
                "stripCount"
            } else {
                "fanCount"
            };
            triangles(ints(field).counts(2))
        }
        "ElevationGrid" => {
            let dimension = |name| {
                let ints = node.value(name).and_then(Value::as_int32s).unwrap_or(&[]);
                ints.first().map_or(0, |&d| u64::from(d.max(0) as u32))
            };
            let (x, z) = (dimension("xDimension"), dimension("zDimension"));
            triangles(
                x.saturating_sub(1)
                    .saturating_mul(z.saturating_sub(1))
                    .saturating_mul(2),
            )
        }
        "IndexedLineSet" => Primitives {
            lines: ints("coordIndex").index_runs(1),
            ..Primitives::default()
        },
        "LineSet" => Primitives {
            lines: ints("vertexCount").counts(1),
            ..Primitives::default()
        },
        "PointSet" => Primitives {
            points: coordinates(doc, node),
            ..Primitives::default()
        },
        _ => Primitives::default(),
    }
}

/// An MFInt32 value, whole or summarized (none when unset or not MFInt32).
enum Ints<'a> {
    Whole(&'a [i32]),
    Summary(&'a Summary),
}

impl<'a> Ints<'a> {
    fn of(value: Option<&'a Value>) -> Ints<'a> {
        match value {
            Some(Value::Summary(s)) if s.scalar == Scalar::Int32 => Ints::Summary(s),
            other => Ints::Whole(other.and_then(Value::as_int32s).unwrap_or(&[])),
        }
    }

    fn len(&self) -> u64 {
        match self {
            Ints::Whole(v) => v.len() as u64,
            Ints::Summary(s) => s.len as u64,
        }
    }

    /// Σ max(n − k, 0) over the runs of n indices ended by −1 (a last run without −1
    /// counts too); k is 1 or 2.
    fn index_runs(&self, k: u64) -> u64 {
        match self {
            Ints::Whole(v) => v
                .split(|&i| i == -1)
                .map(|run| (run.len() as u64).saturating_sub(k))
                .sum(),
            Ints::Summary(s) => s.index_runs[k as usize - 1],
        }
    }

    /// Σ max(n − k, 0) over the non-negative vertex counts n (negative ones define
    /// nothing); k is 1 or 2.
    fn counts(&self, k: u64) -> u64 {
        match self {
            Ints::Whole(v) => v
                .iter()
                .map(|&n| u64::from(n.max(0) as u32).saturating_sub(k))
                .sum(),
            Ints::Summary(s) => s.counts[k as usize - 1],
        }
    }
}

/// Points in the Coordinate or CoordinateDouble node of the `coord` field.
fn coordinates(doc: &Document, node: &Node) -> u64 {
    let Some(coord) = node.child("coord").and_then(|id| doc.nodes.get(id.index())) else {
        return 0;
    };
    match coord.value("point") {
        Some(v @ (Value::Floats(_) | Value::Doubles(_))) => v.len() as u64 / 3,
        Some(Value::Summary(s)) if matches!(s.scalar, Scalar::Float | Scalar::Double) => {
            s.len as u64 / 3
        }
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::builder::testing::{named, parent_of};
    use crate::model::builder::Parent;
    use crate::model::{Builder, Encoding, FieldEntry, NodeId, Origin, Span};

    struct Scene(Builder);

    impl Scene {
        fn node(
            &mut self,
            ty: &str,
            parent: Option<(NodeId, &str)>,
            fields: Vec<(&str, Value)>,
        ) -> NodeId {
            let kind = self.0.node_kind(ty);
            let id = self
                .0
                .begin_node(kind, Span::default(), parent_of(parent))
                .expect("shallow test scene");
            for (name, value) in fields {
                let field = self.0.field_ref(id, name);
                let entry = FieldEntry {
                    field,
                    name_span: Span::default(),
                    span: Span::default(),
                    origin: Origin::Attribute,
                    value,
                };
                self.0.add_field(id, entry);
            }
            self.0.end_node(id, Span::default());
            id
        }

        fn with_coord(&mut self, ty: &str, coord: &str, point: Value) -> NodeId {
            let kind = self.0.node_kind(ty);
            let id = self
                .0
                .begin_node(kind, Span::default(), Parent::TopLevel)
                .expect("shallow test scene");
            self.node(coord, Some((id, "coord")), vec![("point", point)]);
            self.0.end_node(id, Span::default());
            id
        }
    }

    #[test]
    fn primitives_per_geometry() {
        let mut s = Scene(Builder::new(Encoding::Xml));
        let ints = |v: &[i32]| Value::Int32s(v.to_vec());
        s.node(
            "IndexedFaceSet",
            None,
            vec![(
                "coordIndex",
                ints(&[0, 1, 2, 3, -1, 0, 1, 2, -1, 5, 6, -1, 1, 2, 3, 4, 5]),
            )],
        );
        s.node(
            "IndexedTriangleSet",
            None,
            vec![("index", ints(&[0, 1, 2, 3, 4, 5, 6]))],
        );
        s.with_coord("TriangleSet", "Coordinate", Value::Floats(vec![0.0; 27]));
        s.node(
            "IndexedTriangleStripSet",
            None,
            vec![("index", ints(&[0, 1, 2, 3, -1, 4, 5]))],
        );
        s.node(
            "TriangleFanSet",
            None,
            vec![("fanCount", ints(&[3, 5, -1, 2]))],
        );
        s.node(
            "ElevationGrid",
            None,
            vec![("xDimension", ints(&[3])), ("zDimension", ints(&[4]))],
        );
        s.node(
            "ElevationGrid",
            None,
            vec![("xDimension", ints(&[-5])), ("zDimension", ints(&[4]))],
        );
        s.node(
            "IndexedLineSet",
            None,
            vec![("coordIndex", ints(&[0, 1, 2, -1, 3, 4, -1, 5]))],
        );
        s.node("LineSet", None, vec![("vertexCount", ints(&[2, 3, -4]))]);
        s.with_coord(
            "PointSet",
            "CoordinateDouble",
            Value::Doubles(vec![0.0; 12]),
        );
        s.node("Box", None, vec![]);
        let stats = Stats::of(s.0.doc());
        assert_eq!(stats.triangles, 6 + 2 + 3 + 2 + 4 + 12);
        assert_eq!(stats.lines, 3 + 3);
        assert_eq!(stats.points, 4);
    }

    #[test]
    fn shared_nodes_count_once() {
        let mut s = Scene(Builder::new(Encoding::Xml));
        let kind = s.0.node_kind("Shape");
        let shape =
            s.0.begin_node(kind, Span::default(), Parent::TopLevel)
                .expect("shallow test scene");
        s.0.define(shape, named("S"));
        s.node(
            "IndexedTriangleSet",
            Some((shape, "geometry")),
            vec![("index", Value::Int32s(vec![0, 1, 2]))],
        );
        s.0.end_node(shape, Span::default());
        s.0.use_node(
            &named("S"),
            Some("Shape"),
            Span::default(),
            Parent::TopLevel,
        );
        s.node("DirectionalLight", None, vec![]);
        s.node("ImageTexture", None, vec![]);
        let stats = Stats::of(s.0.doc());
        assert_eq!((stats.nodes, stats.shapes, stats.triangles), (4, 1, 1));
        assert_eq!(
            (stats.defs, stats.uses, stats.lights, stats.textures),
            (1, 1, 1, 1)
        );
        assert_eq!(stats.node_types.get("Shape"), Some(&1));
    }
}
