//! PIXEL_TEXTURE_SIZE_MISMATCH: an SFImage whose pixels do not match its header.

use crate::diagnostic::{Diagnostic, Severity};
use crate::model::{FieldEntry, NodeId, Value};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Checks every SFImage and MFImage value (PixelTexture.image and any other image
    /// field) and PixelTexture3D.image: reports a negative width, height or depth, a
    /// component count outside 0–4 (1–4 for PixelTexture3D), a pixel count other than
    /// width × height (× depth), and pixel values too large for the component count
    /// (more than 8 bits per component: above 0xFF for one component, 0xFFFF for two,
    /// 0xFFFFFF for three). Negative pixel values are read as their 32-bit two's
    /// complement, so they only fit four components. Repeats of a too-large pixel on one
    /// field are folded into one diagnostic. PixelTexture3D asks for "at least"
    /// width × height × depth pixels, so more than that is a warning there (the extra
    /// values are likely a wrong header, but break no sentence); fewer stay an error.
    ///
    /// ## Why it matters
    /// 5.3.6 (SFImage): "Each pixel is read as a single unsigned number", "width × height"
    /// of them, each holding `components` 8-bit values. With too few pixels the texture is
    /// garbage or refused; extra high bits are dropped differently by each browser.
    ///
    /// ## Example
    /// ```xml
    /// <PixelTexture image='2 2 1 0xFF 0x00 0xFF'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 5.3.6 SFImage and MFImage; 18.4.6 PixelTexture; 33.4.5 PixelTexture3D.
    /// > "SFImage fields contain three integers representing the width, height and number of components in the image, followed by width×height hexadecimal or integer values" (19775-1 5.3.6, the form of the value)
    ///
    /// > "There shall be at least width × height × depth number of pixel values provided." (19775-1 PixelTexture3D, read in H3D's copy of the 3.x text, `Pixel3DTexture.h`)
    ///
    /// Issue 33: the PixelTexture3D sentence is a minimum, so extra pixels there are
    /// reported per finding as a warning under this code.
    pub static PIXEL_TEXTURE_SIZE_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "5.3.6",
        versions: "all",
        check: Some(check),
    }
}

/// An image's header and pixels, wherever they come from.
struct Header {
    /// Width, height and, for PixelTexture3D, depth.
    sizes: Vec<i64>,
    components: i64,
    /// Whether 0 components is allowed (SFImage: the empty image `0 0 0`).
    zero_components: bool,
    /// Whether the pixel count is a minimum (PixelTexture3D: "at least"), so that extra
    /// pixels are a warning, not an error.
    at_least: bool,
    /// Scalar positions in the field's text of the first size number, the component count
    /// and the first pixel.
    sizes_at: usize,
    components_at: usize,
    pixels_at: usize,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    for (id, node) in doc.iter() {
        for entry in &node.fields {
            match &entry.value {
                Value::Images(images) => {
                    let mut offset = 0;
                    for (j, image) in images.iter().enumerate() {
                        let header = Header {
                            sizes: vec![image.width.into(), image.height.into()],
                            components: image.components.into(),
                            zero_components: true,
                            at_least: false,
                            sizes_at: offset,
                            components_at: offset + 2,
                            pixels_at: offset + 3,
                        };
                        let index = (images.len() > 1).then_some(j);
                        check_image(ctx, id, entry, &header, &image.pixels, index);
                        offset += 3 + image.pixels.len();
                    }
                }
                Value::Int32s(values)
                    if node.type_name() == "PixelTexture3D" && entry.name() == "image" =>
                {
                    if values.len() < 4 {
                        report_header(ctx, id, entry, "PixelTexture3D.image needs `components width height depth` before its pixels".into());
                        continue;
                    }
                    let header = Header {
                        components: values[0].into(),
                        sizes: values[1..4].iter().map(|&v| i64::from(v)).collect(),
                        zero_components: false,
                        at_least: true,
                        sizes_at: 1,
                        components_at: 0,
                        pixels_at: 4,
                    };
                    let pixels: Vec<u32> = values[4..].iter().map(|&v| v as u32).collect();
                    check_image(ctx, id, entry, &header, &pixels, None);
                }
                _ => {}
            }
        }
    }
}

fn check_image(
    ctx: &mut Ctx,
    id: NodeId,
    entry: &FieldEntry,
    header: &Header,
    pixels: &[u32],
    index: Option<usize>,
) {
    let what = format!(
        "{}.{}{}",
        ctx.doc.node(id).type_name(),
        entry.name(),
        index.map_or(String::new(), |j| format!("[{j}]"))
    );
    let names = ["width", "height", "depth"];
    if let Some(k) = header.sizes.iter().position(|&s| s < 0) {
        let span = ctx.scalar_span(entry, header.sizes_at + k);
        ctx.report(
            Diagnostic::new(
                &PIXEL_TEXTURE_SIZE_MISMATCH,
                span,
                format!("{what}: {} {} is negative", names[k], header.sizes[k]),
            )
            .node(id),
        );
        return;
    }
    let lowest = if header.zero_components { 0 } else { 1 };
    if !(lowest..=4).contains(&header.components) {
        let span = ctx.scalar_span(entry, header.components_at);
        ctx.report(
            Diagnostic::new(
                &PIXEL_TEXTURE_SIZE_MISMATCH,
                span,
                format!(
                    "{what}: {} components; an image has {lowest} to 4",
                    header.components
                ),
            )
            .node(id),
        );
        return;
    }
    let expected = header
        .sizes
        .iter()
        .fold(1u128, |product, &s| product.saturating_mul(s as u128));
    let pixels_at = header.pixels_at;
    if expected != pixels.len() as u128 {
        let size = header
            .sizes
            .iter()
            .map(i64::to_string)
            .collect::<Vec<_>>()
            .join(" × ");
        let excess = pixels.len() as u128 > expected;
        let span = match excess {
            true => ctx.scalar_span(entry, pixels_at + expected as usize),
            false => entry.span,
        };
        let severity = match excess && header.at_least {
            true => Severity::Warning,
            false => PIXEL_TEXTURE_SIZE_MISMATCH.severity,
        };
        ctx.report(
            Diagnostic::new(
                &PIXEL_TEXTURE_SIZE_MISMATCH,
                span,
                format!(
                    "{what}: {} pixel values for a {size} image, which needs {expected}",
                    pixels.len()
                ),
            )
            .severity(severity)
            .node(id),
        );
    }
    let max = max_pixel(header.components);
    for (k, &pixel) in pixels.iter().enumerate() {
        if pixel > max {
            let span = ctx.scalar_span(entry, pixels_at + k);
            let components = header.components;
            let field = format!("{}#{}", entry.name(), index.unwrap_or(0));
            let what = what.clone();
            ctx.report_repeated(&PIXEL_TEXTURE_SIZE_MISMATCH, id, &field, k, || {
                Diagnostic::new(
                    &PIXEL_TEXTURE_SIZE_MISMATCH,
                    span,
                    format!("{what}: pixel {k} = {pixel:#X} does not fit {components} component{} (at most {max:#X})", if components == 1 { "" } else { "s" }),
                )
                .node(id)
                .value(format!("{pixel:#X}"))
            });
        }
    }
}

fn report_header(ctx: &mut Ctx, id: NodeId, entry: &FieldEntry, message: String) {
    ctx.report(Diagnostic::new(&PIXEL_TEXTURE_SIZE_MISMATCH, entry.span, message).node(id));
}

/// The largest pixel value `components` 8-bit components hold.
fn max_pixel(components: i64) -> u32 {
    match components {
        0 => 0,
        1..=3 => (1u32 << (8 * components)) - 1,
        _ => u32::MAX,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_limits_per_component_count() {
        assert_eq!(max_pixel(0), 0);
        assert_eq!(max_pixel(1), 0xFF);
        assert_eq!(max_pixel(2), 0xFFFF);
        assert_eq!(max_pixel(3), 0xFF_FFFF);
        assert_eq!(max_pixel(4), u32::MAX);
    }
}
