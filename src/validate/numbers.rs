//! Numbers for the rules: computed numbers as messages print them (short, as precise as
//! the single-precision fields they come from, in exponent notation where positional
//! digits would run long, ±3.4e38, 1.4e-45, and never `inf`: what a rule prints has been
//! checked finite), counts as messages word them, and the order of a list that shall not
//! decrease.

/// A computed value for a message. Within the normal f32 range (or zero) it is the
/// shortest text that reads back as the same f32, the precision of the fields it comes
/// from; beyond that range (an f64 length of f32 components, bounds carried through
/// transforms) or in the subnormal range, where f32 keeps only a few digits, it is the
/// f64 value to 7 significant digits. Positional between 1e-4 and 1e7, exponent notation
/// outside; -0 prints as 0; ±∞ as `∞` and `-∞`, like the ranges of the interface tables.
pub fn readable(value: f64) -> String {
    if value.is_infinite() {
        return if value > 0.0 { "∞" } else { "-∞" }.to_string();
    }
    if value == 0.0 {
        return "0".to_string();
    }
    let magnitude = value.abs();
    let positional = (1e-4..1e7).contains(&magnitude);
    let single = value as f32;
    if magnitude <= f64::from(f32::MAX) && single.is_normal() {
        return if positional {
            format!("{single}")
        } else {
            format!("{single:e}")
        };
    }
    let text = format!("{value:.6e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) => {
            let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
            format!("{mantissa}e{exponent}")
        }
        None => text,
    }
}

/// The index of the first value smaller than the one before it, in a list that shall not
/// decrease (interpolator and sequencer keys, background angles, NURBS knots). Pairs with
/// a NaN or an infinity have no order to judge (FIELD_VALUE_NONFINITE reports those).
/// SFFloat values compare exactly as f64.
pub fn first_decrease<T: Copy + Into<f64>>(values: &[T]) -> Option<usize> {
    values
        .windows(2)
        .position(|pair| {
            let (before, after) = (pair[0].into(), pair[1].into());
            before.is_finite() && after.is_finite() && after < before
        })
        .map(|at| at + 1)
}

/// `n` things, in the singular for one: "1 key", "3 keys".
pub fn plural(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

#[cfg(test)]
mod tests {
    use super::{first_decrease, readable};

    #[test]
    fn first_decrease_skips_equal_and_nonfinite_neighbours() {
        assert_eq!(first_decrease(&[0.0, 0.5, 0.5, 1.0]), None);
        assert_eq!(first_decrease(&[0.0, 0.6, 0.4, 0.2]), Some(2));
        assert_eq!(first_decrease(&[1.0, f32::NAN, 0.0]), None);
        assert_eq!(first_decrease::<f32>(&[]), None);
    }

    #[test]
    fn short_and_exact_at_single_precision() {
        assert_eq!(readable(2.0), "2");
        assert_eq!(readable(-1.5), "-1.5");
        assert_eq!(readable(-0.0), "0");
        assert_eq!(readable(39f64.next_up()), "39");
        // What the f32 holds, not the decimal it was written as.
        assert_eq!(readable(f64::from(1.0100001f32)), "1.0100001");
        assert_eq!(readable(f64::from(0.1f32)), "0.1");
        assert_eq!(readable(1e-4), "0.0001");
        assert_eq!(readable(1.2e-5), "1.2e-5");
        assert_eq!(readable(9_999_999.0), "9999999");
        assert_eq!(readable(1e7), "1e7");
        assert_eq!(readable(f64::from(f32::MAX)), "3.4028235e38");
        assert_eq!(readable(-f64::from(f32::MIN_POSITIVE)), "-1.1754944e-38");
    }

    #[test]
    fn beyond_single_precision_seven_digits() {
        assert_eq!(readable(f64::from(f32::MAX) * 3f64.sqrt()), "5.893863e38");
        assert_eq!(readable(f64::from(f32::from_bits(1))), "1.401298e-45");
        assert_eq!(readable(9.183549615799121e-41), "9.18355e-41");
        assert_eq!(readable(1e300), "1e300");
        assert_eq!(readable(-f64::MAX), "-1.797693e308");
        assert_eq!(readable(f64::from_bits(1)), "4.940656e-324");
        assert_eq!(readable(f64::INFINITY), "∞");
        assert_eq!(readable(f64::NEG_INFINITY), "-∞");
    }
}
