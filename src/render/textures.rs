//! Texture nodes to RGBA images: ImageTexture (PNG, JPEG, GIF files next to the
//! document), PixelTexture (SFImage, rows from the bottom up), with the sampling of
//! repeatS/repeatT and TextureProperties.

use std::path::{Path, PathBuf};

use super::draw_list::Texture;
use super::fields::{boolean, child};
use crate::limits::MAX_IMAGE_SIDE;
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
    let type_name = doc.node(node).type_name();
    let (rgba, width, height, channels) = match type_name {
        "ImageTexture" => image_texture(doc, node, base, root)?,
        "PixelTexture" => pixel_texture(doc, node)?,
        other => return Err(format!("{other} is not drawn").into()),
    };
    let translucent = rgba.chunks_exact(4).any(|p| p[3] < 255);
    let mut repeat_s = boolean(doc, node, "repeatS", true);
    let mut repeat_t = boolean(doc, node, "repeatT", true);
    let mut linear = true;
    if let Some(properties) = child(doc, node, "textureProperties") {
        let mode = |name: &str| doc.string_of(properties, name).unwrap_or_default();
        // 18.4.8: REPEAT (and MIRRORED_REPEAT, drawn as REPEAT) repeat; the CLAMP modes clamp.
        repeat_s = mode("boundaryModeS").ends_with("REPEAT");
        repeat_t = mode("boundaryModeT").ends_with("REPEAT");
        linear = !matches!(
            mode("magnificationFilter").as_str(),
            "NEAREST_PIXEL" | "FASTEST"
        );
    }
    Ok(Loaded {
        texture: Texture {
            width,
            height,
            rgba,
            repeat_s,
            repeat_t,
            linear,
        },
        channels,
        translucent,
    })
}

type Pixels = (Vec<u8>, u32, u32, u8);

fn image_texture(
    doc: &Document,
    node: NodeId,
    base: &Path,
    root: &Path,
) -> Result<Pixels, NotDrawn> {
    let urls = doc
        .value_of(node, "url")
        .and_then(|v| v.as_strings().map(<[String]>::to_vec))
        .unwrap_or_default();
    let mut reasons = Vec::new();
    let mut limit = false;
    for url in &urls {
        match local_file(url, base, root) {
            Ok(path) => match decode(&path) {
                Ok(pixels) => return Ok(pixels),
                Err(e) => {
                    limit |= e.limit;
                    reasons.push(format!("{url}: {}", e.message));
                }
            },
            Err(e) => reasons.push(format!("{url}: {e}")),
        }
    }
    if reasons.is_empty() {
        return Err("ImageTexture has no url".into());
    }
    Err(NotDrawn {
        message: format!("ImageTexture not drawn ({})", reasons.join("; ")),
        limit,
    })
}

/// A url as a file under `root` (the directory tree of the named document), or why not.
pub fn local_file(url: &str, base: &Path, root: &Path) -> Result<PathBuf, String> {
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

fn decode(path: &Path) -> Result<Pixels, NotDrawn> {
    let reader = image::ImageReader::open(path)
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
    let mut reader = image::ImageReader::open(path)
        .map_err(|e| e.to_string())?
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    // The header's size was checked above; these also bound what decoding may allocate.
    reader.limits(crate::validate::texturing::files::image_limits());
    let image = reader.decode().map_err(|e| e.to_string())?;
    let channels = image.color().channel_count();
    let rgba = image.to_rgba8();
    Ok((rgba.into_raw(), width, height, channels))
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
