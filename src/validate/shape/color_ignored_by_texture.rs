//! COLOR_IGNORED_BY_TEXTURE: a Shape whose geometry's Color node is replaced by an RGB or
//! RGBA texture.

use super::analysis::shape_pairs;
use crate::diagnostic::{Diagnostic, Level};
use crate::model::data_url;
use crate::model::NodeId;
use crate::validate::texturing::files::{bytes_channels, file_channels, Resolution, Resolver};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Shape whose geometry has a Color or ColorRGBA node in its `color` field
    /// while its Appearance's `texture` is an RGB or RGBA texture. Judged per Shape, that
    /// is per Appearance × geometry pair the scene forms, since both are shared by USE:
    /// one diagnostic per pair, at the geometry's `color` node.
    ///
    /// Whether a texture is RGB or RGBA is known from the document for a PixelTexture
    /// (the components of its SFImage: 3 or 4). An ImageTexture's components are those
    /// of its image, which the deep level reads: the first `url` entry that is a local
    /// file or a `data:` URL (entries naming missing files are skipped, as a browser
    /// skips them; an entry that cannot be read here, such as a network URL, ends the
    /// search with no verdict), judged by the channels its header announces (grey 1,
    /// grey and alpha 2, RGB 3, RGBA 4; a palette image counts as RGB or RGBA). Below the
    /// deep level an ImageTexture is not judged. A MovieTexture's frames and a
    /// MultiTexture, which combines its textures by its modes, are never judged, nor is a
    /// PointSet whose Appearance has a PointProperties (point sprites, whose `colorMode`
    /// may blend the point colours with the texture): the rule prefers a miss to a guess.
    ///
    /// ## Why it matters
    /// "RGB or RGBA textures take precedence over colours; specifying both an RGB or RGBA
    /// texture and a Color node for geometric shape will result in the Color node being
    /// ignored" (11.2; Tables 17.2 and 17.3 of 17.2.2): the per-vertex colours the author
    /// wrote never show.
    ///
    /// ## Example
    /// ```xml
    /// <Shape>
    ///   <Appearance><PixelTexture image='1 1 3 0xFF0000'/></Appearance>
    ///   <TriangleSet>
    ///     <Color color='1 0 0 0 1 0 0 0 1'/>
    ///     <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    ///   </TriangleSet>
    /// </Shape>
    /// ```
    ///
    /// ## Use instead
    /// An intensity (one- or two-component) texture, which modulates the colours, or no
    /// Color node.
    ///
    /// ## Clause
    /// 19775-1 11.2 (geometric properties, Color); 17.2.2 Lighting model, Tables 17.2 and
    /// 17.3.
    pub static COLOR_IGNORED_BY_TEXTURE = {
        severity: Info,
        level: Standard,
        clause: "17.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for pair in shape_pairs(doc) {
        let Some(appearance) = pair.appearance else {
            continue;
        };
        let Some(texture) = doc.node(appearance).children("texture").first().copied() else {
            continue;
        };
        let Some(components) = rgb_components(ctx, texture.node) else {
            continue;
        };
        let geometry = doc.node(pair.geometry);
        // Point sprites (a PointProperties beside the texture) blend point and texture
        // colours by PointProperties.colorMode (12.4.7 of the 4.0 drafts, and the xj3d
        // extension before it): not judged.
        let sprites =
            geometry.is_a("PointSet") && doc.node(appearance).child("pointProperties").is_some();
        if geometry.is_connected("color") || sprites {
            continue;
        }
        let Some(&color) = geometry.children("color").first() else {
            continue;
        };
        if doc.node(color.node).is_a("X3DColorNode") {
            found.push((pair.shape, pair.geometry, color, texture, components));
        }
    }
    for (shape, geometry, color, texture, components) in found {
        let colour_type = ctx.doc.node(color.node).type_name().to_string();
        let kind = if components == 3 { "RGB" } else { "RGBA" };
        let diagnostic = Diagnostic::new(
            &COLOR_IGNORED_BY_TEXTURE,
            color.span,
            format!(
                "the {colour_type} node of this {} is ignored: the Shape's Appearance applies an {kind} texture, which takes precedence over colours",
                ctx.doc.node(geometry).type_name()
            ),
        )
        .node(geometry)
        .related(texture.span, format!("the {kind} texture"))
        .related(ctx.doc.node(shape).name_span, "the Shape");
        ctx.report(diagnostic);
    }
}

/// The components (3 or 4) of a texture known to be RGB or RGBA: a PixelTexture's from
/// the document, an ImageTexture's from its image at the deep level; None for any other
/// texture or one that cannot be told.
fn rgb_components(ctx: &Ctx, texture: NodeId) -> Option<i32> {
    let node = ctx.doc.node(texture);
    let components = match node.type_name() {
        "PixelTexture" if !node.is_connected("image") => {
            node.value("image")?.as_images()?.first()?.components
        }
        "ImageTexture" if ctx.config.level >= Level::Deep && !node.is_connected("url") => {
            i32::from(image_channels(
                ctx,
                texture,
                node.value("url")?.as_strings()?,
            )?)
        }
        _ => return None,
    };
    matches!(components, 3 | 4).then_some(components)
}

/// The channels of the image a browser would load from `urls` of `texture`: the first
/// local file or `data:` URL, skipping missing files; None when an entry before it cannot
/// be judged.
fn image_channels(ctx: &Ctx, texture: NodeId, urls: &[String]) -> Option<u8> {
    let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
    for url in urls {
        if let Some(data) = data_url::decode(url) {
            return bytes_channels(&data.ok()?.bytes);
        }
        match resolver.resolve_node(ctx.doc, texture, url) {
            Resolution::Local(path) => return file_channels(&path),
            Resolution::Missing { .. } => continue,
            _ => return None,
        }
    }
    None
}
