//! COUNT_EXCEEDS_COORDS: vertexCount, stripCount or fanCount asks for more vertices than
//! there are coordinates.

use super::geometry::counted;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a LineSet whose `vertexCount`, a TriangleStripSet whose `stripCount` or a
    /// TriangleFanSet whose `fanCount` values add up to more vertices than its `coord`
    /// node has. Each count takes the next vertices from the coordinates in order, so the
    /// sum is the number of coordinates the node needs.
    ///
    /// ## Why it matters
    /// "Coordinates are assigned to each strip by taking `stripCount[n]` vertices from the
    /// coordinate field": the last polylines, strips or fans would take coordinates that
    /// do not exist, and browsers drop them or read garbage.
    ///
    /// ## Example
    /// ```xml
    /// <LineSet vertexCount='2 3'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0 0 1 0'/>
    /// </LineSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.5 LineSet, 11.4.12 TriangleFanSet, 11.4.14 TriangleStripSet.
    /// A warning, not an error (issue 32): the clauses constrain each count ("Each value
    /// of the vertexCount array shall be greater than or equal to two", 11.4.5; three for
    /// fanCount and stripCount) but no sentence requires the coordinates to suffice for
    /// their sum; "Coordinates are assigned to each line by taking `vertexCount[n]` vertices
    /// from the coordinate field" describes the reading, and what a browser draws when the
    /// coordinates run out is left undefined.
    pub static COUNT_EXCEEDS_COORDS = {
        severity: Warning,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, c) in counted(ctx.doc) {
        if c.total <= c.coord.len as u64 {
            continue;
        }
        let Some(entry) = c.entry else { continue };
        let message = format!(
            "{}.{} adds up to {} vertices but {} has only {} coordinates",
            c.type_name, c.field, c.total, c.coord.type_name, c.coord.len
        );
        ctx.report(
            Diagnostic::new(&COUNT_EXCEEDS_COORDS, entry.span, message)
                .node(id)
                .related(
                    c.coord.child_span,
                    format!("{} with {} coordinates", c.coord.type_name, c.coord.len),
                ),
        );
    }
}
