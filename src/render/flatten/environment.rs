//! The bindable environment nodes a still image uses: the first Background (sky and
//! ground gradients, the panorama's six images), Fog and NavigationInfo (headlight, near and far planes) of the
//! checked document in each layer, as a browser binds the first of each (24.2, 23.2;
//! each layer has its own binding stacks, 35.2.3).

use glam::{DMat4, DQuat};

use super::{Context, Walker};
use crate::model::NodeId;
use crate::render::cube_map;
use crate::render::draw_list::{Background, Fog, MAX_GRADIENT};
use crate::render::fields::{boolean, color, float, floats, unit};

#[derive(Default)]
pub struct Environment {
    pub background: Option<Background>,
    /// The first Fog, once bound (None inside: it is off, visibilityRange 0).
    pub fog: Option<Option<Fog>>,
    pub navigation: Option<Navigation>,
}

#[derive(Clone, Copy)]
pub struct Navigation {
    pub headlight: bool,
    pub avatar_size: Option<f32>,
    pub visibility_limit: f32,
}

impl Environment {
    /// NavigationInfo.headlight, TRUE without a NavigationInfo.
    pub fn headlight(&self) -> bool {
        self.navigation.is_none_or(|n| n.headlight)
    }
}

impl Walker<'_> {
    pub(super) fn environment_node(&mut self, context: Context, id: NodeId, world: DMat4) {
        if context.serial != 0 {
            return;
        }
        let doc = context.doc;
        let node = doc.node(id);
        let name = node.type_name();
        if node.is_a("X3DBackgroundNode") {
            if self.environment.background.is_some() {
                return;
            }
            let (_, rotation, _) = world.to_scale_rotation_translation();
            let mut background = Background {
                sky: self.gradient(context, id, "skyColor", "skyAngle", std::f32::consts::PI),
                ground: self.gradient(
                    context,
                    id,
                    "groundColor",
                    "groundAngle",
                    std::f32::consts::FRAC_PI_2,
                ),
                orientation: if rotation.is_finite() {
                    rotation.normalize().as_quat()
                } else {
                    DQuat::IDENTITY.as_quat()
                },
                // X3D 4: how much of the layers below shows through (24.4.1).
                transparency: unit(float(doc, id, "transparency", 0.0)),
                panorama: None,
            };
            let mut notes = Vec::new();
            let panorama = cube_map::background(
                doc,
                id,
                context.base,
                &self.options.root,
                self.cube_side(),
                &mut notes,
            );
            if !notes.is_empty() {
                // One note for the faces left transparent, as a browser shows them.
                let reasons: Vec<&str> = notes.iter().map(|n| n.message.as_str()).collect();
                let message = format!(
                    "{name}: panorama faces drawn transparent: {}",
                    reasons.join("; ")
                );
                self.push_note(context, id, message, notes.iter().any(|n| n.limit));
            }
            background.panorama = panorama.and_then(|cube| self.add_cube(context, id, cube));
            self.environment.background = Some(background);
        } else if name == "Fog" {
            if self.environment.fog.is_some() {
                return;
            }
            let range = float(doc, id, "visibilityRange", 0.0);
            // A visibilityRange of 0 disables fog (24.4.2); it still binds.
            self.environment.fog = Some((range > 0.0).then(|| Fog {
                color: color(doc, id, "color", [1.0; 3]),
                exponential: doc.string_of(id, "fogType").as_deref() == Some("EXPONENTIAL"),
                visibility_range: range,
            }));
        } else if name == "NavigationInfo" {
            if self.environment.navigation.is_some() {
                return;
            }
            let avatar = floats(doc, id, "avatarSize");
            self.environment.navigation = Some(Navigation {
                headlight: boolean(doc, id, "headlight", true),
                avatar_size: avatar
                    .first()
                    .copied()
                    .filter(|a| a.is_finite() && *a > 0.0),
                visibility_limit: float(doc, id, "visibilityLimit", 0.0).max(0.0),
            });
        }
    }

    /// Colours with the angles they apply at: the first at 0, the i-th at angle i − 1,
    /// angles clamped to [previous, limit] (24.4.1).
    fn gradient(
        &mut self,
        context: Context,
        id: NodeId,
        colors: &str,
        angles: &str,
        limit: f32,
    ) -> Vec<([f32; 3], f32)> {
        let doc = context.doc;
        let values = floats(doc, id, colors);
        let angle_values = floats(doc, id, angles);
        let mut out: Vec<([f32; 3], f32)> = Vec::new();
        for (i, c) in values.chunks_exact(3).enumerate() {
            let angle = if i == 0 {
                0.0
            } else {
                match angle_values.get(i - 1) {
                    Some(a) if a.is_finite() => a.clamp(out.last().map_or(0.0, |e| e.1), limit),
                    // A colour without its angle is not shown (24.4.1: N colours, N − 1 angles).
                    _ => break,
                }
            };
            if out.len() == MAX_GRADIENT {
                let name = doc.node(id).type_name();
                self.note(
                    context,
                    id,
                    format!(
                        "{name}.{colors}: colours beyond the first {MAX_GRADIENT} are not drawn"
                    ),
                );
                break;
            }
            out.push(([unit(c[0]), unit(c[1]), unit(c[2])], angle));
        }
        out
    }
}
