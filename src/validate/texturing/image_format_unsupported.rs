//! IMAGE_FORMAT_UNSUPPORTED: a texture in a format browsers need not support.

use super::files::{format_name, url_fields, Content, Probe, Prober, Resolution, Resolver};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an ImageTexture or Background url whose local file is an image in a format
    /// other than PNG, JPEG and GIF: BMP, TIFF, WebP or Radiance HDR that decodes (a file
    /// that does not decode is IMAGE_UNREADABLE's), or a format x3dcheck recognises by its
    /// extension but does not decode (DDS, KTX, KTX2, TGA, OpenEXR, SVG, JPEG 2000,
    /// AVIF). The format is read from the file's content, not its name. Which files are
    /// read: see URL_UNRESOLVED.
    ///
    /// ## Why it matters
    /// 18.4.1: "X3D browsers shall support the JPEG and PNG image file formats", and GIF is
    /// recommended; "X3D browsers may support other image formats". Another format works
    /// in some browsers only.
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture url='"bricks.bmp"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.1 ImageTexture; 18.2.1 Texture map image formats.
    pub static IMAGE_FORMAT_UNSUPPORTED = {
        severity: Warning,
        level: Deep,
        clause: "18.4.1",
        versions: "all",
        check: Some(check),
    }
}

/// The formats every browser reads (PNG, JPEG) or is recommended to (GIF).
fn is_portable(format: image::ImageFormat) -> bool {
    matches!(
        format,
        image::ImageFormat::Png | image::ImageFormat::Jpeg | image::ImageFormat::Gif
    )
}

fn check(ctx: &mut Ctx) {
    let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
    let mut prober = Prober::default();
    let mut found = Vec::new();
    for field in url_fields(ctx.doc) {
        if field.content != Content::Image {
            continue;
        }
        for url in field.entry.value.as_strings().unwrap_or_default() {
            let Resolution::Local(path) = resolver.resolve_node(ctx.doc, field.node, url) else {
                continue;
            };
            // The header tells PNG, JPEG and GIF apart without a full decode.
            if prober.format(&path).is_some_and(is_portable) {
                continue;
            }
            let what = match prober.decode(&path) {
                Probe::Decodes(format) => format!("a {} image", format_name(format)),
                Probe::Undecoded(name) => format!("a {name} image (not decoded by x3dcheck)"),
                Probe::Broken(_) | Probe::TooLarge(_) => continue,
            };
            let type_name = ctx.doc.node(field.node).type_name();
            found.push(
                Diagnostic::new(
                    &IMAGE_FORMAT_UNSUPPORTED,
                    field.entry.span,
                    format!(
                        "{type_name}.{}: \"{url}\" is {what}; browsers must read only PNG and JPEG (and should read GIF)",
                        field.entry.name()
                    ),
                )
                .node(field.node)
                .value(url.clone())
                .help("convert it to PNG or JPEG"),
            );
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
