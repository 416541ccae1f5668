//! COORD_MISSING: a geometry that draws from coordinates has none.

use super::geometry::{property, Property};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

/// The geometry types that draw nothing without a `coord` node.
const NEEDS_COORD: &[&str] = &[
    "IndexedFaceSet",
    "IndexedLineSet",
    "IndexedTriangleFanSet",
    "IndexedTriangleSet",
    "IndexedTriangleStripSet",
    "LineSet",
    "PointSet",
    "TriangleFanSet",
    "TriangleSet",
    "TriangleStripSet",
    "IndexedQuadSet",
    "QuadSet",
];

crate::declare_rule! {
    /// ## What it does
    /// Reports a geometry node that takes its vertices from a `coord` field
    /// (IndexedFaceSet, IndexedLineSet, LineSet, PointSet, the triangle and quad sets)
    /// when that field is NULL. Not reported when the field is connected to a prototype
    /// field (`IS`) or the geometry has a DEF name: a ROUTE or a Script can then set the
    /// field at run time (an empty DEF'd geometry filled by a Script is a common idiom).
    ///
    /// ## Why it matters
    /// Without coordinates the geometry is empty ("If the coord field is NULL, the point
    /// set is considered empty", 11.4.11): nothing is drawn, usually because the
    /// Coordinate node was lost or given the wrong containerField.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet coordIndex='0 1 2 -1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.3 X3DComposedGeometryNode and 11.4 (each node's coord field), 13.3.6
    /// IndexedFaceSet.
    pub static COORD_MISSING = {
        severity: Warning,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        if !NEEDS_COORD.contains(&def.name) {
            continue;
        }
        if !matches!(property(doc, id, "coord"), Property::Missing) {
            continue;
        }
        // A DEF'd geometry can be given its coord by a ROUTE or a Script at run time.
        if node.def_name.is_some() {
            continue;
        }
        let message = format!("{} has no coord node: nothing is drawn", def.name);
        ctx.report(Diagnostic::new(&COORD_MISSING, node.name_span, message).node(id));
    }
}
