//! DEGENERATE_TRIANGLE at the extremes of f32 coordinates: the decision is
//! scale-invariant (a triangle and its copies scaled by 2^±100 or translated far away
//! decide alike, bit for bit, while the coordinates stay exact), never fires on
//! well-shaped triangles however huge, tiny or far out their coordinates, always fires on
//! repeated or collinear vertices, and leaves triangles with a non-finite corner to
//! FIELD_VALUE_NONFINITE (no NaN from them, no count).

use proptest::prelude::*;
use x3dcheck::diagnostic::Level;
use x3dcheck::schema::Version;
use x3dcheck::validate::rendering::geometry::is_degenerate;

use crate::support::{check, document, has_non_finite_word, of, El, ENCODINGS};

type Point = [f32; 3];

fn decide(t: [Point; 3]) -> Option<bool> {
    let [a, b, c] = t.map(|p| p.map(f64::from));
    is_degenerate(a, b, c)
}

fn exact_scale(t: [Point; 3], k: i32) -> [Point; 3] {
    let s = 2f64.powi(k);
    t.map(|p| p.map(|c| (f64::from(c) * s) as f32))
}

fn exact_translate(t: [Point; 3], by: [f64; 3]) -> [Point; 3] {
    t.map(|p| std::array::from_fn(|i| (f64::from(p[i]) + by[i]) as f32))
}

/// Integer corners up to 2^20 (exact in f32 with room to translate), often close to
/// collinear: `c` is `a` plus a multiple of `b - a` plus a small offset, which puts the
/// sine of the angle at `a` around the 1e-6 threshold.
fn integer_triangle() -> impl Strategy<Value = [Point; 3]> {
    let coordinate = |n: i32| (-n..=n).prop_map(|x| x as f32);
    (
        prop::array::uniform3(coordinate(1 << 12)),
        prop::array::uniform3(coordinate(1 << 10)),
        -(1i32 << 9)..(1 << 9),
        prop::array::uniform3(coordinate(2)),
    )
        .prop_map(|(a, u, t, w)| {
            let b = std::array::from_fn(|i| a[i] + u[i]);
            let c = std::array::from_fn(|i| a[i] + t as f32 * u[i] + w[i]);
            [a, b, c]
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn the_decision_is_invariant_under_exact_scaling_and_translation(
        t in integer_triangle(),
        k in -100i32..=100,
        shift in prop::array::uniform3(-(1i64 << 22)..(1 << 22)),
    ) {
        let decision = decide(t);
        prop_assert!(decision.is_some());
        let by = shift.map(|s| s as f64);
        let moved = exact_translate(t, by);
        // Exact: every coordinate stays an integer below 2^24.
        prop_assert!(moved.iter().flatten().all(|c| c.abs() < (1 << 24) as f32));
        prop_assert_eq!(decide(exact_scale(t, k)), decision);
        prop_assert_eq!(decide(moved), decision);
        prop_assert_eq!(decide(exact_scale(moved, k)), decision);
    }
}

/// A triangle to write, with the decision it must get: Some(true) zero-area, Some(false)
/// not, None not judged (a non-finite corner).
#[derive(Clone, Debug)]
struct Written {
    coordinates: [[String; 3]; 3],
    expected: Option<bool>,
}

fn written(t: [Point; 3], expected: Option<bool>) -> Written {
    Written {
        coordinates: t.map(|p| p.map(|c| format!("{c:e}"))),
        expected,
    }
}

/// Corners on a circle with arcs of at least 0.5 between them (so every angle is at
/// least 0.25 rad), in a random plane, scaled by 2^k and moved by up to 2^10 times its
/// size: well-shaped at any scale f32 has, subnormal included.
fn well_shaped() -> impl Strategy<Value = [Point; 3]> {
    (
        0.0f64..std::f64::consts::TAU,
        0.5f64..2.5,
        0.5f64..2.5,
        prop::array::uniform3(-1.0f64..1.0),
        prop::array::uniform3(-1.0f64..1.0),
        -140i32..=116,
        prop::array::uniform3(-1024.0f64..1024.0),
    )
        .prop_filter_map(
            "a plane and arcs that leave room",
            |(start, arc1, arc2, u, v, k, shift)| {
                if arc1 + arc2 > std::f64::consts::TAU - 0.5 {
                    return None;
                }
                let (u, v) = orthonormal(u, v)?;
                let s = 2f64.powi(k);
                let corner = |angle: f64| -> Point {
                    std::array::from_fn(|i| {
                        ((angle.cos() * u[i] + angle.sin() * v[i] + shift[i]) * s) as f32
                    })
                };
                Some([
                    corner(start),
                    corner(start + arc1),
                    corner(start + arc1 + arc2),
                ])
            },
        )
}

fn orthonormal(u: [f64; 3], v: [f64; 3]) -> Option<([f64; 3], [f64; 3])> {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let norm = |a: [f64; 3]| dot(a, a).sqrt();
    let n = norm(u);
    if n < 0.1 {
        return None;
    }
    let u = u.map(|c| c / n);
    let d = dot(u, v);
    let w: [f64; 3] = std::array::from_fn(|i| v[i] - d * u[i]);
    let m = norm(w);
    (m >= 0.1).then(|| (u, w.map(|c| c / m)))
}

/// A well-shaped triangle blown up until its largest coordinate is near ±f32::MAX.
fn huge() -> impl Strategy<Value = [Point; 3]> {
    (well_shaped(), 0.5f64..1.0).prop_map(|(t, fill)| {
        let largest = t
            .iter()
            .flatten()
            .fold(0.0f64, |m, c| m.max(f64::from(*c).abs()));
        let s = fill * f64::from(f32::MAX) / largest;
        t.map(|p| p.map(|c| (f64::from(c) * s) as f32))
    })
}

/// `a`, `a + t1·d`, `a + t2·d` with small integers, times 2^k: exactly collinear.
fn collinear() -> impl Strategy<Value = [Point; 3]> {
    (
        prop::array::uniform3(-1024i32..=1024),
        prop::array::uniform3(-64i32..=64),
        -64i32..=64,
        -64i32..=64,
        -100i32..=100,
    )
        .prop_filter_map("a direction", |(a, d, t1, t2, k)| {
            if d == [0; 3] {
                return None;
            }
            let s = 2f64.powi(k);
            let point = |t: i32| -> Point {
                std::array::from_fn(|i| (f64::from(a[i] + t * d[i]) * s) as f32)
            };
            Some([point(0), point(t1), point(t2)])
        })
}

fn triangle() -> impl Strategy<Value = Written> {
    prop_oneof![
        3 => well_shaped().prop_map(|t| written(t, Some(false))),
        1 => huge().prop_map(|t| written(t, Some(false))),
        2 => collinear().prop_map(|t| written(t, Some(true))),
        1 => (well_shaped(), 0usize..3, 1usize..3).prop_map(|(mut t, i, step)| {
            t[(i + step) % 3] = t[i];
            written(t, Some(true))
        }),
        1 => (well_shaped(), 0usize..9, prop::sample::select(vec!["1e39", "-1e39", "3.4028236e38", "-1e400"]))
            .prop_map(|(t, at, text)| {
                let mut w = written(t, None);
                w.coordinates[at / 3][at % 3] = text.to_string();
                w
            }),
    ]
}

/// The geometry node kinds a triangle list is written as, with the stream position of
/// triangle n's first corner.
const GEOMETRIES: [(&str, usize); 3] = [
    ("TriangleSet", 3),
    ("IndexedTriangleSet", 3),
    ("IndexedFaceSet", 4),
];

fn geometry(kind: &'static str, triangles: &[Written]) -> El {
    let points: Vec<String> = triangles
        .iter()
        .flat_map(|t| t.coordinates.iter().flatten().cloned())
        .collect();
    let n = triangles.len();
    let node = El::new(kind);
    let node = match kind {
        "IndexedTriangleSet" => node.field("index", 0..3 * n),
        "IndexedFaceSet" => node.field(
            "coordIndex",
            (0..n).flat_map(|k| [3 * k as i64, 3 * k as i64 + 1, 3 * k as i64 + 2, -1]),
        ),
        _ => node,
    };
    El::new("Shape").child(
        "geometry",
        node.child("coord", El::new("Coordinate").field("point", points)),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn degenerate_triangles_are_counted_exactly(
        triangles in prop::collection::vec(triangle(), 1..8),
        kind in 0usize..3,
    ) {
        let (kind, stride) = GEOMETRIES[kind];
        let judged = triangles.iter().filter(|t| t.expected.is_some()).count();
        let degenerate: Vec<usize> = (0..triangles.len())
            .filter(|&k| triangles[k].expected == Some(true))
            .collect();
        for encoding in ENCODINGS {
            let source = document(encoding, Version::V4_0, &[geometry(kind, &triangles)]);
            let report = check(&source, Level::Deep);
            for d in &report.diagnostics {
                prop_assert!(!has_non_finite_word(&d.message), "{}", d.message);
            }
            let found = of(&report, "DEGENERATE_TRIANGLE");
            let Some(&first) = degenerate.first() else {
                prop_assert!(found.is_empty(), "{}", found[0].message);
                continue;
            };
            prop_assert_eq!(found.len(), 1);
            let d = found[0];
            let words: Vec<&str> = d.message.split_whitespace().collect();
            // "<Kind>: D of its T faces/triangles have zero area (first: face N, at …)"
            prop_assert_eq!(words[1].parse::<usize>().ok(), Some(degenerate.len()), "{}", d.message);
            prop_assert_eq!(words[4].parse::<usize>().ok(), Some(judged), "{}", d.message);
            prop_assert_eq!(d.count, degenerate.len());
            let number = format!("(first: {} {first},", if kind == "IndexedFaceSet" { "face" } else { "triangle" });
            prop_assert!(d.message.contains(&number), "{} lacks {}", d.message, number);
            prop_assert_eq!(d.index, Some(stride * first));
        }
    }
}

/// The corner cases by name, through the library function.
#[test]
fn named_extremes() {
    let max = f32::MAX;
    let tiny = f32::from_bits(1);
    let cases: &[([Point; 3], Option<bool>)] = &[
        (
            [[-max, -max, 0.0], [max, -max, 0.0], [0.0, max, 0.0]],
            Some(false),
        ),
        (
            [[-max, 0.0, 0.0], [max, 0.0, 0.0], [0.0, 0.0, 0.0]],
            Some(true),
        ),
        (
            [[-max, -max, -max], [max, max, max], [0.0, 0.0, 0.0]],
            Some(true),
        ),
        ([[0.0; 3], [tiny, 0.0, 0.0], [0.0, tiny, 0.0]], Some(false)),
        (
            [[0.0; 3], [tiny, 0.0, 0.0], [2.0 * tiny, 0.0, 0.0]],
            Some(true),
        ),
        ([[0.0; 3], [tiny, 0.0, 0.0], [0.0, 0.0, max]], Some(false)),
        ([[0.0; 3], [0.0; 3], [0.0; 3]], Some(true)),
        ([[-0.0, 0.0, -0.0], [0.0; 3], [1.0, 0.0, 0.0]], Some(true)),
        ([[f32::INFINITY, 0.0, 0.0], [0.0; 3], [1.0, 0.0, 0.0]], None),
        ([[f32::NAN, 0.0, 0.0], [0.0; 3], [1.0, 0.0, 0.0]], None),
        ([[0.0; 3], [f32::NEG_INFINITY; 3], [1.0, 0.0, 0.0]], None),
    ];
    for &(t, expected) in cases {
        assert_eq!(decide(t), expected, "{t:?}");
    }
}

/// Non-finite corners in a document (NaN and INF in XML): nothing judged, nothing NaN.
#[test]
fn non_finite_corners_in_a_document() {
    let source = "<X3D profile='Full' version='4.0'><Scene><Shape><TriangleSet>\
        <Coordinate point='NaN 0 0 1 0 0 0 1 0  INF 0 0 -INF 0 0 0 0 1  0 0 0 1 1 1 2 2 2'/>\
        </TriangleSet></Shape></Scene></X3D>";
    let report = check(source, Level::Deep);
    let found = of(&report, "DEGENERATE_TRIANGLE");
    assert_eq!(found.len(), 1);
    assert!(
        found[0]
            .message
            .starts_with("TriangleSet: 1 of its 1 triangles has zero area (first: triangle 2,"),
        "{}",
        found[0].message
    );
    assert_eq!(of(&report, "FIELD_VALUE_NONFINITE")[0].count, 3);
}
