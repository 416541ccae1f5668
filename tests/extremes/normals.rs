//! NORMAL_ZERO and NORMAL_NOT_UNIT on vectors at the extremes: components near f32::MAX
//! (whose squares overflow in f32), subnormal components (whose squares underflow in
//! f32), power-of-two scaled copies of unit vectors, zeros of either sign. NORMAL_ZERO
//! fires for true zero vectors only; NORMAL_NOT_UNIT is decided on the f64 length, which
//! is compared here with an independent one (in f64 the squares of f32 values neither
//! overflow nor underflow, so the plain formula is accurate to a few ulps), and exactly at
//! the tolerance: a length of exactly 1 ± tolerance passes, one ulp further does not.

use proptest::prelude::*;
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;
use x3dcheck::report::FileReport;
use x3dcheck::schema::Version;

use crate::support::{check_with, document, has_non_finite_word, of, El, Encoding, ENCODINGS};

/// A scene whose one face uses the first of `vectors` as its normal, all in one Normal.
fn scene(vectors: &[[String; 3]]) -> El {
    El::new("Shape").child(
        "geometry",
        El::new("IndexedFaceSet")
            .field("coordIndex", ["0", "1", "2", "-1"])
            .field("normalPerVertex", ["false"])
            .child(
                "coord",
                El::new("Coordinate").field("point", ["0", "0", "0", "1", "0", "0", "0", "1", "0"]),
            )
            .child(
                "normal",
                El::new("Normal").field("vector", vectors.concat()),
            ),
    )
}

fn deep(tolerance: f64) -> CheckConfig {
    CheckConfig {
        level: Level::Deep,
        fold: false,
        normal_tolerance: tolerance,
        ..CheckConfig::default()
    }
}

fn checked(encoding: Encoding, vectors: &[[String; 3]], tolerance: f64) -> (String, FileReport) {
    let source = document(encoding, Version::V4_0, &[scene(vectors)]);
    let report = check_with(&source, &deep(tolerance));
    (source, report)
}

fn indices(report: &FileReport, code: &str) -> Vec<usize> {
    of(report, code).iter().map(|d| d.index.unwrap()).collect()
}

/// The length of an f32 vector in f64, by the plain formula (exact squares: f32 values
/// squared stay far inside f64's range), to compare the rule's scaled computation with.
fn reference_length(v: [f32; 3]) -> f64 {
    v.iter()
        .map(|&c| f64::from(c) * f64::from(c))
        .sum::<f64>()
        .sqrt()
}

fn texts(v: [f32; 3]) -> [String; 3] {
    v.map(|c| format!("{c:e}"))
}

/// A direction rounded to f32, times 2^k (exact unless it leaves the normal range).
fn scaled_unit() -> impl Strategy<Value = [f32; 3]> {
    (prop::array::uniform3(-1.0f64..1.0), -160i32..130).prop_filter_map(
        "a direction that is not (nearly) zero, still finite when scaled",
        |(d, k)| {
            let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if n < 1e-3 {
                return None;
            }
            let v = d.map(|c| (c / n * 2f64.powi(k)) as f32);
            v.iter().all(|c| c.is_finite()).then_some(v)
        },
    )
}

fn signed_zero() -> impl Strategy<Value = f32> {
    prop_oneof![Just(0.0f32), Just(-0.0f32)]
}

fn near_max() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(f32::MAX),
        Just(-f32::MAX),
        Just(f32::MAX.next_down()),
        1e38f32..f32::MAX,
        -f32::MAX..-1e38f32,
        signed_zero(),
    ]
}

fn subnormal() -> impl Strategy<Value = f32> {
    prop_oneof![
        (1u32..0x0080_0000).prop_map(f32::from_bits),
        (1u32..0x0080_0000).prop_map(|b| -f32::from_bits(b)),
        Just(f32::from_bits(1)),
        signed_zero(),
    ]
}

fn finite_f32() -> impl Strategy<Value = f32> {
    any::<u32>()
        .prop_map(f32::from_bits)
        .prop_filter("finite", |x| x.is_finite())
}

fn vector() -> impl Strategy<Value = [f32; 3]> {
    prop_oneof![
        prop::array::uniform3(signed_zero()),
        scaled_unit(),
        prop::array::uniform3(near_max()),
        prop::array::uniform3(subnormal()),
        (near_max(), subnormal(), subnormal()).prop_map(|(a, b, c)| [a, b, c]),
        prop::array::uniform3(finite_f32()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn zero_only_for_zero_vectors_and_unit_decided_on_the_f64_length(
        vectors in prop::collection::vec(vector(), 1..8),
        tolerance in prop_oneof![Just(0.01f64), Just(1e-6), Just(0.5), 1e-9f64..0.9],
    ) {
        let written: Vec<[String; 3]> = vectors.iter().map(|v| texts(*v)).collect();
        for encoding in ENCODINGS {
            let (_, report) = checked(encoding, &written, tolerance);
            let zero: Vec<usize> = (0..vectors.len())
                .filter(|&k| vectors[k].iter().all(|&c| c == 0.0))
                .collect();
            prop_assert_eq!(indices(&report, "NORMAL_ZERO"), zero, "{:?}", encoding);
            let not_unit = indices(&report, "NORMAL_NOT_UNIT");
            for (k, v) in vectors.iter().enumerate() {
                let length = reference_length(*v);
                let off = (length - 1.0).abs() - tolerance;
                let margin = 1e-13 * (1.0 + length);
                let reported = not_unit.contains(&k);
                if length == 0.0 || off < -margin {
                    prop_assert!(!reported, "{:?} (length {:e}) reported", v, length);
                } else if off > margin {
                    prop_assert!(reported, "{:?} (length {:e}) not reported", v, length);
                }
            }
            for d in of(&report, "NORMAL_NOT_UNIT") {
                let k = d.index.unwrap();
                let printed = d.message.split("has length ").nth(1).and_then(|t| t.split(',').next()).unwrap();
                let printed: f64 = printed.parse().unwrap_or_else(|_| panic!("{:?}", d.message));
                let length = reference_length(vectors[k]);
                prop_assert!((printed - length).abs() <= 1e-6 * length, "{} for length {:e}", d.message, length);
            }
            for d in &report.diagnostics {
                prop_assert!(!has_non_finite_word(&d.message), "{}", d.message);
            }
        }
    }

    /// Exactly at the tolerance: |length − 1| = tolerance passes, one ulp further fails.
    /// Tolerances that are multiples of the f32 spacing near 1 make 1 ± tolerance an f32.
    #[test]
    fn the_tolerance_bound_is_exact(
        steps in 1u32..(1 << 22),
        axis in 0usize..3,
        negative in any::<bool>(),
        above in any::<bool>(),
    ) {
        let (tolerance, at, beyond) = if above {
            let t = f64::from(steps) * f64::from(f32::EPSILON);
            let at = (1.0 + t) as f32;
            (t, at, at.next_up())
        } else {
            let t = f64::from(steps) * f64::from(f32::EPSILON) / 2.0;
            let at = (1.0 - t) as f32;
            (t, at, at.next_down())
        };
        prop_assert_eq!((f64::from(at) - 1.0).abs(), tolerance);
        let vector = |length: f32| {
            let mut v = [0.0f32; 3];
            v[axis] = if negative { -length } else { length };
            texts(v)
        };
        for encoding in ENCODINGS {
            let (_, report) = checked(encoding, &[vector(at), vector(beyond)], tolerance);
            prop_assert_eq!(indices(&report, "NORMAL_NOT_UNIT"), vec![1]);
            prop_assert!(indices(&report, "NORMAL_ZERO").is_empty());
        }
    }
}

/// Lengths the f32 formula would get wrong: squares that overflow to ∞ or underflow to 0.
#[test]
fn lengths_that_overflow_or_underflow_in_f32() {
    let max = f32::MAX;
    let tiny = f32::from_bits(1);
    let cases: &[([f32; 3], bool, f64)] = &[
        ([max, max, max], false, f64::from(max) * 3f64.sqrt()),
        ([max, 0.0, 0.0], false, f64::from(max)),
        ([-max, 0.0, -0.0], false, f64::from(max)),
        ([tiny, 0.0, 0.0], false, f64::from(tiny)),
        ([tiny, tiny, tiny], false, f64::from(tiny) * 3f64.sqrt()),
        ([-0.0, 0.0, -0.0], true, 0.0),
        ([3e-30, 4e-30, 0.0], false, 5e-30),
        // Exact lengths from Pythagorean quadruples, scaled by powers of two.
        (
            [2f32.powi(-100), 2f32.powi(-99), 2f32.powi(-99)],
            false,
            3.0 * 2f64.powi(-100),
        ),
        (
            [
                2.0 * 2f32.powi(100),
                3.0 * 2f32.powi(100),
                6.0 * 2f32.powi(100),
            ],
            false,
            7.0 * 2f64.powi(100),
        ),
    ];
    for &(v, zero, length) in cases {
        for encoding in ENCODINGS {
            let (_, report) = checked(encoding, &[texts(v)], 0.01);
            assert_eq!(
                indices(&report, "NORMAL_ZERO").len(),
                usize::from(zero),
                "{v:?}"
            );
            let not_unit = of(&report, "NORMAL_NOT_UNIT");
            assert_eq!(not_unit.len(), usize::from(!zero), "{v:?}");
            if let Some(d) = not_unit.first() {
                let printed = d
                    .message
                    .split("has length ")
                    .nth(1)
                    .and_then(|t| t.split(',').next())
                    .unwrap();
                let printed: f64 = printed.parse().unwrap();
                assert!(
                    (printed - length).abs() <= 1e-6 * length,
                    "{v:?}: {}",
                    d.message
                );
            }
        }
    }
}

/// Vectors with a non-finite component are FIELD_VALUE_NONFINITE's, not judged here.
#[test]
fn non_finite_vectors_are_left_to_field_value_nonfinite() {
    let vectors: Vec<[String; 3]> = [
        ["1e39", "0", "0"],
        ["0", "-3.4028236e38", "0"],
        ["0", "0", "0"],
        ["NaN", "0", "0"],
        ["INF", "-INF", "0"],
        ["0", "0", "2"],
    ]
    .iter()
    .map(|v| v.map(String::from))
    .collect();
    let (source, report) = checked(Encoding::Xml, &vectors, 0.01);
    assert_eq!(indices(&report, "NORMAL_ZERO"), vec![2], "{source}");
    assert_eq!(indices(&report, "NORMAL_NOT_UNIT"), vec![5]);
    let nonfinite = of(&report, "FIELD_VALUE_NONFINITE");
    assert_eq!(nonfinite.len(), 1);
    assert_eq!(nonfinite[0].count, 5);
    let json: Vec<[String; 3]> = vectors[..3].to_vec();
    let (_, report) = checked(Encoding::Json, &json, 0.01);
    assert_eq!(indices(&report, "NORMAL_ZERO"), vec![2]);
    assert!(indices(&report, "NORMAL_NOT_UNIT").is_empty());
}
