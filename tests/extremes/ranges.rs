//! FIELD_OUT_OF_RANGE is exact at every bound of every ranged numeric field of the four
//! seed clauses (Rendering 11, Shape 12, Lighting 17, Texturing 18), in every version:
//! the fields come from the schema tables, not from a list here. For each finite bound,
//! the value exactly at it, one ulp inside and one ulp outside (at the field's precision:
//! f32 for SFFloat-based types, f64 for SFDouble and SFTime, 1 for SFInt32), as an SF
//! value or as one element of an MF value among in-range neighbours, in XML and in JSON,
//! in shortest and in exponent notation: the rule fires exactly for the outside values
//! (and at an exclusive bound) and names the element. Decimal text that rounds onto one
//! of those values (`1.00000001` is 1.0f32) is judged as that value; so is text at the
//! exact midpoint between two of them, which rounds to even.
//!
//! Geometry index fields (`coordIndex`, `index`, …) are INDEX_NEGATIVE's, which knows the
//! -1 separator: for them the outside value must raise that rule instead.

use proptest::prelude::*;
use x3dcheck::diagnostic::Level;
use x3dcheck::schema::{schema, Bound, FieldDef, NodeDef, Scalar, Version};

use crate::support::{check, document, of, El, Encoding, ENCODINGS};

const SEED_COMPONENTS: [&str; 4] = ["Rendering", "Shape", "Lighting", "Texturing"];

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Side {
    Min,
    Max,
}

/// One finite bound of one field of one node type, in one version.
#[derive(Copy, Clone, Debug)]
struct BoundCase {
    version: Version,
    node: &'static NodeDef,
    field: &'static FieldDef,
    side: Side,
    bound: Bound,
}

impl BoundCase {
    fn name(&self) -> String {
        format!(
            "X3D {} {}.{} ({}) {:?} bound {}{}",
            self.version,
            self.node.name,
            self.field.name,
            self.field.ty,
            self.side,
            self.bound.value,
            if self.bound.inclusive {
                " inclusive"
            } else {
                " exclusive"
            }
        )
    }

    /// Index fields of geometry, which INDEX_NEGATIVE judges instead.
    fn is_geometry_index(&self) -> bool {
        let name = self.field.name;
        (name == "index" || name.ends_with("Index")) && self.node.is_a("X3DGeometryNode")
    }

    /// The rule that must fire for an outside value, and the level it runs at.
    fn rule(&self) -> (&'static str, Level) {
        if self.is_geometry_index() {
            ("INDEX_NEGATIVE", Level::Standard)
        } else {
            ("FIELD_OUT_OF_RANGE", Level::Fast)
        }
    }
}

/// Every finite bound of every initializable numeric field of the seed components'
/// nodes, in one version.
fn bound_cases(version: Version) -> Vec<BoundCase> {
    let mut cases = Vec::new();
    for node in schema(version).nodes {
        if !SEED_COMPONENTS.contains(&node.component.component) {
            continue;
        }
        for &field in node.fields {
            let numeric = matches!(
                field.ty.scalar(),
                Scalar::Float | Scalar::Double | Scalar::Int32
            );
            if !numeric || !field.access.is_initializable() {
                continue;
            }
            for (side, bound) in [(Side::Min, field.min), (Side::Max, field.max)] {
                let Some(bound) = bound.filter(|b| b.value.is_finite()) else {
                    continue;
                };
                cases.push(BoundCase {
                    version,
                    node,
                    field,
                    side,
                    bound,
                });
            }
        }
    }
    cases
}

/// A number at the field's precision.
#[derive(Copy, Clone, Debug, PartialEq)]
enum Number {
    Single(f32),
    Double(f64),
    Int(i64),
}

impl Number {
    /// Shortest round-trip text, and the same in exponent notation.
    fn texts(self) -> [String; 2] {
        match self {
            Number::Single(x) => [format!("{x}"), format!("{x:e}")],
            Number::Double(x) => [format!("{x}"), format!("{x:e}")],
            Number::Int(x) => [format!("{x}"), format!("{x}")],
        }
    }
}

/// Where a value stands against one bound.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Place {
    At,
    Inside,
    Outside,
}

/// The value at, one ulp inside, or one ulp outside a bound, at the field's precision;
/// "at" is the bound rounded to that precision, what the field can hold.
fn probe(case: &BoundCase, place: Place) -> Number {
    let toward_inside = match place {
        Place::At => 0,
        Place::Inside => 1,
        Place::Outside => -1,
    } * if case.side == Side::Min { 1 } else { -1 };
    let step_f32 = |x: f32| match toward_inside {
        1 => x.next_up(),
        -1 => x.next_down(),
        _ => x,
    };
    let step_f64 = |x: f64| match toward_inside {
        1 => x.next_up(),
        -1 => x.next_down(),
        _ => x,
    };
    match case.field.ty.scalar() {
        Scalar::Float => Number::Single(step_f32(case.bound.value as f32)),
        Scalar::Double => Number::Double(step_f64(case.bound.value)),
        _ => {
            assert_eq!(case.bound.value.fract(), 0.0, "{}", case.name());
            Number::Int(case.bound.value as i64 + toward_inside)
        }
    }
}

/// Whether a value at `place` is in range (against this bound; the others are far).
fn in_range(case: &BoundCase, place: Place) -> bool {
    match place {
        Place::At => case.bound.inclusive,
        Place::Inside => true,
        Place::Outside => false,
    }
}

/// A small deterministic generator, so that the "random" element index of each case is
/// the same in every run.
struct SplitMix(u64);

impl SplitMix {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) % n as u64) as usize
    }
}

/// Where the probe goes in the value: element and component.
#[derive(Copy, Clone, Debug)]
struct Slot {
    elements: usize,
    element: usize,
    component: usize,
}

impl Slot {
    fn pick(case: &BoundCase, random: &mut SplitMix) -> Slot {
        let elements = if case.field.ty.is_mf() {
            1 + random.below(6)
        } else {
            1
        };
        Slot {
            elements,
            element: random.below(elements),
            component: random.below(case.field.ty.arity()),
        }
    }

    /// The value's tokens: `text` in the slot, in-range filler elsewhere.
    fn tokens(&self, case: &BoundCase, text: &str) -> Vec<String> {
        let arity = case.field.ty.arity();
        let filler = probe(case, Place::Inside).texts()[0].clone();
        let mut tokens = vec![filler; self.elements * arity];
        tokens[self.element * arity + self.component] = text.to_string();
        tokens
    }

    /// The diagnostic's index: the MF element, or an SF vector's component.
    fn index(&self, case: &BoundCase) -> usize {
        if case.field.ty.is_mf() {
            self.element
        } else {
            self.component
        }
    }

    /// How FIELD_OUT_OF_RANGE's message names the place: `.f[2] component 1 = …`.
    fn place_text(&self, case: &BoundCase) -> String {
        let ty = case.field.ty;
        let field = case.field.name;
        match (ty.is_mf(), ty.arity()) {
            (true, 1) => format!(".{field}[{}] = ", self.element),
            (true, _) => format!(".{field}[{}] component {} = ", self.element, self.component),
            (false, 1) => format!(".{field} = "),
            (false, _) => format!(".{field} component {} = ", self.component),
        }
    }
}

/// Checks one text in one slot, in one encoding: the case's rule fires iff `expect_in`
/// is false, once, at the slot, quoting the text.
fn judge(case: &BoundCase, slot: &Slot, encoding: Encoding, text: &str, expect_in: bool) {
    let (rule, level) = case.rule();
    let node = El::new(case.node.name).field(case.field.name, slot.tokens(case, text));
    let source = document(encoding, case.version, &[node]);
    let report = check(&source, level);
    let what = format!("{}: `{text}` in {encoding:?} at {slot:?}", case.name());
    for code in ["FIELD_VALUE_SYNTAX", "FIELD_VALUE_NONFINITE"] {
        if text != "NaN" {
            assert!(of(&report, code).is_empty(), "{what}: {code}");
        }
    }
    if rule != "FIELD_OUT_OF_RANGE" {
        assert!(of(&report, "FIELD_OUT_OF_RANGE").is_empty(), "{what}");
    }
    let found = of(&report, rule);
    if expect_in {
        assert!(found.is_empty(), "{what}: {rule}: {}", found[0].message);
        return;
    }
    assert_eq!(found.len(), 1, "{what}: {rule} expected once");
    let d = found[0];
    assert_eq!(d.index, Some(slot.index(case)), "{what}: {}", d.message);
    assert_eq!(d.count, 1, "{what}: {}", d.message);
    assert_eq!(&source[d.span.range()], text, "{what}: points elsewhere");
    if rule == "FIELD_OUT_OF_RANGE" {
        let expected = format!(
            "{}{}{text} is outside",
            case.node.name,
            slot.place_text(case)
        );
        assert!(d.message.contains(&expected), "{what}: {:?}", d.message);
        assert_eq!(d.value.as_deref(), Some(text), "{what}");
    }
}

#[test]
fn every_bound_of_the_seed_clauses_is_exact() {
    let mut random = SplitMix(19775);
    let mut summary = Vec::new();
    for version in Version::X3D {
        let cases = bound_cases(version);
        for component in SEED_COMPONENTS {
            assert!(
                cases
                    .iter()
                    .any(|c| c.node.component.component == component),
                "X3D {version}: no ranged field in {component}"
            );
        }
        let mut fields: Vec<(&str, &str)> =
            cases.iter().map(|c| (c.node.name, c.field.name)).collect();
        fields.dedup();
        summary.push(format!(
            "X3D {version}: {} fields, {} bounds",
            fields.len(),
            cases.len()
        ));
        for case in &cases {
            let slot = Slot::pick(case, &mut random);
            for place in [Place::At, Place::Inside, Place::Outside] {
                let number = probe(case, place);
                for text in number.texts() {
                    for encoding in ENCODINGS {
                        judge(case, &slot, encoding, &text, in_range(case, place));
                    }
                }
            }
            // -0 equals 0; NaN is never in range (XML has a token for it, JSON none).
            if case.bound.value == 0.0 && case.field.ty.scalar() != Scalar::Int32 {
                for encoding in ENCODINGS {
                    judge(case, &slot, encoding, "-0", case.bound.inclusive);
                    judge(case, &slot, encoding, "-0.0e0", case.bound.inclusive);
                }
            }
            if case.field.ty.scalar() != Scalar::Int32 && !case.is_geometry_index() {
                judge(case, &slot, Encoding::Xml, "NaN", false);
            }
        }
    }
    println!("{}", summary.join("\n"));
}

/// The intensity of lights is [0,1] in 3.x and [0,∞) in 4.x (003_): both come out of the
/// enumeration, so it reads the versions' own tables.
#[test]
fn light_intensity_differs_between_versions() {
    for version in Version::X3D {
        let cases = bound_cases(version);
        let max = cases.iter().find(|c| {
            c.node.name == "PointLight" && c.field.name == "intensity" && c.side == Side::Max
        });
        assert_eq!(max.is_some(), !version.is_4x(), "X3D {version}");
    }
}

/// The values at, inside and outside a bound of a floating-point case, as f64 (exact for
/// f32 too), with their decisions.
fn float_decisions(case: &BoundCase) -> Vec<(f64, bool)> {
    [Place::At, Place::Inside, Place::Outside]
        .into_iter()
        .filter_map(|p| {
            let x = match probe(case, p) {
                Number::Single(x) => f64::from(x),
                Number::Double(x) => x,
                Number::Int(_) => return None,
            };
            Some((x, in_range(case, p)))
        })
        .collect()
}

/// The digits of |x| in positional notation with `FRACTION` decimals: exact for every
/// f64 (the smallest subnormal has 1074).
const FRACTION: usize = 1100;

fn fixed_digits(x: f64) -> Vec<u8> {
    format!("{:.FRACTION$}", x.abs())
        .bytes()
        .filter(u8::is_ascii_digit)
        .map(|b| b - b'0')
        .collect()
}

/// The exact midpoint of two neighbouring floats (f64, or f32 widened) as decimal text,
/// and texts just below and just above it in magnitude: the digits are summed and halved
/// as decimals, so no rounding is involved.
fn midpoint_texts(a: f64, b: f64) -> [String; 3] {
    let (mut x, mut y) = (fixed_digits(a), fixed_digits(b));
    let width = x.len().max(y.len()) + 1;
    for v in [&mut x, &mut y] {
        v.splice(0..0, std::iter::repeat_n(0, width - v.len()));
    }
    // Sum, then halve, most significant digit first; the sum of two integers in units of
    // 10^-FRACTION may be odd, which the halving carries into one more digit.
    let mut sum = vec![0u8; width];
    let mut carry = 0;
    for i in (0..width).rev() {
        let d = x[i] + y[i] + carry;
        sum[i] = d % 10;
        carry = d / 10;
    }
    sum.push(0);
    let mut half = Vec::with_capacity(sum.len());
    let mut remainder = 0;
    for d in sum {
        let v = remainder * 10 + d;
        half.push(v / 2);
        remainder = v % 2;
    }
    let point = width - FRACTION;
    let int: String = half[..point].iter().map(|d| char::from(b'0' + d)).collect();
    let fraction: String = half[point..].iter().map(|d| char::from(b'0' + d)).collect();
    let int = int.trim_start_matches('0');
    let fraction = fraction.trim_end_matches('0');
    let sign = if a < 0.0 || b < 0.0 { "-" } else { "" };
    let exact = format!(
        "{sign}{}.{}",
        if int.is_empty() { "0" } else { int },
        if fraction.is_empty() { "0" } else { fraction }
    );
    // The midpoint is never a short decimal: cutting its last digit lowers the magnitude,
    // appending a 1 raises it.
    let below = exact[..exact.len() - 1].to_string();
    let above = format!("{exact}1");
    [below, exact, above]
}

#[test]
fn midpoints_are_exact() {
    let [below, exact, above] = midpoint_texts(1.0, f64::from(1.0f32.next_up()));
    assert_eq!(exact, "1.000000059604644775390625");
    assert_eq!(
        (below.as_str(), above.as_str()),
        ("1.00000005960464477539062", "1.0000000596046447753906251")
    );
    let [below, exact, above] = midpoint_texts(0.0, -f64::from_bits(1));
    assert!(exact.starts_with("-0.000") && exact.ends_with("4703282292062327208828439643411068618252990130716238221279284125033775363510437593264991818081799618989828234772285886546332835517796989819938739800539093906315035659515570226392290858392449105184435931802849936536152500319370457678249219365623669863658480757001585769269903706311928279558551332927834338409351978015531246597263579574622766465272827220056374006485499977096599470454020828166226237857393450736339007967761930577506740176324673600968951340535537458516661134223766678604162159680461914467291840300530057530849048765391711386591646239524912623653881879636239373280423891018672348497668235089863388587925628302755995657524455507255189313690836254779186948667994968324049705821028513185451396213837722826145437693412532098591327667236328125"));
    // 2^-1075: a tie, to even (-0); a hair either side rounds either way.
    assert_eq!(exact.parse::<f64>().unwrap().to_bits(), (-0.0f64).to_bits());
    assert_eq!(below.parse::<f64>().unwrap().to_bits(), (-0.0f64).to_bits());
    assert_eq!(above.parse::<f64>().unwrap(), -f64::from_bits(1));
}

fn float_cases() -> Vec<BoundCase> {
    Version::X3D
        .into_iter()
        .flat_map(bound_cases)
        .filter(|c| matches!(c.field.ty.scalar(), Scalar::Float | Scalar::Double))
        .collect()
}

/// Text at, just below and just above the midpoints between the value at the bound and
/// its neighbours, for f32 and f64 fields: each is judged as the value the standard
/// library rounds it to at the field's precision. At an exact midpoint, ties go to the
/// even neighbour, which for a bound at 0 is 0 itself.
#[test]
fn text_around_the_rounding_midpoints() {
    let mut random = SplitMix(1_000_003);
    let mut ties = 0;
    for case in float_cases() {
        let slot = Slot::pick(&case, &mut random);
        let decisions = float_decisions(&case);
        let single = case.field.ty.scalar() == Scalar::Float;
        let at = decisions[0].0;
        let neighbours = if single {
            let at = at as f32;
            [at.next_up(), at.next_down()].map(f64::from)
        } else {
            [at.next_up(), at.next_down()]
        };
        for neighbour in neighbours {
            for text in midpoint_texts(at, neighbour) {
                let rounded = if single {
                    f64::from(text.parse::<f32>().unwrap())
                } else {
                    text.parse::<f64>().unwrap()
                };
                let Some(&(_, expect_in)) = decisions.iter().find(|(x, _)| *x == rounded) else {
                    continue;
                };
                ties += 1;
                for encoding in ENCODINGS {
                    judge(&case, &slot, encoding, &text, expect_in);
                }
            }
        }
    }
    assert!(ties > 0);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any decimal text that rounds onto the value at, inside or outside a bound (not its
    /// shortest form: a random point of the value's rounding interval, with 9 to 17
    /// digits, like `1.00000001` for 1.0f32) gets that value's decision.
    #[test]
    fn text_rounding_onto_a_bound_is_judged_as_the_bound(
        pick in any::<prop::sample::Index>(),
        place in 0usize..3,
        fraction in 0.001f64..0.999,
        digits in 8usize..17,
        seed in any::<u64>(),
    ) {
        let cases: Vec<BoundCase> = float_cases()
            .into_iter()
            .filter(|c| c.field.ty.scalar() == Scalar::Float)
            .collect();
        let case = cases[pick.index(cases.len())];
        let (x, expect_in) = float_decisions(&case)[place];
        let x = x as f32;
        let (low, high) = (f64::from(x.next_down()), f64::from(x.next_up()));
        let x64 = f64::from(x);
        // A point strictly inside the interval that rounds to x: between the midpoints.
        let from = (low + x64) / 2.0;
        let to = (x64 + high) / 2.0;
        let t = from + (to - from) * fraction;
        let text = format!("{t:.digits$e}");
        let rounded: f32 = text.parse().unwrap();
        prop_assume!(rounded == x);
        let slot = Slot::pick(&case, &mut SplitMix(seed));
        for encoding in ENCODINGS {
            judge(&case, &slot, encoding, &text, expect_in);
        }
    }
}
