//! Every rule, group by group in catalogue order (RULES.md §1–§8). `x3dcheck rules`, the
//! docs, the fixtures test and the checks all read this. Each group lists its own rules in
//! its `mod.rs`.

use std::sync::LazyLock;

use super::{
    document, environmental_effects, events, geometry2d, geometry3d, geospatial, grouping, hanim,
    interpolation, layering, layout, lighting, navigation, networking, nurbs, particles, picking,
    prototypes, rendering, rigid_body, scripting, sensors, shaders, shape, sound, text,
    texture_projection, texturing, Check,
};
use crate::diagnostic::{find_rule_in, Rule};

/// Every rule with its check function (None for those reported while reading).
pub static CHECKS: LazyLock<Vec<&'static Check>> = LazyLock::new(|| {
    [
        document::RULES,
        shape::RULES,
        rendering::RULES,
        geometry2d::RULES,
        geometry3d::RULES,
        text::RULES,
        lighting::RULES,
        texturing::RULES,
        events::RULES,
        prototypes::RULES,
        shaders::RULES,
        networking::RULES,
        grouping::RULES,
        scripting::RULES,
        interpolation::RULES,
        sensors::RULES,
        navigation::RULES,
        environmental_effects::RULES,
        nurbs::RULES,
        hanim::RULES,
        geospatial::RULES,
        sound::RULES,
        particles::RULES,
        rigid_body::RULES,
        picking::RULES,
        texture_projection::RULES,
        layering::RULES,
        layout::RULES,
    ]
    .concat()
});

/// Every rule, in catalogue order.
pub static RULES: LazyLock<Vec<&'static Rule>> =
    LazyLock::new(|| CHECKS.iter().map(|check| check.rule).collect());

pub fn find_rule(code: &str) -> Option<&'static Rule> {
    find_rule_in(&RULES, code)
}
