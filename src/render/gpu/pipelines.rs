//! The shader, its bind group layouts and the render pipelines, one per combination of
//! primitive, blending, culling and the vertex attributes a mesh has (made when first
//! needed: a scene uses few combinations).

use std::collections::HashMap;

use super::uniforms::{Globals, GpuDraw};
use super::Shading;
use crate::render::draw_list::{Mesh, Primitive, MAX_TEX_COORD_SETS};

pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Texture bindings of group 2, in the shader's order: four MultiTexture stages, then
/// emissive, normal, occlusion, specular or metallicRoughness, shininess, ambient. Each
/// texture's sampler follows at `binding + TEXTURE_SLOTS`.
pub const TEXTURE_SLOTS: usize = 10;
/// Group 2's binding of the first stage's cube map texture (its sampler follows).
pub const CUBE_BINDING: u32 = 2 * TEXTURE_SLOTS as u32;

/// Vertex buffer slots: position, normal, colour, tangent, then the texture coordinate
/// sets. An attribute a mesh lacks reads a constant zero (an instance-rate buffer).
pub const VERTEX_SLOTS: usize = 4 + MAX_TEX_COORD_SETS;
const FORMATS: [wgpu::VertexFormat; VERTEX_SLOTS] = [
    wgpu::VertexFormat::Float32x3,
    wgpu::VertexFormat::Float32x3,
    wgpu::VertexFormat::Float32x4,
    wgpu::VertexFormat::Float32x4,
    wgpu::VertexFormat::Float32x2,
    wgpu::VertexFormat::Float32x2,
    wgpu::VertexFormat::Float32x2,
    wgpu::VertexFormat::Float32x2,
];

/// Lines and points are drawn as instanced quads: per instance the two ends (a point's
/// twice) each with the length of its polyline up to it, then their two colours.
pub const STROKE_ENDS_STRIDE: u64 = 32;
pub const STROKE_COLORS_STRIDE: u64 = 32;

/// Which pipeline a mesh needs.
#[derive(Copy, Clone, PartialEq, Eq, Hash)]
pub struct PipelineKey {
    primitive: u8,
    blended: bool,
    cull_back: bool,
    /// Bit i: vertex slot i has per-vertex data.
    attributes: u8,
}

impl PipelineKey {
    pub fn of(mesh: &Mesh) -> PipelineKey {
        let present = [
            true,
            mesh.normals.is_some(),
            mesh.colors.is_some(),
            mesh.tangents.is_some(),
        ]
        .into_iter()
        .chain((0..MAX_TEX_COORD_SETS).map(|i| i < mesh.tex_coords.len()));
        PipelineKey {
            primitive: match mesh.primitive {
                Primitive::Triangles => 0,
                Primitive::Lines => 1,
                Primitive::Points => 2,
            },
            blended: mesh.blended,
            cull_back: mesh.back.is_none() && mesh.primitive == Primitive::Triangles,
            attributes: present
                .enumerate()
                .fold(0, |bits, (i, p)| bits | (u8::from(p) << i)),
        }
    }

    pub fn has(&self, slot: usize) -> bool {
        self.attributes & (1 << slot) != 0
    }
}

/// Where the shader reads its per-frame and per-draw parameters (`globals`, `draw`).
///
/// Read-only storage buffers wherever the vertex stage can read them: lavapipe (Mesa
/// 22.3, Debian 12) specializes a shader on the uniform-buffer values its branches test
/// each time a pipeline is bound, compiling the variant with LLVM and keeping it until
/// the pipeline is destroyed, with no cache. A frame binds its pipelines again in every
/// render pass, so uniform buffers cost a compilation per pass and 0.67 MB that stays:
/// 56 MB more by the 85th pass of the benchmark scene at `fast`; peak RSS 190 MB against
/// 176 MB with storage buffers (README, "Render memory"). It never specializes on
/// storage buffers. OpenGL adapters may lack storage buffers in the vertex stage
/// (`DownlevelFlags::VERTEX_STORAGE`) and keep uniform buffers; the bytes are the same.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Parameters {
    Uniform,
    Storage,
}

impl Parameters {
    pub fn for_device(device: &wgpu::Device) -> Parameters {
        match device.adapter_info().backend {
            wgpu::Backend::Gl => Parameters::Uniform,
            _ => Parameters::Storage,
        }
    }

    pub fn usage(self) -> wgpu::BufferUsages {
        match self {
            Parameters::Uniform => wgpu::BufferUsages::UNIFORM,
            Parameters::Storage => wgpu::BufferUsages::STORAGE,
        }
    }

    /// The alignment of a dynamic offset into a parameter buffer.
    pub fn offset_alignment(self, limits: &wgpu::Limits) -> u32 {
        match self {
            Parameters::Uniform => limits.min_uniform_buffer_offset_alignment,
            Parameters::Storage => limits.min_storage_buffer_offset_alignment,
        }
    }

    fn binding_type(self) -> wgpu::BufferBindingType {
        match self {
            Parameters::Uniform => wgpu::BufferBindingType::Uniform,
            Parameters::Storage => wgpu::BufferBindingType::Storage { read_only: true },
        }
    }

    /// The shader's source with its parameters declared in this address space
    /// (`shader.wgsl` declares them as uniforms).
    pub fn shader_source(self) -> std::borrow::Cow<'static, str> {
        let source = super::super::SHADER_WGSL;
        match self {
            Parameters::Uniform => source.into(),
            Parameters::Storage => source.replace("var<uniform>", "var<storage, read>").into(),
        }
    }
}

pub struct Pipelines<'d> {
    device: &'d wgpu::Device,
    pub parameters: Parameters,
    shader: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    background_layout: wgpu::PipelineLayout,
    pub globals_layout: wgpu::BindGroupLayout,
    pub draw_layout: wgpu::BindGroupLayout,
    pub texture_layout: wgpu::BindGroupLayout,
    samples: u32,
    shading: Shading,
    made: HashMap<PipelineKey, wgpu::RenderPipeline>,
}

impl<'d> Pipelines<'d> {
    pub fn new(device: &'d wgpu::Device, samples: u32, shading: Shading) -> Self {
        let parameters = Parameters::for_device(device);
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("x3d lighting"),
            source: wgpu::ShaderSource::Wgsl(parameters.shader_source()),
        });
        let parameter_entry = |dynamic: bool, size: usize| wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: parameters.binding_type(),
                has_dynamic_offset: dynamic,
                min_binding_size: wgpu::BufferSize::new(size as u64),
            },
            count: None,
        };
        let [panorama, panorama_sampler] = cube_entries(5);
        // The globals, then the EnvironmentLight's maps (`environment::Maps`): the
        // prefiltered radiance and the irradiance cubes, the BRDF table, their sampler.
        let environment_texture = |binding, view_dimension| wgpu::BindGroupLayoutEntry {
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ..texture_entry(binding, view_dimension)
        };
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[
                parameter_entry(false, size_of::<Globals>()),
                environment_texture(1, wgpu::TextureViewDimension::Cube),
                environment_texture(2, wgpu::TextureViewDimension::Cube),
                environment_texture(3, wgpu::TextureViewDimension::D2),
                wgpu::BindGroupLayoutEntry {
                    binding: 4,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
                panorama,
                panorama_sampler,
            ],
        });
        let draw_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("draw"),
            entries: &[parameter_entry(true, size_of::<GpuDraw>())],
        });
        let textures = (0..TEXTURE_SLOTS as u32)
            .map(|binding| texture_entry(binding, wgpu::TextureViewDimension::D2));
        let samplers = (0..TEXTURE_SLOTS as u32).map(|slot| wgpu::BindGroupLayoutEntry {
            binding: TEXTURE_SLOTS as u32 + slot,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        });
        let entries: Vec<_> = textures
            .chain(samplers)
            .chain(cube_entries(CUBE_BINDING))
            .collect();
        let texture_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("textures"),
            entries: &entries,
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
        let background_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("background"),
            bind_group_layouts: &[Some(&globals_layout)],
            immediate_size: 0,
        });
        Pipelines {
            device,
            parameters,
            shader,
            layout,
            background_layout,
            globals_layout,
            draw_layout,
            texture_layout,
            samples,
            shading,
            made: HashMap::new(),
        }
    }

    pub fn get(&mut self, key: PipelineKey) -> &wgpu::RenderPipeline {
        if !self.made.contains_key(&key) {
            let pipeline = self.make(key);
            self.made.insert(key, pipeline);
        }
        &self.made[&key]
    }

    fn make(&self, key: PipelineKey) -> wgpu::RenderPipeline {
        let attributes: Vec<[wgpu::VertexAttribute; 1]> = FORMATS
            .iter()
            .enumerate()
            .map(|(slot, &format)| {
                [wgpu::VertexAttribute {
                    format,
                    offset: 0,
                    shader_location: slot as u32,
                }]
            })
            .collect();
        let surface_buffers: Vec<Option<wgpu::VertexBufferLayout>> = attributes
            .iter()
            .enumerate()
            .map(|(slot, attribute)| {
                Some(wgpu::VertexBufferLayout {
                    array_stride: attribute[0].format.size(),
                    step_mode: if key.has(slot) {
                        wgpu::VertexStepMode::Vertex
                    } else {
                        wgpu::VertexStepMode::Instance
                    },
                    attributes: attribute,
                })
            })
            .collect();
        let stroke_buffers = [
            Some(wgpu::VertexBufferLayout {
                array_stride: STROKE_ENDS_STRIDE,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4],
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: STROKE_COLORS_STRIDE,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &wgpu::vertex_attr_array![2 => Float32x4, 3 => Float32x4],
            }),
        ];
        let stroke = key.primitive != 0;
        let blend = if key.blended {
            wgpu::BlendState::ALPHA_BLENDING
        } else {
            wgpu::BlendState::REPLACE
        };
        let (vertex, fragment) = match (stroke, self.shading) {
            (true, _) => ("vs_stroke", "fs_phong"),
            (false, Shading::Gouraud) => ("vs_gouraud", "fs_gouraud"),
            (false, Shading::Phong) => ("vs_main", "fs_phong"),
        };
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("x3d shapes"),
                layout: Some(&self.layout),
                vertex: wgpu::VertexState {
                    module: &self.shader,
                    entry_point: Some(vertex),
                    compilation_options: Default::default(),
                    buffers: if stroke {
                        &stroke_buffers
                    } else {
                        &surface_buffers
                    },
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
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
                    entry_point: Some(fragment),
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

    /// The Background gradient, drawn first in its layer, behind everything (no depth
    /// written), over the layers below as its transparency lets them show.
    pub fn background(&self) -> wgpu::RenderPipeline {
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("background"),
                layout: Some(&self.background_layout),
                vertex: wgpu::VertexState {
                    module: &self.shader,
                    entry_point: Some("vs_background"),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(false),
                    depth_compare: Some(wgpu::CompareFunction::Always),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: self.samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: &self.shader,
                    entry_point: Some("fs_background"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: COLOR_FORMAT,
                        blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
    }
}

/// A filterable float texture of `view_dimension` at `binding`, for the fragment shader.
fn texture_entry(
    binding: u32,
    view_dimension: wgpu::TextureViewDimension,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: true },
            view_dimension,
            multisampled: false,
        },
        count: None,
    }
}

/// A cube texture and its sampler at `binding` and the next, for the fragment shader.
pub(super) fn cube_entries(binding: u32) -> [wgpu::BindGroupLayoutEntry; 2] {
    [
        texture_entry(binding, wgpu::TextureViewDimension::Cube),
        wgpu::BindGroupLayoutEntry {
            binding: binding + 1,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::Parameters;

    /// The shader parses and validates (naga, as wgpu does), without a GPU, with its
    /// parameters in uniform buffers and in storage buffers.
    #[test]
    fn the_shader_is_valid_wgsl() {
        for parameters in [Parameters::Uniform, Parameters::Storage] {
            let source = parameters.shader_source();
            let module = naga::front::wgsl::parse_str(&source)
                .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
            naga::valid::Validator::new(
                naga::valid::ValidationFlags::all(),
                naga::valid::Capabilities::empty(),
            )
            .validate(&module)
            .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
        }
        let storage = Parameters::Storage.shader_source();
        assert!(!storage.contains("var<uniform>"));
        assert_eq!(
            storage.matches("var<storage, read>").count(),
            2,
            "globals and draw"
        );
    }
}
