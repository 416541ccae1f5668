//! An EnvironmentLight's textures on the GPU (the split-sum image-based lighting of the
//! glTF Sample Viewer): the radiance cube prefiltered by GGX roughness into a mip chain,
//! an irradiance cube, and the table of the BRDF's integral over the hemisphere (Karis,
//! "Real Shading in Unreal Engine 4", 2013), which the shader reads by n·v and roughness.
//!
//! The prefilter and irradiance passes take any cube texture with filterable float texels
//! (mip levels, where it has them, make the prefiltering smoother).

use std::sync::OnceLock;

use wgpu::util::DeviceExt;

use super::pipelines::cube_entries;
use crate::render::cube_map::{cube_view, CubeImage};
use crate::render::draw_list::Environment;

/// Bits of `env_info.x` in the shader.
pub const ENV_SH: u32 = 1;
pub const ENV_SPECULAR: u32 = 2;
pub const ENV_DIFFUSE: u32 = 4;

/// The largest face of the prefiltered radiance, and of the computed irradiance.
const SPECULAR_SIZE: u32 = 128;
const IRRADIANCE_SIZE: u32 = 32;
/// The BRDF table's side (n·v across, roughness down) and its samples per entry.
const BRDF_SIZE: u32 = 64;
const BRDF_SAMPLES: u32 = 256;

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;
const ENVIRONMENT_WGSL: &str = include_str!("../environment.wgsl");

/// What the shader has of the environment (`ENV_…` bits): the SH irradiance, a
/// prefiltered radiance, an irradiance cube (given, or computed from the radiance when
/// there are no coefficients).
pub fn flags(environment: &Environment) -> u32 {
    let mut flags = 0;
    if environment.irradiance.is_some() {
        flags |= ENV_SH;
    }
    if environment.specular.is_some() {
        flags |= ENV_SPECULAR;
    }
    if environment.diffuse.is_some()
        || (environment.specular.is_some() && environment.irradiance.is_none())
    {
        flags |= ENV_DIFFUSE;
    }
    flags
}

/// Mip levels of the prefiltered radiance of a cube `size` texels wide: down to 4 × 4,
/// the last one for roughness 1.
pub fn specular_levels(size: u32) -> u32 {
    let size = size.clamp(1, SPECULAR_SIZE);
    (size.ilog2() + 1).saturating_sub(2).max(1)
}

/// The views group 0 of the shader binds beside the globals.
pub struct Maps {
    pub specular: wgpu::TextureView,
    pub diffuse: wgpu::TextureView,
    pub brdf: wgpu::TextureView,
    pub sampler: wgpu::Sampler,
}

impl Maps {
    /// A layer's maps: 1 × 1 black cubes where its environment has none.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        environment: Option<&Environment>,
    ) -> Maps {
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("environment"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        let blank = || cube_view(&CubeImage::uniform([0, 0, 0, 255]).upload(device, queue));
        let radiance = environment
            .and_then(|e| e.specular.as_ref())
            .map(|cube| cube.upload(device, queue));
        let specular = match &radiance {
            Some(source) => cube_view(&prefilter(device, queue, source, &sampler)),
            None => blank(),
        };
        let diffuse = match (environment, &radiance) {
            (
                Some(Environment {
                    diffuse: Some(cube),
                    ..
                }),
                _,
            ) => cube_view(&cube.upload(device, queue)),
            (Some(e), Some(source)) if e.irradiance.is_none() => {
                cube_view(&irradiance(device, queue, source, &sampler))
            }
            _ => blank(),
        };
        // Without an environment the table is not read: one texel stands in.
        let (side, table) = match environment {
            Some(_) => (BRDF_SIZE, brdf_table()),
            None => (1, &[0u8, 0, 0, 255][..]),
        };
        let brdf = device.create_texture_with_data(
            queue,
            &wgpu::TextureDescriptor {
                label: Some("brdf table"),
                size: wgpu::Extent3d {
                    width: side,
                    height: side,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba8Unorm,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            table,
        );
        Maps {
            specular,
            diffuse,
            brdf: brdf.create_view(&Default::default()),
            sampler,
        }
    }
}

/// The radiance `source` prefiltered by GGX: level m for roughness m / (levels − 1).
pub fn prefilter(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    source: &wgpu::Texture,
    sampler: &wgpu::Sampler,
) -> wgpu::Texture {
    let size = source.width().clamp(1, SPECULAR_SIZE);
    let levels = specular_levels(size);
    let target = cube_target(device, size, levels);
    let roughness = |level: u32| level as f32 / (levels - 1).max(1) as f32;
    draw_faces(
        device,
        queue,
        source,
        sampler,
        &target,
        "fs_prefilter",
        roughness,
    );
    target
}

/// The irradiance over π of the radiance `source`.
pub fn irradiance(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    source: &wgpu::Texture,
    sampler: &wgpu::Sampler,
) -> wgpu::Texture {
    let target = cube_target(device, IRRADIANCE_SIZE, 1);
    draw_faces(
        device,
        queue,
        source,
        sampler,
        &target,
        "fs_irradiance",
        |_| 1.0,
    );
    target
}

fn cube_target(device: &wgpu::Device, size: u32, levels: u32) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("environment map"),
        size: wgpu::Extent3d {
            width: size,
            height: size,
            depth_or_array_layers: 6,
        },
        mip_level_count: levels,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: FORMAT,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    })
}

/// Draws every face of every level of `target` with the fragment stage `entry`.
fn draw_faces(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    source: &wgpu::Texture,
    sampler: &wgpu::Sampler,
    target: &wgpu::Texture,
    entry: &str,
    roughness: impl Fn(u32) -> f32,
) {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("environment"),
        source: wgpu::ShaderSource::Wgsl(ENVIRONMENT_WGSL.into()),
    });
    let [cube, cube_sampler] = cube_entries(1);
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("environment pass"),
        entries: &[
            wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            },
            cube,
            cube_sampler,
        ],
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(entry),
        layout: Some(
            &device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("environment pass"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            }),
        ),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs_face"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            targets: &[Some(FORMAT.into())],
        }),
        multiview_mask: None,
        cache: None,
    });
    let source_view = cube_view(source);
    let mut encoder = device.create_command_encoder(&Default::default());
    for level in 0..target.mip_level_count() {
        let size = (target.width() >> level).max(1);
        for face in 0..6u32 {
            let words: [f32; 8] = [
                face as f32,
                roughness(level),
                size as f32,
                source.width() as f32,
                source.mip_level_count() as f32,
                0.0,
                0.0,
                0.0,
            ];
            let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("environment pass"),
                contents: bytemuck::bytes_of(&words),
                usage: wgpu::BufferUsages::UNIFORM,
            });
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: &layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: buffer.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(&source_view),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::Sampler(sampler),
                    },
                ],
            });
            let view = target.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_mip_level: level,
                mip_level_count: Some(1),
                base_array_layer: face,
                array_layer_count: Some(1),
                ..Default::default()
            });
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("environment face"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                ..Default::default()
            });
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &group, &[]);
            pass.draw(0..3, 0..1);
        }
    }
    queue.submit([encoder.finish()]);
}

/// The split-sum BRDF table, RGBA8: red the scale and green the bias on F0 of the
/// specular BRDF's hemispherical integral, by n·v (across, from 0) and roughness (down,
/// from 0), with the height-correlated Smith visibility of `light_physical`. Computed
/// once per process (~20 ms).
fn brdf_table() -> &'static [u8] {
    static TABLE: OnceLock<Vec<u8>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut out = Vec::with_capacity((BRDF_SIZE * BRDF_SIZE * 4) as usize);
        for row in 0..BRDF_SIZE {
            let roughness = (row as f32 + 0.5) / BRDF_SIZE as f32;
            for column in 0..BRDF_SIZE {
                let n_dot_v = (column as f32 + 0.5) / BRDF_SIZE as f32;
                let (scale, bias) = integrate_brdf(n_dot_v, roughness);
                let byte = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
                out.extend_from_slice(&[byte(scale), byte(bias), 0, 255]);
            }
        }
        out
    })
}

/// ∫ f·(n·l) over the hemisphere for F0 = 1 split into the parts times F0 and times 1,
/// by GGX importance sampling (v in the xz plane, n = +z).
pub fn integrate_brdf(n_dot_v: f32, roughness: f32) -> (f32, f32) {
    let alpha = roughness * roughness;
    let alpha2 = alpha * alpha;
    let v = glam::Vec3::new((1.0 - n_dot_v * n_dot_v).max(0.0).sqrt(), 0.0, n_dot_v);
    let (mut scale, mut bias) = (0.0, 0.0);
    for i in 0..BRDF_SAMPLES {
        let (u1, u2) = (
            i as f32 / BRDF_SAMPLES as f32,
            i.reverse_bits() as f32 * 2.328_306_4e-10,
        );
        let cos_h = ((1.0 - u2) / (1.0 + (alpha2 - 1.0) * u2)).sqrt();
        let sin_h = (1.0 - cos_h * cos_h).max(0.0).sqrt();
        let phi = std::f32::consts::TAU * u1;
        let h = glam::Vec3::new(sin_h * phi.cos(), sin_h * phi.sin(), cos_h);
        let l = 2.0 * v.dot(h) * h - v;
        let (n_dot_l, n_dot_h, v_dot_h) = (l.z, h.z, v.dot(h).max(0.0));
        if n_dot_l <= 0.0 || n_dot_h <= 0.0 {
            continue;
        }
        let visibility = 0.5
            / (n_dot_l * (n_dot_v * n_dot_v * (1.0 - alpha2) + alpha2).sqrt()
                + n_dot_v * (n_dot_l * n_dot_l * (1.0 - alpha2) + alpha2).sqrt());
        // f·(n·l) / pdf with pdf = D (n·h) / (4 v·h): D cancels.
        let weight = 4.0 * visibility * n_dot_l * v_dot_h / n_dot_h;
        let fresnel = (1.0 - v_dot_h).powi(5);
        scale += (1.0 - fresnel) * weight;
        bias += fresnel * weight;
    }
    (scale / BRDF_SAMPLES as f32, bias / BRDF_SAMPLES as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The integral of a smooth surface seen head-on is F0 (scale 1, bias 0); every
    /// entry stays within [0, 1] as energy conservation requires.
    #[test]
    fn the_brdf_integral_is_bounded_and_a_mirror_reflects_f0() {
        let (scale, bias) = integrate_brdf(1.0, 0.02);
        assert!((scale - 1.0).abs() < 0.02 && bias < 0.01, "{scale} {bias}");
        for r in [0.1, 0.5, 1.0] {
            for v in [0.05, 0.5, 1.0] {
                let (s, b) = integrate_brdf(v, r);
                assert!(s >= 0.0 && b >= 0.0 && s + b <= 1.01, "{v} {r}: {s} {b}");
            }
        }
    }

    #[test]
    fn specular_levels_reach_four_texels() {
        assert_eq!(specular_levels(128), 6);
        assert_eq!(specular_levels(16), 3);
        assert_eq!(specular_levels(1), 1);
    }
}
