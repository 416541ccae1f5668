//! COLOR_PER_VERTEX_IGNORED: colorPerVertex FALSE on a node that ignores it.

use crate::diagnostic::Diagnostic;
use crate::model::faces::PolygonKind;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports `colorPerVertex='false'` on IndexedTriangleFanSet, IndexedTriangleSet,
    /// IndexedTriangleStripSet, TriangleFanSet, TriangleSet, TriangleStripSet,
    /// IndexedQuadSet and QuadSet: each of these says "The value of the colorPerVertex
    /// field is ignored and always treated as TRUE". (IndexedFaceSet, ElevationGrid and
    /// IndexedLineSet honour the field and are not reported.)
    ///
    /// ## Why it matters
    /// The author asked for one colour per face but gets one per vertex: the colours are
    /// read in a different order than intended, and the Color node needs as many values
    /// as there are coordinates.
    ///
    /// ## Example
    /// ```xml
    /// <TriangleSet colorPerVertex='false'>
    ///   <Color color='1 0 0'/>
    ///   <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    /// </TriangleSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.6–11.4.8, 11.4.12–11.4.14; 32.4.5 IndexedQuadSet, 32.4.6 QuadSet.
    pub static COLOR_PER_VERTEX_IGNORED = {
        severity: Hint,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        let Some(kind) = node.def().and_then(|d| PolygonKind::of(d.name)) else {
            continue;
        };
        if !kind.colors_always_per_vertex() {
            continue;
        }
        let Some(entry) = node.entry("colorPerVertex") else {
            continue;
        };
        if entry.value.as_bools() != Some(&[false]) {
            continue;
        }
        let message = format!(
            "{}.colorPerVertex FALSE is ignored: colours are always applied per vertex",
            kind.name()
        );
        ctx.report(Diagnostic::new(&COLOR_PER_VERTEX_IGNORED, entry.span, message).node(id));
    }
}
