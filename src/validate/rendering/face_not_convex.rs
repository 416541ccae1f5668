//! FACE_NOT_CONVEX: an IndexedFaceSet declared convex with a concave or non-planar face
//! (deep level).

use super::geometry::{
    corner_point, cross, dot, face_normal, judge_polygonal, length, sub, unit, Checked, Points,
    ScalarSpans,
};
use crate::diagnostic::Diagnostic;
use crate::model::faces::{Face, PolygonKind};
use crate::validate::Ctx;

/// How far a corner may lie off its face's plane, relative to the face's size (its
/// longest distance from the first corner), before the face counts as not planar. f32
/// coordinates carry about 7 digits and exporters round further: 1e-3 leaves their noise
/// alone and catches a visibly warped face.
const PLANAR_TOLERANCE: f64 = 1e-3;

/// How far a turn may bend against the face's normal, as the sine of its angle, before
/// the corner counts as reflex: collinear corners (sine 0) and rounding are not concave.
const REFLEX_SINE: f64 = 1e-6;

crate::declare_rule! {
    /// ## What it does
    /// Reports an IndexedFaceSet whose `convex` is TRUE (the default) and which has a face
    /// of four or more corners that is concave or not planar, in one diagnostic per
    /// geometry naming the first such face and counting them:
    /// - not planar: a corner lies off the face's plane (through its first corner, normal
    ///   to the sum of its fan's cross products) by more than 1e-3 of the face's size;
    /// - concave: walking the corners in order, a turn bends against the face's normal
    ///   (the sine of its angle below −1e-6), or the turns wind more than once around
    ///   (a star).
    ///
    /// Computed in f64. Triangles are always convex and planar; faces with fewer than three
    /// distinct corners, zero area or an unresolvable corner are other rules' findings
    /// (DEGENERATE_TRIANGLE, INDEX_OUT_OF_RANGE) and are not judged; repeated consecutive
    /// corners are skipped. `convex` connected by `IS` is not judged.
    ///
    /// ## Why it matters
    /// "If the convex field is TRUE, the faces are assumed to be convex; if it is FALSE no
    /// assumption is made" and "results are undefined" for faces that break the assumption
    /// (11.2.3; 13.3.6 also requires planar faces): a browser fans the face from its first
    /// corner, so a concave face draws triangles outside its outline, and a warped one
    /// shades as a crease.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet coordIndex='0 1 2 3 -1'>
    ///   <Coordinate point='0 0 0 2 0 0 1 0.5 0 1 2 0'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Use instead
    /// For a concave face, `convex='false'`, or split it into convex ones. For a face that
    /// is not planar, split it into planar ones: `convex='false'` leaves it undefined
    /// (13.3.6 asks for planar faces whatever `convex` says), so the message does not
    /// suggest it there.
    ///
    /// ## Clause
    /// 19775-1 11.2.3 Common geometry fields (convex); 13.3.6 IndexedFaceSet.
    pub static FACE_NOT_CONVEX = {
        severity: Warning,
        level: Deep,
        clause: "11.2.3",
        versions: "all",
        check: Some(check),
    }
}

/// What is wrong with a face.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
enum Fault {
    NotPlanar,
    Concave,
}

/// The first faulty face (number, first corner's position, fault), the count, and how
/// many of them are not planar.
struct Found {
    first: (usize, usize, Fault),
    count: usize,
    not_planar: usize,
    faces: usize,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let judged = judge_polygonal(doc, |geometry| {
        if geometry.faces.kind != PolygonKind::IndexedFaceSet
            || geometry.node.is_connected("convex")
            || !doc.bool_of(geometry.id, "convex").unwrap_or(true)
        {
            return None;
        }
        let points = Points::of(doc, geometry)?;
        let (mut first, mut count, mut not_planar, mut faces) = (None, 0, 0, 0);
        for face in geometry.faces.faces() {
            faces += 1;
            if let Some(fault) = fault(geometry, &points, &face) {
                count += 1;
                not_planar += usize::from(fault == Fault::NotPlanar);
                first.get_or_insert((face.number, face.corner(0), fault));
            }
        }
        Some(Found {
            first: first?,
            count,
            not_planar,
            faces,
        })
    });
    for (geometry, found) in judged {
        let (number, position, fault) = found.first;
        let span = match geometry.node.entry("coordIndex") {
            Some(entry) => ScalarSpans::new(ctx.source, entry).span(position),
            None => geometry.node.name_span,
        };
        let what = match fault {
            Fault::NotPlanar => "is not planar",
            Fault::Concave => "is concave",
        };
        // Most files never write `convex`: say that TRUE is then the default.
        let convex = if geometry.node.entry("convex").is_some() {
            "convex TRUE"
        } else {
            "convex TRUE, the default"
        };
        let message = format!(
            "IndexedFaceSet is declared convex ({convex}) but {} of its {} faces {} not convex and planar (first: face {number}, at coordIndex[{position}], {what})",
            found.count,
            found.faces,
            if found.count == 1 { "is" } else { "are" },
        );
        // convex FALSE only tells a browser to triangulate a concave face; a face off its
        // plane stays undefined either way (13.3.6 wants planar faces).
        let help = if found.not_planar == 0 {
            "set convex='false' or split the faces into convex ones"
        } else if found.not_planar == found.count {
            "split the faces into planar ones: convex='false' does not help a face that is \
             not planar, whose rendering is undefined either way"
        } else {
            "split the faces that are not planar (convex='false' does not help them: their \
             rendering is undefined either way); for the concave ones, convex='false' is \
             enough"
        };
        let mut diagnostic = Diagnostic::new(&FACE_NOT_CONVEX, span, message)
            .node(geometry.id)
            .index(position)
            .help(help);
        diagnostic.count = found.count;
        ctx.report(diagnostic);
    }
}

/// Why a face is not convex and planar; None when it is, or cannot be judged.
fn fault(g: &Checked, points: &Points, face: &Face) -> Option<Fault> {
    let (corners, normal) = face_corners(g, points, face)?;
    if is_warped(&corners, normal)? {
        return Some(Fault::NotPlanar);
    }
    // Each turn's signed angle about the normal; a convex face turns one way, once round.
    let n = corners.len();
    let mut winding = 0.0;
    for k in 0..n {
        let (a, b, c) = (corners[k], corners[(k + 1) % n], corners[(k + 2) % n]);
        let (u, v) = (unit(sub(b, a))?, unit(sub(c, b))?);
        let sine = dot(cross(u, v), normal);
        if sine < -REFLEX_SINE {
            return Some(Fault::Concave);
        }
        winding += sine.atan2(dot(u, v));
    }
    // One full turn is 2π; a star winds 4π or more.
    (winding > 3.0 * std::f64::consts::PI).then_some(Fault::Concave)
}

/// A face's distinct corners in order (a corner repeated next to itself, or the first
/// repeated at the end, counts once) and its normal; None for a face of fewer than four
/// distinct corners (a triangle is always planar and convex) or one that cannot be judged.
pub(super) fn face_corners(
    g: &Checked,
    points: &Points,
    face: &Face,
) -> Option<(Vec<[f64; 3]>, [f64; 3])> {
    if face.len() < 4 {
        return None;
    }
    let normal = face_normal(g, points, face)?;
    let mut corners: Vec<[f64; 3]> = Vec::with_capacity(face.len());
    for position in face.corners() {
        let p = corner_point(g, points, position)?;
        if corners.last() != Some(&p) {
            corners.push(p);
        }
    }
    while corners.len() > 1 && corners.first() == corners.last() {
        corners.pop();
    }
    (corners.len() >= 4).then_some((corners, normal))
}

/// Whether a corner lies off the face's plane (through its first corner, normal to
/// `normal`) by more than [`PLANAR_TOLERANCE`] of the face's size, its longest distance
/// from the first corner; None for a face of no finite size.
pub(super) fn is_warped(corners: &[[f64; 3]], normal: [f64; 3]) -> Option<bool> {
    let origin = *corners.first()?;
    let size = corners
        .iter()
        .map(|&p| length(sub(p, origin)))
        .fold(0.0, f64::max);
    if !size.is_finite() || size == 0.0 {
        return None;
    }
    Some(
        corners
            .iter()
            .any(|&p| dot(sub(p, origin), normal).abs() > PLANAR_TOLERANCE * size),
    )
}
