//! NURBS_CONTROL_POINTS_TOO_FEW: fewer control points than the order.

use super::{nurbs_nodes, report};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a NURBS curve with control points but fewer of them than its `order`, and
    /// a NURBS surface (or NurbsSurfaceInterpolator, NurbsTextureCoordinate) whose
    /// `uDimension` or `vDimension` is above 0 but below `uOrder` or `vOrder`. A node
    /// with no control points at all is left to the rules on empty geometry, and fields
    /// a ROUTE or `IS` sets are left alone.
    ///
    /// ## Why it matters
    /// A B-spline of order k is made of pieces that each blend k control points; with
    /// fewer than k there is no piece to evaluate. Browsers draw nothing, or fall back to
    /// a lower order of their own choosing, which differs from browser to browser.
    ///
    /// ## Example
    /// ```xml
    /// <NurbsCurve order='4'>
    ///   <Coordinate point='0 0 0 1 1 0 2 0 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NurbsCurve order='3'>
    ///   <Coordinate point='0 0 0 1 1 0 2 0 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 27.4.4 NurbsCurve, and the same for each direction of the surfaces
    /// (27.3.2 X3DNurbsSurfaceGeometryNode: `uDimension` and `vDimension` are the numbers
    /// of control points in each direction). The sentences as the 3.x text has them (read
    /// in H3D's copies, `NurbsCurve.h` and the surface nodes; issue 33 corrected the
    /// wording this doc quoted before, which no copy has):
    /// > "The number of control points shall be at least equal to the order of the curve." (19775-1 27.4.4 NurbsCurve)
    ///
    /// > "The number of control points shall be equal or greater than the order." (19775-1 27.3.2 X3DNurbsSurfaceGeometryNode)
    pub static NURBS_CONTROL_POINTS_TOO_FEW = {
        severity: Error,
        level: Standard,
        clause: "27.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let mut found = Vec::new();
    for (id, directions) in nurbs_nodes(ctx.doc) {
        let node = ctx.doc.node(id);
        for d in directions {
            if d.points == 0 || d.points as i64 >= i64::from(d.order) {
                continue;
            }
            let order_field = d.order_field();
            let span = node.entry(order_field).map_or(node.name_span, |e| e.span);
            let along = if d.dimension.is_some() {
                " in each direction"
            } else {
                ""
            };
            let message = format!(
                "{} has {} but {order_field} {}: a NURBS of order k needs at least k control points{along}",
                node.type_name(),
                d.points_text(),
                d.order
            );
            found.push((id, span, message));
        }
    }
    report(
        ctx,
        &NURBS_CONTROL_POINTS_TOO_FEW,
        found,
        "lower the order to the number of control points, or add control points",
    );
}
