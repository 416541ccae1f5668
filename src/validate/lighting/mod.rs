//! Lighting component (clause 17), RULES.md §4.

pub mod attenuation_zero;
pub mod light_direction_zero;
pub mod light_radius_zero;
pub mod light_reaches_nothing;
pub mod physical_ambient_intensity;
pub mod spot_beam_exceeds_cutoff;

use super::Rule;
use crate::model::Node;

/// This group's rules, in catalogue order.
pub static RULES: &[&Rule] = &[
    &spot_beam_exceeds_cutoff::SPOT_BEAM_EXCEEDS_CUTOFF,
    &light_direction_zero::LIGHT_DIRECTION_ZERO,
    &light_radius_zero::LIGHT_RADIUS_ZERO,
    &attenuation_zero::ATTENUATION_ZERO,
    &physical_ambient_intensity::PHYSICAL_AMBIENT_INTENSITY,
    &light_reaches_nothing::LIGHT_REACHES_NOTHING,
];

/// PointLight and SpotLight: the lights with a location and a radius.
fn is_positional_light(node: &Node) -> bool {
    matches!(node.type_name(), "PointLight" | "SpotLight")
}
