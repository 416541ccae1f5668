//! Light nodes (17.4) into draw-list lights: world location and direction composed in
//! f64, parameters clamped to what the lighting equations accept, and the headlight.

use glam::{DMat4, DQuat, DVec3};

use super::{place, Context, Walker};
use crate::model::NodeId;
use crate::render::cube_map::{self, CubeImage};
use crate::render::draw_list::{Environment, Light, LightKind, MAX_LIGHTS};
use crate::render::fields::{boolean, child, color, float, floats, rotation, unit, vec3};

/// The largest intensity drawn (4.x allows [0, ∞)).
pub const MAX_INTENSITY: f32 = 1e15;

/// The largest face side an EnvironmentLight texture is loaded at: the GPU prefilters the
/// radiance into faces of at most 128 texels, sampling this finer level for the sharpest
/// of them; an irradiance map has no detail beyond it.
const ENVIRONMENT_SIDE: u32 = 256;

pub struct PendingLight {
    pub light: Light,
    /// World location (point and spot lights), made relative to the eye at the end.
    pub location: DVec3,
}

impl Walker<'_> {
    /// Registers a light; its bit, or None when it is off or over the limit.
    pub(super) fn add_light(&mut self, context: Context, id: NodeId, world: DMat4) -> Option<u32> {
        let doc = context.doc;
        if !boolean(doc, id, "on", true) {
            return None;
        }
        if self.lights.len() >= MAX_LIGHTS - 1 {
            // One slot stays free for the headlight.
            self.note(
                context,
                id,
                format!("lights beyond the first {} are not drawn", MAX_LIGHTS - 1),
            );
            return None;
        }
        let kind = match doc.node(id).type_name() {
            "DirectionalLight" => LightKind::Directional,
            "PointLight" => LightKind::Point,
            "SpotLight" => LightKind::Spot,
            "EnvironmentLight" if self.image_light.is_some() => {
                self.note(
                    context,
                    id,
                    "only the first EnvironmentLight of a layer is drawn".into(),
                );
                return None;
            }
            "EnvironmentLight" => LightKind::Environment,
            other => {
                self.note(context, id, format!("{other} is not drawn"));
                return None;
            }
        };
        let direction = world.transform_vector3(DVec3::from_array(
            vec3(doc, id, "direction", [0.0, 0.0, -1.0]).map(f64::from),
        ));
        let location = world.transform_point3(DVec3::from_array(
            vec3(doc, id, "location", [0.0; 3]).map(f64::from),
        ));
        // 17.4.3: attenuation (0, 0, 0) is (1, 0, 0); negative values are out of range.
        let mut attenuation = vec3(doc, id, "attenuation", [1.0, 0.0, 0.0]).map(|c| c.max(0.0));
        if attenuation == [0.0; 3] {
            attenuation = [1.0, 0.0, 0.0];
        }
        let scale = world.to_scale_rotation_translation().0.abs().max_element();
        let radius = f64::from(float(doc, id, "radius", 100.0).max(0.0)) * scale;
        // 17.4.4: angles in [0, π/2]; a beamWidth beyond cutOffAngle is cutOffAngle.
        let cut_off_angle = float(doc, id, "cutOffAngle", std::f32::consts::FRAC_PI_2)
            .clamp(0.0, std::f32::consts::FRAC_PI_2);
        let beam_width =
            float(doc, id, "beamWidth", std::f32::consts::FRAC_PI_4).clamp(0.0, cut_off_angle);
        let light = Light {
            kind,
            color: color(doc, id, "color", [1.0; 3]),
            // Any intensity beyond MAX_INTENSITY already saturates every lit pixel; the cap
            // keeps the shader's sums finite.
            intensity: float(doc, id, "intensity", 1.0).clamp(0.0, MAX_INTENSITY),
            ambient_intensity: unit(float(doc, id, "ambientIntensity", 0.0)),
            location: [0.0; 3],
            direction: place::unit_vector(direction),
            attenuation,
            // NaN (an infinite scale times 0) reaches nothing; beyond f32, f32::MAX.
            radius: if radius.is_nan() {
                0.0
            } else {
                radius.min(f64::from(f32::MAX)) as f32
            },
            beam_width,
            cut_off_angle,
        };
        if kind == LightKind::Environment {
            let environment = self.image_light(context, id, world);
            self.image_light = Some(environment);
        }
        self.lights.push(PendingLight { light, location });
        Some(1 << (self.lights.len() - 1))
    }

    /// An EnvironmentLight's image-based part.
    fn image_light(&mut self, context: Context, id: NodeId, world: DMat4) -> Environment {
        let doc = context.doc;
        let turned = world.to_scale_rotation_translation().1 * rotation(doc, id, "rotation");
        let coefficients = floats(doc, id, "diffuseCoefficients");
        let irradiance = match coefficients.len() {
            0 => None,
            27 if coefficients.iter().all(|c| c.is_finite()) => Some(std::array::from_fn(|i| {
                std::array::from_fn(|c| coefficients[3 * i + c])
            })),
            n => {
                self.note(
                    context,
                    id,
                    format!(
                        "EnvironmentLight diffuseCoefficients is not used: it needs 27 finite \
                         values (nine RGB spherical harmonic coefficients), it has {n}"
                    ),
                );
                None
            }
        };
        let specular = self.environment_cube(context, id, "specularTexture");
        let diffuse = self.environment_cube(context, id, "diffuseTexture");
        if irradiance.is_some() && diffuse.is_some() {
            self.note(
                context,
                id,
                "EnvironmentLight has both diffuseCoefficients and a diffuseTexture: the \
                 diffuseTexture is drawn (X3D 4.1 does not say which one wins)"
                    .into(),
            );
        }
        if irradiance.is_none() && specular.is_none() && diffuse.is_none() {
            self.note(
                context,
                id,
                "EnvironmentLight without diffuseCoefficients or a drawn texture lights nothing"
                    .into(),
            );
        }
        Environment {
            from_world: turned.inverse().as_quat(),
            irradiance,
            specular,
            diffuse,
        }
    }

    /// The cube of an EnvironmentLight texture field, in linear light; None (noted) when
    /// it cannot be drawn.
    fn environment_cube(&mut self, context: Context, id: NodeId, field: &str) -> Option<CubeImage> {
        let doc = context.doc;
        let texture = child(doc, id, field)?;
        let name = doc.node(texture).type_name();
        if name == "GeneratedCubeMapTexture" {
            let message = format!(
                "EnvironmentLight {field}: GeneratedCubeMapTexture is not drawn: the scene \
                 around it is not rendered into it"
            );
            self.note(context, texture, message);
            return None;
        }
        let loaded = cube_map::load(
            doc,
            texture,
            context.base,
            &self.options.root,
            ENVIRONMENT_SIDE,
        );
        match loaded {
            Ok(cube) => {
                let cube = cube.linear();
                self.spend_on_cube(context, texture, cube.bytes())
                    .then_some(cube)
            }
            Err(not_drawn) => {
                let message = format!("EnvironmentLight {field}: {}", not_drawn.message);
                self.push_note(context, texture, message, not_drawn.limit);
                None
            }
        }
    }
}

/// NavigationInfo.headlight: a white directional light along the view (23.4.4).
pub fn headlight(orientation: DQuat) -> Light {
    Light {
        kind: LightKind::Directional,
        color: [1.0; 3],
        intensity: 1.0,
        ambient_intensity: 0.0,
        location: [0.0; 3],
        direction: place::unit_vector(orientation * DVec3::NEG_Z),
        attenuation: [1.0, 0.0, 0.0],
        radius: f32::INFINITY,
        beam_width: 0.0,
        cut_off_angle: 0.0,
    }
}
