//! NURBS_WEIGHT_COUNT_MISMATCH: weights written, but not one per control point.

use super::{control_points, nurbs_nodes, report};
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a NURBS curve, surface, NurbsSurfaceInterpolator or NurbsTextureCoordinate
    /// whose `weight` field is written but does not hold one weight per control point.
    /// An empty `weight` (the default: every weight 1, a non-rational spline) is left
    /// alone, as are fields a ROUTE or `IS` sets.
    ///
    /// ## Why it matters
    /// With fewer weights than control points the browser ignores them all and uses 1.0
    /// for each: a rational shape (a circle, an arc, a cone) comes out as a plain
    /// B-spline that only approximates it. With more, the extra weights belong to no
    /// control point, which usually means a control point was lost.
    ///
    /// ## Example
    /// ```xml
    /// <NurbsCurve order='3' weight='1 0.707'>
    ///   <Coordinate point='1 0 0 1 1 0 0 1 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NurbsCurve order='3' weight='1 0.707 1'>
    ///   <Coordinate point='1 0 0 1 1 0 0 1 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 27.3.2 X3DNurbsSurfaceGeometryNode ("A weight value that shall be greater
    /// than zero is assigned to each controlPoint … The number of values shall be
    /// identical to the number of control points … If the number of weight values is less
    /// than the number of control points, all weight values shall be ignored and a value
    /// of 1.0 shall be used"), the same in 27.4.13 NurbsTextureCoordinate. Reading: the
    /// curves pair `weight[i]` with control point i in the same way (27.4.4 NurbsCurve),
    /// so the count is held to them too.
    /// > "The number of values shall be identical to the number of control points" (19775-1 27.3.2)
    pub static NURBS_WEIGHT_COUNT_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "27.3.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, _) in nurbs_nodes(doc) {
        if set_elsewhere(doc, &routed, id, "weight") {
            continue;
        }
        let node = doc.node(id);
        let Some(entry) = node.entry("weight") else {
            continue;
        };
        let weights = entry.value.len();
        let Some(points) = control_points(doc, &routed, id) else {
            continue;
        };
        if weights == 0 || weights == points {
            continue;
        }
        let effect = if weights < points {
            "the browser ignores them all and uses 1.0"
        } else {
            "the extra ones weigh no control point"
        };
        let message = format!(
            "{} has {} for {}: {effect}",
            node.type_name(),
            plural(weights, "weight"),
            plural(points, "control point")
        );
        found.push((id, entry.span, message));
    }
    report(
        ctx,
        &NURBS_WEIGHT_COUNT_MISMATCH,
        found,
        "give one weight per control point, in the order of the control points, or none",
    );
}
