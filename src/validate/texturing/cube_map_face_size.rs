//! CUBE_MAP_FACE_SIZE: a ComposedCubeMapTexture face that is not square, not a power of
//! two, or not the size of the other faces.

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
    /// ImageCubeMapTexture is not checked: its one file holds all six faces in a cube-map
    /// layout (DDS), which x3dcheck does not read.
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
    /// Six faces of one square, power-of-two size (`2 2 1 …` for each).
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
    for diagnostic in found {
        ctx.report(diagnostic);
    }
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
