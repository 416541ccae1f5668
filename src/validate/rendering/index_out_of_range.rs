//! INDEX_OUT_OF_RANGE: an index past the end of the list it refers to.

use super::geometry::ScalarSpans;
use super::geometry::{attribute_lists, coord_list, shape_is_known, PropertyList};
use crate::diagnostic::Diagnostic;
use crate::model::faces::Attribute;
use crate::model::NodeId;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an index that refers past the end of the list it selects from:
    /// `coordIndex` (IndexedFaceSet, IndexedLineSet) or `index` (IndexedTriangleSet,
    /// IndexedTriangleFanSet, IndexedTriangleStripSet, IndexedQuadSet) against the points
    /// of the `coord` node; IndexedFaceSet `colorIndex`, `normalIndex` and `texCoordIndex`
    /// against the `color`, `normal` and `texCoord` node (each TextureCoordinate of a
    /// MultiTextureCoordinate); IndexedLineSet `colorIndex` against `color`. Every index
    /// is checked; the repeats on one field fold into one diagnostic with a count.
    ///
    /// Where an attribute has no index list and the coordinate indices select its values
    /// instead, a short list is ATTRIBUTE_COUNT_INSUFFICIENT, not this. Negative indices
    /// are INDEX_NEGATIVE. Nothing is checked against a list that cannot be known (a
    /// prototype field connected by IS, a ProtoInstance, a generator).
    ///
    /// ## Why it matters
    /// "If the greatest index in the colorIndex field is N, then there shall be N+1
    /// colours" (13.3.6); the same holds for every index. Browsers drop the face, draw
    /// garbage or stop rendering the shape.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet coordIndex='0 1 2 -1 0 2 3 -1'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4.4 (IndexedLineSet), 11.4.6–11.4.8 (indexed triangle sets), 13.3.6
    /// (IndexedFaceSet), 32.4.5 (IndexedQuadSet).
    /// > "If the greatest index in the colorIndex field is N, then there shall be N+1 colours in the Color node" (19775-1 13.3.6; the same for the other index fields)
    pub static INDEX_OUT_OF_RANGE = {
        severity: Error,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

/// The geometry types with a vertex index field, and that field.
const INDEXED: &[(&str, &str)] = &[
    ("IndexedFaceSet", "coordIndex"),
    ("IndexedLineSet", "coordIndex"),
    ("IndexedTriangleSet", "index"),
    ("IndexedTriangleFanSet", "index"),
    ("IndexedTriangleStripSet", "index"),
    ("IndexedQuadSet", "index"),
];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        let Some(&(_, field)) = INDEXED.iter().find(|(name, _)| *name == def.name) else {
            continue;
        };
        if !shape_is_known(node) {
            continue;
        }
        if let Some(coord) = coord_list(doc, id) {
            check_list(ctx, id, field, &coord, "coordinates");
        }
        let attributes: &[Attribute] = match def.name {
            "IndexedFaceSet" => &[Attribute::Color, Attribute::Normal, Attribute::TexCoord],
            "IndexedLineSet" => &[Attribute::Color],
            _ => &[],
        };
        for &attribute in attributes {
            let noun = match attribute {
                Attribute::Color => "colours",
                Attribute::Normal => "normals",
                Attribute::TexCoord => "texture coordinates",
            };
            for list in attribute_lists(doc, id, attribute).unwrap_or_default() {
                check_list(ctx, id, attribute.index_field(), &list, noun);
            }
        }
    }
}

fn check_list(ctx: &mut Ctx, id: NodeId, field: &str, list: &PropertyList, noun: &str) {
    let doc = ctx.doc;
    let node = doc.node(id);
    let Some(entry) = node.entry(field) else {
        return;
    };
    let Some(indices) = entry.value.as_int32s() else {
        return;
    };
    // The largest index first, in a loop without branches the compiler vectorizes:
    // nearly every list has nothing to report.
    let highest = indices
        .iter()
        .fold(i32::MIN, |high, &index| high.max(index));
    if highest < 0 || (highest as usize) < list.len {
        return;
    }
    let mut spans = ScalarSpans::new(ctx.source, entry);
    for (at, &index) in indices.iter().enumerate() {
        if index < 0 || (index as usize) < list.len {
            continue;
        }
        ctx.report_repeated(&INDEX_OUT_OF_RANGE, id, field, at, || {
            let message = format!(
                "{}.{field}[{at}] = {index} is past the end of the {} {noun} of {}",
                node.type_name(),
                list.len,
                list.type_name
            );
            Diagnostic::new(&INDEX_OUT_OF_RANGE, spans.span(at), message)
                .node(id)
                .value(index.to_string())
                .related(
                    list.child_span,
                    format!("{} with {} {noun}", list.type_name, list.len),
                )
        });
    }
}
