//! The uniform blocks of `shader.wgsl`, filled from the draw list. Field order and sizes
//! match the WGSL structs (every member a 16-byte vector, so no hidden padding).

use bytemuck::{Pod, Zeroable};

use crate::render::cube_map::{CubeFormat, CubeImage};
use crate::render::draw_list::{
    Camera, Layer, LightKind, LightingModel, Material, Mesh, Primitive, Projection, TextureRef,
    MAX_CLIP_PLANES, MAX_GRADIENT, MAX_LIGHTS, MAX_STAGES,
};

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
pub struct GpuLight {
    color_intensity: [f32; 4],
    location_kind: [f32; 4],
    direction_ambient: [f32; 4],
    attenuation_radius: [f32; 4],
    spot: [f32; 4],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
pub struct Globals {
    view_projection: [[f32; 4]; 4],
    background_from_clip: [[f32; 4]; 4],
    camera_from_world: [[f32; 4]; 4],
    environment: [u32; 4],
    viewport: [f32; 4],
    forward_near: [f32; 4],
    fog_color_range: [f32; 4],
    counts: [u32; 4],
    sky: [[f32; 4]; MAX_GRADIENT],
    ground: [[f32; 4]; MAX_GRADIENT],
    lights: [GpuLight; MAX_LIGHTS],
    /// The EnvironmentLight's SH irradiance coefficients (rgb).
    env_sh: [[f32; 4]; 9],
    /// Columns of the rotation from world axes to the environment's.
    env_from_world: [[f32; 4]; 3],
    /// What it has (`environment::ENV_…`), its prefiltered mip levels.
    env_info: [u32; 4],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
pub struct GpuMaterial {
    diffuse_alpha: [f32; 4],
    emissive_model: [f32; 4],
    specular_shininess: [f32; 4],
    params: [f32; 4],
    extra: [f32; 4],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
pub struct GpuDraw {
    front: GpuMaterial,
    back: GpuMaterial,
    misc: [u32; 4],
    sets_main: [u32; 4],
    sets_roles: [u32; 4],
    sets_more: [u32; 4],
    factor: [f32; 4],
    cutoff: [f32; 4],
    stroke: [f32; 4],
    stroke_attenuation: [f32; 4],
    stages: [[u32; 4]; MAX_STAGES],
    clip_planes: [[f32; 4]; MAX_CLIP_PLANES],
}

/// Bits of the roles present (`ROLE_…` in the shader).
const ROLE_EMISSIVE: u32 = 1;
const ROLE_NORMAL: u32 = 2;
const ROLE_OCCLUSION: u32 = 4;
const ROLE_SPECULAR_OR_MR: u32 = 8;
const ROLE_SHININESS: u32 = 16;
const ROLE_AMBIENT: u32 = 32;

fn gpu_material(m: &Material) -> GpuMaterial {
    let model = match m.model {
        LightingModel::Unlit => 0.0,
        LightingModel::Phong => 1.0,
        LightingModel::Physical => 2.0,
    };
    let [dr, dg, db] = m.diffuse;
    let [er, eg, eb] = m.emissive;
    let [sr, sg, sb] = m.specular;
    GpuMaterial {
        diffuse_alpha: [dr, dg, db, m.alpha],
        emissive_model: [er, eg, eb, model],
        specular_shininess: [sr, sg, sb, m.shininess],
        params: [m.ambient_intensity, m.metallic, m.roughness, m.normal_scale],
        extra: [
            m.occlusion_strength,
            f32::from(u8::from(m.texture_replaces_rgb)),
            f32::from(u8::from(m.ambient_of_diffuse_factor)),
            0.0,
        ],
    }
}

/// `cubes`: the draw list's cube textures (a cube map stage's is looked up).
pub fn draw_uniform(mesh: &Mesh, cubes: &[CubeImage]) -> GpuDraw {
    let front = gpu_material(&mesh.front);
    let textures = &mesh.textures;
    let color_mode = match (&mesh.colors, mesh.colors_have_alpha) {
        (None, _) => 0,
        (Some(_), false) => 1,
        (Some(_), true) => 2,
    };
    let set = |t: Option<TextureRef>| t.map_or(0, |t| t.tex_coords as u32);
    let specular_or_mr = textures.specular.or(textures.metallic_roughness);
    let mut roles = 0;
    for (present, bit) in [
        (textures.emissive.is_some(), ROLE_EMISSIVE),
        (
            textures.normal.is_some() && mesh.tangents.is_some(),
            ROLE_NORMAL,
        ),
        (textures.occlusion.is_some(), ROLE_OCCLUSION),
        (specular_or_mr.is_some(), ROLE_SPECULAR_OR_MR),
        (textures.shininess.is_some(), ROLE_SHININESS),
        (textures.ambient.is_some(), ROLE_AMBIENT),
    ] {
        if present {
            roles |= bit;
        }
    }
    let mut sets_main = [0; 4];
    let mut stages = [[0; 4]; MAX_STAGES];
    for (i, stage) in textures.main.iter().take(MAX_STAGES).enumerate() {
        sets_main[i] = stage.texture.tex_coords as u32;
        stages[i] = [
            stage.mode as u32,
            stage.alpha_mode as u32,
            stage.source as u32,
            stage.function as u32,
        ];
    }
    let mut clip_planes = [[0.0; 4]; MAX_CLIP_PLANES];
    for (slot, plane) in clip_planes.iter_mut().zip(&mesh.clip_planes) {
        *slot = *plane;
    }
    GpuDraw {
        front,
        back: mesh.back.as_ref().map_or(front, gpu_material),
        misc: [
            mesh.light_mask,
            color_mode,
            roles,
            textures.main.len().min(MAX_STAGES) as u32,
        ],
        sets_main,
        sets_roles: [
            set(textures.emissive),
            set(textures.normal),
            set(textures.occlusion),
            set(specular_or_mr),
        ],
        sets_more: [
            set(textures.shininess),
            set(textures.ambient),
            mesh.clip_planes.len().min(MAX_CLIP_PLANES) as u32,
            // The first stage's cube map: how it is looked up, and bit 2 for linear texels.
            textures
                .main
                .first()
                .and_then(|stage| stage.cube)
                .map_or(0, |lookup| {
                    let linear = cubes
                        .get(textures.main[0].texture.texture)
                        .is_some_and(|c| c.format == CubeFormat::Rgba16Float);
                    lookup as u32 | u32::from(linear) << 2
                }),
        ],
        factor: textures.factor,
        cutoff: [mesh.alpha_cutoff, 0.0, 0.0, 0.0],
        stroke: [
            mesh.stroke.size,
            mesh.stroke.min,
            mesh.stroke.max,
            f32::from(u8::from(mesh.primitive == Primitive::Points)),
        ],
        stroke_attenuation: {
            let [a, b, c] = mesh.stroke.attenuation;
            [a, b, c, mesh.stroke.linetype as f32]
        },
        stages,
        clip_planes,
    }
}

impl Globals {
    /// The camera as the vertex shaders apply it, for a layer drawn within `rect`.
    pub fn camera(&self, rect: [u32; 4]) -> super::reach::Camera {
        super::reach::Camera {
            view_projection: glam::Mat4::from_cols_array_2d(&self.view_projection),
            forward_near: glam::Vec4::from(self.forward_near),
            rect,
        }
    }
}

/// A layer's uniforms for its `width` × `height` rectangle of a target drawn `scale`
/// times larger than the image (supersampling): stroke sizes are in image pixels.
pub fn globals(list: &Layer, width: u32, height: u32, scale: u32, cubes: &[CubeImage]) -> Globals {
    let camera = &list.camera;
    let projection = projection(camera, width as f32 / height as f32);
    let view = glam::Mat4::from_quat(camera.orientation.inverse());
    let view_projection = projection * view;
    let background = list.background.clone().unwrap_or_default();
    let to_background = glam::Mat4::from_quat(background.orientation.inverse());
    let mut lights = [GpuLight::zeroed(); MAX_LIGHTS];
    for (slot, light) in lights.iter_mut().zip(&list.lights) {
        let kind = match light.kind {
            LightKind::Directional => 0.0,
            LightKind::Point => 1.0,
            LightKind::Spot => 2.0,
            LightKind::Environment => 3.0,
        };
        let [r, g, b] = light.color;
        let [x, y, z] = light.location;
        let [dx, dy, dz] = light.direction;
        let [c1, c2, c3] = light.attenuation;
        *slot = GpuLight {
            color_intensity: [r, g, b, light.intensity],
            location_kind: [x, y, z, kind],
            direction_ambient: [dx, dy, dz, light.ambient_intensity],
            attenuation_radius: [c1, c2, c3, light.radius],
            spot: [light.beam_width, light.cut_off_angle, 0.0, 0.0],
        };
    }
    let (fog_kind, fog_color_range) = match &list.fog {
        None => (0, [0.0; 4]),
        Some(fog) => {
            let [r, g, b] = fog.color;
            (
                if fog.exponential { 2 } else { 1 },
                [r, g, b, fog.visibility_range],
            )
        }
    };
    let gradient = |entries: &[([f32; 3], f32)]| {
        let mut out = [[0.0; 4]; MAX_GRADIENT];
        for (slot, ([r, g, b], angle)) in out.iter_mut().zip(entries) {
            *slot = [*r, *g, *b, *angle];
        }
        out
    };
    Globals {
        view_projection: view_projection.to_cols_array_2d(),
        background_from_clip: (to_background * view_projection.inverse()).to_cols_array_2d(),
        camera_from_world: view.to_cols_array_2d(),
        environment: [
            u32::from(
                background
                    .panorama
                    .and_then(|p| cubes.get(p))
                    .is_some_and(|c| c.format == CubeFormat::Rgba16Float),
            ),
            0,
            0,
            0,
        ],
        viewport: [
            width as f32,
            height as f32,
            scale as f32,
            background.transparency,
        ],
        forward_near: {
            let forward = camera.orientation * glam::Vec3::NEG_Z;
            [forward.x, forward.y, forward.z, camera.near]
        },
        fog_color_range,
        counts: [
            fog_kind,
            list.lights.len().min(MAX_LIGHTS) as u32,
            background.sky.len().clamp(1, MAX_GRADIENT) as u32,
            background.ground.len().min(MAX_GRADIENT) as u32,
        ],
        sky: gradient(&background.sky),
        ground: gradient(&background.ground),
        lights,
        env_sh: match list.environment.as_ref().and_then(|e| e.irradiance) {
            Some(sh) => sh.map(|[r, g, b]| [r, g, b, 0.0]),
            None => [[0.0; 4]; 9],
        },
        env_from_world: {
            let rotation = list
                .environment
                .as_ref()
                .map_or(glam::Quat::IDENTITY, |e| e.from_world);
            let m = glam::Mat3::from_quat(rotation);
            [m.x_axis, m.y_axis, m.z_axis].map(|c| c.extend(0.0).to_array())
        },
        env_info: match &list.environment {
            Some(e) => [
                super::environment::flags(e),
                super::environment::specular_levels(e.specular.as_ref().map_or(1, |c| c.side)),
                0,
                0,
            ],
            None => [0; 4],
        },
    }
}

/// Into WebGPU clip space with reversed depth (near → 1, far → 0), which spreads f32
/// depth precision evenly over distance.
fn projection(camera: &Camera, aspect: f32) -> glam::Mat4 {
    let (near, far) = (f64::from(camera.near), f64::from(camera.far));
    match camera.projection {
        Projection::Perspective { field_of_view } => {
            // The field of view applies to the smaller side (Viewpoint.fieldOfView).
            let fov_y = if aspect >= 1.0 {
                field_of_view
            } else {
                2.0 * ((field_of_view / 2.0).tan() / aspect).atan()
            };
            let f = 1.0 / (fov_y / 2.0).tan();
            let a = (near / (far - near)) as f32;
            let b = (near * far / (far - near)) as f32;
            glam::Mat4::from_cols(
                glam::Vec4::new(f / aspect, 0.0, 0.0, 0.0),
                glam::Vec4::new(0.0, f, 0.0, 0.0),
                glam::Vec4::new(0.0, 0.0, a, -1.0),
                glam::Vec4::new(0.0, 0.0, b, 0.0),
            )
        }
        Projection::Orthographic {
            rectangle: [min_x, min_y, max_x, max_y],
        } => {
            // OrthoViewpoint (23.4.5): the smaller dimension is widened to the image's
            // aspect ratio, about the rectangle's centre.
            let (mut half_w, mut half_h) = ((max_x - min_x) / 2.0, (max_y - min_y) / 2.0);
            let (cx, cy) = ((min_x + max_x) / 2.0, (min_y + max_y) / 2.0);
            if half_w / half_h < aspect {
                half_w = half_h * aspect;
            } else {
                half_h = half_w / aspect;
            }
            let depth = (far - near) as f32;
            glam::Mat4::from_cols(
                glam::Vec4::new(1.0 / half_w, 0.0, 0.0, 0.0),
                glam::Vec4::new(0.0, 1.0 / half_h, 0.0, 0.0),
                glam::Vec4::new(0.0, 0.0, 1.0 / depth, 0.0),
                glam::Vec4::new(-cx / half_w, -cy / half_h, far as f32 / depth, 1.0),
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera(projection: Projection) -> Camera {
        Camera {
            orientation: glam::Quat::IDENTITY,
            projection,
            near: 0.5,
            far: 50.0,
        }
    }

    #[test]
    fn depth_is_reversed_in_both_projections() {
        for projection in [
            Projection::Perspective { field_of_view: 0.8 },
            Projection::Orthographic {
                rectangle: [-1.0, -2.0, 3.0, 2.0],
            },
        ] {
            let m = super::projection(&camera(projection), 1.5);
            let depth = |z: f32| {
                let c = m * glam::Vec4::new(0.0, 0.0, z, 1.0);
                c.z / c.w
            };
            assert!((depth(-0.5) - 1.0).abs() < 1e-5, "{projection:?}");
            assert!(depth(-50.0).abs() < 1e-5, "{projection:?}");
        }
    }

    #[test]
    fn orthographic_rectangle_fills_the_image_keeping_its_aspect() {
        // A 4 × 4 rectangle centred at (1, 0) in a 2:1 image: x widens to ±4 about 1.
        let m = super::projection(
            &camera(Projection::Orthographic {
                rectangle: [-1.0, -2.0, 3.0, 2.0],
            }),
            2.0,
        );
        let at = |x: f32, y: f32| {
            let c = m * glam::Vec4::new(x, y, -1.0, 1.0);
            (c.x / c.w, c.y / c.w)
        };
        assert_eq!(at(1.0, 0.0), (0.0, 0.0));
        let (x, y) = at(5.0, 2.0);
        assert!((x - 1.0).abs() < 1e-6 && (y - 1.0).abs() < 1e-6, "{x} {y}");
    }
}
