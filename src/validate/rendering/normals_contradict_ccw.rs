//! NORMALS_CONTRADICT_CCW: supplied normals point against the faces' winding (deep level).

use super::geometry::{
    attribute_lists, dot, face_normal, judge_polygonal, scaled, unit, Checked, Points, PropertyList,
};
use crate::model::faces::{Attribute, Binding, Face};
use crate::report::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a polygonal geometry (IndexedFaceSet, ElevationGrid, the triangle and quad
    /// sets) whose supplied normals point against the geometric normals of most of its
    /// faces, given `ccw`. The geometric normal of a face follows the right-hand rule over
    /// its corners in order (the sum of the cross products of its fan, in f64), reversed
    /// when ccw is FALSE. The supplied normal of a face is its per-face normal, or the sum
    /// of its corners' unit per-vertex normals, bound as 13.3.6 and 11.4 say.
    ///
    /// "Most" means: at least two thirds of the faces that can be judged contradict
    /// (negative dot product) rather than agree (positive). The faces judged are those
    /// whose corners resolve to finite coordinates, whose geometric normal is not
    /// degenerate (relative to the face's edges, as DEGENERATE_TRIANGLE decides) and
    /// whose supplied normal is not zero. A mesh with a few flipped faces, or with
    /// windings mixed at random, is therefore not reported; one whose normals or ccw are
    /// inverted is. Geospatial coordinates are not judged.
    ///
    /// ## Why it matters
    /// "If normals are not generated but are supplied using a Normal node, and the
    /// orientation of the normals does not match the setting of the ccw field, results
    /// are undefined" (11.2.3): depending on the browser the shape is lit from the wrong
    /// side, appears black, or is culled when solid is TRUE.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet coordIndex='0 1 2 -1' normalPerVertex='false'>
    ///   <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    ///   <Normal vector='0 0 -1'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.2.3 Common geometry fields (ccw).
    pub static NORMALS_CONTRADICT_CCW = {
        severity: Warning,
        level: Deep,
        clause: "11.2.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let judged = judge_polygonal(doc, |geometry| {
        let lists = attribute_lists(doc, geometry.id, Attribute::Normal)?;
        let [normals] = lists.as_slice() else {
            return None;
        };
        let points = Points::of(doc, geometry)?;
        let (mut agree, mut contradict) = (0usize, 0usize);
        for face in geometry.faces.faces() {
            let Some(geometric) = face_normal(geometry, &points, &face) else {
                continue;
            };
            let Some(supplied) = supplied_normal(geometry, normals, &face) else {
                continue;
            };
            let d = dot(geometric, supplied);
            let d = if geometry.faces.ccw { d } else { -d };
            if d > 0.0 {
                agree += 1;
            } else if d < 0.0 {
                contradict += 1;
            }
        }
        Some((normals.child_span, agree, contradict))
    });
    for (geometry, (normals_span, agree, contradict)) in judged {
        // "Most": at least two thirds of the judged faces.
        if contradict == 0 || contradict < 2 * agree {
            continue;
        }
        let ccw = if geometry.faces.ccw { "TRUE" } else { "FALSE" };
        let message = format!(
            "{}: the supplied normals point against the winding of {contradict} of {} faces (ccw {ccw}): results are undefined",
            geometry.faces.kind.name(),
            agree + contradict
        );
        ctx.report(
            Diagnostic::new(&NORMALS_CONTRADICT_CCW, normals_span, message)
                .node(geometry.id)
                .help(format!(
                    "set ccw='{}' or reverse the normals",
                    if geometry.faces.ccw { "false" } else { "true" }
                )),
        );
    }
}

/// The face's supplied normal direction (not normalized: only the sign of its dot product
/// with the geometric normal is used): its per-face normal, or the sum of its corners'
/// unit normals; None where an index or a normal is missing or zero, or the sum is zero.
fn supplied_normal(geometry: &Checked, normals: &PropertyList, face: &Face) -> Option<[f64; 3]> {
    let per_face = matches!(
        geometry.faces.binding(Attribute::Normal),
        Binding::PerFace { .. }
    );
    let mut sum = [0.0; 3];
    for position in face.corners() {
        let index = geometry
            .faces
            .attribute_index(Attribute::Normal, face, position)?;
        let n = unit(normals.values.vec3(index)?)?;
        for (s, c) in sum.iter_mut().zip(n) {
            *s += c;
        }
        if per_face {
            break;
        }
    }
    scaled(sum).map(|_| sum)
}
