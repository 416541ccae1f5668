//! HANIM_SKIN_COORD_INDEX_OUT_OF_RANGE: a joint's skinCoordIndex names a vertex its
//! humanoid's skinCoord does not have.

use std::collections::HashSet;

use super::{humanoids, name_suffix};
use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, NodeKind, Span};
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::rendering::geometry::ScalarSpans;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a `skinCoordIndex` value of an HAnimJoint that is not smaller than the
    /// number of points of the `skinCoord` coordinate node of the HAnimHumanoid whose
    /// skeleton holds the joint. Joints outside any humanoid's skeleton, humanoids without
    /// a `skinCoord`, and fields a ROUTE or `IS` sets are left alone. Negative indices are
    /// FIELD_OUT_OF_RANGE.
    ///
    /// ## Why it matters
    /// The index names the skin vertex the joint moves. Past the end of the skin's points
    /// it names nothing: the joint's weight for it is lost, and some browsers stop
    /// skinning the humanoid altogether. It usually means the skin mesh was changed
    /// (decimated, split) after the weights were exported.
    ///
    /// ## Example
    /// ```xml
    /// <HAnimHumanoid name='Jo' version='2.0'>
    ///   <HAnimJoint containerField='skeleton' name='humanoid_root'
    ///               skinCoordIndex='0 1 2 3' skinCoordWeight='1 1 1 1'/>
    ///   <Coordinate containerField='skinCoord' point='0 0 0 0 1 0 1 1 0'/>
    /// </HAnimHumanoid>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <HAnimHumanoid name='Jo' version='2.0'>
    ///   <HAnimJoint containerField='skeleton' name='humanoid_root'
    ///               skinCoordIndex='0 1 2' skinCoordWeight='1 1 1'/>
    ///   <Coordinate containerField='skinCoord' point='0 0 0 0 1 0 1 1 0'/>
    /// </HAnimHumanoid>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 26.3.3 HAnimJoint, with the Joint object of ISO/IEC 19774 and 19774-1: each
    /// skinCoordWeight "has a corresponding index value in the skinCoordIndex field of the
    /// Joint object indicating exactly which coordinate is to be influenced", a vertex
    /// "from the skinCoord field of the Humanoid object". An index with no such vertex
    /// indicates none.
    /// A warning, not an error (issue 32): unlike the geometry indices ("If the greatest
    /// index in the colorIndex field is N, then there shall be N+1 colours", 13.3.6,
    /// INDEX_OUT_OF_RANGE's sentence), no sentence found puts a "shall" on the upper bound
    /// of skinCoordIndex: the interface table gives it `[0,∞)` (X3DUOM 4.0: "Coordinate
    /// index values referencing which vertices are influenced by the HAnimJoint"), and what
    /// a browser does with an index past the skin is left undefined.
    pub static HANIM_SKIN_COORD_INDEX_OUT_OF_RANGE = {
        severity: Warning,
        level: Standard,
        clause: "26.3.3",
        versions: "all",
        check: Some(check),
    }
}

/// A humanoid's skin points: how many, and where the coordinate node is.
struct Skin {
    points: usize,
    span: Span,
    type_name: String,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut done: HashSet<NodeId> = HashSet::new();
    for humanoid in humanoids(doc) {
        let Some(skin) = skin(ctx, &routed, humanoid.id) else {
            continue;
        };
        for &joint in &humanoid.joints {
            if !done.insert(joint) || set_elsewhere(doc, &routed, joint, "skinCoordIndex") {
                continue;
            }
            let node = doc.node(joint);
            let Some(entry) = node.entry("skinCoordIndex") else {
                continue;
            };
            let Some(indices) = entry.value.as_int32s() else {
                continue;
            };
            let mut spans = ScalarSpans::new(ctx.source, entry);
            let name = name_suffix(doc, joint);
            for (at, &index) in indices.iter().enumerate() {
                if index < 0 || (index as usize) < skin.points {
                    continue;
                }
                ctx.report_repeated(
                    &HANIM_SKIN_COORD_INDEX_OUT_OF_RANGE,
                    joint,
                    "skinCoordIndex",
                    at,
                    || {
                        let message = format!(
                            "HAnimJoint{name}.skinCoordIndex[{at}] = {index} is past the end of the {} points of the humanoid's skinCoord",
                            skin.points
                        );
                        Diagnostic::new(&HANIM_SKIN_COORD_INDEX_OUT_OF_RANGE, spans.span(at), message)
                            .node(joint)
                            .value(index.to_string())
                            .related(skin.span, format!("skinCoord {} with {} points", skin.type_name, skin.points))
                            .help("index the points of the HAnimHumanoid's skinCoord, from 0 to one less than their number")
                    },
                );
            }
        }
    }
}

/// The skinCoord of a humanoid, when it is a coordinate node whose points the file gives.
fn skin(ctx: &Ctx, routed: &HashSet<(NodeId, String)>, humanoid: NodeId) -> Option<Skin> {
    let doc = ctx.doc;
    if set_elsewhere(doc, routed, humanoid, "skinCoord") {
        return None;
    }
    let coord = doc.node(humanoid).child("skinCoord")?;
    let node = doc.node(coord);
    if !matches!(node.kind, NodeKind::Known { .. }) || set_elsewhere(doc, routed, coord, "point") {
        return None;
    }
    let values = node.value("point")?.len();
    (values % 3 == 0).then(|| Skin {
        points: values / 3,
        span: node.span,
        type_name: node.type_name().to_string(),
    })
}
