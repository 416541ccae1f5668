//! DEGENERATE_TRIANGLE: zero-area faces, counted per geometry (deep level).

use super::face_survey::counts_runs;
use super::geometry::{Checked, ScalarSpans};
use crate::diagnostic::Diagnostic;
use crate::model::faces::PolygonKind;
use crate::model::Span;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Counts the zero-area faces of each polygonal geometry and reports them in one
    /// diagnostic per geometry, naming the first:
    /// - IndexedFaceSet: a face with fewer than three vertices or with all its vertices
    ///   collinear or coincident ("at least three non-coincident vertices", 13.3.6);
    /// - IndexedTriangleSet, TriangleSet: a triangle with repeated or collinear corners;
    ///   IndexedQuadSet, QuadSet, ElevationGrid cells: a quad with all corners collinear;
    /// - strips and fans (indexed or counted): a strip or fan without three non-coincident,
    ///   non-collinear vertices, that is all of whose triangles are zero-area ("Each strip
    ///   shall have at least three non-coincident vertices", 11.4.6, 11.4.8). Single
    ///   zero-area triangles inside a strip are the usual way of joining strips and are
    ///   not counted.
    ///
    /// The test is relative, in f64: a triangle is zero-area when the sine of the angle
    /// between its edges from the first corner is below 1e-6 (each edge scaled by its
    /// largest component first), so huge finite coordinates such as ±3e38 give no false
    /// positives and tiny ones no false negatives. Faces with an unresolvable corner
    /// (negative or out-of-range index, non-finite coordinate) are left to the rules
    /// that report those. Geospatial coordinates are not judged.
    ///
    /// ## Why it matters
    /// A zero-area face draws nothing, has no defined normal (generated normals around it
    /// come out wrong or NaN) and usually means welded or duplicated vertices.
    ///
    /// ## Example
    /// ```xml
    /// <TriangleSet>
    ///   <Coordinate point='0 0 0 1 0 0 0 1 0  0 0 0 1 1 1 2 2 2'/>
    /// </TriangleSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.6, 11.4.8 (strips and fans), 13.3.6 (IndexedFaceSet faces).
    ///
    /// An info, the severity ../shared/RULES.md gives the code, which is API (issue 33).
    /// IndexedFaceSet's "shall" comes with its consequence: "Each face of the
    /// IndexedFaceSet shall have: at least three non-coincident vertices; … Otherwise, The
    /// results are undefined." (H3D's copy of the 3.x text, `IndexedFaceSet.h`); a
    /// zero-area triangle draws nothing, and exporters write many of them.
    pub static DEGENERATE_TRIANGLE = {
        severity: Info,
        level: Deep,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let surveyed = ctx.face_survey();
    for (geometry, survey) in surveyed.iter() {
        let Some(count) = &survey.degenerate else {
            continue;
        };
        let kind = geometry.faces.kind;
        let count_runs = counts_runs(kind);
        let noun = match kind {
            PolygonKind::IndexedTriangleStripSet | PolygonKind::TriangleStripSet => "strips",
            PolygonKind::IndexedTriangleFanSet | PolygonKind::TriangleFanSet => "fans",
            PolygonKind::IndexedFaceSet => "faces",
            PolygonKind::IndexedTriangleSet | PolygonKind::TriangleSet => "triangles",
            _ => "quads",
        };
        let Some((number, position)) = count.first else {
            continue;
        };
        let (place, span) = locate(ctx, geometry, position);
        let what = if count_runs {
            format!(
                "{} of its {} {noun} {} no three non-collinear vertices",
                count.degenerate,
                count.total,
                if count.degenerate == 1 { "has" } else { "have" }
            )
        } else {
            format!(
                "{} of its {} {noun} {} zero area",
                count.degenerate,
                count.total,
                if count.degenerate == 1 { "has" } else { "have" }
            )
        };
        let singular = noun.trim_end_matches('s');
        let message = format!(
            "{}: {what} (first: {singular} {number}, at {place})",
            kind.name()
        );
        let mut diagnostic = Diagnostic::new(&DEGENERATE_TRIANGLE, span, message)
            .node(geometry.id)
            .index(position);
        diagnostic.count = count.degenerate;
        ctx.report(diagnostic);
    }
}

/// Where a stream position stands in the document: the index field's entry, the
/// coordinates of a non-indexed node, or an ElevationGrid height.
fn locate(ctx: &Ctx, geometry: &Checked, position: usize) -> (String, Span) {
    let kind = geometry.faces.kind;
    let node = geometry.node;
    if let Some(field) = kind.index_field() {
        let name = format!("{}[{position}]", field);
        return match node.entry(field) {
            Some(entry) => (name, ScalarSpans::new(ctx.source, entry).span(position)),
            None => (name, node.name_span),
        };
    }
    if kind == PolygonKind::ElevationGrid {
        let name = format!("height[{position}]");
        return match node.entry("height") {
            Some(entry) => (name, ScalarSpans::new(ctx.source, entry).span(position)),
            None => (name, node.name_span),
        };
    }
    match &geometry.coord {
        Some(coord) => {
            let name = format!("{}.point[{position}]", coord.type_name);
            match coord.entry {
                Some(entry) => (
                    name,
                    ScalarSpans::new(ctx.source, entry).span_of(3 * position, 3 * position + 2),
                ),
                None => (name, coord.child_span),
            }
        }
        None => (format!("vertex {position}"), node.name_span),
    }
}
