//! Transform composition and bounds (`model::bounds`) at the extremes: scales from
//! subnormal to ±3.4e38 and 0, rotations about zero, huge or tiny axes and by huge angles,
//! translations and centres at ±3e38, nested up to the depth limit. Bounds never hold NaN
//! and contain every transformed point, computed here independently (point by point in
//! f64, rotations by Rodrigues' formula) within a tolerance relative to the magnitudes
//! involved; they are unknown (None) exactly when a transform value is not finite or the
//! computation leaves f64's range.

use proptest::prelude::*;
use x3dcheck::diagnostic::Level;
use x3dcheck::model::bounds::{scene_bounds, Affine};
use x3dcheck::schema::Version;

use crate::support::{check, document, has_non_finite_word, of, read, El, Encoding, ENCODINGS};

type V = [f64; 3];

fn add(a: V, b: V) -> V {
    std::array::from_fn(|i| a[i] + b[i])
}

fn sub(a: V, b: V) -> V {
    std::array::from_fn(|i| a[i] - b[i])
}

fn norm(a: V) -> f64 {
    a.iter().fold(0.0f64, |m, c| m.hypot(*c))
}

/// An SFRotation's effect on a vector, by Rodrigues' formula; a zero axis turns nothing.
fn rotate(rotation: [f32; 4], v: V, inverse: bool) -> V {
    let axis = [rotation[0], rotation[1], rotation[2]].map(f64::from);
    let length = norm(axis);
    if length == 0.0 {
        return v;
    }
    let k = axis.map(|c| c / length);
    let angle = f64::from(rotation[3]) * if inverse { -1.0 } else { 1.0 };
    let (s, c) = angle.sin_cos();
    let cross = [
        k[1] * v[2] - k[2] * v[1],
        k[2] * v[0] - k[0] * v[2],
        k[0] * v[1] - k[1] * v[0],
    ];
    let dot = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    std::array::from_fn(|i| v[i] * c + cross[i] * s + k[i] * dot * (1.0 - c))
}

#[derive(Clone, Debug)]
struct Transform {
    translation: [f32; 3],
    center: [f32; 3],
    rotation: [f32; 4],
    scale: [f32; 3],
    scale_orientation: [f32; 4],
}

impl Transform {
    /// 10.4.4: P' = T × C × R × SR × S × -SR × -C × P.
    fn apply(&self, p: V) -> V {
        let f = |v: [f32; 3]| v.map(f64::from);
        let c = f(self.center);
        let mut v = sub(p, c);
        v = rotate(self.scale_orientation, v, true);
        v = std::array::from_fn(|i| v[i] * f64::from(self.scale[i]));
        v = rotate(self.scale_orientation, v, false);
        v = rotate(self.rotation, v, false);
        add(add(v, c), f(self.translation))
    }

    /// A bound on the magnitudes the computation of `apply` goes through, for `p` of
    /// magnitude `m`: rotations keep lengths, scales stretch by at most their largest.
    fn magnitude(&self, m: f64) -> f64 {
        let f = |v: [f32; 3]| norm(v.map(f64::from));
        let stretch = self
            .scale
            .iter()
            .fold(0.0f64, |s, c| s.max(f64::from(*c).abs()));
        f(self.translation) + f(self.center) + stretch * (m + f(self.center))
    }

    fn values(&self) -> impl Iterator<Item = f32> + '_ {
        self.translation
            .iter()
            .chain(&self.center)
            .chain(&self.rotation)
            .chain(&self.scale)
            .chain(&self.scale_orientation)
            .copied()
    }

    fn element(&self, inner: El) -> El {
        El::new("Transform")
            .field("translation", self.translation.map(text))
            .field("center", self.center.map(text))
            .field("rotation", self.rotation.map(text))
            .field("scale", self.scale.map(text))
            .field("scaleOrientation", self.scale_orientation.map(text))
            .child("children", inner)
    }
}

/// A value as a document writes it; infinities as the overflow that makes them.
fn text(x: f32) -> String {
    if x == f32::INFINITY {
        "1e39".to_string()
    } else if x == f32::NEG_INFINITY {
        "-1e39".to_string()
    } else if x.is_nan() {
        "NaN".to_string()
    } else {
        format!("{x:e}")
    }
}

fn extreme() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => -10.0f32..10.0,
        1 => Just(0.0f32),
        1 => Just(-0.0f32),
        1 => prop_oneof![Just(3e38f32), Just(-3e38f32), Just(f32::MAX), Just(-f32::MAX)],
        1 => (-126i32..=127, any::<bool>()).prop_map(|(k, neg)| {
            let x = 2f32.powi(k);
            if neg { -x } else { x }
        }),
        1 => (1u32..0x0080_0000).prop_map(f32::from_bits),
    ]
}

fn non_finite() -> impl Strategy<Value = f32> {
    prop_oneof![Just(f32::INFINITY), Just(f32::NEG_INFINITY), Just(f32::NAN)]
}

/// Mostly ordinary values, sometimes extreme, rarely not finite.
fn component() -> impl Strategy<Value = f32> {
    prop_oneof![20 => extreme(), 1 => non_finite()]
}

fn rotation() -> impl Strategy<Value = [f32; 4]> {
    prop_oneof![
        3 => (prop::array::uniform3(-1.0f32..1.0), -7.0f32..7.0).prop_map(|(a, t)| [a[0], a[1], a[2], t]),
        1 => Just([0.0, 0.0, 0.0, 1.0]),
        1 => (prop::array::uniform3(component()), component()).prop_map(|(a, t)| [a[0], a[1], a[2], t]),
    ]
}

fn transform() -> impl Strategy<Value = Transform> {
    (
        prop::array::uniform3(component()),
        prop::array::uniform3(component()),
        rotation(),
        prop::array::uniform3(component()),
        rotation(),
    )
        .prop_map(
            |(translation, center, rotation, scale, scale_orientation)| Transform {
                translation,
                center,
                rotation,
                scale,
                scale_orientation,
            },
        )
}

fn scene(transforms: &[Transform], points: &[[f32; 3]]) -> El {
    let shape = El::new("Shape").child(
        "geometry",
        El::new("PointSet").child(
            "coord",
            El::new("Coordinate").field("point", points.iter().flatten().map(|c| text(*c))),
        ),
    );
    transforms
        .iter()
        .rev()
        .fold(shape, |inner, t| t.element(inner))
}

/// The world positions of the points, innermost transform first, with the magnitude
/// each computation went through; non-finite points are not drawn.
fn reference(transforms: &[Transform], points: &[[f32; 3]]) -> Vec<(V, f64)> {
    points
        .iter()
        .filter(|p| p.iter().all(|c| c.is_finite()))
        .map(|p| {
            let mut v = p.map(f64::from);
            let mut m = norm(v);
            for t in transforms.iter().rev() {
                v = t.apply(v);
                m = t.magnitude(m);
            }
            (v, m)
        })
        .collect()
}

/// The largest product of scale factors along the chain: how far composed matrices go.
fn stretch(transforms: &[Transform]) -> f64 {
    transforms.iter().fold(1.0f64, |s, t| {
        s * t
            .scale
            .iter()
            .fold(1.0f64, |m, c| m.max(f64::from(*c).abs()))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn bounds_contain_the_transformed_points(
        transforms in prop::collection::vec(transform(), 1..8),
        points in prop::collection::vec(prop::array::uniform3(component()), 1..5),
    ) {
        let source = document(Encoding::Xml, Version::V4_0, &[scene(&transforms, &points)]);
        let doc = read(&source);
        let bounds = scene_bounds(&doc);
        let expected = reference(&transforms, &points);
        let non_finite_transform = transforms.iter().any(|t| t.values().any(|v| !v.is_finite()));
        let magnitude = expected.iter().fold(stretch(&transforms), |m, (_, pm)| m.max(*pm));
        let beyond_f64 = !magnitude.is_finite() || magnitude >= 1e300;
        let Some(b) = bounds else {
            prop_assert!(
                non_finite_transform || beyond_f64,
                "unknown bounds for finite transforms (magnitude {:e})", magnitude
            );
            return Ok(());
        };
        prop_assert!(!non_finite_transform, "bounds through a non-finite transform: {:?}", b);
        prop_assert!(b.min.iter().chain(&b.max).all(|v| !v.is_nan()), "{:?}", b);
        if expected.is_empty() {
            prop_assert!(b.is_empty(), "{:?}", b);
            return Ok(());
        }
        prop_assert!(b.min.iter().chain(&b.max).all(|v| v.is_finite()), "{:?}", b);
        if beyond_f64 {
            // Near the end of f64's range the two computations may round differently.
            return Ok(());
        }
        let tolerance = 1e-10 * magnitude;
        for i in 0..3 {
            let low = expected.iter().map(|(p, _)| p[i]).fold(f64::INFINITY, f64::min);
            let high = expected.iter().map(|(p, _)| p[i]).fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(
                (b.min[i] - low).abs() <= tolerance && (b.max[i] - high).abs() <= tolerance,
                "axis {}: bounds {:e}..{:e}, points {:e}..{:e} (tolerance {:e})",
                i, b.min[i], b.max[i], low, high, tolerance
            );
        }
    }

    /// The whole deep check of such scenes: no panic, no NaN or inf in a message.
    #[test]
    fn deep_check_of_extreme_transforms(
        transforms in prop::collection::vec(transform(), 1..5),
        points in prop::collection::vec(prop::array::uniform3(extreme()), 1..4),
        radius in extreme(),
    ) {
        let light = El::new("PointLight").field("radius", [text(radius)]);
        let scene = scene(&transforms, &points);
        let group = El::new("Group").field("bboxSize", ["1", "1", "1"]).child("children", scene).child("children", light);
        for encoding in ENCODINGS {
            let any_nan = transforms.iter().any(|t| t.values().any(f32::is_nan));
            if encoding == Encoding::Json && any_nan {
                continue;
            }
            let source = document(encoding, Version::V4_0, std::slice::from_ref(&group));
            let report = check(&source, Level::Deep);
            for d in &report.diagnostics {
                if d.code != "FIELD_VALUE_NONFINITE" {
                    prop_assert!(!has_non_finite_word(&d.message), "{}", d.message);
                }
            }
        }
    }

    /// The largest stretch bounds every stretch, even where LᵀL would overflow f64.
    #[test]
    fn max_stretch_bounds_every_stretch(
        transforms in prop::collection::vec(transform(), 1..8),
        v in prop::array::uniform3(-1.0f64..1.0),
    ) {
        let affine = transforms.iter().fold(Affine::IDENTITY, |outer, t| {
            let r = |q: [f32; 4]| Affine::rotate([q[0], q[1], q[2]].map(f64::from), f64::from(q[3]));
            let s = Affine::scale(t.scale.map(f64::from));
            let inverse = r([t.scale_orientation[0], t.scale_orientation[1], t.scale_orientation[2], -t.scale_orientation[3]]);
            outer.then_after(&r(t.rotation).then_after(&r(t.scale_orientation)).then_after(&s).then_after(&inverse))
        });
        let stretch = affine.max_stretch();
        if !affine.is_finite() {
            prop_assert!(stretch.is_nan());
            return Ok(());
        }
        prop_assert!(stretch >= 0.0, "{}", stretch);
        let frobenius = affine.linear.iter().flatten().fold(0.0f64, |m, c| m.hypot(*c));
        prop_assert!(stretch <= frobenius * (1.0 + 1e-9), "{:e} > {:e}", stretch, frobenius);
        let n = norm(v);
        prop_assume!(n > 1e-3);
        let image = norm(affine.apply_linear(v));
        if image.is_finite() {
            prop_assert!(image / n <= stretch * (1.0 + 1e-9), "{:e} stretched by {:e} > {:e}", n, image / n, stretch);
        }
    }
}

/// A light under scales whose LᵀL overflows f64 (five nested 1e38, rotated about x, which
/// keeps the box 0.2 away from the light along x) still reaches the box: the radius used
/// to come out 0 there.
#[test]
fn a_light_under_huge_rotated_scales_reaches_its_neighbour() {
    let inner = El::new("Group")
        .child(
            "children",
            El::new("PointLight")
                .field("location", [0, 0, 0])
                .field("radius", [1]),
        )
        .child(
            "children",
            El::new("Transform")
                .field("translation", ["1.2", "0", "0"])
                .child(
                    "children",
                    El::new("Shape").child("geometry", El::new("Box")),
                ),
        );
    let nested = (0..5).fold(inner, |inner, _| {
        El::new("Transform")
            .field("scale", ["1e38", "1e38", "1e38"])
            .field("rotation", ["1", "0", "0", "0.5"])
            .child("children", inner)
    });
    for encoding in ENCODINGS {
        let source = document(encoding, Version::V4_0, std::slice::from_ref(&nested));
        let report = check(&source, Level::Deep);
        assert!(
            of(&report, "LIGHT_REACHES_NOTHING").is_empty(),
            "{encoding:?}: {:?}",
            report.diagnostics
        );
    }
}

/// A rotation with a non-finite axis is a non-finite transform (unknown bounds), like a
/// non-finite angle, not a rotation about nothing.
#[test]
fn non_finite_rotation_axes_make_bounds_unknown() {
    for rotation in [
        "1e39 0 0 1",
        "NaN 0 0 1",
        "0 1 0 1e39",
        "0 1 0 NaN",
        "0 0 0 INF",
    ] {
        let source = format!(
            "<X3D profile='Full' version='4.0'><Scene><Transform rotation='{rotation}'>\
             <Shape><Box/></Shape></Transform></Scene></X3D>"
        );
        assert_eq!(scene_bounds(&read(&source)), None, "{rotation}");
    }
    let zero_axis = "<X3D profile='Full' version='4.0'><Scene><Transform rotation='0 0 0 1'>\
         <Shape><Box/></Shape></Transform></Scene></X3D>";
    let b = scene_bounds(&read(zero_axis)).unwrap();
    assert_eq!((b.min, b.max), ([-1.0; 3], [1.0; 3]));
}

/// Nested far below the limit, every level counts; beyond it the bounds are unknown, and
/// nothing overflows the stack.
#[test]
fn deep_nesting() {
    let nest = |depth: usize| {
        let point = El::new("Shape").child(
            "geometry",
            El::new("PointSet").child("coord", El::new("Coordinate").field("point", [0, 0, 0])),
        );
        (0..depth).fold(point, |inner, _| {
            El::new("Transform")
                .field("translation", [1, 0, 0])
                .field("scale", ["2", "0.5", "1"])
                .child("children", inner)
        })
    };
    let b = scene_bounds(&read(&document(Encoding::Xml, Version::V4_0, &[nest(100)]))).unwrap();
    // Translations 1, 2, 4, … (each inner one scaled by 2 more): 2^100 − 1 in all.
    assert_eq!(b.min, [2f64.powi(100) - 1.0, 0.0, 0.0]);
    assert_eq!(b.min, b.max);
    let deep = document(Encoding::Xml, Version::V4_0, &[nest(400)]);
    assert_eq!(scene_bounds(&read(&deep)), None);
    let report = check(&deep, Level::Deep);
    assert!(report
        .diagnostics
        .iter()
        .all(|d| !has_non_finite_word(&d.message)));
}
