//! The GPU part: draws a [`DrawList`] offscreen with wgpu and reads the image back. It
//! trusts the draw list's guarantees (see [`super::draw_list`]) and knows nothing of X3D.

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use wgpu::util::DeviceExt;

use super::cli_args::Quality;
use super::draw_list::{DrawList, LightKind, LightingModel, Material, Mesh, Primitive, MAX_LIGHTS};

/// Why no image could be made.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error(
        "no graphics adapter found (not even a software one); install Mesa's software \
         drivers, e.g. on Debian/Ubuntu `apt-get install mesa-vulkan-drivers` (lavapipe, \
         Vulkan) or `libegl1 libgl1-mesa-dri` (llvmpipe, OpenGL)"
    )]
    NoAdapter,
    #[error("the graphics device could not be opened: {0}")]
    Device(String),
    #[error("the graphics device failed while rendering: {0}")]
    Failed(String),
}

const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Renders the draw list into a `width` × `height` RGBA image (rows from the top).
pub fn render(
    list: &DrawList,
    width: u32,
    height: u32,
    quality: Quality,
) -> Result<image::RgbaImage, GpuError> {
    pollster::block_on(render_async(list, width, height, quality))
}

async fn render_async(
    list: &DrawList,
    width: u32,
    height: u32,
    quality: Quality,
) -> Result<image::RgbaImage, GpuError> {
    let (device, queue) = open_device().await?;
    let max_side = device.limits().max_texture_dimension_2d;
    let scale = quality.supersampling();
    let scale = if width * scale <= max_side && height * scale <= max_side {
        scale
    } else {
        1
    };
    if width > max_side || height > max_side {
        return Err(GpuError::Device(format!(
            "the image is larger than the device's largest texture ({max_side} pixels)"
        )));
    }
    let (target_width, target_height) = (width * scale, height * scale);
    let renderer = Renderer::new(&device, &queue, list, quality.msaa_samples());
    let pixels = renderer.draw(list, target_width, target_height).await?;
    let image = image::RgbaImage::from_raw(target_width, target_height, pixels)
        .ok_or_else(|| GpuError::Failed("the read-back image has the wrong size".into()))?;
    Ok(if scale == 1 {
        image
    } else {
        downsample(&image, scale)
    })
}

async fn open_device() -> Result<(wgpu::Device, wgpu::Queue), GpuError> {
    let adapter = find_adapter().await.ok_or(GpuError::NoAdapter)?;
    adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("x3dcheck"),
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            ..Default::default()
        })
        .await
        .map_err(|e| GpuError::Device(e.to_string()))
}

/// Any adapter, software ones included. Vulkan first (lavapipe is the most complete
/// software driver, and probing GL/EGL without a display prints warnings), then the
/// others; `WGPU_BACKEND` overrides the choice.
async fn find_adapter() -> Option<wgpu::Adapter> {
    let from_env = wgpu::Backends::from_env();
    let attempts = match from_env {
        Some(backends) => vec![backends],
        None => vec![
            wgpu::Backends::VULKAN | wgpu::Backends::METAL | wgpu::Backends::DX12,
            wgpu::Backends::GL,
        ],
    };
    for backends in attempts {
        let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle();
        descriptor.backends = backends;
        let instance = wgpu::Instance::new(descriptor);
        if let Ok(adapter) = instance
            .request_adapter(&wgpu::RequestAdapterOptions::default())
            .await
        {
            return Some(adapter);
        }
        if let Some(adapter) = instance
            .enumerate_adapters(backends)
            .await
            .into_iter()
            .next()
        {
            return Some(adapter);
        }
    }
    None
}

/// Averages `scale` × `scale` blocks (supersampling).
fn downsample(image: &image::RgbaImage, scale: u32) -> image::RgbaImage {
    let (width, height) = (image.width() / scale, image.height() / scale);
    let count = scale * scale;
    image::RgbaImage::from_fn(width, height, |x, y| {
        let mut sum = [0u32; 4];
        for dy in 0..scale {
            for dx in 0..scale {
                let p = image.get_pixel(x * scale + dx, y * scale + dy).0;
                for c in 0..4 {
                    sum[c] += u32::from(p[c]);
                }
            }
        }
        image::Rgba(sum.map(|s| ((s + count / 2) / count) as u8))
    })
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
struct GpuLight {
    color_intensity: [f32; 4],
    location_kind: [f32; 4],
    direction_ambient: [f32; 4],
    attenuation_radius: [f32; 4],
    spot: [f32; 4],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
struct Globals {
    view_projection: [[f32; 4]; 4],
    fog_color_range: [f32; 4],
    counts: [u32; 4],
    lights: [GpuLight; MAX_LIGHTS],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
struct GpuMaterial {
    diffuse_alpha: [f32; 4],
    emissive_model: [f32; 4],
    specular_shininess: [f32; 4],
    params: [f32; 4],
    flags: [u32; 4],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
struct GpuDraw {
    front: GpuMaterial,
    back: GpuMaterial,
    misc: [u32; 4],
    cutoff: [f32; 4],
}

#[repr(C)]
#[derive(Copy, Clone, Pod, Zeroable)]
struct Vertex {
    position: [f32; 3],
    normal: [f32; 3],
    color: [f32; 4],
    tex_coord: [f32; 2],
}

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
        params: [m.ambient_intensity, m.metallic, m.roughness, 0.0],
        flags: [
            u32::from(m.texture.is_some()),
            u32::from(m.texture_replaces_rgb),
            u32::from(m.texture_replaces_alpha),
            0,
        ],
    }
}

fn gpu_draw(mesh: &Mesh) -> GpuDraw {
    let front = gpu_material(&mesh.front);
    let color_mode = match &mesh.colors {
        None => 0,
        // ColorRGBA replaces alpha too; a Color node's alpha is 1 and keeps the material's.
        Some(colors) if colors.iter().any(|c| c[3] < 1.0) => 2,
        Some(_) => 1,
    };
    GpuDraw {
        front,
        back: mesh.back.as_ref().map_or(front, gpu_material),
        misc: [mesh.light_mask, color_mode, 0, 0],
        cutoff: [mesh.alpha_cutoff, 0.0, 0.0, 0.0],
    }
}

fn globals(list: &DrawList, aspect: f32) -> Globals {
    let camera = &list.camera;
    // The field of view applies to the smaller side (Viewpoint.fieldOfView).
    let fov_y = if aspect >= 1.0 {
        camera.field_of_view
    } else {
        2.0 * ((camera.field_of_view / 2.0).tan() / aspect).atan()
    };
    let projection = reversed_perspective(fov_y, aspect, camera.near, camera.far);
    let view = glam::Mat4::from_quat(camera.orientation.inverse());
    let mut lights = [GpuLight::zeroed(); MAX_LIGHTS];
    for (slot, light) in lights.iter_mut().zip(&list.lights) {
        let kind = match light.kind {
            LightKind::Directional => 0.0,
            LightKind::Point => 1.0,
            LightKind::Spot => 2.0,
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
    Globals {
        view_projection: (projection * view).to_cols_array_2d(),
        fog_color_range,
        counts: [fog_kind, list.lights.len().min(MAX_LIGHTS) as u32, 0, 0],
        lights,
    }
}

/// A right-handed perspective projection into WebGPU clip space with reversed depth
/// (near → 1, far → 0), which spreads f32 depth precision evenly over distance.
fn reversed_perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> glam::Mat4 {
    let f = 1.0 / (fov_y / 2.0).tan();
    let (near, far) = (f64::from(near), f64::from(far));
    let a = (near / (far - near)) as f32;
    let b = (near * far / (far - near)) as f32;
    glam::Mat4::from_cols(
        glam::Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        glam::Vec4::new(0.0, f, 0.0, 0.0),
        glam::Vec4::new(0.0, 0.0, a, -1.0),
        glam::Vec4::new(0.0, 0.0, b, 0.0),
    )
}

/// Which pipeline a mesh needs.
#[derive(Copy, Clone, PartialEq, Eq, Hash)]
struct PipelineKey {
    primitive: u8,
    blended: bool,
    cull_back: bool,
}

struct Renderer<'a> {
    device: &'a wgpu::Device,
    queue: &'a wgpu::Queue,
    samples: u32,
    shader: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    globals_layout: wgpu::BindGroupLayout,
    draw_layout: wgpu::BindGroupLayout,
    texture_bind_groups: Vec<wgpu::BindGroup>,
    white_bind_group: wgpu::BindGroup,
}

impl<'a> Renderer<'a> {
    fn new(
        device: &'a wgpu::Device,
        queue: &'a wgpu::Queue,
        list: &DrawList,
        samples: u32,
    ) -> Self {
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("x3d lighting"),
            source: wgpu::ShaderSource::Wgsl(include_str!("shader.wgsl").into()),
        });
        let uniform_entry = |dynamic: bool, size: usize| wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: dynamic,
                min_binding_size: wgpu::BufferSize::new(size as u64),
            },
            count: None,
        };
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[uniform_entry(false, size_of::<Globals>())],
        });
        let draw_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("draw"),
            entries: &[uniform_entry(true, size_of::<GpuDraw>())],
        });
        let texture_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("texture"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("x3d"),
            bind_group_layouts: &[
                Some(&globals_layout),
                Some(&draw_layout),
                Some(&texture_layout),
            ],
            immediate_size: 0,
        });
        let max_side = device.limits().max_texture_dimension_2d;
        let texture_bind_groups = list
            .textures
            .iter()
            .map(|t| {
                if t.width <= max_side && t.height <= max_side {
                    texture_bind_group(device, queue, &texture_layout, t)
                } else {
                    texture_bind_group(device, queue, &texture_layout, &white_texture())
                }
            })
            .collect();
        let white_bind_group = texture_bind_group(device, queue, &texture_layout, &white_texture());
        Renderer {
            device,
            queue,
            samples,
            shader,
            layout,
            globals_layout,
            draw_layout,
            texture_bind_groups,
            white_bind_group,
        }
    }

    fn pipeline(&self, key: PipelineKey) -> wgpu::RenderPipeline {
        let attributes = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x4, 3 => Float32x2];
        let topology = match key.primitive {
            0 => wgpu::PrimitiveTopology::TriangleList,
            1 => wgpu::PrimitiveTopology::LineList,
            _ => wgpu::PrimitiveTopology::PointList,
        };
        let blend = if key.blended {
            wgpu::BlendState::ALPHA_BLENDING
        } else {
            wgpu::BlendState::REPLACE
        };
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("x3d shapes"),
                layout: Some(&self.layout),
                vertex: wgpu::VertexState {
                    module: &self.shader,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: size_of::<Vertex>() as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &attributes,
                    })],
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    front_face: wgpu::FrontFace::Ccw,
                    cull_mode: key.cull_back.then_some(wgpu::Face::Back),
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(!key.blended),
                    depth_compare: Some(wgpu::CompareFunction::GreaterEqual),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: self.samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: &self.shader,
                    entry_point: Some("fs_main"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: COLOR_FORMAT,
                        blend: Some(blend),
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
    }

    async fn draw(&self, list: &DrawList, width: u32, height: u32) -> Result<Vec<u8>, GpuError> {
        let device = self.device;
        let extent = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let target = |format, samples, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: extent,
                mip_level_count: 1,
                sample_count: samples,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let resolved = target(
            COLOR_FORMAT,
            1,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let multisampled = (self.samples > 1).then(|| {
            target(
                COLOR_FORMAT,
                self.samples,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            )
        });
        let depth = target(
            DEPTH_FORMAT,
            self.samples,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let resolved_view = resolved.create_view(&Default::default());
        let multisampled_view = multisampled
            .as_ref()
            .map(|t| t.create_view(&Default::default()));
        let depth_view = depth.create_view(&Default::default());

        let globals = globals(list, width as f32 / height as f32);
        let globals_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("globals"),
            contents: bytemuck::bytes_of(&globals),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let globals_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &self.globals_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals_buffer.as_entire_binding(),
            }],
        });

        let order = draw_order(list);
        let alignment = device.limits().min_uniform_buffer_offset_alignment as usize;
        let stride = size_of::<GpuDraw>().div_ceil(alignment) * alignment;
        let mut draw_bytes = vec![0u8; stride * order.len().max(1)];
        for (slot, &index) in order.iter().enumerate() {
            let bytes = bytemuck::bytes_of(&gpu_draw(&list.meshes[index])).to_vec();
            draw_bytes[slot * stride..slot * stride + bytes.len()].copy_from_slice(&bytes);
        }
        let draw_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("draws"),
            contents: &draw_bytes,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let draw_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &self.draw_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &draw_buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(size_of::<GpuDraw>() as u64),
                }),
            }],
        });
        let buffers = order
            .iter()
            .map(|&index| self.mesh_buffers(&list.meshes[index]))
            .collect::<Result<Vec<_>, _>>()?;
        let mut pipelines: HashMap<PipelineKey, wgpu::RenderPipeline> = HashMap::new();
        for &index in &order {
            let key = pipeline_key(&list.meshes[index]);
            pipelines.entry(key).or_insert_with(|| self.pipeline(key));
        }

        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let [r, g, b] = list.background.map(f64::from);
            let (view, resolve_target) = match &multisampled_view {
                Some(ms) => (ms, Some(&resolved_view)),
                None => (&resolved_view, None),
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("scene"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a: 1.0 }),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(0.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_bind_group(0, &globals_group, &[]);
            for (slot, (&index, (vertices, indices))) in order.iter().zip(&buffers).enumerate() {
                let mesh = &list.meshes[index];
                pass.set_pipeline(&pipelines[&pipeline_key(mesh)]);
                pass.set_bind_group(1, &draw_group, &[(slot * stride) as u32]);
                let texture = mesh.front.texture.or(mesh.back.and_then(|b| b.texture));
                let group = texture
                    .and_then(|t| self.texture_bind_groups.get(t))
                    .unwrap_or(&self.white_bind_group);
                pass.set_bind_group(2, group, &[]);
                pass.set_vertex_buffer(0, vertices.slice(..));
                pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.indices.len() as u32, 0, 0..1);
            }
        }
        let pixels = self.read_back(encoder, &resolved, width, height).await?;
        Ok(pixels)
    }

    /// The mesh's vertex and index buffers. Vertices are interleaved in small batches
    /// straight into the mapped buffer: no full intermediate copy of a large mesh.
    fn mesh_buffers(&self, mesh: &Mesh) -> Result<(wgpu::Buffer, wgpu::Buffer), GpuError> {
        const BATCH: usize = 4096;
        let count = mesh.positions.len();
        let stride = size_of::<Vertex>();
        // A zero-sized buffer cannot be mapped; an empty mesh draws nothing anyway.
        let vertex_buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("vertices"),
            size: (count.max(1) * stride) as u64,
            usage: wgpu::BufferUsages::VERTEX,
            mapped_at_creation: true,
        });
        {
            let mut mapped = vertex_buffer
                .slice(..)
                .get_mapped_range_mut()
                .map_err(|e| GpuError::Failed(e.to_string()))?;
            let mut batch = Vec::with_capacity(BATCH.min(count));
            for start in (0..count).step_by(BATCH) {
                batch.clear();
                batch.extend((start..count.min(start + BATCH)).map(|i| Vertex {
                    position: mesh.positions[i],
                    normal: mesh.normals.as_ref().map_or([0.0; 3], |n| n[i]),
                    color: mesh.colors.as_ref().map_or([1.0; 4], |c| c[i]),
                    tex_coord: mesh.tex_coords.as_ref().map_or([0.0; 2], |t| t[i]),
                }));
                let bytes: &[u8] = bytemuck::cast_slice(&batch);
                mapped
                    .slice(start * stride..start * stride + bytes.len())
                    .copy_from_slice(bytes);
            }
        }
        vertex_buffer.unmap();
        let index_buffer = self
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("indices"),
                contents: bytemuck::cast_slice(&mesh.indices),
                usage: wgpu::BufferUsages::INDEX,
            });
        Ok((vertex_buffer, index_buffer))
    }

    async fn read_back(
        &self,
        mut encoder: wgpu::CommandEncoder,
        texture: &wgpu::Texture,
        width: u32,
        height: u32,
    ) -> Result<Vec<u8>, GpuError> {
        let row = width * 4;
        let padded_row =
            row.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("read back"),
            size: u64::from(padded_row) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row),
                    rows_per_image: Some(height),
                },
            },
            wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
        );
        self.queue.submit([encoder.finish()]);
        let slice = buffer.slice(..);
        let (sender, receiver) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |result| {
            let _ = sender.send(result);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Failed(e.to_string()))?;
        receiver
            .recv()
            .map_err(|e| GpuError::Failed(e.to_string()))?
            .map_err(|e| GpuError::Failed(e.to_string()))?;
        let mapped = slice
            .get_mapped_range()
            .map_err(|e| GpuError::Failed(e.to_string()))?;
        let mut pixels = Vec::with_capacity((row * height) as usize);
        for y in 0..height as usize {
            let start = y * padded_row as usize;
            pixels.extend_from_slice(&mapped[start..start + row as usize]);
        }
        // The preview is opaque: blending leaves coverage, not transparency, in alpha.
        for alpha in pixels.iter_mut().skip(3).step_by(4) {
            *alpha = 255;
        }
        Ok(pixels)
    }
}

fn pipeline_key(mesh: &Mesh) -> PipelineKey {
    PipelineKey {
        primitive: match mesh.primitive {
            Primitive::Triangles => 0,
            Primitive::Lines => 1,
            Primitive::Points => 2,
        },
        blended: mesh.blended,
        cull_back: mesh.back.is_none() && mesh.primitive == Primitive::Triangles,
    }
}

/// Opaque meshes first, in list order; then blended ones from the farthest to the nearest
/// (by the distance of their bounding-box centre from the eye).
fn draw_order(list: &DrawList) -> Vec<usize> {
    let mut opaque = Vec::new();
    let mut blended = Vec::new();
    for (i, mesh) in list.meshes.iter().enumerate() {
        if mesh.indices.is_empty() {
            continue;
        }
        if mesh.blended {
            blended.push((centre_distance(mesh), i));
        } else {
            opaque.push(i);
        }
    }
    blended.sort_by(|a, b| b.0.total_cmp(&a.0));
    opaque.extend(blended.into_iter().map(|(_, i)| i));
    opaque
}

fn centre_distance(mesh: &Mesh) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in &mesh.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(f64::from(p[k]));
            hi[k] = hi[k].max(f64::from(p[k]));
        }
    }
    (0..3)
        .map(|k| ((lo[k] + hi[k]) / 2.0).powi(2))
        .sum::<f64>()
        .sqrt()
}

fn white_texture() -> super::draw_list::Texture {
    super::draw_list::Texture {
        width: 1,
        height: 1,
        rgba: vec![255; 4],
        repeat_s: true,
        repeat_t: true,
        linear: false,
    }
}

fn texture_bind_group(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    layout: &wgpu::BindGroupLayout,
    texture: &super::draw_list::Texture,
) -> wgpu::BindGroup {
    let extent = wgpu::Extent3d {
        width: texture.width,
        height: texture.height,
        depth_or_array_layers: 1,
    };
    let gpu_texture = device.create_texture_with_data(
        queue,
        &wgpu::TextureDescriptor {
            label: Some("texture"),
            size: extent,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        &texture.rgba,
    );
    let address = |repeat: bool| {
        if repeat {
            wgpu::AddressMode::Repeat
        } else {
            wgpu::AddressMode::ClampToEdge
        }
    };
    let filter = if texture.linear {
        wgpu::FilterMode::Linear
    } else {
        wgpu::FilterMode::Nearest
    };
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        address_mode_u: address(texture.repeat_s),
        address_mode_v: address(texture.repeat_t),
        mag_filter: filter,
        min_filter: filter,
        ..Default::default()
    });
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(
                    &gpu_texture.create_view(&Default::default()),
                ),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: wgpu::BindingResource::Sampler(&sampler),
            },
        ],
    })
}
