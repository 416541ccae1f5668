//! BBOX_TOO_SMALL: a declared bounding box that does not enclose the geometry.

use crate::diagnostic::Diagnostic;
use crate::model::bounds::{self, Affine, Bounds};
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Shape or grouping node whose declared `bboxSize` (anything but the
    /// default `-1 -1 -1`, "not specified") and `bboxCenter` do not enclose what the node
    /// draws: a Shape's geometry, a grouping node's children, in the node's own coordinate
    /// system (a Transform's box is in the coordinates of its children).
    ///
    /// Only exact bounds are compared (see `model::bounds`): nothing is reported when the
    /// content's bounds are unknown (Text, Inline, prototypes, …) or only approximated
    /// (Extrusion, arcs). A Switch counts its current choice only. Float noise is
    /// tolerated: the content may stick out by 1e-4 of the larger of the declared and the
    /// actual box's largest side, plus 1e-6 of the largest coordinate's magnitude (f32
    /// coordinates far from the origin are that coarse).
    ///
    /// ## Why it matters
    /// 12.4.8, 10.2.2: the box is a hint for culling and collision; "The results are
    /// undefined if the specified bounding box is smaller than the actual bounding box".
    /// Browsers that trust it cull the shape while it is still on screen.
    ///
    /// ## Example
    /// ```xml
    /// <Shape bboxSize='1 1 1'><Sphere radius='2'/></Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.8 Shape; 10.2.2 Bounding boxes.
    ///
    /// A warning, the severity ../shared/RULES.md gives the code, which is API (issue 33).
    /// Transform's text has a "shall" ("The bounding box shall be large enough at all
    /// times to enclose the union of the group's children's bounding boxes"), but the
    /// same paragraph says what follows when it is not, as do those of Group, Shape,
    /// Anchor, Collision and Inline: "This is a hint that may be used for optimization
    /// purposes. The results are undefined if the specified bounding box is smaller than
    /// the actual bounding box of the children at any time." (H3D's copy of the 3.x text,
    /// `Transform.h`). A small box changes what a browser may cull, not what the file means.
    pub static BBOX_TOO_SMALL = {
        severity: Warning,
        level: Deep,
        clause: "12.4.8",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    // UNIT statements rescale angles and lengths (not modelled here): judge nothing.
    if !doc.head.units.is_empty() {
        return;
    }
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        let Some(entry) = node.entry("bboxSize") else {
            continue;
        };
        let Some(&[sx, sy, sz]) = entry.value.as_floats() else {
            continue;
        };
        if [sx, sy, sz] == [-1.0; 3]
            || node
                .connects
                .iter()
                .any(|c| c.node_field.text.starts_with("bbox"))
        {
            continue;
        }
        let size = [sx, sy, sz].map(f64::from);
        let center = match doc
            .value_of(id, "bboxCenter")
            .as_deref()
            .and_then(|v| v.as_floats())
        {
            Some(&[x, y, z]) => [x, y, z].map(f64::from),
            _ => continue,
        };
        if !size.iter().chain(&center).all(|v| v.is_finite()) || size.iter().any(|s| *s < 0.0) {
            continue;
        }
        let Some(actual) = bounds::content_bounds(doc, id, &Affine::IDENTITY) else {
            continue;
        };
        if !actual.exact || actual.is_empty() {
            continue;
        }
        if let Some(axis) = outside_axis(&actual, center, size) {
            found.push((id, entry.span, actual, axis));
        }
    }
    for (id, span, actual, axis) in found {
        let node = doc.node(id);
        let (center, size) = (actual.center(), actual.size());
        // A box beyond the f32 range could not be written in the SFVec3f fields.
        let help = center
            .iter()
            .chain(&size)
            .all(|v| (*v as f32).is_finite())
            .then(|| {
                format!(
                    "a box that fits: bboxCenter='{}' bboxSize='{}'",
                    triple(center),
                    triple(size)
                )
            });
        ctx.report(
            Diagnostic::new(
                &BBOX_TOO_SMALL,
                span,
                format!(
                    "{}.bboxSize does not enclose its {}: along {} the content spans {} to {}",
                    node.type_name(),
                    if node.type_name() == "Shape" {
                        "geometry"
                    } else {
                        "children"
                    },
                    ["x", "y", "z"][axis],
                    short(actual.min[axis]),
                    short(actual.max[axis])
                ),
            )
            .node(id)
            .help_opt(help),
        );
    }
}

/// The first axis along which `actual` leaves the declared box by more than the noise.
fn outside_axis(actual: &Bounds, center: [f64; 3], size: [f64; 3]) -> Option<usize> {
    let largest_side = size
        .iter()
        .chain(&actual.size())
        .fold(0.0f64, |m, s| m.max(*s));
    let largest_coordinate = actual
        .min
        .iter()
        .chain(&actual.max)
        .chain(&center)
        .fold(0.0f64, |m, c| m.max(c.abs()));
    let tolerance = 1e-4 * largest_side + 1e-6 * largest_coordinate;
    (0..3).find(|&i| {
        let (low, high) = (center[i] - size[i] / 2.0, center[i] + size[i] / 2.0);
        actual.min[i] < low - tolerance || actual.max[i] > high + tolerance
    })
}

/// A coordinate rounded to 6 decimals, which hides the noise of rotations (6e-17 for
/// cos π/2); from 1e7 on, where f32 has no decimals left, as `readable` gives it.
fn short(value: f64) -> String {
    if value.abs() >= 1e7 {
        return readable(value);
    }
    let text = format!("{value:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

fn triple(v: [f64; 3]) -> String {
    v.map(short).join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Bounds {
        Bounds {
            min: [-1.0; 3],
            max: [1.0; 3],
            exact: true,
        }
    }

    #[test]
    fn float_noise_is_tolerated_and_real_overhang_is_not() {
        assert_eq!(outside_axis(&unit(), [0.0; 3], [2.0; 3]), None);
        assert_eq!(outside_axis(&unit(), [0.0; 3], [1.99999; 3]), None);
        assert_eq!(outside_axis(&unit(), [0.0; 3], [1.99; 3]), Some(0));
        assert_eq!(outside_axis(&unit(), [0.0, 0.1, 0.0], [2.0; 3]), Some(1));
    }

    #[test]
    fn far_from_origin_uses_the_coordinate_scale() {
        let far = Bounds {
            min: [1e6 - 1.0, -1.0, -1.0],
            max: [1e6 + 1.0, 1.0, 1.0],
            exact: true,
        };
        // f32 near 1e6 has a 0.0625 step: a box written with f32 rounding still fits.
        assert_eq!(outside_axis(&far, [1e6 + 0.0625, 0.0, 0.0], [2.0; 3]), None);
        assert_eq!(outside_axis(&far, [1e6 + 5.0, 0.0, 0.0], [2.0; 3]), Some(0));
    }
}
