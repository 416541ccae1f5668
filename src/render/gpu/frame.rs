//! One frame, drawn tile by tile (see [`TILE_SAMPLES`]): render targets of a tile's size,
//! then for each tile layer by layer (each over the previous with the depth cleared,
//! within its rectangle) the background and the meshes in their order (opaque first,
//! then blended ones back to front), each pass piece only where it can reach the tile
//! (see `reach`), and the read-back of the tile's pixels.

use wgpu::util::DeviceExt;

use super::environment;
use super::pipelines::{PipelineKey, Pipelines, COLOR_FORMAT, DEPTH_FORMAT, VERTEX_SLOTS};
use super::reach::{reach, stroke_pad};
use super::resources::{
    index_bounds, upload_indices, upload_mesh, upload_surface_part, MeshBuffers, SurfacePart,
    TextureBindings,
};
use super::uniforms::{draw_uniform, globals, Globals, GpuDraw};
use super::{GpuError, Shading};
use crate::render::draw_list::{DrawList, Mesh, Primitive};

#[derive(Copy, Clone)]
pub struct Target {
    pub width: u32,
    pub height: u32,
    /// How many times larger than the image the target is (supersampling).
    pub scale: u32,
    pub samples: u32,
    pub shading: Shading,
    /// The most indices in one render pass (see [`PASS_INDICES`]).
    pub pass_indices: u32,
    /// The most samples (pixels × `samples`) in one tile (see [`TILE_SAMPLES`]).
    pub tile_samples: u32,
}

/// Draws the list and returns the image, `target.scale` times smaller than the target on
/// each side.
pub async fn draw(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    mut list: DrawList,
    target: Target,
) -> Result<image::RgbaImage, GpuError> {
    let (tile_width, tile_height) = tile_size(&target);
    let extent = wgpu::Extent3d {
        width: tile_width,
        height: tile_height,
        depth_or_array_layers: 1,
    };
    let texture = |format, samples, usage| {
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
    let resolved = texture(
        COLOR_FORMAT,
        1,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let multisampled = (target.samples > 1).then(|| {
        texture(
            COLOR_FORMAT,
            target.samples,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        )
    });
    let depth = texture(
        DEPTH_FORMAT,
        target.samples,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    );
    let resolved_view = resolved.create_view(&Default::default());
    let multisampled_view = multisampled
        .as_ref()
        .map(|t| t.create_view(&Default::default()));
    let depth_view = depth.create_view(&Default::default());

    let mut pipelines = Pipelines::new(device, target.samples, target.shading);
    // Each layer's rectangle of the target, and its uniforms.
    let rects: Vec<[u32; 4]> = list
        .layers
        .iter()
        .map(|layer| layer.viewport.pixels(target.width, target.height))
        .collect();
    let texture_layout = pipelines.texture_layout.clone();
    let mut bindings = TextureBindings::new(
        device,
        queue,
        &texture_layout,
        &list.textures,
        &list.cube_textures,
    );
    let layer_globals: Vec<Globals> = list
        .layers
        .iter()
        .zip(&rects)
        .map(|(layer, rect)| {
            let (width, height) = (rect[2].max(1), rect[3].max(1));
            globals(layer, width, height, target.scale, &list.cube_textures)
        })
        .collect();
    let globals_groups: Vec<wgpu::BindGroup> = list
        .layers
        .iter()
        .zip(&layer_globals)
        .map(|(layer, globals)| {
            let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("globals"),
                contents: bytemuck::bytes_of(globals),
                usage: pipelines.parameters.usage(),
            });
            let maps = environment::Maps::new(device, queue, layer.environment.as_ref());
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: &pipelines.globals_layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: buffer.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(&maps.specular),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::TextureView(&maps.diffuse),
                    },
                    wgpu::BindGroupEntry {
                        binding: 3,
                        resource: wgpu::BindingResource::TextureView(&maps.brdf),
                    },
                    wgpu::BindGroupEntry {
                        binding: 4,
                        resource: wgpu::BindingResource::Sampler(&maps.sampler),
                    },
                    wgpu::BindGroupEntry {
                        binding: 5,
                        resource: wgpu::BindingResource::TextureView(
                            bindings.panorama(layer.background.as_ref().and_then(|b| b.panorama)),
                        ),
                    },
                    wgpu::BindGroupEntry {
                        binding: 6,
                        resource: wgpu::BindingResource::Sampler(bindings.cube_sampler()),
                    },
                ],
            })
        })
        .collect();

    // Every layer's meshes in drawing order: (layer, mesh).
    let order: Vec<(usize, usize)> = list
        .layers
        .iter()
        .enumerate()
        .flat_map(|(l, layer)| draw_order(&layer.meshes).into_iter().map(move |m| (l, m)))
        .collect();
    let alignment = pipelines.parameters.offset_alignment(&device.limits()) as usize;
    let stride = size_of::<GpuDraw>().div_ceil(alignment) * alignment;
    let mut draw_bytes = vec![0u8; stride * order.len().max(1)];
    for (slot, &(l, m)) in order.iter().enumerate() {
        let uniform = draw_uniform(&list.layers[l].meshes[m], &list.cube_textures);
        let bytes = bytemuck::bytes_of(&uniform).to_vec();
        draw_bytes[slot * stride..slot * stride + bytes.len()].copy_from_slice(&bytes);
    }
    let draw_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("draws"),
        contents: &draw_bytes,
        usage: pipelines.parameters.usage(),
    });
    drop(draw_bytes);
    let draw_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipelines.draw_layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer: &draw_buffer,
                offset: 0,
                size: wgpu::BufferSize::new(size_of::<GpuDraw>() as u64),
            }),
        }],
    });
    list.textures = Vec::new();
    list.cube_textures = Vec::new();
    let zeros = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("absent attribute"),
        contents: &[0u8; 16],
        usage: wgpu::BufferUsages::VERTEX,
    });
    // Each draw's pipeline and textures exist before the first pass begins; each pass
    // gets only its own part of the indices, and of a surface's vertices those its part
    // names when they are few (see `local`), in 16-bit indices where they fit: on the
    // benchmark scene a fifth less than the draw list's arrays, which are freed as their
    // parts are made (on a software driver the GPU's buffers are in the process's own
    // memory). The last tile frees each pass's buffers once it is drawn.
    let mut draws = Vec::with_capacity(order.len());
    let mut scissors = Vec::with_capacity(order.len());
    let mut counts = Vec::with_capacity(order.len());
    for &(l, m) in &order {
        let mesh = &mut list.layers[l].meshes[m];
        let key = PipelineKey::of(mesh);
        pipelines.get(key);
        bindings.group(&mesh.textures);
        let textures = std::mem::take(&mut mesh.textures);
        scissors.push(match mesh.scissor {
            Some(viewport) => intersect(rects[l], viewport.pixels(target.width, target.height)),
            None => rects[l],
        });
        counts.push(draw_size(mesh));
        draws.push((key, textures));
    }
    let background = list
        .layers
        .iter()
        .any(|layer| layer.background.is_some())
        .then(|| pipelines.background());

    let (view, resolve_target) = match &multisampled_view {
        Some(ms) => (ms, Some(&resolved_view)),
        None => (&resolved_view, None),
    };
    // Each layer's passes: its first clears the depth, so that it covers the layers
    // below; the image's first clears the colour to black.
    let mut passes: Vec<(usize, bool, Vec<Piece>)> = Vec::new();
    let mut first_slot = 0;
    for (l, layer) in list.layers.iter().enumerate() {
        let count = order[first_slot..]
            .iter()
            .take_while(|(of, _)| *of == l)
            .count();
        let slots = first_slot..first_slot + count;
        first_slot += count;
        let [_, _, w, h] = rects[l];
        if w == 0 || h == 0 || (count == 0 && layer.background.is_none()) {
            continue;
        }
        for (n, pieces) in cut(counts[slots.clone()].iter().copied(), target.pass_indices)
            .into_iter()
            .enumerate()
        {
            let pieces = pieces
                .into_iter()
                .map(|p| Piece {
                    slot: p.slot + slots.start,
                    range: p.range,
                })
                .collect();
            passes.push((l, n == 0, pieces));
        }
    }
    // The last pass drawing each slot: its buffers are freed once that pass is done.
    let mut last_pass = vec![0; order.len()];
    for (n, (_, _, pieces)) in passes.iter().enumerate() {
        for piece in pieces {
            last_pass[piece.slot] = n;
        }
    }
    let starts_layer: Vec<bool> = passes.iter().map(|(_, first, _)| *first).collect();
    // Where each piece can draw, within its scissor (see `reach`), found from its
    // vertices while they are here: a tile skips the pieces that cannot reach it, and
    // the passes with none that can (but a layer's first, which clears the depth).
    let scale = target.scale.max(1);
    let reaches: Vec<Vec<[u32; 4]>> = passes
        .iter()
        .map(|(l, _, pieces)| {
            let camera = layer_globals[*l].camera(rects[*l]);
            pieces
                .iter()
                .map(|piece| {
                    let (l, m) = order[piece.slot];
                    let mesh = &list.layers[l].meshes[m];
                    // A stroke's pieces count instances of `arity` indices.
                    let unit = match mesh.primitive {
                        Primitive::Triangles => 1,
                        primitive => primitive.arity(),
                    };
                    let range = piece.range.start as usize * unit..piece.range.end as usize * unit;
                    let pad = stroke_pad(mesh, scale);
                    intersect(
                        scissors[piece.slot],
                        reach(&camera, mesh, &mesh.indices[range], pad),
                    )
                })
                .collect()
        })
        .collect();
    // Every pass's buffers, made before the first tile (each tile draws those reaching
    // it) and each mesh's arrays freed after its last pass's: a surface's part when its
    // vertices are local, else the vertices of the whole mesh, made for its first pass,
    // and the pass's indices.
    let mut uploaded: Vec<Option<MeshBuffers>> = (0..order.len()).map(|_| None).collect();
    let mut prepared: Vec<Vec<PieceBuffers>> = Vec::with_capacity(passes.len());
    for (n, (_, _, pieces)) in passes.iter().enumerate() {
        let mut buffers = Vec::with_capacity(pieces.len());
        for piece in pieces {
            let (l, m) = order[piece.slot];
            let mesh = &mut list.layers[l].meshes[m];
            let range = piece.range.start as usize..piece.range.end as usize;
            if uploaded[piece.slot].is_none()
                && mesh.primitive == Primitive::Triangles
                && local(index_bounds(&mesh.indices[range.clone()]), range.len())
            {
                buffers.push(PieceBuffers::Part(upload_surface_part(device, mesh, range)));
                continue;
            }
            if uploaded[piece.slot].is_none() {
                uploaded[piece.slot] = Some(upload_mesh(device, mesh));
            }
            buffers.push(PieceBuffers::Whole(match uploaded[piece.slot] {
                Some(MeshBuffers::Surface { .. }) => {
                    Some(upload_indices(device, &mesh.indices[range]))
                }
                _ => None,
            }));
        }
        prepared.push(buffers);
        for (slot, &last) in last_pass.iter().enumerate() {
            if last == n {
                let (l, m) = order[slot];
                free_arrays(&mut list.layers[l].meshes[m]);
            }
        }
    }
    let mut image = image::RgbaImage::new(target.width / scale, target.height / scale);
    let tiles = tiles(&target, tile_width, tile_height);
    for (t, &tile) in tiles.iter().enumerate() {
        let [tx, ty, ..] = tile;
        let in_tile = |rect| in_tile(rect, tile);
        let reaches_tile = |rect| {
            let [.., w, h] = in_tile(rect);
            w > 0 && h > 0
        };
        // The passes this tile draws; the last tile frees each pass's buffers once it is
        // done (or skipped).
        let drawn: Vec<usize> = (0..passes.len())
            .filter(|&n| starts_layer[n] || reaches[n].iter().any(|&r| reaches_tile(r)))
            .collect();
        let last_tile = t + 1 == tiles.len();
        let mut encoder = device.create_command_encoder(&Default::default());
        if passes.is_empty() {
            // Nothing to draw: a black image.
            clear_pass(&mut encoder, view, resolve_target, &depth_view);
        }
        let mut freed = 0;
        for (k, &n) in drawn.iter().enumerate() {
            let (l, first_of_layer, pieces) = &passes[n];
            let (l, first_of_layer) = (*l, *first_of_layer);
            if k > 0 {
                // The previous pass is finished before this one is recorded, and what only
                // it used is freed.
                queue.submit([std::mem::replace(
                    &mut encoder,
                    device.create_command_encoder(&Default::default()),
                )
                .finish()]);
                device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .map_err(|e| GpuError::Failed(e.to_string()))?;
                if last_tile {
                    // The passes before this one are done (drawn or skipped).
                    for buffers in &mut prepared[freed..n] {
                        *buffers = Vec::new();
                    }
                    for (slot, &last) in last_pass.iter().enumerate() {
                        if (freed..n).contains(&last) {
                            uploaded[slot] = None;
                        }
                    }
                    freed = n;
                }
            }
            let last_of_layer = drawn.get(k + 1).is_none_or(|&next| starts_layer[next]);
            // The samples are resolved into the image once, by the tile's last pass: a
            // resolve reads every sample of the tile (after every pass, on the benchmark
            // scene at balanced, about 1 s of CPU time more, of 7–8).
            let last_of_tile = k + 1 == drawn.len();
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("scene"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: resolve_target.filter(|_| last_of_tile),
                    ops: wgpu::Operations {
                        load: if n == 0 {
                            wgpu::LoadOp::Clear(wgpu::Color::BLACK)
                        } else {
                            wgpu::LoadOp::Load
                        },
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: Some(wgpu::Operations {
                        load: if first_of_layer {
                            wgpu::LoadOp::Clear(0.0)
                        } else {
                            wgpu::LoadOp::Load
                        },
                        store: if last_of_layer {
                            wgpu::StoreOp::Discard
                        } else {
                            wgpu::StoreOp::Store
                        },
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            // The layer's viewport moved by the tile's corner (it may reach past the tile),
            // so every tile draws the same projection; the scissor keeps to the tile.
            let [x, y, w, h] = rects[l];
            pass.set_viewport(
                x as f32 - tx as f32,
                y as f32 - ty as f32,
                w as f32,
                h as f32,
                0.0,
                1.0,
            );
            let layer_scissor = in_tile(rects[l]);
            let [sx, sy, sw, sh] = layer_scissor;
            pass.set_scissor_rect(sx, sy, sw, sh);
            pass.set_bind_group(0, &globals_groups[l], &[]);
            if let (true, Some(background), Some(_)) =
                (first_of_layer, &background, &list.layers[l].background)
            {
                pass.set_pipeline(background);
                pass.draw(0..3, 0..1);
            }
            let mut scissor = layer_scissor;
            for ((&Piece { slot, ref range }, buffers), &reach) in
                pieces.iter().zip(&prepared[n]).zip(&reaches[n])
            {
                if !reaches_tile(reach) {
                    continue;
                }
                let [sx, sy, sw, sh] = in_tile(scissors[slot]);
                if [sx, sy, sw, sh] != scissor {
                    scissor = [sx, sy, sw, sh];
                    pass.set_scissor_rect(sx, sy, sw, sh);
                }
                let (key, textures) = &draws[slot];
                pass.set_pipeline(pipelines.get(*key));
                pass.set_bind_group(1, &draw_group, &[(slot * stride) as u32]);
                pass.set_bind_group(2, bindings.group(textures), &[]);
                let indices = match buffers {
                    PieceBuffers::Part(part) => {
                        for (i, buffer) in part.vertices.iter().enumerate() {
                            pass.set_vertex_buffer(
                                i as u32,
                                buffer.as_ref().unwrap_or(&zeros).slice(..),
                            );
                        }
                        pass.set_index_buffer(part.indices.slice(..), part.format);
                        pass.draw_indexed(0..range.end - range.start, 0, 0..1);
                        continue;
                    }
                    PieceBuffers::Whole(indices) => indices,
                };
                match (&uploaded[slot], indices) {
                    (Some(MeshBuffers::Surface { vertices }), Some(indices)) => {
                        for (i, buffer) in vertices.iter().enumerate().take(VERTEX_SLOTS) {
                            pass.set_vertex_buffer(
                                i as u32,
                                buffer.as_ref().unwrap_or(&zeros).slice(..),
                            );
                        }
                        pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
                        pass.draw_indexed(0..range.end - range.start, 0, 0..1);
                    }
                    (Some(MeshBuffers::Stroke { ends, colors }), _) => {
                        pass.set_vertex_buffer(0, ends.slice(..));
                        pass.set_vertex_buffer(1, colors.slice(..));
                        pass.draw(0..6, range.clone());
                    }
                    _ => unreachable!("every piece's buffers were made above"),
                }
            }
        }
        read_back(device, queue, encoder, &resolved, tile, scale, &mut image).await?;
    }
    Ok(image)
}

/// Whether a pass draws its part of a surface from buffers of only the vertices that part
/// names (from the smallest index to the largest): when they are fewer than its indices.
/// A connected mesh in a sensible order names few vertices per pass (a grid: about one per
/// six indices); one whose indices jump across it would upload most of its vertices again
/// for every pass, so it gets buffers of the whole mesh, made once.
fn local((first, last): (u32, u32), indices: usize) -> bool {
    ((last - first) as usize) < indices
}

/// Frees a mesh's arrays once its last pass is done.
fn free_arrays(mesh: &mut Mesh) {
    drop(std::mem::take(&mut mesh.positions));
    mesh.normals = None;
    mesh.tangents = None;
    mesh.colors = None;
    drop(std::mem::take(&mut mesh.tex_coords));
    drop(std::mem::take(&mut mesh.indices));
}

/// At most this many indices (or line and point instances, six vertices each) go into
/// one render pass by default. A software rasterizer keeps every binned triangle of a
/// pass until the pass ends, several times the meshes' own size for millions of
/// triangles; passes of this size, each finished before the next begins, bound that.
/// Measured on the benchmark scene (800×600, peak RSS of the whole run, GNU time,
/// thousand KiB): passes of 65,536 indices: fast 172, balanced 190, accurate 251 (largest
/// of 3); 32,768: 164.6, 183.1, 238.5 (largest of 2). Smaller passes used to cost more,
/// while the parameters were uniform buffers (see `pipelines::Parameters`): 16,384 then
/// took fast to 319 MB. The image is the same.
pub const PASS_INDICES: u32 = 1 << 15;

/// A piece's buffers: its part of a surface, or (in [`MeshBuffers`]) a whole mesh's
/// vertices and the piece's indices (None for a stroke).
enum PieceBuffers {
    Part(SurfacePart),
    Whole(Option<wgpu::Buffer>),
}

/// A draw call: part of one mesh's indices (or stroke instances).
struct Piece {
    slot: usize,
    range: std::ops::Range<u32>,
}

/// A draw's size for [`cut`]: a surface's indices (whole triangles), or a stroke's
/// instances (six indices each).
fn draw_size(mesh: &Mesh) -> (u32, u32, u32) {
    match mesh.primitive {
        Primitive::Triangles => (mesh.indices.len() as u32, 3, 1),
        primitive => ((mesh.indices.len() / primitive.arity()) as u32, 1, 6),
    }
}

/// The draws cut into passes of at most `limit` indices (whole triangles; a triangle or
/// stroke larger than the limit gets a pass of its own), in order; at least one pass,
/// empty for a layer without meshes. Draws are given as (count, unit, weight): `count`
/// indices or instances, never cut within `unit` of them, each `weight` indices.
fn cut(draws: impl Iterator<Item = (u32, u32, u32)>, limit: u32) -> Vec<Vec<Piece>> {
    let mut passes = Vec::new();
    let mut current = Vec::new();
    let mut room = limit;
    for (slot, (count, unit, weight)) in draws.enumerate() {
        let mut start = 0;
        while start < count {
            if room < unit * weight && !current.is_empty() {
                passes.push(std::mem::take(&mut current));
                room = limit;
            }
            let take = (room / weight / unit * unit).max(unit).min(count - start);
            current.push(Piece {
                slot,
                range: start..start + take,
            });
            room = room.saturating_sub(take * weight);
            start += take;
        }
    }
    passes.push(current);
    passes
}

/// A pass that only clears the image to black.
fn clear_pass(
    encoder: &mut wgpu::CommandEncoder,
    view: &wgpu::TextureView,
    resolve_target: Option<&wgpu::TextureView>,
    depth: &wgpu::TextureView,
) {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("clear"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
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
}

/// The tile's pixels of a rectangle of the target, counted from the tile's corner; none:
/// all zero (a scissor must lie within the tile even when empty).
pub(super) fn in_tile(rect: [u32; 4], tile: [u32; 4]) -> [u32; 4] {
    match intersect(rect, tile) {
        [_, _, 0, _] | [_, _, _, 0] => [0; 4],
        [x, y, w, h] => [x - tile[0], y - tile[1], w, h],
    }
}

/// The overlap of two pixel rectangles (x, y, width, height); empty: zero width or height.
fn intersect(a: [u32; 4], b: [u32; 4]) -> [u32; 4] {
    let x0 = a[0].max(b[0]);
    let y0 = a[1].max(b[1]);
    let x1 = (a[0] + a[2]).min(b[0] + b[2]);
    let y1 = (a[1] + a[3]).min(b[1] + b[3]);
    [x0, y0, x1.saturating_sub(x0), y1.saturating_sub(y0)]
}

/// Reads a tile of the target back and averages it into its part of the image.
async fn read_back(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    mut encoder: wgpu::CommandEncoder,
    texture: &wgpu::Texture,
    [tx, ty, width, height]: [u32; 4],
    scale: u32,
    image: &mut image::RgbaImage,
) -> Result<(), GpuError> {
    let padded_row = (width * 4).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
        * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
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
    queue.submit([encoder.finish()]);
    let slice = buffer.slice(..);
    let (sender, receiver) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        let _ = sender.send(result);
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    receiver
        .recv()
        .map_err(|e| GpuError::Failed(e.to_string()))?
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    let mapped = slice
        .get_mapped_range()
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    let scale = scale.max(1);
    average_into(
        &mapped,
        padded_row as usize,
        scale,
        [tx / scale, ty / scale, width / scale, height / scale],
        image,
    );
    Ok(())
}

/// Writes the image's pixels in `rect` (x, y, width, height), each the average of a
/// `scale` × `scale` block of the read-back rows (`padded_row` bytes apart, from the
/// rectangle's corner), read in place rather than copied first (a supersampled target
/// is 7.7 MB at 800×600). The preview is opaque: blending leaves coverage, not
/// transparency, in alpha.
fn average_into(
    rows: &[u8],
    padded_row: usize,
    scale: u32,
    [x0, y0, width, height]: [u32; 4],
    image: &mut image::RgbaImage,
) {
    let count = scale * scale;
    for y in 0..height {
        for x in 0..width {
            let mut sum = [0u32; 3];
            for dy in 0..scale {
                let row = &rows[(y * scale + dy) as usize * padded_row..];
                for dx in 0..scale {
                    let at = (x * scale + dx) as usize * 4;
                    for (c, total) in sum.iter_mut().enumerate() {
                        *total += u32::from(row[at + c]);
                    }
                }
            }
            let [r, g, b] = sum.map(|s| ((s + count / 2) / count) as u8);
            image.put_pixel(x0 + x, y0 + y, image::Rgba([r, g, b, 255]));
        }
    }
}

/// The most samples of a tile by default: the target is drawn in tiles of at most this
/// many pixels × samples, one after the other, each drawing the pieces of the list that
/// can reach it (see `reach`), so that the render targets (4 bytes of colour and 4 of
/// depth per sample, on a software driver in the process's own memory) stay small.
/// 800×600 at one sample: fast's image at the default size is one tile; balanced's 4
/// samples four tiles of 400×300; accurate's 1600×1200 with 4 samples 16.
pub const TILE_SAMPLES: u32 = 800 * 600;

/// A tile's size: the target halved, its longer side first, until a tile has at most
/// `target.tile_samples` samples; a whole number of supersampled blocks on each side.
fn tile_size(target: &Target) -> (u32, u32) {
    let scale = target.scale.max(1);
    let (mut width, mut height) = (target.width / scale, target.height / scale);
    let samples =
        |w: u32, h: u32| u64::from(w * scale) * u64::from(h * scale) * u64::from(target.samples);
    while samples(width, height) > u64::from(target.tile_samples) && (width > 1 || height > 1) {
        if width >= height {
            width = width.div_ceil(2);
        } else {
            height = height.div_ceil(2);
        }
    }
    (width * scale, height * scale)
}

/// The tiles (x, y, width, height) covering the target, rows from the top (none for an
/// empty target).
fn tiles(target: &Target, tile_width: u32, tile_height: u32) -> Vec<[u32; 4]> {
    let mut tiles = Vec::new();
    for y in (0..target.height).step_by(tile_height.max(1) as usize) {
        for x in (0..target.width).step_by(tile_width.max(1) as usize) {
            tiles.push([
                x,
                y,
                tile_width.min(target.width - x),
                tile_height.min(target.height - y),
            ]);
        }
    }
    tiles
}

/// Opaque meshes first, in list order; then blended ones from the farthest to the nearest
/// (by the distance of their bounding-box centre from the eye). Empty meshes are left out.
fn draw_order(meshes: &[Mesh]) -> Vec<usize> {
    let mut opaque = Vec::new();
    let mut blended = Vec::new();
    for (i, mesh) in meshes.iter().enumerate() {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::CheckConfig;
    use crate::render::{preview, ImageSize, Quality, RenderArgs};

    #[test]
    fn passes_cover_every_draw_once_in_order_within_the_limit() {
        // Two surfaces (indices, whole triangles) and a stroke (instances of 6 indices).
        let draws = [(3000, 3, 1), (9, 3, 1), (50, 1, 6)];
        for limit in [1, 5, 6, 7, 300, 1000, 3005, u32::MAX] {
            let passes = cut(draws.into_iter(), limit);
            assert!(!passes.is_empty());
            let pieces: Vec<&Piece> = passes.iter().flatten().collect();
            let mut next = [0u32; 3];
            for piece in &pieces {
                let (_, unit, _) = draws[piece.slot];
                assert_eq!(piece.range.start, next[piece.slot], "in order, no gap");
                assert!(piece.range.end > piece.range.start);
                assert_eq!(piece.range.start % unit, 0, "whole triangles");
                next[piece.slot] = piece.range.end;
            }
            assert_eq!(next, [3000, 9, 50], "limit {limit}: everything drawn");
            for pass in &passes {
                let weight: u32 = pass
                    .iter()
                    .map(|p| (p.range.end - p.range.start) * draws[p.slot].2)
                    .sum();
                // A unit larger than the limit gets a pass of its own.
                assert!(weight <= limit.max(6), "limit {limit}: a pass of {weight}");
            }
        }
        assert_eq!(
            cut(std::iter::empty(), 10).len(),
            1,
            "an empty scene: one pass"
        );
    }

    #[test]
    fn tiles_cover_the_target_once_in_whole_blocks_within_the_limit() {
        for (width, height, scale, samples, limit) in [
            (800, 600, 1, 1, TILE_SAMPLES),
            (800, 600, 1, 4, TILE_SAMPLES),
            (1600, 1200, 2, 4, TILE_SAMPLES),
            (1602, 998, 2, 4, 1000),
            (7, 5, 1, 4, 1),
        ] {
            let target = Target {
                width,
                height,
                scale,
                samples,
                shading: Shading::Phong,
                pass_indices: PASS_INDICES,
                tile_samples: limit,
            };
            let (tile_width, tile_height) = tile_size(&target);
            assert_eq!((tile_width % scale, tile_height % scale), (0, 0));
            assert!(
                tile_width * tile_height * samples <= limit.max(scale * scale * samples),
                "{width}x{height}: a tile of {tile_width}x{tile_height}"
            );
            let mut covered = vec![0u8; (width * height) as usize];
            for [x, y, w, h] in tiles(&target, tile_width, tile_height) {
                assert_eq!((x % scale, y % scale, w % scale, h % scale), (0, 0, 0, 0));
                for row in y..y + h {
                    for column in x..x + w {
                        covered[(row * width + column) as usize] += 1;
                    }
                }
            }
            assert!(
                covered.iter().all(|&c| c == 1),
                "{width}x{height}: covered once"
            );
        }
        // A layer's or a mesh's rectangle against a tile: inside, across, outside.
        let tile = [400, 300, 400, 300];
        assert_eq!(in_tile([450, 350, 10, 10], tile), [50, 50, 10, 10]);
        assert_eq!(in_tile([0, 0, 800, 600], tile), [0, 0, 400, 300]);
        assert_eq!(in_tile([0, 0, 400, 300], tile), [0; 4]);
        assert_eq!(in_tile([800, 0, 100, 600], tile), [0; 4]);
        let fast = Target {
            width: 800,
            height: 600,
            scale: 1,
            samples: 1,
            shading: Shading::Gouraud,
            pass_indices: PASS_INDICES,
            tile_samples: TILE_SAMPLES,
        };
        assert_eq!(
            tile_size(&fast),
            (800, 600),
            "fast at the default size: one tile"
        );
    }

    #[test]
    fn a_frame_cut_into_passes_is_the_frame_drawn_in_one() {
        if !crate::render::adapter_for_test("a_frame_cut_into_passes_is_the_frame_drawn_in_one") {
            return;
        }
        // Opaque triangles over a background gradient, a blended shape, lines and points.
        let source = "<X3D profile='Full' version='4.0'><Scene>\
            <Background skyColor='0 0 0.2 0.3 0.3 0.8' skyAngle='1.6'/>\
            <Viewpoint position='2 3 9'/>\
            <Shape><Appearance><Material diffuseColor='0.8 0.4 0.1'/></Appearance>\
            <ElevationGrid xDimension='30' zDimension='30' xSpacing='0.2' zSpacing='0.2' \
            creaseAngle='1' height='"
            .to_string()
            + &(0..900)
                .map(|k| format!("{:.3}", ((k % 30) as f32 * 0.4).sin() * 0.5))
                .collect::<Vec<_>>()
                .join(" ")
            + "'/></Shape>\
            <Transform translation='3 0.5 2'><Shape><Appearance>\
            <Material diffuseColor='0 0.6 1' transparency='0.5'/></Appearance>\
            <Sphere radius='1.5'/></Shape></Transform>\
            <Shape><IndexedLineSet coordIndex='0 1 2 3 0 -1'>\
            <Coordinate point='0 1 0 6 1 0 6 1 6 0 1 6'/></IndexedLineSet></Shape>\
            <Shape><PointSet><Coordinate point='1 2 1 2 2 2 3 2 3'/></PointSet></Shape>\
            </Scene></X3D>";
        let crate::check::Checked {
            mut report,
            document: doc,
            ..
        } = crate::check::check_document("passes.x3d", source.as_bytes(), &CheckConfig::default());
        let args = RenderArgs {
            render: None,
            size: ImageSize {
                width: 96,
                height: 72,
            },
            quality: Quality::Balanced,
            camera: "auto".to_string(),
            island: 1,
        };
        let list = preview(
            &args,
            Quality::Balanced.settings(),
            std::path::Path::new("passes.x3d"),
            None,
            source.as_bytes(),
            doc.as_ref(),
            &mut report,
        )
        .expect("a preview")
        .list()
        .clone();
        let gpu = super::super::Gpu::open().expect("an adapter");
        let draw = |samples, shading, pass_indices, tile_samples| {
            let target = Target {
                width: 96,
                height: 72,
                scale: 1,
                samples,
                shading,
                pass_indices,
                tile_samples,
            };
            pollster::block_on(draw(&gpu.device, &gpu.queue, list.clone(), target))
                .unwrap()
                .into_raw()
        };
        for (samples, shading) in [(1, Shading::Gouraud), (4, Shading::Phong)] {
            let whole = draw(samples, shading, u32::MAX, u32::MAX);
            // A few hundred passes, cutting meshes and strokes apart.
            let cut = draw(samples, shading, 30, u32::MAX);
            assert!(whole.iter().any(|&b| b != whole[0]), "something is drawn");
            assert!(whole == cut, "{samples} samples: the cut frame differs");
            // Four tiles of 48×36: the viewport moves by whole pixels, which the driver
            // may round differently at a few edges.
            let tiled = draw(samples, shading, 30, 48 * 36 * samples);
            let differing = whole
                .chunks(4)
                .zip(tiled.chunks(4))
                .filter(|(a, b)| a != b)
                .count();
            assert!(
                differing * 100 < whole.len() / 4,
                "{samples} samples: {differing} pixels of the tiled frame differ"
            );
        }
    }
}
