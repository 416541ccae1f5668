//! Number text at the extremes, read by both readers into the model and judged by the
//! fast rules: the value stored is the correctly rounded one at the field's precision
//! (f32 for SFFloat-based types, f64 for SFDouble/SFTime, exact integers for SFInt32),
//! the same in XML and JSON, and the decision follows from that value alone.
//!
//! The decision for text that overflows the field's precision (`1e39` in an SFFloat,
//! `1e400` in an SFDouble): 5.3.4 and 5.3.2 make SFFloat and SFDouble IEEE 754 single and
//! double precision values, and RULES.md compares values "after rounding to f32 / f64"; a
//! number beyond the largest finite value rounds to infinity, which is no X3D value, so it
//! is FIELD_VALUE_NONFINITE, like `INF`. It is also FIELD_OUT_OF_RANGE exactly when the
//! field's range has a finite bound on that side (∞ lies in `[0,∞)` but not in `[0,1]`),
//! as NaN is ("NaN is never in range"). Text below half the smallest subnormal rounds to
//! a zero of its sign: a number, finite, judged as 0 (and -0 equals 0).

use proptest::prelude::*;
use x3dcheck::diagnostic::Level;
use x3dcheck::model::Value;
use x3dcheck::schema::{schema, Version};

use crate::support::{
    check, document, is_json_number, of, read, value_of, El, Encoding, ENCODINGS,
};

/// SFFloat and MFVec3f fields without a range, so that only the number itself is judged.
const SF_FLOAT: (&str, &str) = ("TextureTransform", "rotation");
const MF_FLOAT: (&str, &str) = ("Coordinate", "point");
const SF_DOUBLE: (&str, &str) = ("TimeSensor", "startTime");
const MF_DOUBLE: (&str, &str) = ("CoordinateDouble", "point");
const SF_INT: (&str, &str) = ("IntegerTrigger", "integerKey");
const MF_INT: (&str, &str) = ("MetadataInteger", "value");

fn assert_unbounded((node, field): (&str, &str)) {
    for version in Version::X3D {
        if let Some(def) = schema(version).node(node).and_then(|n| n.field(field)) {
            assert!(
                def.min.is_none() && def.max.is_none(),
                "{node}.{field} has a range in {version}: pick another field"
            );
        }
    }
}

/// The filler around the probed element of an MF value, and where the probe goes.
const FILLER: &str = "0.5";
const PROBE_AT: usize = 4;

/// One reading of a text: where it went, what the model stored (widened to f64, which is
/// exact for f32 and keeps the sign of zero), and what the fast rules said.
struct Reading {
    place: String,
    index: usize,
    stored: Option<f64>,
    nonfinite: Vec<Option<usize>>,
    syntax: usize,
}

/// Reads `text` as the whole SF value of `sf` and as element `PROBE_AT` of the MF value of
/// `mf`, in every encoding where it is a number.
fn readings(
    text: &str,
    sf: (&'static str, &'static str),
    mf: (&'static str, &'static str),
    get: impl Fn(&Value, usize) -> Option<f64>,
) -> Vec<Reading> {
    let mut out = Vec::new();
    for encoding in ENCODINGS {
        if encoding == Encoding::Json && !is_json_number(text) {
            continue;
        }
        for is_mf in [false, true] {
            let (node, field) = if is_mf { mf } else { sf };
            let (tokens, index) = if is_mf {
                let mut t = vec![FILLER.to_string(); 9];
                t[PROBE_AT] = text.to_string();
                (t, PROBE_AT)
            } else {
                (vec![text.to_string()], 0)
            };
            let source = document(
                encoding,
                Version::V4_0,
                &[El::new(node).field(field, tokens)],
            );
            let doc = read(&source);
            let report = check(&source, Level::Fast);
            out.push(Reading {
                place: format!("{text:?} in {encoding:?} {node}.{field}"),
                index,
                stored: value_of(&doc, node, field).and_then(|v| get(v, index)),
                nonfinite: of(&report, "FIELD_VALUE_NONFINITE")
                    .iter()
                    .map(|d| d.index)
                    .collect(),
                syntax: of(&report, "FIELD_VALUE_SYNTAX").len(),
            });
        }
    }
    out
}

/// Checks that every reading of `text` stored `expected` (bit for bit, or NaN) and was
/// reported non-finite exactly when it is, at the right element.
fn expect(readings: Vec<Reading>, expected: f64) {
    for r in readings {
        let place = &r.place;
        assert_eq!(r.syntax, 0, "{place}: FIELD_VALUE_SYNTAX");
        let stored = r.stored.unwrap_or_else(|| panic!("{place}: not stored"));
        assert!(
            stored.to_bits() == expected.to_bits() || stored.is_nan() && expected.is_nan(),
            "{place}: stored {stored:e}, expected {expected:e}"
        );
        let reports = if expected.is_finite() {
            vec![]
        } else {
            vec![Some(r.index)]
        };
        assert_eq!(r.nonfinite, reports, "{place}: FIELD_VALUE_NONFINITE");
    }
}

/// `text` in an SFFloat and an MFVec3f.
fn expect_f32(text: &str, expected: f32) {
    let get = |v: &Value, i: usize| v.as_floats()?.get(i).map(|x| f64::from(*x));
    expect(readings(text, SF_FLOAT, MF_FLOAT, get), f64::from(expected));
}

/// `text` in an SFTime and an MFVec3d.
fn expect_f64(text: &str, expected: f64) {
    let get = |v: &Value, i: usize| v.as_doubles()?.get(i).copied();
    expect(readings(text, SF_DOUBLE, MF_DOUBLE, get), expected);
}

#[test]
fn the_probe_fields_have_no_range() {
    for probe in [SF_FLOAT, MF_FLOAT, SF_DOUBLE, MF_DOUBLE, SF_INT, MF_INT] {
        assert_unbounded(probe);
    }
}

#[test]
fn single_precision_text_at_the_extremes() {
    let smallest = f32::from_bits(1);
    let cases: &[(&str, f32)] = &[
        ("3.4028235e38", f32::MAX),
        ("-3.4028235e38", -f32::MAX),
        ("340282346638528859811704183484516925440", f32::MAX),
        // The midpoint between f32::MAX and 2^128 rounds to even: to 2^128, that is ∞.
        ("340282356779733661637539395458142568447", f32::MAX),
        ("340282356779733661637539395458142568448", f32::INFINITY),
        ("3.4028235677973366e38", f32::MAX),
        ("3.4028235677973367e38", f32::INFINITY),
        ("-3.4028235677973367e38", f32::NEG_INFINITY),
        ("3.4028236e38", f32::INFINITY),
        ("1e39", f32::INFINITY),
        ("1e400", f32::INFINITY),
        ("-1e400", f32::NEG_INFINITY),
        ("1E+99999999999999999999", f32::INFINITY),
        ("1e-400", 0.0),
        ("-1e-400", -0.0),
        ("1e-99999999999999999999", 0.0),
        ("1.17549435e-38", f32::MIN_POSITIVE),
        ("1.1754942e-38", f32::from_bits(0x007f_ffff)),
        ("1.401298464324817e-45", smallest),
        ("1e-45", smallest),
        ("-1e-45", -smallest),
        // Half the smallest subnormal, 2^-150, exactly: a tie, to even (zero).
        (
            "7.00649232162408535461864791644958065640130970938257885878534141944895541342930300743319094181060791015625e-46",
            0.0,
        ),
        (
            "7.006492321624085354618647916449580656401309709382578858785341419448955413429303007433190941810607910156251e-46",
            smallest,
        ),
        ("7e-46", 0.0),
        ("-0", -0.0),
        ("-0.0", -0.0),
        ("-0e0", -0.0),
        ("0e999999", 0.0),
        ("0.0000000000000000000000000000000000000000000000000", 0.0),
        ("1.00000001", 1.0),
        ("1.0000001", 1.0000001),
        ("0.99999997", 0.99999994),
        ("NaN", f32::NAN),
        ("INF", f32::INFINITY),
        ("-INF", f32::NEG_INFINITY),
    ];
    for &(text, expected) in cases {
        expect_f32(text, expected);
    }
}

#[test]
fn double_precision_text_at_the_extremes() {
    let smallest = f64::from_bits(1);
    let cases: &[(&str, f64)] = &[
        ("1.7976931348623157e308", f64::MAX),
        ("-1.7976931348623157e308", -f64::MAX),
        ("1.7976931348623158e308", f64::MAX),
        ("1.7976931348623159e308", f64::INFINITY),
        ("1e309", f64::INFINITY),
        ("-1e400", f64::NEG_INFINITY),
        ("3.4028236e38", 3.4028236e38),
        ("1e39", 1e39),
        ("1e-46", 1e-46),
        ("4.9e-324", smallest),
        ("5e-324", smallest),
        ("-5e-324", -smallest),
        // Half the smallest subnormal is 2.4703282292062327208…e-324.
        ("2.4703282292062327e-324", 0.0),
        ("2.4703282292062328e-324", smallest),
        ("-2.4703282292062328e-324", -smallest),
        ("2.2250738585072014e-308", f64::MIN_POSITIVE),
        ("1e-400", 0.0),
        ("-1e-400", -0.0),
        ("-0", -0.0),
        ("NaN", f64::NAN),
        ("-INF", f64::NEG_INFINITY),
    ];
    for &(text, expected) in cases {
        expect_f64(text, expected);
    }
}

#[test]
fn long_digit_strings() {
    let ones = "1".repeat(400);
    expect_f32(&ones, f32::INFINITY);
    expect_f64(&ones, f64::INFINITY);
    let tiny = format!("0.{}1", "0".repeat(400));
    expect_f32(&tiny, 0.0);
    expect_f64(&tiny, 0.0);
    let one = format!("1.{}", "0".repeat(400));
    expect_f32(&one, 1.0);
    expect_f64(&one, 1.0);
    // 1 + 2^-24 (the midpoint above 1.0 in f32) followed by many zeros and a final 1:
    // above the midpoint, so it rounds up, which a conversion through f64 gets wrong.
    let above = format!("1.000000059604644775390625{}1", "0".repeat(300));
    expect_f32(&above, 1.0 + f32::EPSILON);
    let max_digits = format!(
        "340282346638528859811704183484516925440.{}",
        "0".repeat(300)
    );
    expect_f32(&max_digits, f32::MAX);
    let fraction = format!("0.{}", "9".repeat(500));
    expect_f32(&fraction, 1.0);
    expect_f64(&fraction, 1.0);
}

/// `(text, value in XML, value in JSON)`; None: FIELD_VALUE_SYNTAX and nothing stored.
#[test]
fn int32_text_at_the_extremes() {
    let cases: &[(&str, Option<i32>, Option<i32>)] = &[
        ("2147483647", Some(i32::MAX), Some(i32::MAX)),
        ("-2147483648", Some(i32::MIN), Some(i32::MIN)),
        ("2147483648", None, None),
        ("-2147483649", None, None),
        ("99999999999999999999999", None, None),
        ("-0", Some(0), Some(0)),
        ("0x7FFFFFFF", Some(i32::MAX), None),
        ("0x80000000", None, None),
        ("-0x80000000", Some(i32::MIN), None),
        // JSON numbers are numbers: a whole value in any notation is an SFInt32.
        ("2147483647.0", None, Some(i32::MAX)),
        ("2.147483647e9", None, Some(i32::MAX)),
        ("-2.147483648E+9", None, Some(i32::MIN)),
        ("2.147483648e9", None, None),
        ("1e400", None, None),
        ("1e-400", None, None),
        ("2147483646.5", None, None),
        // Not whole, though the nearest f64 is: decided on the text, not on a rounding.
        ("2147483647.0000000001", None, None),
        ("1.00000000000000000001", None, None),
        ("-2147483648.00000000000000000001", None, None),
        ("1234567891e-1", None, None),
        ("21474836470e-1", None, Some(i32::MAX)),
    ];
    let one = format!("0.{}1e52", "0".repeat(51));
    let cases = [cases, &[(one.as_str(), None, Some(1))]].concat();
    for &(text, xml, json) in &cases {
        for (encoding, expected) in [(Encoding::Xml, xml), (Encoding::Json, json)] {
            if encoding == Encoding::Json && !is_json_number(text) {
                continue;
            }
            for mf in [false, true] {
                let (node, field) = if mf { MF_INT } else { SF_INT };
                let tokens: Vec<String> = if mf {
                    let mut t = vec!["7".to_string(); 6];
                    t[PROBE_AT] = text.to_string();
                    t
                } else {
                    vec![text.to_string()]
                };
                let source = document(
                    encoding,
                    Version::V4_0,
                    &[El::new(node).field(field, tokens)],
                );
                let place = format!("{text:?} in {encoding:?} (MF: {mf})");
                let report = check(&source, Level::Fast);
                let syntax = of(&report, "FIELD_VALUE_SYNTAX");
                let doc = read(&source);
                let stored = value_of(&doc, node, field)
                    .and_then(Value::as_int32s)
                    .map(|v| v[if mf { PROBE_AT } else { 0 }]);
                match expected {
                    Some(v) => {
                        assert!(syntax.is_empty(), "{place}: {:?}", syntax[0].message);
                        assert_eq!(stored, Some(v), "{place}");
                    }
                    None => {
                        assert_eq!(syntax.len(), 1, "{place}: no FIELD_VALUE_SYNTAX");
                        assert_eq!(stored, None, "{place}: a value was stored");
                        // Pointing at the token, in an MF value among its neighbours.
                        assert_eq!(&source[syntax[0].span.range()], text, "{place}");
                    }
                }
            }
        }
    }
}

/// A field's range decides on the rounded value: overflow is FIELD_VALUE_NONFINITE, and
/// FIELD_OUT_OF_RANGE too where the range has a finite bound on that side; underflow is
/// a zero, in or out of range as zero is.
#[test]
fn overflow_and_underflow_against_ranges() {
    // (version, node, field, text, nonfinite, out of range)
    let cases: &[(Version, &str, &str, &str, bool, bool)] = &[
        (
            Version::V4_0,
            "Material",
            "transparency",
            "1e39",
            true,
            true,
        ),
        (
            Version::V4_0,
            "Material",
            "transparency",
            "-1e39",
            true,
            true,
        ),
        (Version::V4_0, "Material", "transparency", "NaN", true, true),
        (
            Version::V4_0,
            "Material",
            "transparency",
            "-1e-46",
            false,
            false,
        ),
        (
            Version::V4_0,
            "Material",
            "transparency",
            "1.00000001",
            false,
            false,
        ),
        (
            Version::V4_0,
            "Material",
            "transparency",
            "1.0000001",
            false,
            true,
        ),
        (
            Version::V4_0,
            "Material",
            "transparency",
            "-1.4e-45",
            false,
            true,
        ),
        (
            Version::V4_0,
            "PointLight",
            "intensity",
            "1e39",
            true,
            false,
        ),
        (
            Version::V4_0,
            "PointLight",
            "intensity",
            "3.4028235e38",
            false,
            false,
        ),
        (Version::V4_0, "PointLight", "intensity", "INF", true, false),
        (
            Version::V4_0,
            "PointLight",
            "intensity",
            "-1e39",
            true,
            true,
        ),
        (Version::V3_3, "PointLight", "intensity", "1e39", true, true),
        (
            Version::V3_3,
            "PointLight",
            "intensity",
            "1.00000001",
            false,
            false,
        ),
        (Version::V4_0, "MovieTexture", "pitch", "1e-46", false, true),
        (
            Version::V4_0,
            "MovieTexture",
            "pitch",
            "1e-45",
            false,
            false,
        ),
        (Version::V4_0, "MovieTexture", "pitch", "-0", false, true),
        (
            Version::V4_0,
            "ImageTexture",
            "autoRefresh",
            "-1e-400",
            false,
            false,
        ),
        (
            Version::V4_0,
            "ImageTexture",
            "autoRefresh",
            "-2.4703282292062328e-324",
            false,
            true,
        ),
        (
            Version::V4_0,
            "ImageTexture",
            "autoRefresh",
            "1e400",
            true,
            false,
        ),
        (
            Version::V4_0,
            "ImageTexture",
            "autoRefresh",
            "-1e400",
            true,
            true,
        ),
        (
            Version::V4_0,
            "ImageTexture",
            "autoRefresh",
            "-1e-46",
            false,
            true,
        ),
        (
            Version::V4_0,
            "TextureProperties",
            "borderWidth",
            "1",
            false,
            false,
        ),
        (
            Version::V4_0,
            "TextureProperties",
            "borderWidth",
            "2",
            false,
            true,
        ),
        // [0,1] in 3.3 too (18.4.9; issue 12 item 16).
        (
            Version::V3_3,
            "TextureProperties",
            "borderWidth",
            "2147483647",
            false,
            true,
        ),
        (
            Version::V3_3,
            "TextureProperties",
            "borderWidth",
            "-2147483648",
            false,
            true,
        ),
    ];
    for &(version, node, field, text, nonfinite, out) in cases {
        for encoding in ENCODINGS {
            if encoding == Encoding::Json && !is_json_number(text) {
                continue;
            }
            let source = document(encoding, version, &[El::new(node).field(field, [text])]);
            let report = check(&source, Level::Fast);
            let place = format!("{node}.{field} = {text} in X3D {version}, {encoding:?}");
            assert_eq!(
                of(&report, "FIELD_VALUE_NONFINITE").len(),
                usize::from(nonfinite),
                "{place}: FIELD_VALUE_NONFINITE"
            );
            assert_eq!(
                of(&report, "FIELD_OUT_OF_RANGE").len(),
                usize::from(out),
                "{place}: FIELD_OUT_OF_RANGE"
            );
            assert!(of(&report, "FIELD_VALUE_SYNTAX").is_empty(), "{place}");
        }
    }
}

/// A number in one of Rust's three notations: exponent, debug and shortest positional.
fn written<T: std::fmt::LowerExp + std::fmt::Debug + std::fmt::Display>(
    x: T,
    notation: usize,
) -> String {
    match notation {
        0 => format!("{x:e}"),
        1 => format!("{x:?}"),
        _ => format!("{x}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any f32 bit pattern, printed in several notations, reads back bit for bit in both
    /// encodings, and is reported non-finite exactly when it is.
    #[test]
    fn any_f32_reads_back_exactly(bits in any::<u32>(), notation in 0usize..3) {
        let x = f32::from_bits(bits);
        expect_f32(&written(x, notation), x);
    }

    #[test]
    fn any_f64_reads_back_exactly(bits in any::<u64>(), notation in 0usize..3) {
        let x = f64::from_bits(bits);
        expect_f64(&written(x, notation), x);
    }

    /// Decimal text near f32::MAX, the subnormal range and zero: stored as std rounds it.
    #[test]
    fn f32_text_near_the_edges(
        mantissa in 1u64..10_000_000_000_000_000,
        exponent in prop_oneof![20i32..60, -70i32..-30],
        negative in any::<bool>(),
    ) {
        let sign = if negative { "-" } else { "" };
        let text = format!("{sign}{mantissa}e{exponent}");
        let std: f32 = text.parse().unwrap();
        expect_f32(&text, std);
        let std64: f64 = text.parse().unwrap();
        expect_f64(&text, std64);
    }
}
