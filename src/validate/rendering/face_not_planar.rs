//! FACE_NOT_PLANAR: an IndexedFaceSet declared not convex with a face that is not planar
//! (deep level).

use super::face_not_convex::{face_corners, is_warped};
use super::geometry::{judge_polygonal, Points, ScalarSpans};
use crate::diagnostic::Diagnostic;
use crate::model::faces::PolygonKind;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an IndexedFaceSet whose `convex` is FALSE and which has a face of four or
    /// more corners that is not planar: a corner lies off the face's plane (through its
    /// first corner, normal to the sum of its fan's cross products) by more than 1e-3 of
    /// the face's size (its longest distance from the first corner), as FACE_NOT_CONVEX
    /// measures it. One diagnostic per geometry names the first such face and counts
    /// them. With `convex` TRUE (the default) FACE_NOT_CONVEX reports these faces, so this
    /// rule does not. Faces with fewer than four distinct corners, zero size or an
    /// unresolvable corner are not judged; `convex` connected by `IS` is not judged.
    ///
    /// ## Why it matters
    /// `convex='false'` asks the browser to triangulate a concave face, and a
    /// triangulation needs the face's plane: a warped face has none, so browsers split it
    /// along different diagonals, and it shades as a crease that moves from one browser to
    /// the next. Exporters write such faces from quads of curved surfaces.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet convex='false' coordIndex='0 1 2 3 -1'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0.5 0 1 0'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Use instead
    /// Split the face into planar ones (here, two triangles):
    /// ```xml
    /// <IndexedFaceSet convex='false' coordIndex='0 1 2 -1 0 2 3 -1'>
    ///   <Coordinate point='0 0 0 1 0 0 1 1 0.5 0 1 0'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 13.3.6 IndexedFaceSet, as ISO/IEC 14772-1 6.23 for VRML97 (read in Coin3D's
    /// SoVRMLIndexedFaceSet documentation, which quotes the VRML97 text; the X3D clause's
    /// wording was not read): "Each face of the IndexedFaceSet shall have: at least three
    /// non-coincident vertices; vertices that define a planar polygon; vertices that
    /// define a non-self-intersecting polygon. Otherwise, The results are undefined." A
    /// warning: the sentence states the outcome, undefined results.
    pub static FACE_NOT_PLANAR = {
        severity: Warning,
        level: Deep,
        clause: "13.3.6",
        versions: "all",
        check: Some(check),
    }
}

/// The first face that is not planar (number, first corner's position), how many are
/// not, and how many faces there are.
struct Found {
    first: (usize, usize),
    count: usize,
    faces: usize,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let judged = judge_polygonal(doc, |geometry| {
        if geometry.faces.kind != PolygonKind::IndexedFaceSet
            || geometry.node.is_connected("convex")
            || doc.bool_of(geometry.id, "convex").unwrap_or(true)
        {
            return None;
        }
        let points = Points::of(doc, geometry)?;
        let (mut first, mut count, mut faces) = (None, 0, 0);
        for face in geometry.faces.faces() {
            faces += 1;
            let warped = face_corners(geometry, &points, &face)
                .and_then(|(corners, normal)| is_warped(&corners, normal));
            if warped == Some(true) {
                count += 1;
                first.get_or_insert((face.number, face.corner(0)));
            }
        }
        Some(Found {
            first: first?,
            count,
            faces,
        })
    });
    for (geometry, found) in judged {
        let (number, position) = found.first;
        let span = match geometry.node.entry("coordIndex") {
            Some(entry) => ScalarSpans::new(ctx.source, entry).span(position),
            None => geometry.node.name_span,
        };
        let message = format!(
            "{} of the {} faces of this IndexedFaceSet {} not planar (first: face {number}, at coordIndex[{position}]): its rendering is undefined",
            found.count,
            found.faces,
            if found.count == 1 { "is" } else { "are" },
        );
        let mut diagnostic = Diagnostic::new(&FACE_NOT_PLANAR, span, message)
            .node(geometry.id)
            .index(position)
            .help("split each face that is not planar into planar ones, e.g. triangles");
        diagnostic.count = found.count;
        ctx.report(diagnostic);
    }
}
