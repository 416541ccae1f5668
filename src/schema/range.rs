//! Whether a value is inside a field's range, at the field's precision: the one decision
//! FIELD_OUT_OF_RANGE and the fast level's summaries ([`crate::model::Summarizer`]) share.

use super::{Bound, FieldDef};

/// Single-precision values are compared with the bound rounded to f32, the precision
/// the field has; NaN compares false everywhere and so is never in range.
#[inline]
pub fn in_range_f32(value: f32, def: &FieldDef) -> bool {
    let above = |b: Bound| {
        if b.inclusive {
            value >= b.value as f32
        } else {
            value > b.value as f32
        }
    };
    let below = |b: Bound| {
        if b.inclusive {
            value <= b.value as f32
        } else {
            value < b.value as f32
        }
    };
    def.min.is_none_or(above) && def.max.is_none_or(below) && !value.is_nan()
}

#[inline]
pub fn in_range_f64(value: f64, def: &FieldDef) -> bool {
    let above = |b: Bound| {
        if b.inclusive {
            value >= b.value
        } else {
            value > b.value
        }
    };
    let below = |b: Bound| {
        if b.inclusive {
            value <= b.value
        } else {
            value < b.value
        }
    };
    def.min.is_none_or(above) && def.max.is_none_or(below) && !value.is_nan()
}

/// The range as the interface tables print it: `[0,1]`, `(0,π/2]`, `[0,∞)`.
pub fn range_text(def: &FieldDef) -> String {
    let number = |v: f64| {
        if v == std::f64::consts::FRAC_PI_2 {
            "π/2".to_string()
        } else if v == std::f64::consts::PI {
            "π".to_string()
        } else {
            format!("{v}")
        }
    };
    let (open, low) = match def.min {
        Some(b) => (if b.inclusive { '[' } else { '(' }, number(b.value)),
        None => ('(', "-∞".to_string()),
    };
    let (high, close) = match def.max {
        Some(b) => (number(b.value), if b.inclusive { ']' } else { ')' }),
        None => ("∞".to_string(), ')'),
    };
    format!("{open}{low},{high}{close}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::schema::{AccessType, FieldType};

    fn def(min: Option<Bound>, max: Option<Bound>) -> FieldDef {
        FieldDef {
            name: "f",
            ty: FieldType::SFFloat,
            access: AccessType::InputOutput,
            default: "",
            min,
            max,
            enumeration: &[],
            enumeration_strict: false,
            acceptable: &[],
            component: None,
        }
    }

    #[test]
    fn bounds_are_compared_in_f32() {
        let half_pi = Bound {
            value: std::f64::consts::FRAC_PI_2,
            inclusive: true,
        };
        let zero_open = Bound {
            value: 0.0,
            inclusive: false,
        };
        let d = def(Some(zero_open), Some(half_pi));
        assert!(in_range_f32("1.570796327".parse().unwrap(), &d));
        assert!(!in_range_f32("1.571".parse().unwrap(), &d));
        assert!(!in_range_f32(0.0, &d));
        assert!(!in_range_f32(-0.0, &d));
        assert!(
            in_range_f32(f32::from_bits(1), &d),
            "the smallest denormal is above 0"
        );
        assert!(!in_range_f32(f32::NAN, &d));
        assert_eq!(range_text(&d), "(0,π/2]");
    }

    #[test]
    fn unbounded_sides_accept_everything_finite_and_infinite() {
        let d = def(
            Some(Bound {
                value: 0.0,
                inclusive: true,
            }),
            None,
        );
        assert!(in_range_f32(f32::MAX, &d));
        assert!(in_range_f32(f32::INFINITY, &d));
        assert!(in_range_f32(-0.0, &d));
        assert!(!in_range_f32(-f32::from_bits(1), &d));
        assert_eq!(range_text(&d), "[0,∞)");
    }
}
