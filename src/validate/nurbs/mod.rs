//! NURBS component (clause 27): the counts that tie a curve's or surface's knots, order,
//! control points and weights together.

pub mod contour2d_not_closed;
pub mod contours;
pub mod nurbs_control_points_too_few;
pub mod nurbs_dimension_mismatch;
pub mod nurbs_knot_count_mismatch;
pub mod nurbs_knot_decreasing;
pub mod nurbs_weight_count_mismatch;
pub mod trimming_loop_clockwise;

use std::collections::HashSet;

use super::events::wiring::{any_set_elsewhere, routed_fields, set_elsewhere};
use super::numbers::plural;
use super::{Check, Ctx};
use crate::diagnostic::{Diagnostic, Rule};
use crate::model::{Document, NodeId, Span};
use crate::schema::FieldType;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &nurbs_knot_count_mismatch::CHECK,
    &nurbs_knot_decreasing::CHECK,
    &nurbs_control_points_too_few::CHECK,
    &nurbs_weight_count_mismatch::CHECK,
    &nurbs_dimension_mismatch::CHECK,
    &contour2d_not_closed::CHECK,
    &trimming_loop_clockwise::CHECK,
];

/// One parametric direction of a NURBS node: a curve has one, a surface two (u and v).
pub(crate) struct Direction {
    /// `knot`, `uKnot` or `vKnot`.
    pub knot: &'static str,
    pub knots: usize,
    /// Where the knots are written, if they are.
    pub knot_span: Option<Span>,
    pub order: i32,
    /// The control points along this direction: a curve's control points, a surface's
    /// `uDimension` or `vDimension`.
    pub points: usize,
    /// The field giving a surface's `points` (`uDimension`, `vDimension`); None for a
    /// curve, whose control points are counted.
    pub dimension: Option<&'static str>,
}

impl Direction {
    /// `4 control points` or `uDimension 4`, for messages.
    pub fn points_text(&self) -> String {
        match self.dimension {
            Some(name) => format!("{name} {}", self.points),
            None => plural(self.points, "control point"),
        }
    }

    /// The field of the order: `order`, `uOrder` or `vOrder`.
    pub fn order_field(&self) -> &'static str {
        match self.knot {
            "uKnot" => "uOrder",
            "vKnot" => "vOrder",
            _ => "order",
        }
    }
}

/// The NURBS nodes whose values the scene does not replace (no ROUTE into and no `IS` on
/// the fields the rules compare), with their directions.
pub(crate) fn nurbs_nodes(doc: &Document) -> Vec<(NodeId, Vec<Direction>)> {
    let routed = routed_fields(doc);
    doc.iter()
        .filter_map(|(id, _)| Some((id, directions(doc, &routed, id)?)))
        .collect()
}

pub(crate) const CURVES: [&str; 4] = [
    "NurbsCurve",
    "NurbsCurve2D",
    "NurbsOrientationInterpolator",
    "NurbsPositionInterpolator",
];

/// The surfaces: every X3DNurbsSurfaceGeometryNode, and the two nodes with the same u/v
/// fields that are no geometry.
pub(crate) fn is_surface(doc: &Document, id: NodeId) -> bool {
    let node = doc.node(id);
    node.is_a("X3DNurbsSurfaceGeometryNode")
        || ["NurbsSurfaceInterpolator", "NurbsTextureCoordinate"].contains(&node.type_name())
}

fn directions(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    id: NodeId,
) -> Option<Vec<Direction>> {
    let node = doc.node(id);
    let is_curve = CURVES.contains(&node.type_name());
    let fields: &[&str] = if is_curve {
        &["knot", "order", "controlPoint"]
    } else if is_surface(doc, id) {
        &[
            "uKnot",
            "uOrder",
            "uDimension",
            "vKnot",
            "vOrder",
            "vDimension",
        ]
    } else {
        return None;
    };
    if any_set_elsewhere(doc, routed, id, fields) {
        return None;
    }
    let direction = |knot: &'static str, order: &str, points: usize, dimension| {
        let knots = doc.value_of(id, knot)?.len();
        Some(Direction {
            knot,
            knots,
            knot_span: node.entry(knot).map(|e| e.span),
            order: doc.i32_of(id, order)?,
            points,
            dimension,
        })
    };
    if is_curve {
        let points = control_points(doc, routed, id)?;
        return Some(vec![direction("knot", "order", points, None)?]);
    }
    let dimension = |name: &str| usize::try_from(doc.i32_of(id, name)?).ok();
    Some(vec![
        direction(
            "uKnot",
            "uOrder",
            dimension("uDimension")?,
            Some("uDimension"),
        )?,
        direction(
            "vKnot",
            "vOrder",
            dimension("vDimension")?,
            Some("vDimension"),
        )?,
    ])
}

/// The number of control points of a node: the points of its `controlPoint` coordinate
/// node, or the vectors of its `controlPoint` array (NurbsCurve2D, NurbsTextureCoordinate,
/// ContourPolyline2D). None when they come from elsewhere (a ROUTE, `IS`) or did not parse.
pub(crate) fn control_points(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    id: NodeId,
) -> Option<usize> {
    let node = doc.node(id);
    let field = node.def()?.field("controlPoint")?;
    let (holder, name, arity) = if field.ty == FieldType::SFNode {
        (doc.child_of(id, "controlPoint")?, "point", 3)
    } else {
        (id, "controlPoint", field.ty.arity())
    };
    if set_elsewhere(doc, routed, holder, name) {
        return None;
    }
    let values = doc.value_of(holder, name)?.len();
    (values % arity == 0).then_some(values / arity)
}

/// Reports each `(node, place, message)` of `found` under `rule`, with one help for all.
pub(crate) fn report(
    ctx: &mut Ctx,
    rule: &'static Rule,
    found: Vec<(NodeId, Span, String)>,
    help: &str,
) {
    for (id, span, message) in found {
        ctx.report(Diagnostic::new(rule, span, message).node(id).help(help));
    }
}
