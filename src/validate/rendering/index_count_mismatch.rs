//! INDEX_COUNT_MISMATCH: a per-vertex colorIndex, normalIndex or texCoordIndex that does
//! not follow coordIndex vertex for vertex.

use super::geometry::{shape_is_known, ScalarSpans};
use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, Value};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a per-vertex index list that does not match coordIndex: fewer entries than
    /// coordIndex (a final `-1` of coordIndex need not be matched), or a `-1` separator
    /// where coordIndex has a vertex, or a vertex where coordIndex has a `-1`. The lists
    /// are those used per vertex:
    /// - IndexedFaceSet (13.3.6): colorIndex with colorPerVertex TRUE, normalIndex with
    ///   normalPerVertex TRUE, and texCoordIndex, when they are not empty;
    /// - IndexedLineSet (11.4): colorIndex with colorPerVertex TRUE, when not empty.
    ///
    /// One diagnostic per list, at its first mismatch. Entries below `-1` are
    /// INDEX_NEGATIVE and are not compared here; per-face lists (colorPerVertex or
    /// normalPerVertex FALSE) are ATTRIBUTE_COUNT_INSUFFICIENT's.
    ///
    /// ## Why it matters
    /// The clauses require it: "the colorIndex field shall contain at least as many indices
    /// as the coordIndex field and shall contain end-of-face markers (-1) in exactly the
    /// same places as the coordIndex field" (13.3.6, and likewise for normalIndex and
    /// texCoordIndex; 11.4 for IndexedLineSet's polylines). A shifted separator pairs every
    /// later vertex with another vertex's colour, normal or texture coordinate, and the
    /// vertices past a short list's end have none: browsers differ in what they draw.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet coordIndex='0 1 2 -1 0 2 3 -1' colorIndex='0 1 2 -1 0 2'>
    ///   <Color color='1 0 0 0 1 0 0 0 1 1 1 0'/>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0 0 1 0'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Use instead
    /// One index per coordIndex entry, with `-1` where coordIndex has one, or an empty
    /// list (coordIndex then selects the values).
    ///
    /// ## Clause
    /// 19775-1 13.3.6 IndexedFaceSet; 11.4 IndexedLineSet (its colour rules).
    /// > "The colorIndex field shall contain at least as many indices as the coordIndex field" (19775-1 13.3.6; the same for normalIndex and texCoordIndex)
    pub static INDEX_COUNT_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "13.3.6",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        let lists: &[(&str, Option<&str>)] = match def.name {
            "IndexedFaceSet" => &[
                ("colorIndex", Some("colorPerVertex")),
                ("normalIndex", Some("normalPerVertex")),
                ("texCoordIndex", None),
            ],
            "IndexedLineSet" => &[("colorIndex", Some("colorPerVertex"))],
            _ => continue,
        };
        if !shape_is_known(node) {
            continue;
        }
        let Some(coord_index) = node.value("coordIndex").and_then(Value::as_int32s) else {
            continue;
        };
        for &(field, switch) in lists {
            if switch.is_some_and(|s| !doc.bool_of(id, s).unwrap_or(true)) {
                continue;
            }
            compare(ctx, id, def.name, field, coord_index);
        }
    }
}

/// Reports the first place where `field` does not follow `coord_index`.
fn compare(ctx: &mut Ctx, id: NodeId, type_name: &str, field: &str, coord_index: &[i32]) {
    let node = ctx.doc.node(id);
    let Some(entry) = node.entry(field) else {
        return;
    };
    let Some(list) = entry.value.as_int32s() else {
        return;
    };
    if list.is_empty() {
        return;
    }
    // A final -1 of coordIndex ends the last face or polyline and needs no match.
    let needed = coord_index
        .iter()
        .rposition(|&i| i != -1)
        .map_or(0, |at| at + 1);
    let shifted = coord_index.iter().zip(list).position(|(&coord, &index)| {
        // Entries below -1 are INDEX_NEGATIVE's: they separate nothing and match nothing.
        coord >= -1 && index >= -1 && (coord == -1) != (index == -1)
    });
    let diagnostic = match shifted {
        Some(at) => {
            let mut spans = ScalarSpans::new(ctx.source, entry);
            let (coord, index) = (coord_index[at], list[at]);
            let what = if index == -1 {
                format!("{field}[{at}] is -1 where coordIndex[{at}] = {coord} is a vertex")
            } else {
                format!("{field}[{at}] = {index} is a vertex where coordIndex[{at}] is -1")
            };
            Diagnostic::new(
                &INDEX_COUNT_MISMATCH,
                spans.span(at),
                format!(
                    "{type_name}.{what}: the -1 separators of a per-vertex {field} must stand where coordIndex has them"
                ),
            )
            .index(at)
            .value(index.to_string())
        }
        None if list.len() < needed => Diagnostic::new(
            &INDEX_COUNT_MISMATCH,
            entry.span,
            format!(
                "{type_name}.{field} has {} entries but coordIndex has {needed}: a per-vertex {field} needs one entry per coordIndex entry",
                list.len()
            ),
        ),
        None => return,
    };
    ctx.report(diagnostic.node(id));
}
