//! INDEX_NEGATIVE: a negative index other than the -1 separator, or a -1 where the list has
//! no separators.

use super::geometry::{shape_is_known, ScalarSpans};
use crate::diagnostic::Diagnostic;
use crate::model::NodeId;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a negative index that the list does not allow:
    /// - below -1 anywhere: `coordIndex`, `colorIndex`, `normalIndex`, `texCoordIndex` of
    ///   IndexedFaceSet and IndexedLineSet, `index` of the indexed triangle and quad sets;
    /// - any negative entry, -1 included, in IndexedTriangleSet.index and
    ///   IndexedQuadSet.index, which take three (four) consecutive indices per face and
    ///   have no separators;
    /// - any negative entry in a `colorIndex` (IndexedFaceSet, IndexedLineSet) or
    ///   `normalIndex` (IndexedFaceSet) that holds one index per face or polyline, that is
    ///   with colorPerVertex (normalPerVertex) FALSE: "The colorIndex field shall not
    ///   contain any negative entries" (13.3.6, 11.4.4).
    ///
    /// The repeats on one field fold into one diagnostic with a count.
    ///
    /// ## Why it matters
    /// A negative index selects nothing: browsers drop the face, split it where the author
    /// did not mean to, or reject the node.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedTriangleSet index='0 1 2 -1 2 1 3'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0 0 1 0'/>
    /// </IndexedTriangleSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.4, 11.4.6–11.4.8, 13.3.6, 32.4.5 (the `[0,∞) or -1` ranges and the
    /// text on per-face index lists).
    /// > "MFInt32 [] coordIndex [] [0,∞) or -1" (19775-1 11.4.4, the interface table's range)
    pub static INDEX_NEGATIVE = {
        severity: Error,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

/// What a list allows below zero.
#[derive(Copy, Clone, PartialEq, Eq)]
enum Allowed {
    /// -1 ends a face, strip, fan or polyline.
    Separator,
    /// Nothing negative: one index per triangle corner, quad corner, face or polyline.
    Nothing,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        if !shape_is_known(node) {
            continue;
        }
        let per_vertex = |field| doc.bool_of(id, field).unwrap_or(true);
        let per_vertex_list = |field| {
            if per_vertex(field) {
                Allowed::Separator
            } else {
                Allowed::Nothing
            }
        };
        let lists: Vec<(&str, Allowed, &str)> = match def.name {
            "IndexedFaceSet" => vec![
                ("coordIndex", Allowed::Separator, ""),
                (
                    "colorIndex",
                    per_vertex_list("colorPerVertex"),
                    "one colour index per face",
                ),
                (
                    "normalIndex",
                    per_vertex_list("normalPerVertex"),
                    "one normal index per face",
                ),
                ("texCoordIndex", Allowed::Separator, ""),
            ],
            "IndexedLineSet" => vec![
                ("coordIndex", Allowed::Separator, ""),
                (
                    "colorIndex",
                    per_vertex_list("colorPerVertex"),
                    "one colour index per polyline",
                ),
            ],
            "IndexedTriangleFanSet" | "IndexedTriangleStripSet" => {
                vec![("index", Allowed::Separator, "")]
            }
            "IndexedTriangleSet" => vec![("index", Allowed::Nothing, "three indices per triangle")],
            "IndexedQuadSet" => vec![("index", Allowed::Nothing, "four indices per quad")],
            _ => continue,
        };
        for (field, allowed, layout) in lists {
            check_list(ctx, id, field, allowed, layout);
        }
    }
}

fn check_list(ctx: &mut Ctx, id: NodeId, field: &str, allowed: Allowed, layout: &str) {
    let doc = ctx.doc;
    let node = doc.node(id);
    let Some(entry) = node.entry(field) else {
        return;
    };
    let Some(indices) = entry.value.as_int32s() else {
        return;
    };
    let lowest_allowed = match allowed {
        Allowed::Separator => -1,
        Allowed::Nothing => 0,
    };
    // The smallest index first, in a loop without branches the compiler vectorizes:
    // nearly every list has nothing to report.
    if indices.iter().fold(i32::MAX, |low, &index| low.min(index)) >= lowest_allowed {
        return;
    }
    let mut spans = ScalarSpans::new(ctx.source, entry);
    for (at, &index) in indices.iter().enumerate() {
        if index >= lowest_allowed {
            continue;
        }
        ctx.report_repeated(&INDEX_NEGATIVE, id, field, at, || {
            let type_name = node.type_name();
            let why = if allowed == Allowed::Separator {
                "only -1 (end of a run) may be negative".to_string()
            } else if field == "index" {
                format!("{type_name}.index has no -1 separators: it holds {layout}")
            } else {
                let switch = if field == "colorIndex" {
                    "colorPerVertex"
                } else {
                    "normalPerVertex"
                };
                format!("with {switch} FALSE, {field} holds {layout} and no -1 separators")
            };
            Diagnostic::new(
                &INDEX_NEGATIVE,
                spans.span(at),
                format!("{type_name}.{field}[{at}] = {index} is negative; {why}"),
            )
            .node(id)
            .value(index.to_string())
        });
    }
}
