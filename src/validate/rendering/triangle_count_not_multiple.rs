//! TRIANGLE_COUNT_NOT_MULTIPLE: an index or coordinate count that leaves a partial
//! triangle (or quad) at the end.

use super::geometry::{coord_list, is_known, shape_is_known};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an IndexedTriangleSet whose `index` length, or a TriangleSet whose number
    /// of coordinates, is not a multiple of 3, and likewise an IndexedQuadSet `index` or a
    /// QuadSet coordinate count that is not a multiple of 4 (the CADGeometry quad sets
    /// say the same of quads), and a TriangleSet2D whose number of `vertices` is not a
    /// multiple of 3. The message says how many entries are left over.
    ///
    /// ## Why it matters
    /// "If the index field does not contain a multiple of three coordinate values, the
    /// remaining vertices shall be ignored": the leftover entries are silently dropped,
    /// which usually means an index or a coordinate was lost on export.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedTriangleSet index='0 1 2 0 2'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0'/>
    /// </IndexedTriangleSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.7 IndexedTriangleSet, 11.4.13 TriangleSet; 32.4.5 IndexedQuadSet,
    /// 32.4.6 QuadSet; 14.4.8 TriangleSet2D ("The number of vertices provided shall be
    /// evenly divisible by three. Excess vertices shall be ignored."), the same leftover
    /// entries dropped, so the same code.
    ///
    /// A warning although TriangleSet2D's sentence says "shall" (issue 33): the severity
    /// is the one ../shared/RULES.md gives the code, which is API, and the next sentence
    /// defines what a browser does with the file: "Excess vertices shall be ignored." (read
    /// in H3D's copy of the 3.x text, `TriangleSet2D.h`). The scene renders the same in
    /// every browser, minus the leftover vertices.
    pub static TRIANGLE_COUNT_NOT_MULTIPLE = {
        severity: Warning,
        level: Standard,
        clause: "11.4.7",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        let (size, shape) = match def.name {
            "IndexedTriangleSet" | "TriangleSet" | "TriangleSet2D" => (3, "triangle"),
            "IndexedQuadSet" | "QuadSet" => (4, "quad"),
            _ => continue,
        };
        if !shape_is_known(node) {
            continue;
        }
        let mut shared = None;
        let (count, what, span) = if def.name == "TriangleSet2D" {
            if !is_known(node, "vertices") {
                continue;
            }
            let Some(entry) = node.entry("vertices") else {
                continue;
            };
            let vertices = entry.value.len() / 2;
            (
                vertices,
                format!("TriangleSet2D has {vertices} vertices"),
                entry.span,
            )
        } else if def.name.starts_with("Indexed") {
            let Some(entry) = node.entry("index") else {
                continue;
            };
            (
                entry.value.len(),
                format!("{}.index has {} entries", def.name, entry.value.len()),
                entry.span,
            )
        } else {
            let Some(coord) = coord_list(doc, id) else {
                continue;
            };
            // A USE'd coordinate node is reported where this geometry uses it, not at
            // its DEF, which may belong to another geometry.
            let used = node.children("coord").first().is_some_and(|c| c.is_use);
            let span = match coord.entry {
                Some(entry) if !used => entry.span,
                Some(entry) => {
                    shared = Some(entry.span);
                    coord.child_span
                }
                None => coord.child_span,
            };
            (
                coord.len,
                format!(
                    "{} has {} coordinates in {}",
                    def.name, coord.len, coord.type_name
                ),
                span,
            )
        };
        let rest = count % size;
        if rest == 0 {
            continue;
        }
        let message = format!(
            "{what}, not a multiple of {size}: the last {rest} {} no {shape} and {} ignored",
            if rest == 1 { "makes" } else { "make" },
            if rest == 1 { "is" } else { "are" },
        );
        let mut diagnostic = Diagnostic::new(&TRIANGLE_COUNT_NOT_MULTIPLE, span, message).node(id);
        if let Some(points) = shared {
            diagnostic = diagnostic.related(points, "the shared coordinates");
        }
        ctx.report(diagnostic);
    }
}
