//! NURBS_DIMENSION_MISMATCH: a surface whose control points are not uDimension × vDimension.

use super::{control_points, is_surface, nurbs_nodes, report};
use crate::validate::events::wiring::routed_fields;
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a NURBS surface (NurbsPatchSurface, NurbsTrimmedSurface), a
    /// NurbsSurfaceInterpolator or a NurbsTextureCoordinate whose number of control points
    /// is not `uDimension` × `vDimension`. Surfaces whose control points or dimensions a
    /// ROUTE or `IS` sets are left alone.
    ///
    /// ## Why it matters
    /// The control points are read as a grid: `uDimension` points along u, then the next
    /// row, `vDimension` rows in all. With a different count the grid is torn: missing
    /// points leave rows incomplete (browsers draw nothing or read past the end), extra
    /// points are never used. Usually a dimension was not updated after the grid changed.
    ///
    /// ## Example
    /// ```xml
    /// <NurbsPatchSurface uDimension='3' vDimension='3' uOrder='2' vOrder='2'>
    ///   <Coordinate point='0 0 0 1 0 0 2 0 0 0 0 1 1 1 1 2 0 1'/>
    /// </NurbsPatchSurface>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NurbsPatchSurface uDimension='3' vDimension='2' uOrder='2' vOrder='2'>
    ///   <Coordinate point='0 0 0 1 0 0 2 0 0 0 0 1 1 1 1 2 0 1'/>
    /// </NurbsPatchSurface>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 27.3.2 X3DNurbsSurfaceGeometryNode ("controlPoint defines a set of control
    /// points of dimension uDimension × vDimension … uDimension points define a polyline
    /// in u-direction followed by further u-polylines with the v-parameter in ascending
    /// order"); 27.4.10 NurbsSurfaceInterpolator and 27.4.13 NurbsTextureCoordinate use
    /// the same fields. Reading: a set "of dimension uDimension × vDimension" has that
    /// many points, so any other count contradicts the dimensions.
    /// A warning, not an error (issue 32): the sentence describes the grid without a
    /// "shall". The constraint stated on the count, that the control points "shall be
    /// equal or greater than the order" (27.3.2; 27.4.4 for curves), is
    /// NURBS_CONTROL_POINTS_TOO_FEW's.
    pub static NURBS_DIMENSION_MISMATCH = {
        severity: Warning,
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
    for (id, directions) in nurbs_nodes(doc) {
        if !is_surface(doc, id) {
            continue;
        }
        let Some(points) = control_points(doc, &routed, id) else {
            continue;
        };
        let [u, v] = [&directions[0], &directions[1]];
        let wanted = u.points * v.points;
        if points == wanted {
            continue;
        }
        let node = doc.node(id);
        let span = node
            .entry("controlPoint")
            .or_else(|| node.entry("uDimension"))
            .map_or(node.name_span, |e| e.span);
        let message = format!(
            "{} has {} but uDimension {} × vDimension {} = {wanted}",
            node.type_name(),
            plural(points, "control point"),
            u.points,
            v.points
        );
        found.push((id, span, message));
    }
    report(
        ctx,
        &NURBS_DIMENSION_MISMATCH,
        found,
        "set uDimension and vDimension to the rows and columns of the control-point grid",
    );
}
