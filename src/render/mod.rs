//! Preview rendering (`--render OUT.png`): [`flatten`] turns the scene model into a
//! [`draw_list::DrawList`] (its guarantees are written there), [`gpu`] draws it offscreen
//! with wgpu, on any adapter including software ones (lavapipe, llvmpipe). What cannot be
//! drawn is reported as VALIDATION_INCOMPLETE info diagnostics beginning "renderer:" (an
//! image past the size limit of [`crate::limits`] as LIMIT_EXCEEDED).

//!
//! The options ([`RenderArgs`]) always exist; the renderer itself is built with the
//! `render` cargo feature (wgpu). Without it, `--render` is refused with that reason.

mod cli_args;
#[cfg(feature = "render")]
pub mod draw_list;
#[cfg(feature = "render")]
mod fields;
#[cfg(feature = "render")]
pub mod flatten;
#[cfg(feature = "render")]
mod geometry;
#[cfg(feature = "render")]
mod gpu;
#[cfg(feature = "render")]
// Face and corner numbers index several parallel arrays at once.
#[allow(clippy::needless_range_loop)]
mod polygons;
#[cfg(feature = "render")]
mod textures;

use std::path::Path;

pub use cli_args::{ImageSize, Quality, RenderArgs};
#[cfg(feature = "render")]
pub use gpu::GpuError;

use crate::model::Document;
use crate::report::FileReport;
#[cfg(feature = "render")]
use crate::report::{resolve, Diagnostic};
#[cfg(feature = "render")]
use crate::validate::document::limit_exceeded::LIMIT_EXCEEDED;
#[cfg(feature = "render")]
use crate::validate::document::validation_incomplete::VALIDATION_INCOMPLETE;

#[cfg(feature = "render")]
/// Renders `doc` (read from `source`, the document at `path`) into an image, adding what
/// cannot be drawn to `report`. Err: why no image could be made (no document, no adapter,
/// bad --camera).
pub fn render_image(
    args: &RenderArgs,
    path: &Path,
    source: &[u8],
    doc: Option<&Document>,
    report: &mut FileReport,
) -> Result<image::RgbaImage, String> {
    let Some(doc) = doc else {
        return Err(format!("{}: no scene to render", path.display()));
    };
    let base_dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
        .to_path_buf();
    let options = flatten::Options {
        camera: (args.camera != "auto").then_some(args.camera.as_str()),
        base_dir,
        x3d_version_3: doc
            .version_text
            .as_ref()
            .is_some_and(|v| v.text.starts_with('3')),
        primitive_budget: flatten::primitive_budget(args.size.width, args.size.height),
    };
    let flattened = flatten::flatten(doc, &options)?;
    let diagnostics: Vec<Diagnostic> = flattened
        .notes
        .iter()
        .map(|note| {
            let span = note.node.map_or(doc.root_span, |n| doc.node(n).name_span);
            let rule = if note.limit {
                &LIMIT_EXCEEDED
            } else {
                &VALIDATION_INCOMPLETE
            };
            let mut d = Diagnostic::new(rule, span, note.message.clone());
            d.node = note.node;
            d
        })
        .collect();
    report
        .diagnostics
        .extend(resolve(&diagnostics, source, Some(doc)));
    gpu::render(
        &flattened.list,
        args.size.width,
        args.size.height,
        args.quality,
    )
    .map_err(|e| e.to_string())
}

/// `--render`: renders `doc` (as [`crate::check::check_document`] read it) and writes the
/// PNG. Does nothing when `--render` was not given.
#[cfg(feature = "render")]
pub fn run(
    args: &RenderArgs,
    path: &Path,
    source: &[u8],
    doc: Option<&Document>,
    report: &mut FileReport,
) -> Result<(), String> {
    let Some(out) = &args.render else {
        return Ok(());
    };
    let image = render_image(args, path, source, doc, report)?;
    image
        .save_with_format(out, image::ImageFormat::Png)
        .map_err(|e| format!("cannot write {}: {e}", out.display()))
}

/// `--render` in a build without the `render` feature.
#[cfg(not(feature = "render"))]
pub fn run(
    args: &RenderArgs,
    _path: &Path,
    _source: &[u8],
    _doc: Option<&Document>,
    _report: &mut FileReport,
) -> Result<(), String> {
    match &args.render {
        None => Ok(()),
        Some(_) => {
            Err("--render: this x3dcheck was built without the `render` feature".to_string())
        }
    }
}
