//! COUNT_LEAVES_COORDS: vertexCount, stripCount or fanCount uses fewer vertices than there
//! are coordinates.

use super::geometry::counted;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a LineSet whose `vertexCount`, a TriangleStripSet whose `stripCount` or a
    /// TriangleFanSet whose `fanCount` values add up to fewer vertices than its `coord`
    /// node has: the coordinates past the sum belong to no polyline, strip or fan. An
    /// unset (empty) count field uses none of them.
    ///
    /// ## Why it matters
    /// The unused coordinates are not drawn. That is allowed, but it is often a count
    /// that was not updated when coordinates were added.
    ///
    /// ## Example
    /// ```xml
    /// <TriangleFanSet fanCount='4'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0 0 1 0 2 2 0'/>
    /// </TriangleFanSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.5 LineSet, 11.4.12 TriangleFanSet, 11.4.14 TriangleStripSet.
    pub static COUNT_LEAVES_COORDS = {
        severity: Info,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, c) in counted(doc) {
        let available = c.coord.len as u64;
        if c.total >= available {
            continue;
        }
        let span = c.entry.map_or(doc.node(id).name_span, |e| e.span);
        let message = format!(
            "{}.{} adds up to {} vertices of the {} coordinates of {}: the last {} not drawn",
            c.type_name,
            c.field,
            c.total,
            available,
            c.coord.type_name,
            match available - c.total {
                1 => "one is".to_string(),
                n => format!("{n} are"),
            }
        );
        ctx.report(Diagnostic::new(&COUNT_LEAVES_COORDS, span, message).node(id));
    }
}
