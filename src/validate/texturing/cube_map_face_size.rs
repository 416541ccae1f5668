//! CUBE_MAP_FACE_SIZE: a ComposedCubeMapTexture face that is not square, not a power of
//! two, or not the size of the other faces; an ImageCubeMapTexture whose file's faces are
//! not square or not a power of two.

use super::files::{bytes_dimensions, file_dimensions, Resolution, Resolver};
use crate::diagnostic::Diagnostic;
use crate::model::data_url;
use crate::model::{NodeId, Span};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reads the size of each face of every ComposedCubeMapTexture: a PixelTexture's
    /// from its `image` header, an ImageTexture's from the header of the image its `url`
    /// loads (the first local file or `data:` URL; only the header is read). Reports a
    /// face that is not square, a square face whose side is not a power of two, and a
    /// well-shaped face whose size differs from the first well-shaped face written (a
    /// misshapen face is reported for its shape only). Faces of other texture types
    /// (MovieTexture, …), empty PixelTextures, urls that do not resolve to a readable
    /// image, and fields that take their value through `IS` are left out.
    ///
    /// ImageCubeMapTexture (issue 33): the first local file or `data:` URL of its `url`
    /// is read as the preview reads it. A DDS cube map (the `CUBEMAP` caps or the DX10
    /// `TEXTURECUBE` flag) has six faces of the header's width × height: reported when
    /// they are not square or not a power of two. An image of 4:3 or 3:4 holds a cross of
    /// six square faces a quarter of its longer side wide: reported when that side is not
    /// a power of two. Other files are left alone: a DDS that is not a cube, KTX2, and 2D
    /// images of other shapes (the text read gives no layout for one image; browsers
    /// differ in the layouts they read, panoramas among them).
    ///
    /// ## Why it matters
    /// A cube map is six equal square images in graphics hardware; a browser handed
    /// faces of different or rectangular sizes refuses the texture, or rescales the faces
    /// and shows seams where they meet.
    ///
    /// ## Example
    /// ```xml
    /// <ComposedCubeMapTexture>
    ///   <PixelTexture containerField='frontTexture' image='2 2 1 0 0 0 0'/>
    ///   <PixelTexture containerField='backTexture' image='1 1 1 0'/>
    /// </ComposedCubeMapTexture>
    /// ```
    ///
    /// ## Use instead
    /// Six faces of one square, power-of-two size (`2 2 1 …` for each); for
    /// ImageCubeMapTexture, a DDS cube of 2ⁿ × 2ⁿ faces or a cross of 2ⁿ-pixel faces
    /// (4·2ⁿ × 3·2ⁿ).
    ///
    /// ## Clause
    /// 19775-1 34.2 Concepts, read in the 3.3 page (web3d.org
    /// `…/19775-1/V3.3/Part01/components/env_texture.html`), which gives as its example
    /// "It is not valid to define the front image as a 64×64 image and the left side
    /// image as 128×128 pixels."
    /// > "All source images shall be square and provide source data in powers of two numbers of pixels. Source images in a cubic environment map shall have identical sizes. Providing differently sized images or rectangular images shall be an error." (19775-1 34.2)
    pub static CUBE_MAP_FACE_SIZE = {
        severity: Error,
        level: Deep,
        clause: "34.2",
        versions: "all",
        check: Some(check),
    }
}

/// The face fields, X3D 4 names and the X3D 3 names they replaced.
const FACES: &[&str] = &[
    "frontTexture",
    "backTexture",
    "leftTexture",
    "rightTexture",
    "topTexture",
    "bottomTexture",
    "front",
    "back",
    "left",
    "right",
    "top",
    "bottom",
];

/// One face whose size is known.
struct Face<'a> {
    field: &'a str,
    texture: NodeId,
    /// Where the size comes from: the PixelTexture's image or the ImageTexture's url.
    span: Span,
    width: u32,
    height: u32,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for cube in doc.nodes_of_type("ComposedCubeMapTexture") {
        let node = doc.node(cube);
        let faces: Vec<Face> = FACES
            .iter()
            .filter(|field| !node.is_connected(field))
            .filter_map(|field| face(ctx, field, node.child(field)?))
            .collect();
        let cube_span = node.name_span;
        // Sizes are compared with the first well-shaped face: a rectangular or
        // non-power-of-two face is reported for its shape only.
        let well_shaped = |face: &&Face| face.width == face.height && face.width.is_power_of_two();
        let reference = faces.iter().find(well_shaped);
        for face in &faces {
            let (width, height) = (face.width, face.height);
            let diagnostic = if width != height {
                Diagnostic::new(
                    &CUBE_MAP_FACE_SIZE,
                    face.span,
                    format!("ComposedCubeMapTexture.{}: its image is {width}×{height}, not square; cube-map faces shall be square", face.field),
                )
            } else if !width.is_power_of_two() {
                Diagnostic::new(
                    &CUBE_MAP_FACE_SIZE,
                    face.span,
                    format!("ComposedCubeMapTexture.{}: its image is {width}×{height}; cube-map faces shall be a power of two pixels on a side", face.field),
                )
            } else if let Some(first) = reference.filter(|first| first.width != width) {
                Diagnostic::new(
                    &CUBE_MAP_FACE_SIZE,
                    face.span,
                    format!(
                        "ComposedCubeMapTexture.{}: its image is {width}×{height} but {}'s is {}×{}; the faces of a cube map shall have identical sizes",
                        face.field, first.field, first.width, first.height
                    ),
                )
                .related(first.span, format!("{}: {}×{}", first.field, first.width, first.height))
            } else {
                continue;
            };
            found.push(
                diagnostic
                    .node(face.texture)
                    .related(cube_span, "the ComposedCubeMapTexture"),
            );
        }
    }
    for cube in doc.nodes_of_type("ImageCubeMapTexture") {
        if let Some(diagnostic) = image_cube_faces(ctx, cube) {
            found.push(diagnostic);
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// How an ImageCubeMapTexture's one file holds its six faces.
#[derive(Debug, PartialEq)]
enum CubeFile {
    /// A DDS cube map: each face is width × height.
    DdsCube { width: u32, height: u32 },
    /// A 2D image of 4:3 or 3:4 read as a cross of square faces of this side.
    Cross { width: u32, height: u32, side: u32 },
}

/// The finding on an ImageCubeMapTexture whose file's faces are misshapen.
fn image_cube_faces(ctx: &Ctx, cube: NodeId) -> Option<Diagnostic> {
    let node = ctx.doc.node(cube);
    if node.is_connected("url") {
        return None;
    }
    let entry = node.entry("url")?;
    let message = match cube_file(ctx, cube, entry.value.as_strings()?)? {
        CubeFile::DdsCube { width, height } if width != height => format!(
            "ImageCubeMapTexture: its DDS cube map's faces are {width}×{height}, not square; cube-map faces shall be square"
        ),
        CubeFile::DdsCube { width, height } if !width.is_power_of_two() => format!(
            "ImageCubeMapTexture: its DDS cube map's faces are {width}×{height}; cube-map faces shall be a power of two pixels on a side"
        ),
        CubeFile::Cross { width, height, side } if !side.is_power_of_two() => format!(
            "ImageCubeMapTexture: its {width}×{height} image is a cross of {side}×{side} faces; cube-map faces shall be a power of two pixels on a side"
        ),
        _ => return None,
    };
    Some(Diagnostic::new(&CUBE_MAP_FACE_SIZE, entry.span, message).node(cube))
}

/// The faces of the file a browser would load from `urls`: the first local file or
/// `data:` URL, skipping missing files; None when it is neither a DDS cube nor a cross,
/// or cannot be read.
fn cube_file(ctx: &Ctx, cube: NodeId, urls: &[String]) -> Option<CubeFile> {
    let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
    for url in urls {
        let bytes = if let Some(data) = data_url::decode(url) {
            data.ok()?.bytes
        } else {
            match resolver.resolve_node(ctx.doc, cube, url) {
                Resolution::Local(path) => read_head(&path)?,
                Resolution::Missing { .. } => continue,
                _ => return None,
            }
        };
        if bytes.starts_with(b"DDS ") {
            return dds_cube(&bytes);
        }
        let (width, height) = bytes_dimensions(&bytes)?;
        let (wide, high) = (u64::from(width), u64::from(height));
        let side = if wide * 3 == high * 4 {
            width / 4
        } else if wide * 4 == high * 3 {
            height / 4
        } else {
            return None;
        };
        return Some(CubeFile::Cross {
            width,
            height,
            side,
        });
    }
    None
}

/// The first bytes of a file, enough for the image headers read here (a JPEG's size may
/// stand after its metadata, so more than a DDS header).
fn read_head(path: &std::path::Path) -> Option<Vec<u8>> {
    use std::io::Read;
    const HEAD: u64 = 1 << 20;
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .ok()?
        .take(HEAD)
        .read_to_end(&mut bytes)
        .ok()?;
    Some(bytes)
}

/// A DDS file's faces when it is a cube map (Microsoft's DDS_HEADER: height at byte 12,
/// width at 16, the pixel format's FourCC at 84, caps2 at 112; with FourCC `DX10`, the
/// DDS_HEADER_DXT10 follows at 128 with its misc flag at 136).
fn dds_cube(bytes: &[u8]) -> Option<CubeFile> {
    const CAPS2_CUBEMAP: u32 = 0x200;
    const MISC_TEXTURECUBE: u32 = 0x4;
    let word = |at: usize| -> Option<u32> {
        Some(u32::from_le_bytes(bytes.get(at..at + 4)?.try_into().ok()?))
    };
    let (height, width) = (word(12)?, word(16)?);
    let dx10 = bytes.get(84..88) == Some(b"DX10".as_slice());
    let cube = word(112)? & CAPS2_CUBEMAP != 0 || (dx10 && word(136)? & MISC_TEXTURECUBE != 0);
    cube.then_some(CubeFile::DdsCube { width, height })
}

/// The face `field` holds with its size, when the size can be told.
fn face<'a>(ctx: &Ctx, field: &'a str, texture: NodeId) -> Option<Face<'a>> {
    let node = ctx.doc.node(texture);
    let (entry, (width, height)) = match node.type_name() {
        "PixelTexture" if !node.is_connected("image") => {
            let entry = node.entry("image")?;
            let image = node.value("image")?.as_images()?.first()?;
            // `0 0 0` is the empty image: no texture, no size to compare.
            let width = u32::try_from(image.width).ok().filter(|&w| w > 0)?;
            let height = u32::try_from(image.height).ok().filter(|&h| h > 0)?;
            (entry, (width, height))
        }
        "ImageTexture" if !node.is_connected("url") => {
            let entry = node.entry("url")?;
            (
                entry,
                image_dimensions(ctx, texture, entry.value.as_strings()?)?,
            )
        }
        _ => return None,
    };
    Some(Face {
        field,
        texture,
        span: entry.span,
        width,
        height,
    })
}

/// The size of the image a browser would load from `urls` of `texture`: the first local
/// file or `data:` URL, skipping missing files; None when an entry before it cannot be
/// judged.
fn image_dimensions(ctx: &Ctx, texture: NodeId, urls: &[String]) -> Option<(u32, u32)> {
    let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
    for url in urls {
        if let Some(data) = data_url::decode(url) {
            return bytes_dimensions(&data.ok()?.bytes);
        }
        match resolver.resolve_node(ctx.doc, texture, url) {
            Resolution::Local(path) => return file_dimensions(&path),
            Resolution::Missing { .. } => continue,
            _ => return None,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A DDS header of `width` × `height` with the given caps2 and, when `dx10_misc` is
    /// set, a DX10 header with that misc flag.
    fn dds(width: u32, height: u32, caps2: u32, dx10_misc: Option<u32>) -> Vec<u8> {
        let mut bytes = vec![0u8; 148];
        bytes[..4].copy_from_slice(b"DDS ");
        bytes[4..8].copy_from_slice(&124u32.to_le_bytes());
        bytes[12..16].copy_from_slice(&height.to_le_bytes());
        bytes[16..20].copy_from_slice(&width.to_le_bytes());
        bytes[112..116].copy_from_slice(&caps2.to_le_bytes());
        if let Some(misc) = dx10_misc {
            bytes[84..88].copy_from_slice(b"DX10");
            bytes[136..140].copy_from_slice(&misc.to_le_bytes());
        }
        bytes
    }

    #[test]
    fn dds_cube_maps_are_told_from_2d_dds() {
        let cube = CubeFile::DdsCube {
            width: 64,
            height: 64,
        };
        assert_eq!(dds_cube(&dds(64, 64, 0xFE00, None)), Some(cube));
        assert_eq!(
            dds_cube(&dds(48, 64, 0, Some(0x4))),
            Some(CubeFile::DdsCube {
                width: 48,
                height: 64
            })
        );
        assert_eq!(dds_cube(&dds(64, 64, 0, None)), None);
        assert_eq!(dds_cube(&dds(64, 64, 0, Some(0))), None);
        assert_eq!(dds_cube(b"DDS short"), None);
    }
}
