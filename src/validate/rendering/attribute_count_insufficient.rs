//! ATTRIBUTE_COUNT_INSUFFICIENT: fewer colours, normals or texture coordinates (or fewer
//! per-face indices) than the geometry needs.

use super::geometry::{
    attribute_lists, coord_list, polygonal, shape_is_known, Checked, PropertyList,
};
use crate::diagnostic::Diagnostic;
use crate::model::faces::{runs, Attribute, Binding, PolygonKind};
use crate::model::{NodeId, Span, Value};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a colour, normal or texture-coordinate list shorter than its geometry
    /// needs, and a per-face index list with fewer entries than faces:
    /// - IndexedTriangleSet, IndexedTriangleFanSet, IndexedTriangleStripSet, TriangleSet,
    ///   TriangleFanSet, TriangleStripSet (11.4), IndexedQuadSet, QuadSet (32.4): "there
    ///   shall be at least as many values as are present in the coord field" for colours
    ///   (always per vertex there), texture coordinates and per-vertex normals. With
    ///   normalPerVertex FALSE the normals are per face, and one per face (triangle or
    ///   quad) is required.
    /// - IndexedFaceSet (13.3.6): per vertex without an index list, coordIndex selects the
    ///   values, so largest coordIndex + 1 are needed; per face (colorPerVertex or
    ///   normalPerVertex FALSE), one index per face in colorIndex/normalIndex or, without
    ///   one, one value per face. A per-vertex colorIndex, normalIndex or texCoordIndex
    ///   shorter than coordIndex, or with its -1 separators elsewhere, is
    ///   INDEX_COUNT_MISMATCH ("at least as many indices as the coordIndex field", 13.3.6).
    /// - ElevationGrid (13.3.4): xDimension × zDimension values per vertex (colours,
    ///   normals, texture coordinates), (xDimension−1) × (zDimension−1) per quadrilateral.
    /// - IndexedLineSet (11.4): per vertex without colorIndex, largest coordIndex + 1
    ///   colours; per polyline, one colorIndex entry or one colour per polyline. A
    ///   per-vertex colorIndex that does not follow coordIndex is INDEX_COUNT_MISMATCH.
    /// - LineSet (11.4.5): one colour per vertex of its polylines; PointSet (11.4.11):
    ///   "at least the number of points contained in the coord node".
    ///
    /// Each TextureCoordinate of a MultiTextureCoordinate is checked; generators and lists
    /// that cannot be known (IS, ProtoInstance) are not. Indices selecting past the end of
    /// an explicit index list's target are INDEX_OUT_OF_RANGE.
    ///
    /// ## Why it matters
    /// The vertices or faces past the end of the list have no colour, normal or texture
    /// coordinate: results are undefined, and browsers differ (black, the last value, or
    /// the whole shape dropped).
    ///
    /// ## Example
    /// ```xml
    /// <TriangleSet>
    ///   <Color color='1 0 0 0 1 0'/>
    ///   <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    /// </TriangleSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4 (the triangle sets, IndexedLineSet, LineSet, PointSet), 13.3.4
    /// ElevationGrid, 13.3.6 IndexedFaceSet, 32.4.5 IndexedQuadSet, 32.4.6 QuadSet.
    /// > "there shall be at least as many values as are present in the coord field" (19775-1 11.4.6, and the other triangle sets of 11.4)
    pub static ATTRIBUTE_COUNT_INSUFFICIENT = {
        severity: Error,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

const ATTRIBUTES: [Attribute; 3] = [Attribute::Color, Attribute::Normal, Attribute::TexCoord];

fn noun(attribute: Attribute, count: usize) -> &'static str {
    match (attribute, count == 1) {
        (Attribute::Color, true) => "colour",
        (Attribute::Color, false) => "colours",
        (Attribute::Normal, true) => "normal",
        (Attribute::Normal, false) => "normals",
        (Attribute::TexCoord, true) => "texture coordinate",
        (Attribute::TexCoord, false) => "texture coordinates",
    }
}

fn entries(count: usize) -> String {
    format!("{count} {}", if count == 1 { "entry" } else { "entries" })
}

fn switch(attribute: Attribute) -> &'static str {
    match attribute {
        Attribute::Normal => "normalPerVertex",
        _ => "colorPerVertex",
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for geometry in polygonal(doc) {
        for attribute in ATTRIBUTES {
            let Some(lists) = attribute_lists(doc, geometry.id, attribute) else {
                continue;
            };
            if lists.is_empty() {
                continue;
            }
            check_polygonal(ctx, &geometry, attribute, &lists);
        }
    }
    for (id, node) in doc.iter() {
        let Some(def) = node.def() else { continue };
        if !matches!(def.name, "IndexedLineSet" | "LineSet" | "PointSet") || !shape_is_known(node) {
            continue;
        }
        let Some(coord) = coord_list(doc, id) else {
            continue;
        };
        let Some(lists) = attribute_lists(doc, id, Attribute::Color) else {
            continue;
        };
        for list in &lists {
            check_lines(ctx, id, def.name, &coord, list);
        }
    }
}

/// What a geometry needs of one attribute: a number of values, or of index entries.
struct Need {
    count: usize,
    why: String,
}

fn check_polygonal(ctx: &mut Ctx, g: &Checked, attribute: Attribute, lists: &[PropertyList]) {
    let doc = ctx.doc;
    let type_name = g.faces.kind.name();
    let coordinates = || g.coord.as_ref().map_or((0, ""), |c| (c.len, c.type_name));
    let need = match (g.faces.kind, g.faces.binding(attribute)) {
        (PolygonKind::ElevationGrid, binding) => {
            let dimension = |f| doc.i32_of(g.id, f).map_or(0, |v| v.max(0) as usize);
            let (x, z) = (dimension("xDimension"), dimension("zDimension"));
            match binding {
                Binding::PerFace { .. } => Need {
                    count: x.saturating_sub(1).saturating_mul(z.saturating_sub(1)),
                    why: format!(
                        "one per grid cell ({}×{}, {} FALSE)",
                        x.saturating_sub(1),
                        z.saturating_sub(1),
                        switch(attribute)
                    ),
                },
                Binding::PerVertex { .. } => Need {
                    count: x.saturating_mul(z),
                    why: format!("one per grid point ({x}×{z})"),
                },
            }
        }
        // A per-vertex index list's length is INDEX_COUNT_MISMATCH's; its values past
        // the lists are INDEX_OUT_OF_RANGE's.
        (PolygonKind::IndexedFaceSet, Binding::PerVertex { index: Some(_) }) => return,
        (PolygonKind::IndexedFaceSet, Binding::PerVertex { index: None }) => {
            let coord_index = g
                .node
                .value("coordIndex")
                .and_then(Value::as_int32s)
                .unwrap_or(&[]);
            let Some(largest) = coord_index.iter().copied().filter(|&i| i >= 0).max() else {
                return;
            };
            // Indices past the coordinates are INDEX_OUT_OF_RANGE already.
            let (available, _) = coordinates();
            Need {
                count: (largest as usize + 1).min(available),
                why: format!(
                    "coordIndex selects them (no {}) and its largest index is {}",
                    attribute.index_field(),
                    (largest as usize).min(available.saturating_sub(1))
                ),
            }
        }
        (_, Binding::PerFace { index: Some(list) }) => {
            let faces = g.faces.face_count();
            if list.len() < faces {
                let field = attribute.index_field();
                let entry_span = g.node.entry(field).map_or(g.node.name_span, |e| e.span);
                let message = format!(
                    "{type_name}.{field} has {} for {faces} faces: with {} FALSE it needs one per face",
                    entries(list.len()),
                    switch(attribute)
                );
                ctx.report(
                    Diagnostic::new(&ATTRIBUTE_COUNT_INSUFFICIENT, entry_span, message).node(g.id),
                );
            }
            return;
        }
        (_, Binding::PerFace { index: None }) => Need {
            count: g.faces.face_count(),
            why: format!("one per face ({} FALSE)", switch(attribute)),
        },
        (_, Binding::PerVertex { .. }) => {
            let (count, coord_type) = coordinates();
            Need {
                count,
                why: format!("one per coordinate of {coord_type}"),
            }
        }
    };
    for list in lists {
        report_short(ctx, g.id, type_name, attribute, list, &need);
    }
}

fn report_short(
    ctx: &mut Ctx,
    id: NodeId,
    type_name: &str,
    attribute: Attribute,
    list: &PropertyList,
    need: &Need,
) {
    if list.len >= need.count {
        return;
    }
    let message = format!(
        "{type_name}.{} holds {} {} in {} but needs at least {}: {}",
        attribute.field(),
        list.len,
        noun(attribute, list.len),
        list.type_name,
        need.count,
        need.why
    );
    let span: Span = list.child_span;
    ctx.report(Diagnostic::new(&ATTRIBUTE_COUNT_INSUFFICIENT, span, message).node(id));
}

fn check_lines(
    ctx: &mut Ctx,
    id: NodeId,
    type_name: &str,
    coord: &PropertyList,
    list: &PropertyList,
) {
    let doc = ctx.doc;
    let node = doc.node(id);
    let ints = |f| node.value(f).and_then(Value::as_int32s).unwrap_or(&[]);
    let need = match type_name {
        "PointSet" => Need {
            count: coord.len,
            why: format!("one per point of {}", coord.type_name),
        },
        "LineSet" => {
            let total: u64 = ints("vertexCount").iter().map(|&c| c.max(0) as u64).sum();
            Need {
                count: total.min(coord.len as u64) as usize,
                why: "one per vertex of the polylines".to_string(),
            }
        }
        _ => {
            let (coord_index, color_index) = (ints("coordIndex"), ints("colorIndex"));
            let per_vertex = doc.bool_of(id, "colorPerVertex").unwrap_or(true);
            match (per_vertex, color_index.is_empty()) {
                // Indices past the colours are INDEX_OUT_OF_RANGE.
                (true, false) => return,
                (true, true) => {
                    let Some(largest) = coord_index.iter().copied().filter(|&i| i >= 0).max()
                    else {
                        return;
                    };
                    let largest = (largest as usize).min(coord.len.saturating_sub(1));
                    Need {
                        count: (largest + 1).min(coord.len),
                        why: format!("coordIndex selects them (no colorIndex) and its largest index is {largest}"),
                    }
                }
                (false, empty) => {
                    let polylines = runs(coord_index).count();
                    if !empty {
                        if color_index.len() < polylines {
                            let span = node.entry("colorIndex").map_or(node.name_span, |e| e.span);
                            let message = format!(
                                "IndexedLineSet.colorIndex has {} for {polylines} polylines: with colorPerVertex FALSE it needs one per polyline",
                                entries(color_index.len())
                            );
                            ctx.report(
                                Diagnostic::new(&ATTRIBUTE_COUNT_INSUFFICIENT, span, message)
                                    .node(id),
                            );
                        }
                        return;
                    }
                    Need {
                        count: polylines,
                        why: "one per polyline (colorPerVertex FALSE)".to_string(),
                    }
                }
            }
        }
    };
    report_short(ctx, id, type_name, Attribute::Color, list, &need);
}
