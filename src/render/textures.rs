//! Texture nodes to RGBA images: ImageTexture (PNG, JPEG, GIF files next to the
//! document, or in `data:` URLs), PixelTexture (SFImage, rows from the bottom up), with the sampling of
//! repeatS/repeatT and TextureProperties (18.4.9) and a mipmap chain where the
//! minification filter uses one.

use std::io::{BufRead, Seek};
use std::path::{Path, PathBuf};

use super::draw_list::{Texture, Wrap};
use super::fields::{boolean, child, float};
use crate::limits::MAX_IMAGE_SIDE;
use crate::model::data_url;
use crate::model::{Document, NodeId};

/// The largest texture side loaded (larger images are reported, not drawn).
const MAX_TEXTURE_SIDE: u32 = 8192;

pub struct Loaded {
    pub texture: Texture,
    /// 1 intensity, 2 intensity + alpha, 3 RGB, 4 RGBA.
    pub channels: u8,
    /// Whether any texel has alpha below 1.
    pub translucent: bool,
}

/// Why a texture is not drawn.
pub struct NotDrawn {
    pub message: String,
    /// Whether an image went past [`MAX_IMAGE_SIDE`] (reported as LIMIT_EXCEEDED).
    pub limit: bool,
}

impl From<String> for NotDrawn {
    fn from(message: String) -> NotDrawn {
        NotDrawn {
            message,
            limit: false,
        }
    }
}

impl From<&str> for NotDrawn {
    fn from(message: &str) -> NotDrawn {
        NotDrawn::from(message.to_string())
    }
}

/// Loads a single-image texture node, or says why it cannot be drawn.
pub fn load(doc: &Document, node: NodeId, base: &Path, root: &Path) -> Result<Loaded, NotDrawn> {
    let (rgba, width, height, channels) = pixels(doc, node, base, root)?;
    let translucent = rgba.chunks_exact(4).any(|p| p[3] < 255);
    let sampling = Sampling::of(doc, node);
    let levels = if sampling.mipmaps.is_some() {
        mipmaps(rgba, width, height)
    } else {
        vec![rgba]
    };
    Ok(Loaded {
        texture: Texture {
            width,
            height,
            levels,
            wrap_s: sampling.wrap_s,
            wrap_t: sampling.wrap_t,
            magnify_linear: sampling.magnify_linear,
            minify_linear: sampling.minify_linear,
            mipmaps: sampling.mipmaps,
            anisotropy: sampling.anisotropy,
        },
        channels,
        translucent,
    })
}

/// The RGBA8 image of a single-image texture node (ImageTexture, PixelTexture), with
/// its width, height and channel count.
pub fn pixels(doc: &Document, node: NodeId, base: &Path, root: &Path) -> Result<Pixels, NotDrawn> {
    match doc.node(node).type_name() {
        "ImageTexture" => {
            let image = first_image(&urls(doc, node, "url"), base, root, "ImageTexture")?;
            Ok(rgba8(image))
        }
        "PixelTexture" => Ok(pixel_texture(doc, node)?),
        other => Err(format!("{other} is not drawn").into()),
    }
}

/// The strings of an MFString url field.
pub fn urls(doc: &Document, node: NodeId, field: &str) -> Vec<String> {
    doc.value_of(node, field)
        .and_then(|v| v.as_strings().map(<[String]>::to_vec))
        .unwrap_or_default()
}

/// How a texture is sampled.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
struct Sampling {
    wrap_s: Wrap,
    wrap_t: Wrap,
    magnify_linear: bool,
    minify_linear: bool,
    mipmaps: Option<bool>,
    anisotropy: u16,
}

impl Sampling {
    /// repeatS/repeatT, or the TextureProperties that override them (18.2.3). Without
    /// TextureProperties the browser's defaults apply: bilinear, trilinear between
    /// mipmaps.
    fn of(doc: &Document, node: NodeId) -> Sampling {
        let repeat = |field| {
            if boolean(doc, node, field, true) {
                Wrap::Repeat
            } else {
                Wrap::Clamp
            }
        };
        let Some(properties) = child(doc, node, "textureProperties") else {
            return Sampling {
                wrap_s: repeat("repeatS"),
                wrap_t: repeat("repeatT"),
                magnify_linear: true,
                minify_linear: true,
                mipmaps: Some(true),
                anisotropy: 1,
            };
        };
        let mode = |name: &str| doc.string_of(properties, name).unwrap_or_default();
        // Table 18.7. CLAMP_TO_BOUNDARY would need a border colour, which not every
        // adapter has; it is drawn as CLAMP_TO_EDGE.
        let wrap = |name: &str| match mode(name).as_str() {
            "MIRRORED_REPEAT" => Wrap::MirroredRepeat,
            "CLAMP" | "CLAMP_TO_EDGE" | "CLAMP_TO_BOUNDARY" => Wrap::Clamp,
            _ => Wrap::Repeat,
        };
        // Tables 18.8 and 18.9: FASTEST is nearest texel; DEFAULT and NICEST linear.
        let magnify_linear = !matches!(
            mode("magnificationFilter").as_str(),
            "NEAREST_PIXEL" | "FASTEST"
        );
        let generate = boolean(doc, properties, "generateMipMaps", false);
        // (linear within a level, between levels: None no mipmaps / nearest / linear);
        // a MIPMAP mode without mipmaps is its non-mipmapped mode (18.4.9).
        let (minify_linear, between) = match mode("minificationFilter").as_str() {
            "AVG_PIXEL" => (true, None),
            "AVG_PIXEL_AVG_MIPMAP" => (true, Some(true)),
            "AVG_PIXEL_NEAREST_MIPMAP" => (true, Some(false)),
            "NEAREST_PIXEL" => (false, None),
            "NEAREST_PIXEL_AVG_MIPMAP" => (false, Some(true)),
            "NEAREST_PIXEL_NEAREST_MIPMAP" | "FASTEST" => (false, Some(false)),
            _ => (true, Some(true)),
        };
        let degree = float(doc, properties, "anisotropicDegree", 1.0);
        Sampling {
            wrap_s: wrap("boundaryModeS"),
            wrap_t: wrap("boundaryModeT"),
            magnify_linear,
            minify_linear,
            mipmaps: between.filter(|_| generate),
            // Values above the maximum are clamped to it (18.4.9); 16 is WebGPU's.
            anisotropy: degree.clamp(1.0, 16.0) as u16,
        }
    }
}

/// The mipmap chain of an RGBA8 image down to 1 × 1: each level halves the sides of the
/// one before (rounding down) and averages the texels each of its texels covers, so an
/// odd side's last row or column is not lost.
fn mipmaps(rgba: Vec<u8>, width: u32, height: u32) -> Vec<Vec<u8>> {
    let mut levels = vec![rgba];
    let (mut w, mut h) = (width as usize, height as usize);
    while w > 1 || h > 1 {
        let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
        let previous = levels.last().map(Vec::as_slice).unwrap_or_default();
        let mut next = Vec::with_capacity(nw * nh * 4);
        for y in 0..nh {
            let rows = y * h / nh..(y + 1) * h / nh;
            for x in 0..nw {
                let columns = x * w / nw..(x + 1) * w / nw;
                let count = (rows.len() * columns.len()) as u32;
                for c in 0..4 {
                    let mut sum = 0u32;
                    for sy in rows.clone() {
                        for sx in columns.clone() {
                            sum += u32::from(previous[(sy * w + sx) * 4 + c]);
                        }
                    }
                    next.push(((sum + count / 2) / count) as u8);
                }
            }
        }
        levels.push(next);
        (w, h) = (nw, nh);
    }
    levels
}

pub type Pixels = (Vec<u8>, u32, u32, u8);

fn rgba8(image: image::DynamicImage) -> Pixels {
    let (width, height) = (image.width(), image.height());
    let channels = image.color().channel_count();
    (image.to_rgba8().into_raw(), width, height, channels)
}

/// The first of `urls` that decodes (files under `root`, or data: URLs), or why none
/// does, naming the node type `what`.
pub fn first_image(
    urls: &[String],
    base: &Path,
    root: &Path,
    what: &str,
) -> Result<image::DynamicImage, NotDrawn> {
    let mut reasons = Vec::new();
    let mut limit = false;
    for url in urls {
        let decoded = match data_url::decode(url) {
            Some(Ok(data)) => decode_bytes(&data.bytes),
            Some(Err(e)) => Err(e.into()),
            None => local_file(url, base, root)
                .map_err(NotDrawn::from)
                .and_then(|path| decode_file(&path)),
        };
        match decoded {
            Ok(image) => return Ok(image),
            Err(e) => {
                limit |= e.limit;
                reasons.push(format!("{}: {}", data_url::shown(url), e.message));
            }
        }
    }
    if reasons.is_empty() {
        return Err(format!("{what} has no url").into());
    }
    Err(NotDrawn {
        message: format!("{what} not drawn ({})", reasons.join("; ")),
        limit,
    })
}

/// A url as a file under `root` (the directory tree of the named document), or why not.
pub fn local_file(url: &str, base: &Path, root: &Path) -> Result<PathBuf, String> {
    if data_url::is_data_url(url) {
        return Err("a data: URL is no file".to_string());
    }
    let lower = url.to_ascii_lowercase();
    if lower.contains("://") && !lower.starts_with("file://") {
        return Err("network urls are not fetched".to_string());
    }
    let relative = url.strip_prefix("file://").unwrap_or(url);
    let relative = relative.split(['#', '?']).next().unwrap_or(relative);
    let path = base.join(relative);
    let canonical = path
        .canonicalize()
        .map_err(|e| format!("cannot open {}: {e}", path.display()))?;
    let root = root.canonicalize().unwrap_or_else(|_| root.to_path_buf());
    if !canonical.starts_with(&root) {
        return Err(format!(
            "{} is outside {}",
            canonical.display(),
            root.display()
        ));
    }
    Ok(canonical)
}

fn decode_file(path: &Path) -> Result<image::DynamicImage, NotDrawn> {
    decode(|| image::ImageReader::open(path))
}

/// An image carried in a data: URL.
fn decode_bytes(bytes: &[u8]) -> Result<image::DynamicImage, NotDrawn> {
    decode(|| Ok(image::ImageReader::new(std::io::Cursor::new(bytes))))
}

/// Decodes the image `open` reads (opened twice: once for the header's size, checked
/// before any pixel is decoded, once to decode).
fn decode<R: BufRead + Seek>(
    open: impl Fn() -> std::io::Result<image::ImageReader<R>>,
) -> Result<image::DynamicImage, NotDrawn> {
    let reader = open()
        .map_err(|e| e.to_string())?
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    let (width, height) = reader.into_dimensions().map_err(|e| e.to_string())?;
    if width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
        return Err(NotDrawn {
            message: format!("{width}×{height} is larger than {MAX_IMAGE_SIDE} pixels a side"),
            limit: true,
        });
    }
    if width > MAX_TEXTURE_SIDE || height > MAX_TEXTURE_SIDE {
        return Err(
            format!("{width}×{height} is larger than {MAX_TEXTURE_SIDE} pixels a side").into(),
        );
    }
    let mut reader = open()
        .map_err(|e| e.to_string())?
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    // The header's size was checked above; these also bound what decoding may allocate.
    reader.limits(crate::limits::image_limits());
    Ok(reader.decode().map_err(|e| e.to_string())?)
}

fn pixel_texture(doc: &Document, node: NodeId) -> Result<Pixels, String> {
    let value = doc.value_of(node, "image");
    let image = value
        .as_ref()
        .and_then(|v| v.as_images())
        .and_then(|i| i.first())
        .ok_or("PixelTexture has no image")?;
    let (width, height) = (image.width.max(0) as u32, image.height.max(0) as u32);
    let components = image.components;
    if width == 0 || height == 0 || !(1..=4).contains(&components) {
        return Err("PixelTexture image is empty".to_string());
    }
    if width > MAX_TEXTURE_SIDE || height > MAX_TEXTURE_SIDE {
        return Err(format!(
            "PixelTexture {width}×{height} is too large to draw"
        ));
    }
    let count = (width * height) as usize;
    if image.pixels.len() < count {
        return Err(format!(
            "PixelTexture has {} of {count} pixels",
            image.pixels.len()
        ));
    }
    let mut rgba = vec![0u8; count * 4];
    for (i, &p) in image.pixels[..count].iter().enumerate() {
        // SFImage rows run from the bottom up; texture rows from the top down.
        let (x, y) = (i % width as usize, i / width as usize);
        let row = height as usize - 1 - y;
        let byte = |k: u32| ((p >> (8 * k)) & 0xff) as u8;
        let texel = match components {
            1 => [byte(0), byte(0), byte(0), 255],
            2 => [byte(1), byte(1), byte(1), byte(0)],
            3 => [byte(2), byte(1), byte(0), 255],
            _ => [byte(3), byte(2), byte(1), byte(0)],
        };
        let at = (row * width as usize + x) * 4;
        rgba[at..at + 4].copy_from_slice(&texel);
    }
    Ok((rgba, width, height, components as u8))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mipmaps_halve_down_to_one_texel_and_average() {
        // 3 × 2: levels 3×2, 1×1; the 1×1 level averages all six texels.
        let grey = [0u8, 100, 200, 255, 40, 60];
        let rgba: Vec<u8> = grey.iter().flat_map(|&v| [v, v, v, 255]).collect();
        let levels = mipmaps(rgba, 3, 2);
        assert_eq!(levels.iter().map(Vec::len).collect::<Vec<_>>(), vec![24, 4]);
        assert_eq!(levels[1][..], [109, 109, 109, 255]);
    }

    fn sampling(properties: &str) -> Sampling {
        let source = format!(
            "<X3D version='4.0'><Scene><Shape><Appearance><PixelTexture>{properties}</PixelTexture></Appearance></Shape></Scene></X3D>"
        );
        let doc = crate::parse::read(source.as_bytes()).document.unwrap();
        let texture = doc.nodes_of_type("PixelTexture").next().unwrap();
        Sampling::of(&doc, texture)
    }

    #[test]
    fn texture_properties_choose_wrapping_and_filters() {
        assert_eq!(sampling("").mipmaps, Some(true));
        let s = sampling(
            "<TextureProperties boundaryModeS='MIRRORED_REPEAT' boundaryModeT='CLAMP_TO_EDGE' \
             magnificationFilter='NEAREST_PIXEL' minificationFilter='AVG_PIXEL_NEAREST_MIPMAP' \
             generateMipMaps='true' anisotropicDegree='64'/>",
        );
        assert_eq!((s.wrap_s, s.wrap_t), (Wrap::MirroredRepeat, Wrap::Clamp));
        assert!(!s.magnify_linear && s.minify_linear);
        assert_eq!((s.mipmaps, s.anisotropy), (Some(false), 16));
        // A MIPMAP filter without generateMipMaps falls back to its plain mode.
        let s = sampling("<TextureProperties minificationFilter='AVG_PIXEL_AVG_MIPMAP'/>");
        assert_eq!(s.mipmaps, None);
    }
}
