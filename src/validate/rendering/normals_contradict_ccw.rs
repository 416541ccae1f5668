//! NORMALS_CONTRADICT_CCW: supplied normals point against the faces' winding (deep level).

use super::face_survey::NormalsCount;
use crate::diagnostic::Diagnostic;
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
    let surveyed = ctx.face_survey();
    for (geometry, survey) in surveyed.iter() {
        let Some(NormalsCount {
            normals_span,
            agree,
            contradict,
        }) = survey.normals
        else {
            continue;
        };
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
