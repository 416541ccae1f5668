//! The number scanners agree bit for bit with the standard library's correctly rounded
//! parsers.

use proptest::prelude::*;
use x3dcheck::model::text::number::{parse_f32, parse_f64, parse_i32};
use x3dcheck::model::text::xml_value::{
    parse_value, parse_value_in, parse_value_in_pieces, Syntax,
};
use x3dcheck::model::Value;
use x3dcheck::schema::FieldType;

fn check_f32(text: &str) {
    let ours = parse_f32(text.as_bytes()).map(f32::to_bits);
    let std = text.parse::<f32>().ok().map(f32::to_bits);
    assert_eq!(ours, std, "{text:?}");
}

fn check_f64(text: &str) {
    let ours = parse_f64(text.as_bytes()).map(f64::to_bits);
    let std = text.parse::<f64>().ok().map(f64::to_bits);
    assert_eq!(ours, std, "{text:?}");
}

/// The tokens, each followed by its separator.
fn joined(tokens: &[impl AsRef<str>], separators: &[String]) -> String {
    let mut text = String::new();
    for (token, separator) in tokens.iter().zip(separators) {
        text.push_str(token.as_ref());
        text.push_str(separator);
    }
    text
}

/// The tokens joined into an MFFloat and an MFDouble value parse to what each token
/// parses to alone with the standard library, bit for bit.
fn floats_as_alone(tokens: &[impl AsRef<str>], separators: &[String]) -> Result<(), TestCaseError> {
    let text = joined(tokens, separators);
    let Ok(Value::Floats(floats)) = parse_value(FieldType::MFFloat, &text) else {
        panic!("{text:?}")
    };
    let Ok(Value::Doubles(doubles)) = parse_value(FieldType::MFDouble, &text) else {
        panic!("{text:?}")
    };
    let alone32: Vec<u32> = tokens
        .iter()
        .map(|t| t.as_ref().parse::<f32>().unwrap().to_bits())
        .collect();
    let alone64: Vec<u64> = tokens
        .iter()
        .map(|t| t.as_ref().parse::<f64>().unwrap().to_bits())
        .collect();
    prop_assert_eq!(
        floats.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        alone32
    );
    prop_assert_eq!(
        doubles.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        alone64
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn f32_round_trips(bits in any::<u32>()) {
        let x = f32::from_bits(bits);
        prop_assume!(x.is_finite());
        for text in [format!("{x}"), format!("{x:e}"), format!("{x:?}"), format!("{x:.3}"), format!("{x:.12e}")] {
            check_f32(&text);
        }
        prop_assert_eq!(parse_f32(format!("{x:e}").as_bytes()).map(f32::to_bits), Some(bits));
    }

    #[test]
    fn f64_round_trips(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        for text in [format!("{x}"), format!("{x:e}"), format!("{x:?}"), format!("{x:.3}"), format!("{x:.20e}")] {
            check_f64(&text);
        }
        prop_assert_eq!(parse_f64(format!("{x:e}").as_bytes()).map(f64::to_bits), Some(bits));
    }

    /// Decimal text near the midpoint between two neighbouring f32 values: the hard cases
    /// for correct rounding, and the ones a conversion through f64 gets wrong.
    #[test]
    fn f32_near_midpoints(bits in 0u32..0x7f7f_ffff, digits in 8usize..20) {
        let low = f32::from_bits(bits) as f64;
        let high = f32::from_bits(bits + 1) as f64;
        let mid = (low + high) / 2.0; // exact in f64
        let below = f64::from_bits(mid.to_bits() - 1);
        let above = f64::from_bits(mid.to_bits() + 1);
        for v in [mid, below, above] {
            check_f32(&format!("{v:e}"));
            check_f32(&format!("{v:.digits$e}"));
            check_f32(&format!("{v}"));
        }
    }

    #[test]
    fn random_decimal_text(text in "[+-]?[0-9]{0,22}(\\.[0-9]{0,22})?([eE][+-]?[0-9]{1,3})?") {
        check_f32(&text);
        check_f64(&text);
    }

    #[test]
    fn short_decimal_text(text in "-?(0|[1-9][0-9]{0,8})\\.[0-9]{1,9}(e-?[0-9]{1,2})?") {
        check_f32(&text);
        check_f64(&text);
    }

    #[test]
    fn i32_text_agrees_with_std(text in "[+-]?0{0,24}[0-9]{0,24}") {
        prop_assert_eq!(parse_i32(text.as_bytes()), text.parse::<i32>().ok());
    }

    #[test]
    fn i32_agrees_with_std(x in any::<i64>()) {
        let text = x.to_string();
        prop_assert_eq!(parse_i32(text.as_bytes()), text.parse::<i32>().ok());
        let small = (x as i32).to_string();
        prop_assert_eq!(parse_i32(small.as_bytes()), Some(x as i32));
    }

    /// Numbers inside a longer text (where digits are read eight bytes at a time) come
    /// out as when parsed alone.
    #[test]
    fn numbers_in_text(
        tokens in prop::collection::vec("[+-]?[0-9]{1,12}(\\.[0-9]{0,20})?([eE][+-]?[0-9]{1,2})?", 0..40),
        separators in prop::collection::vec("[ ,\t\r\n]{1,3}", 40),
    ) {
        floats_as_alone(&tokens, &separators)?;
    }

    /// Tokens of the shape the scanners read in one word (up to eight bytes of digits and
    /// a `.`, then a separator), and a little longer, inside a value: as parsed alone.
    #[test]
    fn short_tokens_in_text(
        tokens in prop::collection::vec("[+-]?[0-9]{0,9}(\\.[0-9]{0,9})?", 0..40),
        separators in prop::collection::vec("[ ,\t\r\n]{1,2}", 40),
    ) {
        let tokens: Vec<&String> = tokens.iter().filter(|t| t.bytes().any(|b| b.is_ascii_digit())).collect();
        floats_as_alone(&tokens, &separators)?;
        let integers: Vec<&&String> = tokens.iter().filter(|t| !t.contains('.')).collect();
        let text = joined(&integers, &separators);
        let parsed = parse_value(FieldType::MFInt32, &text);
        let expected: Option<Vec<i32>> = integers.iter().map(|t| t.parse::<i32>().ok()).collect();
        match expected {
            Some(expected) => prop_assert_eq!(parsed, Ok(Value::Int32s(expected))),
            None => prop_assert!(parsed.is_err()),
        }
    }

    /// A value parsed in pieces (as long values are, on several threads) gives what the
    /// one-piece parse gives: the same numbers bit for bit, or the same first error, at the
    /// same place, or the same misplaced comma.
    #[test]
    fn pieces_parse_as_one(
        tokens in prop::collection::vec(
            prop_oneof![
                8 => "[+-]?[0-9]{1,6}(\\.[0-9]{0,8})?([eE][+-]?[0-9]{1,2})?",
                1 => "(NaN|-INF|1\\.2\\.3|x|0x1F|99999999999|true)",
            ],
            0..60,
        ),
        separators in prop::collection::vec(prop_oneof![8 => "[ \t\r\n]{1,3}", 1 => " ?, ?"], 60),
        ty in prop_oneof![
            Just(FieldType::MFFloat),
            Just(FieldType::MFVec3f),
            Just(FieldType::MFVec2d),
            Just(FieldType::MFInt32),
            Just(FieldType::MFRotation),
        ],
        classic in any::<bool>(),
        piece in 1usize..40,
    ) {
        let mut text = String::new();
        for (token, separator) in tokens.iter().zip(&separators) {
            text.push_str(token);
            text.push_str(separator);
        }
        let syntax = if classic { Syntax::Classic } else { Syntax::Xml };
        let whole = parse_value_in(syntax, ty, &text);
        let pieces = parse_value_in_pieces(syntax, ty, &text, piece);
        prop_assert_eq!(format!("{pieces:?}"), format!("{whole:?}"), "{:?} in pieces of {}", text, piece);
    }
}
