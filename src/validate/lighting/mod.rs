//! Lighting component (clause 17), RULES.md §4.

pub mod attenuation_zero;
pub mod light_direction_zero;
pub mod light_radius_zero;
pub mod light_reaches_nothing;
pub mod physical_ambient_intensity;
pub mod spot_beam_exceeds_cutoff;

use super::Check;
use crate::model::{Document, Node, NodeId, Span};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &spot_beam_exceeds_cutoff::CHECK,
    &light_direction_zero::CHECK,
    &light_radius_zero::CHECK,
    &attenuation_zero::CHECK,
    &physical_ambient_intensity::CHECK,
    &light_reaches_nothing::CHECK,
];

/// PointLight and SpotLight: the lights with a location and a radius.
fn is_positional_light(node: &Node) -> bool {
    matches!(node.type_name(), "PointLight" | "SpotLight")
}

/// Lights that `accepts` and that set `field` themselves (not through `IS`) to a value
/// `matches` holds for: each with the value's span and the light's type name. The
/// texture projectors (clause 42), lights of images, use it too.
pub(crate) fn lights_setting<'a>(
    doc: &'a Document,
    accepts: impl Fn(&Node) -> bool,
    field: &str,
    matches: impl Fn(&[f32]) -> bool,
) -> Vec<(NodeId, Span, &'a str)> {
    doc.iter()
        .filter(|(_, node)| accepts(node) && !node.is_connected(field))
        .filter_map(|(id, node)| {
            let entry = node.entry(field)?;
            let values = entry.value.as_floats()?;
            matches(values).then_some((id, entry.span, node.type_name()))
        })
        .collect()
}

/// Every component zero (-0 included).
pub(crate) fn all_zero(values: &[f32]) -> bool {
    values.len() == 3 && values.iter().all(|c| *c == 0.0)
}
