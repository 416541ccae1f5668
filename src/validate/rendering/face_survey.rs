//! One walk over the faces of every polygonal geometry for the three deep rules that
//! judge faces, DEGENERATE_TRIANGLE, NORMALS_CONTRADICT_CCW and FACE_SELF_INTERSECTING:
//! each face's corners are resolved and its fan's cross products taken once for all, and
//! the walk is made once ([`crate::validate::Ctx::face_survey`]) whichever of them asks
//! first. The faces of a large mesh are most of a deep check's work on it.
//!
//! The rules read what the walk found; the walk does not know the rules (which of them run
//! is handed to it as [`Wanted`]), so the imports go one way.

use std::ops::Range;

use super::face_crossing::{self_crossing, Crossing, Scratch};
use super::geometry::{
    attribute_lists, corner_point, cross, dot, finite, is_degenerate, judge_polygonal, scaled, sub,
    unit, Checked, FaceShape, Points, PropertyList, Scalars, DEGENERATE_SINE,
};
use crate::model::faces::{counted_runs, runs, Attribute, Binding, Face, PolygonKind};
use crate::model::{Document, Span, Value};

/// Which findings the walk is to make: those of the rules that run.
#[derive(Copy, Clone, Default)]
pub struct Wanted {
    /// DEGENERATE_TRIANGLE's.
    pub degenerate: bool,
    /// NORMALS_CONTRADICT_CCW's.
    pub normals: bool,
    /// FACE_SELF_INTERSECTING's.
    pub crossing: bool,
}

/// What the walk found in one geometry, for each rule that asked.
pub struct Survey {
    pub degenerate: Option<DegenerateCount>,
    pub normals: Option<NormalsCount>,
    /// Only for IndexedFaceSets.
    pub crossing: Option<CrossingCount>,
}

/// DEGENERATE_TRIANGLE: the first zero-area face (or strip, or fan) as its number and
/// stream position, and how many there are of how many.
#[derive(Default)]
pub struct DegenerateCount {
    pub first: Option<(usize, usize)>,
    pub degenerate: usize,
    pub total: usize,
}

impl DegenerateCount {
    fn add(&mut self, number: usize, position: usize, degenerate: bool) {
        self.total += 1;
        if degenerate {
            self.degenerate += 1;
            self.first.get_or_insert((number, position));
        }
    }
}

/// NORMALS_CONTRADICT_CCW: where the Normal node stands, and how many judged faces its
/// normals agree with (positive dot product with the geometric normal, ccw applied) and
/// contradict (negative).
pub struct NormalsCount {
    pub normals_span: Span,
    pub agree: usize,
    pub contradict: usize,
}

/// FACE_SELF_INTERSECTING: the first face whose edges cross (its number, its first
/// corner's stream position, the two edges), how many faces cross, of how many.
#[derive(Default)]
pub struct CrossingCount {
    pub first: Option<(usize, usize, Crossing)>,
    pub crossing: usize,
    pub total: usize,
}

/// Every polygonal geometry of [`judge_polygonal`] whose points can be judged, with what
/// the walk finds in it for the rules that want it, in document order.
pub fn survey<'a>(doc: &'a Document, wanted: Wanted) -> Vec<(Checked<'a>, Survey)> {
    judge_polygonal(doc, |geometry| survey_one(doc, geometry, wanted))
}

fn survey_one(doc: &Document, geometry: &Checked, wanted: Wanted) -> Option<Survey> {
    let points = Points::of(doc, geometry)?;
    let by_runs = counts_runs(geometry.faces.kind);
    let mut degenerate = wanted.degenerate.then(DegenerateCount::default);
    if let (true, Some(count)) = (by_runs, degenerate.as_mut()) {
        let fan = matches!(
            geometry.faces.kind,
            PolygonKind::IndexedTriangleFanSet | PolygonKind::TriangleFanSet
        );
        for (number, run) in strip_runs(geometry).enumerate() {
            if let Some(zero) = run_is_degenerate(geometry, &points, run.clone(), fan) {
                count.add(number, run.start, zero);
            }
        }
    }
    let normal_lists = wanted
        .normals
        .then(|| attribute_lists(doc, geometry.id, Attribute::Normal))
        .flatten();
    let normals = match normal_lists.as_deref() {
        Some([list]) => Some(*list),
        _ => None,
    };
    let mut agreement = normals.map(|list| NormalsCount {
        normals_span: list.child_span,
        agree: 0,
        contradict: 0,
    });
    let mut crossing = (wanted.crossing && geometry.faces.kind == PolygonKind::IndexedFaceSet)
        .then(CrossingCount::default);
    let per_face = degenerate.as_mut().filter(|_| !by_runs);
    if per_face.is_some() || agreement.is_some() || crossing.is_some() {
        let found = Found {
            degenerate: per_face,
            normals: normals.zip(agreement.as_mut()),
            crossing: crossing.as_mut(),
        };
        walk_faces(geometry, &points, found);
    }
    Some(Survey {
        degenerate,
        normals: agreement,
        crossing,
    })
}

/// The counts a walk over faces adds to, for the rules that asked.
struct Found<'c, 'a> {
    degenerate: Option<&'c mut DegenerateCount>,
    normals: Option<(PropertyList<'a>, &'c mut NormalsCount)>,
    crossing: Option<&'c mut CrossingCount>,
}

/// Counts zero-area faces, the faces the normals agree and disagree with, and the faces
/// that cross themselves into `found`, resolving each face once.
fn walk_faces(geometry: &Checked, points: &Points, found: Found) {
    // The usual mesh, an index list into single-precision coordinates, has its corners
    // looked up directly rather than through the general stream and point kinds.
    // So are its per-vertex normals when they follow the coordinate index.
    let binding = geometry.faces.binding(Attribute::Normal);
    let bound = |face: &Face, position| geometry.faces.bound_index(binding, face, position);
    match (geometry.faces.indices(), points) {
        (Some(indices), Points::List(Scalars::Single(values)))
            if geometry.faces.kind == PolygonKind::IndexedTriangleSet
                && (found.normals.is_none() || binding == (Binding::PerVertex { index: None })) =>
        {
            walk_triangles(geometry, indices, values, found.degenerate, found.normals)
        }
        (Some(indices), Points::List(Scalars::Single(values))) => {
            let values = Scalars::Single(values);
            let coord_index = |position| usize::try_from(*indices.get(position)?).ok();
            let by_coord = binding == (Binding::PerVertex { index: None });
            walk_faces_with(
                geometry,
                found,
                |position| finite(values.vec3(coord_index(position)?)?),
                |face, position| {
                    if by_coord {
                        coord_index(position)
                    } else {
                        bound(face, position)
                    }
                },
            )
        }
        _ => walk_faces_with(
            geometry,
            found,
            |position| corner_point(geometry, points, position),
            bound,
        ),
    }
}

/// [`walk_faces`] with each corner's point given by `corner` and its normal's index by
/// `normal_index` (from the face and the corner's stream position).
fn walk_faces_with(
    geometry: &Checked,
    found: Found,
    corner: impl Fn(usize) -> Option<[f64; 3]>,
    normal_index: impl Fn(&Face, usize) -> Option<usize>,
) {
    let Found {
        mut degenerate,
        mut normals,
        mut crossing,
    } = found;
    let binding = geometry.faces.binding(Attribute::Normal);
    let units = normals
        .as_ref()
        .map(|(list, _)| UnitNormals::of(list, binding, geometry.faces.stream_len()));
    let mut scratch = Scratch::default();
    for face in geometry.faces.faces() {
        let shape = FaceShape::with(&face, &corner);
        if let (Some(count), Some(zero)) = (degenerate.as_deref_mut(), shape.degenerate) {
            count.add(face.number, face.corner(0), zero);
        }
        if let Some(count) = crossing.as_deref_mut() {
            count.total += 1;
            // A face of three corners cannot cross itself; one with a corner that does
            // not resolve, or of zero area, is other rules' finding.
            if face.len() >= 4 && shape.degenerate == Some(false) {
                // The corners resolved for the shape, so `flat_map` drops none.
                let corners = face.corners().flat_map(&corner);
                if let Some(edges) = self_crossing(corners, &mut scratch) {
                    count.crossing += 1;
                    // The crossing edges as stream positions, from positions in the face.
                    let at = |(a, b): (usize, usize)| (face.corner(a), face.corner(b));
                    let edges = Crossing {
                        first: at(edges.first),
                        second: at(edges.second),
                    };
                    count
                        .first
                        .get_or_insert((face.number, face.corner(0), edges));
                }
            }
        }
        let (Some((_, count)), Some(units)) = (normals.as_mut(), units.as_ref()) else {
            continue;
        };
        let Some(geometric) = shape.normal() else {
            continue;
        };
        let Some(supplied) = supplied_normal(binding, units, &face, &normal_index) else {
            continue;
        };
        let d = dot(geometric, supplied);
        let d = if geometry.faces.ccw { d } else { -d };
        if d > 0.0 {
            count.agree += 1;
        } else if d < 0.0 {
            count.contradict += 1;
        }
    }
}

/// [`walk_faces_with`] for the most common mesh, an IndexedTriangleSet over
/// single-precision coordinates with any normals per vertex by the coordinate index: face
/// `k` is `indices[3k..3k + 3]`, read straight from the list rather than through
/// [`Face`]s and the general corner look-ups, with the same findings.
///
/// Coordinates read as f32 are exact in f64, and so are their differences: a nonzero
/// difference lies within [`UNSCALED`](super::geometry::UNSCALED) (f32 steps are at least
/// 2^-149, and no difference reaches 2^129), so [`FaceShape`]'s degeneracy test is the
/// plain one below; for a zero edge both give "degenerate". Nothing here overflows or underflows: squared lengths and
/// cross products stay between 2^-700 and 2^600. The normal's length and the division by
/// it only decide the sign of the dot product, so a face whose unnormalized dot product is
/// far from zero (against its rounding error) is counted by that sign, and only the rest
/// take [`FaceShape::normal`]'s exact path.
fn walk_triangles(
    geometry: &Checked,
    indices: &[i32],
    values: &[f32],
    degenerate: Option<&mut DegenerateCount>,
    normals: Option<(PropertyList, &mut NormalsCount)>,
) {
    let (points, _) = values.as_chunks::<3>();
    let (count, units) = match normals {
        Some((list, count)) => (
            Some(count),
            Some(UnitNormals::of(
                &list,
                Binding::PerVertex { index: None },
                geometry.faces.stream_len(),
            )),
        ),
        None => (None, None),
    };
    let normals = count.zip(units.as_ref());
    let ccw = geometry.faces.ccw;
    // One pass that vectorizes spares the corners their finiteness tests when, as usual,
    // every coordinate is finite.
    if values.iter().fold(true, |all, v| all & v.is_finite()) {
        triangles::<true>(points, indices, ccw, degenerate, normals)
    } else {
        triangles::<false>(points, indices, ccw, degenerate, normals)
    }
}

/// [`walk_triangles`]'s loop; `FINITE`: every point is known to be finite.
fn triangles<const FINITE: bool>(
    points: &[[f32; 3]],
    indices: &[i32],
    ccw: bool,
    mut degenerate: Option<&mut DegenerateCount>,
    mut normals: Option<(&mut NormalsCount, &UnitNormals)>,
) {
    let point = |index: usize| {
        let p = points.get(index)?.map(f64::from);
        if FINITE {
            Some(p)
        } else {
            finite(p)
        }
    };
    for (number, corners) in indices.chunks_exact(3).enumerate() {
        let vertex = |k: usize| usize::try_from(corners[k]).ok();
        let resolve = || Some((point(vertex(0)?)?, point(vertex(1)?)?, point(vertex(2)?)?));
        let Some((a, b, c)) = resolve() else {
            continue;
        };
        let (e1, e2) = (sub(b, a), sub(c, a));
        let n = cross(e1, e2);
        let squared = dot(n, n);
        let bound = DEGENERATE_SINE * DEGENERATE_SINE * dot(e1, e1) * dot(e2, e2);
        let zero = squared <= bound;
        if let Some(count) = degenerate.as_deref_mut() {
            count.add(number, 3 * number, zero);
        }
        let (Some((count, units)), false) = (normals.as_mut(), zero) else {
            continue;
        };
        // The corners resolved, so their indices are not negative.
        let mut supplied = [0.0; 3];
        let mut resolved = true;
        for k in 0..3 {
            let Some(u) = vertex(k).and_then(|i| units.get(i)) else {
                resolved = false;
                break;
            };
            for (s, c) in supplied.iter_mut().zip(u) {
                *s += c;
            }
        }
        // Unit vectors are finite, and so is a sum of three: `scaled` refuses it exactly
        // when it is zero.
        if !resolved || supplied == [0.0; 3] {
            continue;
        }
        let d = dot(n, supplied);
        let magnitude: f64 = n.iter().zip(supplied).map(|(x, y)| (x * y).abs()).sum();
        let sure = squared > bound * (1.0 + SURE)
            && d.abs() > SURE * magnitude
            && magnitude > SURE_MAGNITUDE;
        let d = if sure {
            d
        } else {
            let normal = resolve().and_then(|(a, b, c)| FaceShape::triangle(a, b, c).normal());
            match normal {
                Some(geometric) => dot(geometric, supplied),
                None => continue,
            }
        };
        let d = if ccw { d } else { -d };
        if d > 0.0 {
            count.agree += 1;
        } else if d < 0.0 {
            count.contradict += 1;
        }
    }
}

/// The relative margin past which [`walk_triangles`] trusts its shortcuts: a face not
/// degenerate by more than this has a normal ([`FaceShape::normal`]'s length test errs
/// by a few units of 2^-53), and an unnormalized dot product larger than this part of the
/// sum of its terms' magnitudes has the normalized one's sign (each errs by less than
/// 2^-49 of that sum).
const SURE: f64 = 1.0 / (1u64 << 40) as f64;

/// Below this sum of magnitudes, underflow could blur the sign: take the exact path.
const SURE_MAGNITUDE: f64 = 1e-200;

/// The face's supplied normal direction (not normalized: only the sign of its dot product
/// with the geometric normal is used): its per-face normal, or the sum of its corners'
/// unit normals; None where an index or a normal is missing or zero, or the sum is zero.
#[inline]
fn supplied_normal(
    binding: Binding,
    normals: &UnitNormals,
    face: &Face,
    normal_index: impl Fn(&Face, usize) -> Option<usize>,
) -> Option<[f64; 3]> {
    let per_face = matches!(binding, Binding::PerFace { .. });
    let mut sum = [0.0; 3];
    for position in face.corners() {
        let index = normal_index(face, position)?;
        let n = normals.get(index)?;
        for (s, c) in sum.iter_mut().zip(n) {
            *s += c;
        }
        if per_face {
            break;
        }
    }
    scaled(sum).map(|_| sum)
}

/// The unit vectors of a Normal node's list. Per-vertex normals are each shared by the
/// faces around their vertex (about six in a triangle mesh), so they are normalized once
/// beforehand, unless the list is longer than the vertex stream that can use them.
enum UnitNormals<'a> {
    Computed(Vec<Option<[f64; 3]>>),
    OnDemand(Scalars<'a>),
}

impl<'a> UnitNormals<'a> {
    fn of(list: &PropertyList<'a>, binding: Binding, stream_len: usize) -> UnitNormals<'a> {
        if !matches!(binding, Binding::PerVertex { .. }) || list.len > stream_len {
            return UnitNormals::OnDemand(list.values);
        }
        UnitNormals::Computed(match list.values {
            // A list's length is its whole vectors: the chunks are its vectors.
            // A nonzero finite f32 vector needs no scaling: `unit` is the division below.
            Scalars::Single(values) => values
                .chunks_exact(3)
                .map(|c| {
                    let v = [c[0], c[1], c[2]].map(f64::from);
                    let squared = dot(v, v);
                    let finite = c.iter().all(|x| x.is_finite());
                    (finite && squared > 0.0).then(|| v.map(|x| x / squared.sqrt()))
                })
                .collect(),
            Scalars::Double(values) => values
                .chunks_exact(3)
                .map(|c| unit([c[0], c[1], c[2]]))
                .collect(),
        })
    }

    /// The unit vector of normal `i`; None past the end and for zero or non-finite ones.
    fn get(&self, i: usize) -> Option<[f64; 3]> {
        match self {
            UnitNormals::Computed(units) => *units.get(i)?,
            UnitNormals::OnDemand(values) => unit(values.vec3(i)?),
        }
    }
}

/// Whether the geometry is judged per strip or fan rather than per face.
pub fn counts_runs(kind: PolygonKind) -> bool {
    matches!(
        kind,
        PolygonKind::IndexedTriangleStripSet
            | PolygonKind::TriangleStripSet
            | PolygonKind::IndexedTriangleFanSet
            | PolygonKind::TriangleFanSet
    )
}

/// The strips or fans of a strip or fan set, as stream positions.
fn strip_runs<'a>(geometry: &'a Checked) -> Box<dyn Iterator<Item = Range<usize>> + 'a> {
    match geometry.faces.kind.index_field() {
        Some(field) => Box::new(runs(
            geometry
                .node
                .value(field)
                .and_then(Value::as_int32s)
                .unwrap_or(&[]),
        )),
        None => {
            let field = geometry.faces.kind.count_field().unwrap_or_default();
            let counts = geometry
                .node
                .value(field)
                .and_then(Value::as_int32s)
                .unwrap_or(&[]);
            Box::new(counted_runs(counts, geometry.faces.stream_len()))
        }
    }
}

/// Whether every triangle of a strip or fan is zero-area; None when too short to be
/// judged (other rules report that) or a vertex does not resolve.
fn run_is_degenerate(
    geometry: &Checked,
    points: &Points,
    run: Range<usize>,
    fan: bool,
) -> Option<bool> {
    if run.len() < 3 {
        return None;
    }
    let point = |p| corner_point(geometry, points, p);
    let mut degenerate = true;
    for k in 0..run.len() - 2 {
        let s = run.start;
        let a = if fan { s } else { s + k };
        degenerate &= is_degenerate(point(a)?, point(s + k + 1)?, point(s + k + 2)?)?;
    }
    Some(degenerate)
}
