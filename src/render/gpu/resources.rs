//! What the draw list puts on the GPU: textures with their samplers, the texture bind
//! group of each distinct combination a mesh uses, and each mesh's vertex and index
//! buffers (only the attributes it has).

use std::collections::HashMap;

use wgpu::util::DeviceExt;

use super::pipelines::{CUBE_BINDING, TEXTURE_SLOTS, VERTEX_SLOTS};
use crate::render::cube_map::{cube_sampler, cube_view, CubeImage};
use crate::render::draw_list::{Mesh, Primitive, Texture, Textures, Wrap, MAX_STAGES};

/// The textures of a draw list on the GPU, and the bind groups made from them.
pub struct TextureBindings<'d> {
    device: &'d wgpu::Device,
    layout: &'d wgpu::BindGroupLayout,
    /// Per draw-list texture: its view and sampler (None: larger than the device allows,
    /// drawn white).
    uploaded: Vec<Option<(wgpu::TextureView, wgpu::Sampler)>>,
    white: (wgpu::TextureView, wgpu::Sampler),
    /// Per draw-list cube texture: its view (None: larger than the device allows).
    cubes: Vec<Option<wgpu::TextureView>>,
    /// Sampled where a mesh has no cube map (never read), and its sampler.
    white_cube: wgpu::TextureView,
    /// The panorama of a Background without one.
    transparent_cube: wgpu::TextureView,
    cube_sampler: wgpu::Sampler,
    groups: HashMap<([Option<usize>; TEXTURE_SLOTS], Option<usize>), wgpu::BindGroup>,
}

impl<'d> TextureBindings<'d> {
    pub fn new(
        device: &'d wgpu::Device,
        queue: &wgpu::Queue,
        layout: &'d wgpu::BindGroupLayout,
        textures: &[Texture],
        cubes: &[CubeImage],
    ) -> Self {
        let max_side = device.limits().max_texture_dimension_2d;
        let uploaded = textures
            .iter()
            .map(|t| {
                (t.width <= max_side && t.height <= max_side).then(|| upload(device, queue, t))
            })
            .collect();
        let white = upload(
            device,
            queue,
            &Texture {
                width: 1,
                height: 1,
                levels: vec![vec![255; 4]],
                wrap_s: Wrap::Repeat,
                wrap_t: Wrap::Repeat,
                magnify_linear: false,
                minify_linear: false,
                mipmaps: None,
                anisotropy: 1,
            },
        );
        let max_cube = device.limits().max_texture_dimension_2d;
        let cubes = cubes
            .iter()
            .map(|c| (c.side <= max_cube).then(|| cube_view(&c.upload(device, queue))))
            .collect();
        TextureBindings {
            device,
            layout,
            uploaded,
            white,
            cubes,
            white_cube: cube_view(&CubeImage::uniform([255; 4]).upload(device, queue)),
            transparent_cube: cube_view(&CubeImage::uniform([0; 4]).upload(device, queue)),
            cube_sampler: cube_sampler(device),
            groups: HashMap::new(),
        }
    }

    /// A Background's panorama: transparent where it has none (or one too large for the
    /// device).
    pub fn panorama(&self, cube: Option<usize>) -> &wgpu::TextureView {
        cube.and_then(|c| self.cubes.get(c).and_then(Option::as_ref))
            .unwrap_or(&self.transparent_cube)
    }

    pub fn cube_sampler(&self) -> &wgpu::Sampler {
        &self.cube_sampler
    }

    /// The bind group for a mesh's textures (shared by every mesh with the same ones).
    pub fn group(&mut self, textures: &Textures) -> &wgpu::BindGroup {
        let key = slots(textures);
        if !self.groups.contains_key(&key) {
            let (slots, cube) = key;
            let cube = cube
                .and_then(|c| self.cubes.get(c).and_then(Option::as_ref))
                .unwrap_or(&self.white_cube);
            let pick = |slot: Option<usize>| {
                slot.and_then(|t| self.uploaded.get(t).and_then(Option::as_ref))
                    .unwrap_or(&self.white)
            };
            let views = slots
                .iter()
                .enumerate()
                .map(|(i, &slot)| wgpu::BindGroupEntry {
                    binding: i as u32,
                    resource: wgpu::BindingResource::TextureView(&pick(slot).0),
                });
            let samplers = slots
                .iter()
                .enumerate()
                .map(|(i, &slot)| wgpu::BindGroupEntry {
                    binding: (TEXTURE_SLOTS + i) as u32,
                    resource: wgpu::BindingResource::Sampler(&pick(slot).1),
                });
            let cube_entries = [
                wgpu::BindGroupEntry {
                    binding: CUBE_BINDING,
                    resource: wgpu::BindingResource::TextureView(cube),
                },
                wgpu::BindGroupEntry {
                    binding: CUBE_BINDING + 1,
                    resource: wgpu::BindingResource::Sampler(&self.cube_sampler),
                },
            ];
            let entries: Vec<_> = views.chain(samplers).chain(cube_entries).collect();
            let group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: self.layout,
                entries: &entries,
            });
            self.groups.insert(key, group);
        }
        &self.groups[&key]
    }
}

/// The draw-list texture in each binding slot (the order of `pipelines::TEXTURE_SLOTS`),
/// and the first stage's cube texture.
fn slots(textures: &Textures) -> ([Option<usize>; TEXTURE_SLOTS], Option<usize>) {
    let mut key = [None; TEXTURE_SLOTS];
    let mut cube = None;
    for (slot, stage) in key.iter_mut().zip(textures.main.iter().take(MAX_STAGES)) {
        match stage.cube {
            Some(_) => cube = Some(stage.texture.texture),
            None => *slot = Some(stage.texture.texture),
        }
    }
    let roles = [
        textures.emissive,
        textures.normal,
        textures.occlusion,
        textures.specular.or(textures.metallic_roughness),
        textures.shininess,
        textures.ambient,
    ];
    for (slot, role) in key[MAX_STAGES..].iter_mut().zip(roles) {
        *slot = role.map(|r| r.texture);
    }
    (key, cube)
}

fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &Texture,
) -> (wgpu::TextureView, wgpu::Sampler) {
    let gpu_texture = device.create_texture_with_data(
        queue,
        &wgpu::TextureDescriptor {
            label: Some("texture"),
            size: wgpu::Extent3d {
                width: texture.width,
                height: texture.height,
                depth_or_array_layers: 1,
            },
            mip_level_count: texture.levels.len() as u32,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        &texture.levels.concat(),
    );
    let address = |wrap: Wrap| match wrap {
        Wrap::Repeat => wgpu::AddressMode::Repeat,
        Wrap::MirroredRepeat => wgpu::AddressMode::MirrorRepeat,
        Wrap::Clamp => wgpu::AddressMode::ClampToEdge,
    };
    let filter = |linear: bool| {
        if linear {
            wgpu::FilterMode::Linear
        } else {
            wgpu::FilterMode::Nearest
        }
    };
    let all_linear =
        texture.magnify_linear && texture.minify_linear && texture.mipmaps == Some(true);
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        address_mode_u: address(texture.wrap_s),
        address_mode_v: address(texture.wrap_t),
        mag_filter: filter(texture.magnify_linear),
        min_filter: filter(texture.minify_linear),
        mipmap_filter: if texture.mipmaps == Some(true) {
            wgpu::MipmapFilterMode::Linear
        } else {
            wgpu::MipmapFilterMode::Nearest
        },
        // Anisotropic filtering needs every filter linear (a WebGPU rule).
        anisotropy_clamp: if all_linear { texture.anisotropy } else { 1 },
        ..Default::default()
    });
    (gpu_texture.create_view(&Default::default()), sampler)
}

/// A mesh's vertex data on the GPU (its indices are uploaded per pass: see
/// [`upload_indices`]).
pub enum MeshBuffers {
    /// Triangles: one buffer per vertex slot (None: the constant zero buffer).
    Surface {
        vertices: Box<[Option<wgpu::Buffer>; VERTEX_SLOTS]>,
    },
    /// Lines and points: per instance its two ends and their colours.
    Stroke {
        ends: wgpu::Buffer,
        colors: wgpu::Buffer,
    },
}

/// A buffer holding `bytes`. Where the device can map vertex and index buffers, they are
/// written in place: `create_buffer_init` would stage the bytes in a second buffer first,
/// which on a software driver is a second copy in the process's memory (6 MB of the
/// benchmark scene's peak).
fn buffer(device: &wgpu::Device, bytes: &[u8], usage: wgpu::BufferUsages) -> wgpu::Buffer {
    if bytes.is_empty()
        || !device
            .features()
            .contains(wgpu::Features::MAPPABLE_PRIMARY_BUFFERS)
    {
        return staged(device, bytes, usage);
    }
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: (bytes.len() as u64).next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT),
        usage: usage | wgpu::BufferUsages::MAP_WRITE,
        mapped_at_creation: true,
    });
    let written = buffer
        .slice(..)
        .get_mapped_range_mut()
        .map(|mut mapped| mapped.slice(..bytes.len()).copy_from_slice(bytes));
    buffer.unmap();
    match written {
        Ok(()) => buffer,
        Err(_) => staged(device, bytes, usage),
    }
}

fn staged(device: &wgpu::Device, bytes: &[u8], usage: wgpu::BufferUsages) -> wgpu::Buffer {
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytes,
        usage,
    })
}

/// Uploads a mesh's vertex arrays and frees them (a surface keeps its indices, uploaded
/// per pass): on a software driver the GPU copy lives in the same memory, so keeping both
/// would double the peak.
pub fn upload_mesh(device: &wgpu::Device, mesh: &mut Mesh) -> MeshBuffers {
    if mesh.primitive != Primitive::Triangles {
        return upload_stroke(mesh, |bytes| {
            buffer(device, bytes, wgpu::BufferUsages::VERTEX)
        });
    }
    let vertex = |bytes: &[u8]| Some(buffer(device, bytes, wgpu::BufferUsages::VERTEX));
    let mut vertices: [Option<wgpu::Buffer>; VERTEX_SLOTS] = Default::default();
    vertices[0] = vertex(bytemuck::cast_slice(&std::mem::take(&mut mesh.positions)));
    vertices[1] = mesh
        .normals
        .take()
        .and_then(|n| vertex(bytemuck::cast_slice(&n)));
    vertices[2] = mesh
        .colors
        .take()
        .and_then(|c| vertex(bytemuck::cast_slice(&c)));
    vertices[3] = mesh
        .tangents
        .take()
        .and_then(|t| vertex(bytemuck::cast_slice(&t)));
    for (slot, set) in vertices[4..]
        .iter_mut()
        .zip(std::mem::take(&mut mesh.tex_coords))
    {
        *slot = vertex(bytemuck::cast_slice(&set));
    }
    MeshBuffers::Surface {
        vertices: Box::new(vertices),
    }
}

/// The index buffer of one pass's part of a surface.
pub fn upload_indices(device: &wgpu::Device, indices: &[u32]) -> wgpu::Buffer {
    buffer(
        device,
        bytemuck::cast_slice(indices),
        wgpu::BufferUsages::INDEX,
    )
}

/// One pass's part of a surface on the GPU: the vertices from the smallest to the
/// largest index it draws (one buffer per vertex slot, None: the constant zero buffer)
/// and its indices counted from the smallest.
pub struct SurfacePart {
    pub vertices: Box<[Option<wgpu::Buffer>; VERTEX_SLOTS]>,
    pub indices: wgpu::Buffer,
    pub format: wgpu::IndexFormat,
}

/// The smallest and largest of some indices ((0, 0) for none).
pub fn index_bounds(indices: &[u32]) -> (u32, u32) {
    let first = indices.iter().copied().min().unwrap_or(0);
    (first, indices.iter().copied().max().unwrap_or(first))
}

/// Uploads the part of a surface that one pass draws, `indices` of its own (whole
/// triangles of `mesh.indices`), leaving the mesh's arrays in place for its other parts:
/// only the vertices from the smallest to the largest index they name, and the indices
/// counted from the smallest, in 16 bits when they span fewer than 65,536 vertices.
pub fn upload_surface_part(
    device: &wgpu::Device,
    mesh: &Mesh,
    indices: std::ops::Range<usize>,
) -> SurfacePart {
    let indices = &mesh.indices[indices];
    let (first, last) = index_bounds(indices);
    let span = first as usize..last as usize + 1;
    let vertex = |bytes: &[u8]| Some(buffer(device, bytes, wgpu::BufferUsages::VERTEX));
    let mut vertices: [Option<wgpu::Buffer>; VERTEX_SLOTS] = Default::default();
    vertices[0] = vertex(bytemuck::cast_slice(&mesh.positions[span.clone()]));
    vertices[1] = mesh
        .normals
        .as_ref()
        .and_then(|n| vertex(bytemuck::cast_slice(&n[span.clone()])));
    vertices[2] = mesh
        .colors
        .as_ref()
        .and_then(|c| vertex(bytemuck::cast_slice(&c[span.clone()])));
    vertices[3] = mesh
        .tangents
        .as_ref()
        .and_then(|t| vertex(bytemuck::cast_slice(&t[span.clone()])));
    for (slot, set) in vertices[4..].iter_mut().zip(&mesh.tex_coords) {
        *slot = vertex(bytemuck::cast_slice(&set[span.clone()]));
    }
    let (bytes, format): (Vec<u8>, _) = if last - first < 1 << 16 {
        let bytes = indices
            .iter()
            .flat_map(|&i| ((i - first) as u16).to_ne_bytes());
        (bytes.collect(), wgpu::IndexFormat::Uint16)
    } else {
        let bytes = indices.iter().flat_map(|&i| (i - first).to_ne_bytes());
        (bytes.collect(), wgpu::IndexFormat::Uint32)
    };
    SurfacePart {
        vertices: Box::new(vertices),
        indices: buffer(device, &bytes, wgpu::BufferUsages::INDEX),
        format,
    }
}

/// Lines and points as instances: a segment's two ends (a point twice), in index order.
fn upload_stroke(mesh: &mut Mesh, buffer: impl Fn(&[u8]) -> wgpu::Buffer) -> MeshBuffers {
    let (ends, colors) = stroke_instances(mesh);
    drop(std::mem::take(&mut mesh.positions));
    mesh.colors = None;
    drop(std::mem::take(&mut mesh.indices));
    MeshBuffers::Stroke {
        ends: buffer(bytemuck::cast_slice(&ends)),
        colors: buffer(bytemuck::cast_slice(&colors)),
    }
}

/// A line's or point's two ends, each with the length of its polyline up to it (the
/// shader lays linetype patterns along it), and their colours.
type Ends = [[f32; 4]; 2];
type EndColors = [[f32; 4]; 2];

/// The instance arrays of a line or point mesh: ends [a, b] and colours [a, b] (white
/// without per-vertex colours: the shader then uses the material's). A segment starting
/// where the one before it ended continues its polyline's length; any other starts at 0.
fn stroke_instances(mesh: &Mesh) -> (Vec<Ends>, Vec<EndColors>) {
    let per = mesh.primitive.arity();
    let color = |i: u32| {
        mesh.colors
            .as_ref()
            .and_then(|c| c.get(i as usize).copied())
            .unwrap_or([1.0; 4])
    };
    let mut previous_end: Option<([f32; 3], f32)> = None;
    mesh.indices
        .chunks_exact(per)
        .map(|ends| {
            let (a, b) = (ends[0], ends[per - 1]);
            let (pa, pb) = (mesh.positions[a as usize], mesh.positions[b as usize]);
            let start = match previous_end {
                Some((end, length)) if end == pa => length,
                _ => 0.0,
            };
            let length = start + distance(pa, pb);
            previous_end = Some((pb, length));
            (
                [[pa[0], pa[1], pa[2], start], [pb[0], pb[1], pb[2], length]],
                [color(a), color(b)],
            )
        })
        .unzip()
}

fn distance(a: [f32; 3], b: [f32; 3]) -> f32 {
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::draw_list::{CubeLookup, Stage, TextureRef};

    #[test]
    fn lines_and_points_become_instances_of_their_two_ends() {
        let mut mesh = Mesh {
            primitive: Primitive::Lines,
            positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
            normals: None,
            tangents: None,
            colors: Some(vec![[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0], [0.0; 4]]),
            colors_have_alpha: false,
            tex_coords: Vec::new(),
            indices: vec![0, 1, 1, 2],
            front: crate::render::flatten::default_material(),
            back: None,
            textures: Textures::default(),
            light_mask: 0,
            clip_planes: Vec::new(),
            scissor: None,
            blended: false,
            alpha_cutoff: 0.0,
            stroke: Default::default(),
        };
        let (ends, colors) = stroke_instances(&mesh);
        // The second segment continues the first: its length runs on from 1.
        assert_eq!(
            ends,
            vec![
                [[0.0; 4], [1.0, 0.0, 0.0, 1.0]],
                [[1.0, 0.0, 0.0, 1.0], [1.0, 1.0, 0.0, 2.0]]
            ]
        );
        assert_eq!(colors[1], [[0.0, 1.0, 0.0, 1.0], [0.0; 4]]);
        // A segment starting elsewhere starts a polyline of its own.
        mesh.indices = vec![0, 1, 2, 0];
        let (ends, _) = stroke_instances(&mesh);
        assert_eq!(ends[1][0], [1.0, 1.0, 0.0, 0.0]);
        mesh.primitive = Primitive::Points;
        mesh.colors = None;
        mesh.indices = vec![2];
        let (ends, colors) = stroke_instances(&mesh);
        assert_eq!(ends, vec![[[1.0, 1.0, 0.0, 0.0]; 2]]);
        assert_eq!(colors, vec![[[1.0; 4]; 2]]);
    }

    #[test]
    fn texture_slots_follow_the_shader_bindings() {
        let at = |texture| TextureRef {
            texture,
            tex_coords: 0,
        };
        let textures = Textures {
            main: vec![Stage::modulate(at(7)), Stage::modulate(at(8))],
            emissive: Some(at(1)),
            metallic_roughness: Some(at(2)),
            ambient: Some(at(3)),
            ..Textures::default()
        };
        assert_eq!(
            slots(&textures),
            (
                [
                    Some(7),
                    Some(8),
                    None,
                    None,
                    Some(1),
                    None,
                    None,
                    Some(2),
                    None,
                    Some(3)
                ],
                None
            )
        );
        // A cube map first stage binds as the cube, its 2D slot left white.
        let cube = Textures {
            main: vec![Stage {
                cube: Some(CubeLookup::WorldReflection),
                ..Stage::modulate(at(5))
            }],
            ..Textures::default()
        };
        assert_eq!(slots(&cube), ([None; TEXTURE_SLOTS], Some(5)));
    }
}
