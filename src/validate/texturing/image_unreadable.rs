//! IMAGE_UNREADABLE: a texture file that exists but does not decode.

use super::files::{probe_bytes, url_fields, Content, Probe, Prober, Resolution, Resolver};
use crate::diagnostic::Diagnostic;
use crate::model::data_url;
use crate::model::rules::LIMIT_EXCEEDED;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Decodes every local image file that an ImageTexture or Background url resolves to
    /// (see URL_UNRESOLVED for how urls resolve and which files may be read) and reports
    /// the ones that do not decode: truncated or corrupt data or a file that is no image at
    /// all. An image larger than 16384 pixels on a side or 1 GiB decoded is refused before
    /// decoding (so a decompression bomb costs nothing) and reported as LIMIT_EXCEEDED.
    /// Each file is decoded once
    /// per document, however many nodes use it. Formats x3dcheck does not decode (DDS,
    /// KTX, TGA, …) are IMAGE_FORMAT_UNSUPPORTED's. The image a `data:` URL carries
    /// (base64 or percent-encoded) is decoded the same way, and reported when its content
    /// does not decode (an invalid data: URL included).
    ///
    /// ## Why it matters
    /// The browser finds the file but cannot show it: the shape is drawn untextured, or
    /// the browser stops with an error. A broken export or a text file saved as `.png` is
    /// a common cause.
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture url='"truncated.png"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.2.1 Texture map image formats; 18.4.1 ImageTexture.
    /// A warning, not an error (issue 32): the X3D document itself is sound (its `url` is a
    /// well-formed MFString), and the spec treats a resource that cannot be had as a
    /// run-time matter of the browser, not a fault of the file: the url field lists
    /// alternatives in order of preference, and a browser that cannot obtain one goes on
    /// to the next (19775-1 9.2.1 URLs; 14772-1 4.5.2). No sentence of 18.2.1 or 18.4.1
    /// puts a "shall" on the image data; the broken image is a fault of another file, or
    /// of the `data:` URL's content.
    pub static IMAGE_UNREADABLE = {
        severity: Warning,
        level: Deep,
        clause: "18.4.1",
        versions: "all",
        check: Some(check),
    }
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
            let probe = match data_url::decode(url) {
                Some(Ok(data)) => probe_bytes(&data.bytes),
                Some(Err(why)) => Probe::Broken(why),
                None => match resolver.resolve_node(ctx.doc, field.node, url) {
                    Resolution::Local(path) => prober.decode(&path),
                    _ => continue,
                },
            };
            let (rule, why) = match probe {
                Probe::Broken(why) => (&IMAGE_UNREADABLE, why),
                Probe::TooLarge(why) => (&LIMIT_EXCEEDED, why),
                Probe::Decodes(_) | Probe::Undecoded(_) => continue,
            };
            let type_name = ctx.doc.node(field.node).type_name();
            let shown = data_url::shown(url);
            found.push(
                Diagnostic::new(
                    rule,
                    field.entry.span,
                    format!("{type_name}.{}: \"{shown}\" {why}", field.entry.name()),
                )
                .node(field.node)
                .value(shown),
            );
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
