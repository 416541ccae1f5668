//! LIGHT_REACHES_NOTHING: a PointLight or SpotLight whose radius reaches no shape.

use std::collections::HashMap;

use super::is_positional_light;
use crate::diagnostic::Diagnostic;
use crate::model::bounds::{self, Affine, Bounds};
use crate::model::NodeId;
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a PointLight or SpotLight none of whose instances in the scene graph reaches
    /// the bounds of any Shape. The light's sphere of influence is its `location` and
    /// `radius` carried to world space by the transforms above it: "scales affect radius
    /// and transformations affect location"; under a non-uniform scale the sphere becomes
    /// an ellipsoid, which is enclosed here by the sphere of the largest stretch. Shapes
    /// count by their world bounds (every Switch choice, every LOD level, every USE).
    ///
    /// The test is conservative: a SpotLight counts as a PointLight (its cone is not
    /// used), `global FALSE` lights are tested against every shape, and nothing is reported
    /// when some part of the scene has unknown bounds (Text, Inline, prototypes, HAnim,
    /// geospatial nodes). Lights with radius 0 are LIGHT_RADIUS_ZERO's.
    ///
    /// ## Why it matters
    /// 17.4.3, 17.4.4: the light "does not emit light outside this radius". A light whose
    /// radius falls short of every shape costs rendering time and lights nothing, usually
    /// because the radius was written in other units than the scene or a scale shrank it.
    ///
    /// ## Example
    /// ```xml
    /// <PointLight location='0 50 0' radius='10'/>
    /// <Shape><Box/></Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 17.4.3 PointLight, 17.4.4 SpotLight.
    pub static LIGHT_REACHES_NOTHING = {
        severity: Info,
        level: Deep,
        clause: "17.4.3",
        versions: "all",
        check: Some(check),
    }
}

/// One placement of a light in the world: its centre and how far it reaches.
struct Reach {
    center: [f64; 3],
    radius: f64,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    // UNIT statements rescale angles and lengths (not modelled here): judge nothing.
    if !doc.head.units.is_empty() {
        return;
    }
    // The shapes' bounds, a walk over every point, matter only when there is a light.
    if !doc.iter().any(|(_, node)| is_positional_light(node)) {
        return;
    }
    let mut shapes: Vec<Bounds> = Vec::new();
    let mut lights: HashMap<NodeId, Vec<Reach>> = HashMap::new();
    let mut unknown = false;
    let complete = bounds::visit_scene(doc, true, |id, to_world| {
        let node = doc.node(id);
        if node.is_a("X3DShapeNode") {
            match bounds::content_bounds(doc, id, to_world) {
                Some(b) if !b.is_empty() => shapes.push(b),
                Some(_) => {}
                None => unknown = true,
            }
        } else if is_positional_light(node)
            && !node.is_connected("radius")
            && !node.is_connected("location")
        {
            if let Some(reach) = reach(doc, id, to_world) {
                lights.entry(id).or_default().push(reach);
            }
        }
    });
    if !complete || unknown {
        return;
    }
    let mut found: Vec<(NodeId, f64)> = lights
        .into_iter()
        .filter_map(|(id, reaches)| {
            let nearest = reaches
                .iter()
                .map(|r| {
                    let gap = shapes
                        .iter()
                        .map(|b| distance_to_box(r.center, b))
                        .fold(f64::INFINITY, f64::min);
                    gap - r.radius
                })
                .fold(f64::INFINITY, f64::min);
            // A relative margin keeps rounding from deciding a light that just touches.
            let margin = 1e-9 * reaches.iter().map(|r| r.radius).fold(1.0, f64::max);
            (nearest > margin).then_some((id, nearest))
        })
        .collect();
    found.sort_by_key(|(id, _)| *id);
    for (id, short) in found {
        let node = doc.node(id);
        let span = node.entry("radius").map_or(node.name_span, |e| e.span);
        let message = if shapes.is_empty() {
            format!(
                "{}: the scene has no shape for it to light",
                node.type_name()
            )
        } else {
            format!(
                "{} reaches no shape: its radius falls {} short of the nearest shape's bounds",
                node.type_name(),
                readable(short)
            )
        };
        ctx.report(Diagnostic::new(&LIGHT_REACHES_NOTHING, span, message).node(id));
    }
}

fn reach(doc: &crate::model::Document, light: NodeId, to_world: &Affine) -> Option<Reach> {
    let radius = f64::from(doc.f32_of(light, "radius")?);
    let location = doc.value_of(light, "location")?;
    let location = location.as_floats().filter(|v| v.len() == 3)?;
    if radius <= 0.0 || !radius.is_finite() {
        return None;
    }
    let center = to_world.apply([location[0], location[1], location[2]].map(f64::from));
    let radius = radius * to_world.max_stretch();
    (center.iter().all(|c| c.is_finite()) && radius.is_finite()).then_some(Reach { center, radius })
}

/// Euclidean distance from a point to a box (0 inside).
fn distance_to_box(p: [f64; 3], b: &Bounds) -> f64 {
    let d: [f64; 3] = std::array::from_fn(|i| (b.min[i] - p[i]).max(p[i] - b.max[i]).max(0.0));
    d[0].hypot(d[1]).hypot(d[2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_to_box_is_zero_inside_and_euclidean_outside() {
        let b = Bounds {
            min: [0.0; 3],
            max: [1.0; 3],
            exact: true,
        };
        assert_eq!(distance_to_box([0.5; 3], &b), 0.0);
        assert_eq!(distance_to_box([4.0, 5.0, 0.5], &b), 5.0);
        assert!(distance_to_box([3e300, 3e300, 0.5], &b).is_finite());
    }
}
