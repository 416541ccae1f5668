//! Environmental effects component (clause 24): a background's sky and ground gradients.

pub mod background_angle_decreasing;
pub mod background_color_count_mismatch;

use super::Check;
use crate::model::Node;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &background_color_count_mismatch::CHECK,
    &background_angle_decreasing::CHECK,
];

/// A background's colour gradient: the part of the sphere it paints, its colour field and
/// the field of the angles between the colours.
pub(crate) struct Gradient {
    pub part: &'static str,
    pub colors: &'static str,
    pub angles: &'static str,
}

/// The sky (from the zenith) and the ground (from the nadir) of X3DBackgroundNode.
pub(crate) const GRADIENTS: [Gradient; 2] = [
    Gradient {
        part: "sky",
        colors: "skyColor",
        angles: "skyAngle",
    },
    Gradient {
        part: "ground",
        colors: "groundColor",
        angles: "groundAngle",
    },
];

/// Background and TextureBackground (and VRML97's Background).
pub(crate) fn is_background(node: &Node) -> bool {
    matches!(node.type_name(), "Background" | "TextureBackground")
}
