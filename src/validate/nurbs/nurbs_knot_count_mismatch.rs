//! NURBS_KNOT_COUNT_MISMATCH: a knot vector whose length is not the number of control
//! points plus the order.

use super::{nurbs_nodes, report};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a NURBS curve or surface whose knot vector is written but does not hold
    /// exactly as many knots as control points plus the order: `knot` against the
    /// control points and `order` of NurbsCurve, NurbsCurve2D, NurbsPositionInterpolator
    /// and NurbsOrientationInterpolator; `uKnot` against `uDimension` + `uOrder` and
    /// `vKnot` against `vDimension` + `vOrder` of NurbsPatchSurface, NurbsTrimmedSurface,
    /// NurbsSurfaceInterpolator and NurbsTextureCoordinate. An empty knot vector (the
    /// default) is left alone, as are fields a ROUTE sends values to or that take their
    /// value through `IS`.
    ///
    /// ## Why it matters
    /// A browser that meets a knot vector of the wrong length does not use it: it computes
    /// a default uniform knot vector instead, so the curve or surface loses the shape the
    /// knots gave it (clamped ends, sharp corners from repeated knots, uneven spacing).
    /// The usual cause is a control point added or removed without its knot.
    ///
    /// ## Example
    /// ```xml
    /// <NurbsCurve order='3' knot='0 0 0 1 1'>
    ///   <Coordinate point='0 0 0 1 1 0 2 0 0 3 1 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <NurbsCurve order='3' knot='0 0 0 0.5 1 1 1'>
    ///   <Coordinate point='0 0 0 1 1 0 2 0 0 3 1 0'/>
    /// </NurbsCurve>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 27.4.4 NurbsCurve ("The number of knots shall be equal to the number of
    /// control points plus the order of the curve … If the length of a knot vector is 0 or
    /// not the exact number required (numcontrolPoint + order), a default uniform knot
    /// vector is computed"), the same for NurbsCurve2D (27.4.5) and the curve
    /// interpolators (27.4.6, 27.4.8), and per direction for the surfaces in 27.3.2
    /// X3DNurbsSurfaceGeometryNode, 27.4.10 NurbsSurfaceInterpolator and 27.4.13
    /// NurbsTextureCoordinate. Reading: the browser's fallback makes the file usable, not
    /// correct, so the "shall" is an error.
    /// > "The number of knots shall be equal to the number of control points plus the order of the curve" (19775-1 27.4.4)
    pub static NURBS_KNOT_COUNT_MISMATCH = {
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
        let type_name = ctx.doc.node(id).type_name();
        for d in directions {
            let Some(span) = d.knot_span else {
                continue;
            };
            let wanted = d.points as i64 + i64::from(d.order);
            if d.knots == 0 || d.knots as i64 == wanted {
                continue;
            }
            let message = format!(
                "{type_name}.{} has {} but needs {wanted}: {} plus {} {}",
                d.knot,
                plural(d.knots, "knot"),
                d.points_text(),
                d.order_field(),
                d.order
            );
            found.push((id, span, message));
        }
    }
    report(ctx, &NURBS_KNOT_COUNT_MISMATCH, found, "give one knot more per control point than the order needs, or leave the knot vector empty for a uniform one");
}
