//! Cube textures: six square faces around a point, as the Background panorama (24.4.1),
//! TextureBackground (24.4.3) and the cube map textures of clause 34 define them, made
//! into one GPU texture of view dimension Cube with a mipmap chain.
//!
//! **Orientation.** The faces are given in X3D's terms ([`Face`]) and each image is seen
//! from the centre of the cube "as if the image were displayed normally in 2D" (24.4.1):
//! front (−Z), back (+Z), left (−X) and right (+X) with +Y up; top (+Y) with +Z up (its
//! bottom row borders the front face); bottom (−Y) with −Z up (its top row borders the
//! front face). ComposedCubeMapTexture's faces are read the same way (as X_ITE does).
//! [`CubeImage`] stores them in the GPU's layer order (+X, −X, +Y, −Y, +Z, −Z) and
//! orientation (the face selection table of Vulkan and WebGPU), so that sampling the cube
//! with an X3D direction (right-handed, in the Background's or the world's axes) gives the
//! texel the X3D face shows in that direction.
//!
//! **Sources.** Six 2D texture nodes or url lists (PNG, JPEG, GIF, data: URLs,
//! PixelTexture, through `textures`); one image holding a cross (4:3 horizontal or 3:4
//! vertical); Radiance `.hdr` (kept as linear half floats, not tone-mapped); DDS and KTX2
//! cube files with uncompressed RGBA8, RGBA16F or RGBA32F faces (their layers used as
//! stored). Block-compressed and supercompressed files are reported as not drawn.

use std::path::Path;

use image::DynamicImage;

use super::textures::{self, NotDrawn};
use crate::model::{Document, NodeId};

/// A face of the cube, in the X3D terms of 24.4.1. Arrays of faces are in this order.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Face {
    Front,
    Back,
    Left,
    Right,
    Top,
    Bottom,
}

impl Face {
    pub const ALL: [Face; 6] = [
        Face::Front,
        Face::Back,
        Face::Left,
        Face::Right,
        Face::Top,
        Face::Bottom,
    ];

    /// The face's name in the field names of Background (`frontUrl`), TextureBackground
    /// and ComposedCubeMapTexture (`frontTexture`, 3.x `front`).
    pub fn name(self) -> &'static str {
        match self {
            Face::Front => "front",
            Face::Back => "back",
            Face::Left => "left",
            Face::Right => "right",
            Face::Top => "top",
            Face::Bottom => "bottom",
        }
    }

    /// The image's right and up directions as seen from the centre (24.4.1).
    fn right_up(self) -> ([i64; 3], [i64; 3]) {
        match self {
            Face::Front => ([1, 0, 0], [0, 1, 0]),
            Face::Back => ([-1, 0, 0], [0, 1, 0]),
            Face::Left => ([0, 0, -1], [0, 1, 0]),
            Face::Right => ([0, 0, 1], [0, 1, 0]),
            Face::Top => ([1, 0, 0], [0, 0, 1]),
            Face::Bottom => ([1, 0, 0], [0, 0, -1]),
        }
    }

    /// The face a direction's major axis points at.
    fn of_axis(axis: usize, positive: bool) -> Face {
        match (axis, positive) {
            (0, true) => Face::Right,
            (0, false) => Face::Left,
            (1, true) => Face::Top,
            (1, false) => Face::Bottom,
            (_, true) => Face::Back,
            (_, false) => Face::Front,
        }
    }
}

/// How the texels are stored.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum CubeFormat {
    /// 8-bit RGBA as the images store them (sRGB-encoded values, used as they are, as
    /// the 2D textures are).
    Rgba8,
    /// Linear half floats (Radiance HDR, float DDS and KTX2): values above 1 kept.
    Rgba16Float,
}

impl CubeFormat {
    pub fn wgpu(self) -> wgpu::TextureFormat {
        match self {
            CubeFormat::Rgba8 => wgpu::TextureFormat::Rgba8Unorm,
            CubeFormat::Rgba16Float => wgpu::TextureFormat::Rgba16Float,
        }
    }
}

/// Six square faces with their mipmap chain, ready to upload.
#[derive(Clone, Debug, PartialEq)]
pub struct CubeImage {
    /// The side of level 0, in texels.
    pub side: u32,
    pub format: CubeFormat,
    /// Level 0 first, each next level half the side (at least 1); each level holds the
    /// six faces in the GPU's layer order (+X, −X, +Y, −Y, +Z, −Z), rows from the top.
    pub levels: Vec<Vec<u8>>,
    /// Whether any texel has alpha below 1 (a missing face is transparent).
    pub translucent: bool,
}

impl CubeImage {
    pub fn bytes(&self) -> usize {
        self.levels.iter().map(Vec::len).sum()
    }

    /// Six faces in [`Face::ALL`] order (None: transparent), made square and of one
    /// size: the largest side given, at most `max_side`.
    pub fn from_faces(faces: [Option<DynamicImage>; 6], max_side: u32) -> Option<CubeImage> {
        let largest = faces
            .iter()
            .flatten()
            .map(|f| f.width().max(f.height()))
            .max()?;
        let side = largest.clamp(1, max_side.max(1));
        let float = faces.iter().flatten().any(is_float);
        let missing = faces.iter().any(Option::is_none);
        let square = |f: DynamicImage| {
            if f.width() == side && f.height() == side {
                f
            } else {
                f.resize_exact(side, side, image::imageops::FilterType::Triangle)
            }
        };
        if float {
            let faces = faces.map(|f| f.map(|f| square(f).into_rgba32f().into_raw()));
            let level = gpu_layers(&faces, side, 0.0);
            let translucent = missing || level.chunks_exact(4).any(|t| t[3] < 1.0);
            let levels = mipmaps(level, side).into_iter().map(half_floats).collect();
            Some(CubeImage {
                side,
                format: CubeFormat::Rgba16Float,
                levels,
                translucent,
            })
        } else {
            let faces = faces.map(|f| f.map(|f| square(f).into_rgba8().into_raw()));
            let level = gpu_layers(&faces, side, 0u8);
            let translucent = missing || level.chunks_exact(4).any(|t| t[3] < 255);
            Some(CubeImage {
                side,
                format: CubeFormat::Rgba8,
                levels: mipmaps(level, side),
                translucent,
            })
        }
    }

    /// A cross of six faces in one image: 4:3 horizontal (left, front, right, back in the
    /// middle row; top above and bottom below the front) or 3:4 vertical (top, front,
    /// bottom, back down the middle column, the back upside down; left and right beside
    /// the front), the layouts HDR probe collections use.
    pub fn from_cross(image: DynamicImage, max_side: u32) -> Result<CubeImage, String> {
        let (w, h) = (image.width(), image.height());
        // (column, row) of each face in Face::ALL order, and whether back is upside down.
        let (side, cells, back_turned) = if w * 3 == h * 4 {
            (
                w / 4,
                [(1, 1), (3, 1), (0, 1), (2, 1), (1, 0), (1, 2)],
                false,
            )
        } else if w * 4 == h * 3 {
            (
                w / 3,
                [(1, 1), (1, 3), (0, 1), (2, 1), (1, 0), (1, 2)],
                true,
            )
        } else {
            return Err(format!(
                "a {w}×{h} image is no cube cross (4:3 horizontal or 3:4 vertical)"
            ));
        };
        if side == 0 {
            return Err("the cross image is empty".to_string());
        }
        let faces = std::array::from_fn(|i| {
            let (column, row) = cells[i];
            let face = image.crop_imm(column * side, row * side, side, side);
            Some(if back_turned && Face::ALL[i] == Face::Back {
                face.rotate180()
            } else {
                face
            })
        });
        CubeImage::from_faces(faces, max_side).ok_or_else(|| "no faces".to_string())
    }

    /// The cube on the GPU, with every level.
    pub fn upload(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> wgpu::Texture {
        use wgpu::util::DeviceExt;
        device.create_texture_with_data(
            queue,
            &wgpu::TextureDescriptor {
                label: Some("cube"),
                size: wgpu::Extent3d {
                    width: self.side,
                    height: self.side,
                    depth_or_array_layers: 6,
                },
                mip_level_count: self.levels.len() as u32,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: self.format.wgpu(),
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::MipMajor,
            &self.levels.concat(),
        )
    }

    /// The cube in linear light, as half floats: 8-bit texels decoded from sRGB (the mip
    /// chain averaged again, in linear light), float texels as they are. Image-based
    /// lighting sums light, which only linear values allow.
    pub fn linear(self) -> CubeImage {
        if self.format == CubeFormat::Rgba16Float {
            return self;
        }
        let decode = |v: u8| {
            let c = f32::from(v) / 255.0;
            if c <= 0.04045 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        };
        let level0: Vec<f32> = self.levels[0]
            .chunks_exact(4)
            .flat_map(|t| {
                [
                    decode(t[0]),
                    decode(t[1]),
                    decode(t[2]),
                    f32::from(t[3]) / 255.0,
                ]
            })
            .collect();
        CubeImage {
            side: self.side,
            format: CubeFormat::Rgba16Float,
            levels: mipmaps(level0, self.side)
                .into_iter()
                .map(half_floats)
                .collect(),
            translucent: self.translucent,
        }
    }

    /// One colour on every face (a stand-in where a cube is absent).
    pub fn uniform(rgba: [u8; 4]) -> CubeImage {
        CubeImage {
            side: 1,
            format: CubeFormat::Rgba8,
            levels: vec![rgba.repeat(6)],
            translucent: rgba[3] < 255,
        }
    }
}

/// A view of an uploaded cube texture as a cube.
pub fn cube_view(texture: &wgpu::Texture) -> wgpu::TextureView {
    texture.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::Cube),
        ..Default::default()
    })
}

/// The sampler cube textures are drawn with: bilinear, trilinear between levels, no
/// wrapping across the faces' edges.
pub fn cube_sampler(device: &wgpu::Device) -> wgpu::Sampler {
    device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("cube"),
        address_mode_u: wgpu::AddressMode::ClampToEdge,
        address_mode_v: wgpu::AddressMode::ClampToEdge,
        address_mode_w: wgpu::AddressMode::ClampToEdge,
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        mipmap_filter: wgpu::MipmapFilterMode::Linear,
        ..Default::default()
    })
}

/// Floats as little-endian half floats.
fn half_floats(values: Vec<f32>) -> Vec<u8> {
    values
        .iter()
        .flat_map(|v| half::f16::from_f32(*v).to_le_bytes())
        .collect()
}

fn is_float(image: &DynamicImage) -> bool {
    matches!(
        image,
        DynamicImage::ImageRgb32F(_) | DynamicImage::ImageRgba32F(_)
    )
}

/// Where each GPU layer texel comes from: for layer `layer`, texel (column, row) of a
/// `side` cube, the X3D face and its (column, row). Exact in integers: texel centres
/// are at odd multiples of 1/side.
fn source_of(layer: usize, column: u32, row: u32, side: u32) -> (Face, u32, u32) {
    let n = i64::from(side);
    let sc = 2 * i64::from(column) + 1 - n;
    let tc = 2 * i64::from(row) + 1 - n;
    // The direction of the texel by the cube face selection table (+X, −X, +Y, −Y, +Z, −Z).
    let d: [i64; 3] = match layer {
        0 => [n, -tc, -sc],
        1 => [-n, -tc, sc],
        2 => [sc, n, tc],
        3 => [sc, -n, -tc],
        4 => [sc, -tc, n],
        _ => [-sc, -tc, -n],
    };
    let face = Face::of_axis(layer / 2, layer.is_multiple_of(2));
    let (right, up) = face.right_up();
    let dot = |a: [i64; 3]| a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
    let (u, v) = (dot(right), dot(up));
    (face, ((u + n - 1) / 2) as u32, ((n - 1 - v) / 2) as u32)
}

/// The six X3D faces (RGBA, `side` square, [`Face::ALL`] order; None filled with `fill`)
/// as the GPU's six layers.
fn gpu_layers<T: Copy>(faces: &[Option<Vec<T>>; 6], side: u32, fill: T) -> Vec<T> {
    let texels = (side * side) as usize;
    let mut out = Vec::with_capacity(texels * 6 * 4);
    for layer in 0..6 {
        for row in 0..side {
            for column in 0..side {
                let (face, x, y) = source_of(layer, column, row, side);
                let index = Face::ALL.iter().position(|f| *f == face).unwrap_or(0);
                match &faces[index] {
                    Some(texels) => {
                        let at = ((y * side + x) * 4) as usize;
                        out.extend_from_slice(&texels[at..at + 4]);
                    }
                    None => out.extend_from_slice(&[fill; 4]),
                }
            }
        }
    }
    out
}

/// A channel value averaged into mipmaps.
trait Channel: Copy {
    fn to_f32(self) -> f32;
    fn from_f32(value: f32) -> Self;
}

impl Channel for u8 {
    fn to_f32(self) -> f32 {
        f32::from(self)
    }
    fn from_f32(value: f32) -> Self {
        value.round().clamp(0.0, 255.0) as u8
    }
}

impl Channel for f32 {
    fn to_f32(self) -> f32 {
        self
    }
    fn from_f32(value: f32) -> Self {
        value
    }
}

/// The mipmap chain of six RGBA faces down to 1 × 1, each face on its own (a level's
/// side is half the previous, rounded down; each texel averages those it covers).
fn mipmaps<T: Channel>(level0: Vec<T>, side: u32) -> Vec<Vec<T>> {
    let mut levels = vec![level0];
    let mut n = side as usize;
    while n > 1 {
        let m = n / 2;
        let previous = levels.last().map(Vec::as_slice).unwrap_or_default();
        let mut next = Vec::with_capacity(m * m * 6 * 4);
        for face in previous.chunks_exact(n * n * 4) {
            for y in 0..m {
                let rows = y * n / m..(y + 1) * n / m;
                for x in 0..m {
                    let columns = x * n / m..(x + 1) * n / m;
                    let count = (rows.len() * columns.len()) as f32;
                    for c in 0..4 {
                        let mut sum = 0.0;
                        for sy in rows.clone() {
                            for sx in columns.clone() {
                                sum += face[(sy * n + sx) * 4 + c].to_f32();
                            }
                        }
                        next.push(T::from_f32(sum / count));
                    }
                }
            }
        }
        levels.push(next);
        n = m;
    }
    levels
}

/// The faces of a Background (its url fields) or TextureBackground (its texture nodes);
/// None when it has none. A face that cannot be read is transparent, with a note in
/// `notes`.
pub(crate) fn background(
    doc: &Document,
    node: NodeId,
    base: &Path,
    root: &Path,
    max_side: u32,
    notes: &mut Vec<NotDrawn>,
) -> Option<CubeImage> {
    let textured = doc.node(node).type_name() == "TextureBackground";
    let faces = Face::ALL.map(|face| {
        let name = face.name();
        let image = if textured {
            let field = format!("{name}Texture");
            let texture = super::fields::child(doc, node, &field)?;
            textures::pixels(doc, texture, base, root)
                .map(rgba_image)
                .map_err(|e| NotDrawn {
                    message: format!("{field}: {}", e.message),
                    limit: e.limit,
                })
        } else {
            let urls = textures::urls(doc, node, &format!("{name}Url"));
            if urls.is_empty() {
                return None;
            }
            textures::first_image(&urls, base, root, &format!("{name}Url"))
        };
        image.map_err(|e| notes.push(e)).ok()
    });
    CubeImage::from_faces(faces, max_side)
}

/// A ComposedCubeMapTexture or ImageCubeMapTexture.
pub(crate) fn load(
    doc: &Document,
    node: NodeId,
    base: &Path,
    root: &Path,
    max_side: u32,
) -> Result<CubeImage, NotDrawn> {
    match doc.node(node).type_name() {
        "ComposedCubeMapTexture" => {
            let mut reasons = Vec::new();
            let faces = Face::ALL.map(|face| {
                let name = face.name();
                let texture = super::fields::child(doc, node, &format!("{name}Texture"))
                    .or_else(|| super::fields::child(doc, node, name))?;
                textures::pixels(doc, texture, base, root)
                    .map(rgba_image)
                    .map_err(|e| reasons.push(format!("{name}: {}", e.message)))
                    .ok()
            });
            let loaded = CubeImage::from_faces(faces, max_side);
            match loaded {
                Some(cube) if reasons.is_empty() => Ok(cube),
                _ if !reasons.is_empty() => {
                    Err(format!("ComposedCubeMapTexture not drawn ({})", reasons.join("; ")).into())
                }
                _ => Err("ComposedCubeMapTexture has no textures".into()),
            }
        }
        "ImageCubeMapTexture" => image_cube(doc, node, base, root, max_side),
        other => Err(format!("{other} is not drawn").into()),
    }
}

fn rgba_image((rgba, width, height, _): textures::Pixels) -> DynamicImage {
    DynamicImage::ImageRgba8(
        image::RgbaImage::from_raw(width, height, rgba)
            .unwrap_or_else(|| image::RgbaImage::new(1, 1)),
    )
}

/// ImageCubeMapTexture: the first url that reads as a DDS or KTX2 cube, or as an image
/// holding a cross.
fn image_cube(
    doc: &Document,
    node: NodeId,
    base: &Path,
    root: &Path,
    max_side: u32,
) -> Result<CubeImage, NotDrawn> {
    let urls = textures::urls(doc, node, "url");
    let mut reasons = Vec::new();
    for url in &urls {
        let lower = url.to_ascii_lowercase();
        let container = [".dds", ".ktx2"].into_iter().find(|ext| {
            lower
                .split(['#', '?'])
                .next()
                .is_some_and(|p| p.ends_with(ext))
        });
        let result = match container {
            Some(ext) => textures::local_file(url, base, root)
                .and_then(|path| std::fs::read(&path).map_err(|e| e.to_string()))
                .and_then(|bytes| match ext {
                    ".dds" => dds(&bytes, max_side),
                    _ => ktx2(&bytes, max_side),
                }),
            None => textures::first_image(std::slice::from_ref(url), base, root, "url")
                .map_err(|e| e.message)
                .and_then(|image| CubeImage::from_cross(image, max_side)),
        };
        match result {
            Ok(cube) => return Ok(cube),
            Err(reason) => reasons.push(format!("{}: {reason}", shown(url))),
        }
    }
    if reasons.is_empty() {
        return Err("ImageCubeMapTexture has no url".into());
    }
    Err(format!("ImageCubeMapTexture not drawn ({})", reasons.join("; ")).into())
}

fn shown(url: &str) -> String {
    crate::model::data_url::shown(url).to_string()
}

/// Layers of a container file (six faces, the GPU's order) as a cube, decoded from
/// `texel` values: RGBA8 bytes or little-endian floats.
fn from_layers(
    layers: Vec<Vec<f32>>,
    float: bool,
    side: u32,
    max_side: u32,
) -> Result<CubeImage, String> {
    // Back to X3D faces, through the same table, so that every source is sized alike.
    let mut faces: [Option<DynamicImage>; 6] = Default::default();
    for (layer, texels) in layers.into_iter().enumerate() {
        let face = Face::of_axis(layer / 2, layer % 2 == 0);
        let mut image = image::Rgba32FImage::new(side, side);
        for row in 0..side {
            for column in 0..side {
                let (_, x, y) = source_of(layer, column, row, side);
                let at = ((row * side + column) * 4) as usize;
                image.put_pixel(
                    x,
                    y,
                    image::Rgba([texels[at], texels[at + 1], texels[at + 2], texels[at + 3]]),
                );
            }
        }
        let index = Face::ALL.iter().position(|f| *f == face).unwrap_or(0);
        faces[index] = Some(if float {
            DynamicImage::ImageRgba32F(image)
        } else {
            DynamicImage::ImageRgba8(DynamicImage::ImageRgba32F(image).into_rgba8())
        });
    }
    CubeImage::from_faces(faces, max_side).ok_or_else(|| "no faces".to_string())
}

/// Texel bytes as RGBA floats (8-bit values scaled to [0, 1]).
fn texels(bytes: &[u8], kind: Texels) -> Vec<f32> {
    match kind {
        Texels::Rgba8 => bytes.iter().map(|b| f32::from(*b) / 255.0).collect(),
        Texels::Bgra8 => bytes
            .chunks_exact(4)
            .flat_map(|p| [p[2], p[1], p[0], p[3]])
            .map(|b| f32::from(b) / 255.0)
            .collect(),
        Texels::Rgba16F => bytes
            .chunks_exact(2)
            .map(|h| half::f16::from_le_bytes([h[0], h[1]]).to_f32())
            .collect(),
        Texels::Rgba32F => bytes
            .chunks_exact(4)
            .map(|f| f32::from_le_bytes([f[0], f[1], f[2], f[3]]))
            .collect(),
    }
}

#[derive(Copy, Clone)]
enum Texels {
    Rgba8,
    Bgra8,
    Rgba16F,
    Rgba32F,
}

impl Texels {
    fn bytes(self) -> usize {
        match self {
            Texels::Rgba8 | Texels::Bgra8 => 4,
            Texels::Rgba16F => 8,
            Texels::Rgba32F => 16,
        }
    }

    fn float(self) -> bool {
        matches!(self, Texels::Rgba16F | Texels::Rgba32F)
    }
}

/// Level 0 of each of six layers stored one after the other, each followed by
/// `layer_stride − side² texels` bytes of smaller levels.
fn split_layers(
    data: &[u8],
    kind: Texels,
    side: u32,
    layer_stride: usize,
) -> Result<Vec<Vec<f32>>, String> {
    let level = (side as usize).pow(2) * kind.bytes();
    (0..6)
        .map(|layer| {
            let start = layer * layer_stride;
            data.get(start..start + level)
                .map(|bytes| texels(bytes, kind))
                .ok_or_else(|| "the file is shorter than its header says".to_string())
        })
        .collect()
}

/// Check before allocating: a side past the texture limit is refused.
fn check_side(side: u32) -> Result<(), String> {
    if side == 0 || side > crate::limits::MAX_IMAGE_SIDE {
        return Err(format!("a cube side of {side} texels is not drawn"));
    }
    Ok(())
}

/// A DDS cube map (all six faces) of uncompressed RGBA8, BGRA8, RGBA16F or RGBA32F.
fn dds(bytes: &[u8], max_side: u32) -> Result<CubeImage, String> {
    use ddsfile::{Caps2, D3DFormat, DxgiFormat};
    let file = ddsfile::Dds::read(bytes).map_err(|e| format!("does not read as DDS: {e}"))?;
    let (width, height) = (file.get_width(), file.get_height());
    if width != height {
        return Err(format!("DDS faces of {width}×{height} are not square"));
    }
    check_side(width)?;
    let cube = file.header.caps2.contains(Caps2::CUBEMAP_ALLFACES)
        || file
            .header10
            .as_ref()
            .is_some_and(|h| h.misc_flag.contains(ddsfile::MiscFlag::TEXTURECUBE));
    if !cube {
        return Err("the DDS file is not a cube map of six faces".to_string());
    }
    let kind = match (file.get_dxgi_format(), file.get_d3d_format()) {
        (Some(DxgiFormat::R8G8B8A8_UNorm | DxgiFormat::R8G8B8A8_UNorm_sRGB), _)
        | (_, Some(D3DFormat::A8B8G8R8)) => Texels::Rgba8,
        (Some(DxgiFormat::B8G8R8A8_UNorm | DxgiFormat::B8G8R8A8_UNorm_sRGB), _)
        | (_, Some(D3DFormat::A8R8G8B8)) => Texels::Bgra8,
        (Some(DxgiFormat::R16G16B16A16_Float), _) | (_, Some(D3DFormat::A16B16G16R16F)) => {
            Texels::Rgba16F
        }
        (Some(DxgiFormat::R32G32B32A32_Float), _) | (_, Some(D3DFormat::A32B32G32R32F)) => {
            Texels::Rgba32F
        }
        (Some(other), _) => return Err(format!("DDS format {other:?} is not drawn")),
        (_, Some(other)) => return Err(format!("DDS format {other:?} is not drawn")),
        _ => return Err("the DDS file's pixel format is not drawn".to_string()),
    };
    let layer_stride = file.data.len() / 6;
    let layers = split_layers(&file.data, kind, width, layer_stride)?;
    from_layers(layers, kind.float(), width, max_side)
}

/// A KTX2 cube map (six faces) of uncompressed RGBA8, RGBA16F or RGBA32F, without
/// supercompression.
fn ktx2(bytes: &[u8], max_side: u32) -> Result<CubeImage, String> {
    use ktx2::Format;
    let reader = ktx2::Reader::new(bytes).map_err(|e| format!("does not read as KTX2: {e}"))?;
    let header = reader.header();
    if header.face_count != 6 {
        return Err("the KTX2 file is not a cube map of six faces".to_string());
    }
    if header.supercompression_scheme.is_some() {
        return Err("supercompressed KTX2 (Basis, zstd, zlib) is not drawn".to_string());
    }
    let (width, height) = (header.pixel_width, header.pixel_height.max(1));
    if width != height {
        return Err(format!("KTX2 faces of {width}×{height} are not square"));
    }
    check_side(width)?;
    let kind = match header.format {
        Some(Format::R8G8B8A8_UNORM | Format::R8G8B8A8_SRGB) => Texels::Rgba8,
        Some(Format::B8G8R8A8_UNORM | Format::B8G8R8A8_SRGB) => Texels::Bgra8,
        Some(Format::R16G16B16A16_SFLOAT) => Texels::Rgba16F,
        Some(Format::R32G32B32A32_SFLOAT) => Texels::Rgba32F,
        Some(other) => return Err(format!("KTX2 format {other:?} is not drawn")),
        None => {
            return Err("KTX2 without a Vulkan format (Basis Universal) is not drawn".to_string())
        }
    };
    // Level 0 holds the six faces one after the other.
    let level = reader
        .levels()
        .next()
        .ok_or_else(|| "the KTX2 file has no levels".to_string())?;
    let face_bytes = (width as usize).pow(2) * kind.bytes();
    let layers = split_layers(level.data, kind, width, face_bytes)?;
    from_layers(layers, kind.float(), width, max_side)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each X3D face in a colour of its own, a marked texel at its top-left corner.
    fn marked_faces(side: u32) -> [Option<DynamicImage>; 6] {
        std::array::from_fn(|i| {
            let mut image =
                image::RgbaImage::from_pixel(side, side, image::Rgba([i as u8 * 40, 0, 0, 255]));
            image.put_pixel(0, 0, image::Rgba([i as u8 * 40, 255, 0, 255]));
            Some(DynamicImage::ImageRgba8(image))
        })
    }

    /// The texel the GPU samples in direction `d` (the selection table of Vulkan).
    fn sample(cube: &CubeImage, d: [f32; 3]) -> [u8; 4] {
        let [x, y, z] = d;
        let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
        let (layer, sc, tc, ma) = if ax >= ay && ax >= az {
            if x > 0.0 {
                (0, -z, -y, ax)
            } else {
                (1, z, -y, ax)
            }
        } else if ay >= az {
            if y > 0.0 {
                (2, x, z, ay)
            } else {
                (3, x, -z, ay)
            }
        } else if z > 0.0 {
            (4, x, -y, az)
        } else {
            (5, -x, -y, az)
        };
        let n = cube.side as f32;
        let s = (((sc / ma + 1.0) / 2.0) * n).floor().min(n - 1.0) as usize;
        let t = (((tc / ma + 1.0) / 2.0) * n).floor().min(n - 1.0) as usize;
        let side = cube.side as usize;
        let at = ((layer * side + t) * side + s) * 4;
        cube.levels[0][at..at + 4].try_into().unwrap()
    }

    #[test]
    fn faces_are_seen_from_the_centre_as_24_4_1_says() {
        let cube = CubeImage::from_faces(marked_faces(4), 64).unwrap();
        let e = 0.99;
        // Seen from the centre, each face's top-left texel is where the clause puts it:
        // front (−Z) towards (−X, +Y); back (+Z) (+X, +Y); left (−X) (+Z, +Y); right (+X)
        // (−Z, +Y); top (+Y, +Z up) (−X, +Z); bottom (−Y, −Z up) (−X, −Z).
        let corners: [(Face, [f32; 3]); 6] = [
            (Face::Front, [-e, e, -1.0]),
            (Face::Back, [e, e, 1.0]),
            (Face::Left, [-1.0, e, e]),
            (Face::Right, [1.0, e, -e]),
            (Face::Top, [-e, 1.0, e]),
            (Face::Bottom, [-e, -1.0, -e]),
        ];
        for (i, (face, d)) in corners.iter().enumerate() {
            assert_eq!(Face::ALL[i], *face);
            assert_eq!(sample(&cube, *d), [i as u8 * 40, 255, 0, 255], "{face:?}");
            // The opposite corner is plain.
            let [x, y, z] = *d;
            let opposite = match face {
                Face::Front | Face::Back => [-x, -y, z],
                Face::Left | Face::Right => [x, -y, -z],
                Face::Top | Face::Bottom => [-x, y, -z],
            };
            assert_eq!(
                sample(&cube, opposite),
                [i as u8 * 40, 0, 0, 255],
                "{face:?}"
            );
        }
    }

    #[test]
    fn a_missing_face_is_transparent_and_levels_reach_one_texel() {
        let mut faces = marked_faces(8);
        faces[4] = None;
        let cube = CubeImage::from_faces(faces, 64).unwrap();
        assert!(cube.translucent);
        assert_eq!(sample(&cube, [0.0, 1.0, 0.0]), [0, 0, 0, 0]);
        let sizes: Vec<usize> = cube.levels.iter().map(Vec::len).collect();
        assert_eq!(sizes, vec![8 * 8 * 24, 4 * 4 * 24, 2 * 2 * 24, 24]);
    }

    #[test]
    fn crosses_are_cut_by_their_aspect_ratio() {
        // A horizontal cross 4 × 3 faces of 2 texels, each cell its own grey.
        let cell = |c: u32, r: u32| (r * 4 + c) as u8 * 10;
        let horizontal = image::RgbaImage::from_fn(8, 6, |x, y| {
            let v = cell(x / 2, y / 2);
            image::Rgba([v, v, v, 255])
        });
        let cube = CubeImage::from_cross(DynamicImage::ImageRgba8(horizontal), 64).unwrap();
        // Front is cell (1, 1), seen looking down −Z.
        assert_eq!(sample(&cube, [0.0, 0.0, -1.0])[0], cell(1, 1));
        assert_eq!(sample(&cube, [0.0, 0.0, 1.0])[0], cell(3, 1));
        assert_eq!(sample(&cube, [0.0, 1.0, 0.0])[0], cell(1, 0));
        let vertical = image::RgbaImage::new(6, 8);
        assert!(CubeImage::from_cross(DynamicImage::ImageRgba8(vertical), 64).is_ok());
        let square = image::RgbaImage::new(6, 6);
        assert!(CubeImage::from_cross(DynamicImage::ImageRgba8(square), 64).is_err());
    }

    #[test]
    fn eight_bit_faces_decode_from_srgb_to_linear_half_floats() {
        let grey = image::RgbaImage::from_pixel(2, 2, image::Rgba([188, 255, 0, 128]));
        let faces = std::array::from_fn(|_| Some(DynamicImage::ImageRgba8(grey.clone())));
        let cube = CubeImage::from_faces(faces, 64).unwrap().linear();
        assert_eq!(cube.format, CubeFormat::Rgba16Float);
        assert_eq!(cube.levels.len(), 2);
        let texel: Vec<f32> = cube.levels[1][..8]
            .chunks_exact(2)
            .map(|h| half::f16::from_le_bytes([h[0], h[1]]).to_f32())
            .collect();
        // sRGB 188 is linear 0.5; alpha stays linear.
        assert!((texel[0] - 0.5).abs() < 0.01, "{texel:?}");
        assert_eq!(
            &texel[1..],
            &[1.0, 0.0, 128.0 / 255.0].map(|v| half::f16::from_f32(v).to_f32())
        );
    }

    #[test]
    fn float_faces_stay_linear_half_floats() {
        let hot = image::Rgba32FImage::from_pixel(2, 2, image::Rgba([4.0, 0.5, 0.0, 1.0]));
        let faces = std::array::from_fn(|_| Some(DynamicImage::ImageRgba32F(hot.clone())));
        let cube = CubeImage::from_faces(faces, 64).unwrap();
        assert_eq!(cube.format, CubeFormat::Rgba16Float);
        let first = half::f16::from_le_bytes([cube.levels[0][0], cube.levels[0][1]]);
        assert_eq!(first.to_f32(), 4.0);
    }
}
