//! Preview rendering (`--render OUT.png`): [`flatten`] turns the scene model into a
//! [`draw_list::DrawList`] (its guarantees are written there), `gpu` draws it offscreen
//! with wgpu, on any adapter including software ones (lavapipe, llvmpipe). What cannot be
//! drawn is reported as VALIDATION_INCOMPLETE info diagnostics beginning "renderer:" (an
//! image past the size limit of [`crate::limits`] as LIMIT_EXCEEDED).

//!
//! The options ([`RenderArgs`]) always exist; the renderer itself is built with the
//! `render` cargo feature (wgpu). Without it, `--render` is refused with that reason.

mod cli_args;
#[cfg(feature = "render")]
pub mod cube_map;
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
mod mesh;
#[cfg(feature = "render")]
// Face and corner numbers index several parallel arrays at once.
#[allow(clippy::needless_range_loop)]
mod polygons;
#[cfg(feature = "render")]
mod tangents;
#[cfg(feature = "render")]
mod test_adapter;
#[cfg(feature = "render")]
mod texgen;
#[cfg(feature = "render")]
mod text;
#[cfg(feature = "render")]
mod textures;

use std::path::Path;

pub use cli_args::{ImageSize, Quality, RenderArgs};

/// The lighting equations in WGSL (one light at one point), on their own for tests.
#[cfg(feature = "render")]
pub const LIGHTING_WGSL: &str = include_str!("lighting.wgsl");
/// The whole shader: the lighting equations, then the shading that uses them.
#[cfg(feature = "render")]
const SHADER_WGSL: &str = concat!(include_str!("lighting.wgsl"), include_str!("shader.wgsl"));
#[cfg(feature = "render")]
pub use gpu::{open_device, Gpu, GpuError, Settings, Shading};
#[cfg(feature = "render")]
pub use test_adapter::{adapter_for_test, REQUIRE_GPU};

#[cfg(feature = "render")]
use crate::diagnostic::Diagnostic;
#[cfg(feature = "render")]
use crate::model::rules::LIMIT_EXCEEDED;
use crate::model::Document;
#[cfg(feature = "render")]
use crate::report::resolve;
use crate::report::FileReport;
#[cfg(feature = "render")]
use crate::validate::document::validation_incomplete::VALIDATION_INCOMPLETE;

/// A scene ready to draw: the draw list, taken apart from the document, so that the
/// document and its source can be freed before the GPU work (the two together can be
/// larger than the meshes).
#[cfg(feature = "render")]
pub struct Preview {
    list: draw_list::DrawList,
    width: u32,
    height: u32,
    settings: Settings,
    out: Option<std::path::PathBuf>,
}

/// Without the renderer there is never a preview.
#[cfg(not(feature = "render"))]
pub enum Preview {}

#[cfg(feature = "render")]
impl Preview {
    /// What will be drawn.
    pub fn list(&self) -> &draw_list::DrawList {
        &self.list
    }

    /// Draws the image.
    pub fn draw(self) -> Result<image::RgbaImage, String> {
        gpu::render(self.list, self.width, self.height, self.settings).map_err(|e| e.to_string())
    }

    /// Draws the image on a device already open.
    pub fn draw_on(self, gpu: &Gpu) -> Result<image::RgbaImage, String> {
        gpu.render(self.list, self.width, self.height, self.settings)
            .map_err(|e| e.to_string())
    }

    /// Draws the image into the `--render` file.
    pub fn save(self) -> Result<(), String> {
        let Some(out) = self.out.clone() else {
            return Ok(());
        };
        self.draw()?
            .save_with_format(&out, image::ImageFormat::Png)
            .map_err(|e| format!("cannot write {}: {e}", out.display()))
    }
}

#[cfg(not(feature = "render"))]
impl Preview {
    pub fn save(self) -> Result<(), String> {
        match self {}
    }
}

/// `--render`: takes `doc` (as [`crate::check::check_document`] read it, from `source`,
/// the document at `path`) apart into a [`Preview`], adding what cannot be drawn to
/// `report`. Inlines and textures are read from the tree `root` (the check's
/// [`crate::config::CheckConfig::root`]; None: the document's directory) and never from
/// outside it. None when `--render` was not given; Err: why no image can be made (no
/// document, bad --camera, a build without the renderer).
// Without the renderer `Unresolved` has no values, so everything after its first use is
// unreachable; the function is kept so that callers need no feature gates.
#[cfg_attr(not(feature = "render"), allow(unreachable_code, unused_variables))]
pub fn prepare(
    args: &RenderArgs,
    path: &Path,
    root: Option<&Path>,
    source: &[u8],
    doc: Option<&Document>,
    report: &mut FileReport,
) -> Result<Option<Preview>, String> {
    Ok(match (prepare_unresolved(args, path, root, doc)?, doc) {
        (Some(unresolved), Some(doc)) => Some(unresolved.resolve(source, doc, report)),
        _ => None,
    })
}

/// [`prepare`] without the source: the notes are placed afterwards by
/// [`Unresolved::resolve`], so that a caller can free the source before the scene is
/// flattened (with the document and the draw list, it made the peak of a large scene's
/// memory) and read it again only when there are notes to place.
pub fn prepare_unresolved(
    args: &RenderArgs,
    path: &Path,
    root: Option<&Path>,
    doc: Option<&Document>,
) -> Result<Option<Unresolved>, String> {
    if args.render.is_none() {
        return Ok(None);
    }
    #[cfg(feature = "render")]
    {
        let doc = doc.ok_or_else(|| no_scene(path))?;
        unresolved(args, args.quality.settings(), path, root, doc).map(Some)
    }
    #[cfg(not(feature = "render"))]
    {
        let _ = (path, root, doc);
        Err("--render: this x3dcheck was built without the `render` feature".to_string())
    }
}

/// A [`Preview`] whose notes (what cannot be drawn) are not yet in the report: placing
/// them takes the source.
#[cfg(feature = "render")]
pub struct Unresolved {
    preview: Preview,
    notes: Vec<Diagnostic>,
}

/// Without the renderer there is never a preview.
#[cfg(not(feature = "render"))]
pub enum Unresolved {}

#[cfg(feature = "render")]
impl Unresolved {
    /// Whether [`Unresolved::resolve`] needs the source.
    pub fn has_notes(&self) -> bool {
        !self.notes.is_empty()
    }

    /// Adds the notes to `report`, placed in `source`, the text `doc` was read from.
    pub fn resolve(self, source: &[u8], doc: &Document, report: &mut FileReport) -> Preview {
        report
            .diagnostics
            .extend(resolve(&self.notes, source, &(), Some(doc)));
        self.preview
    }
}

#[cfg(not(feature = "render"))]
impl Unresolved {
    pub fn has_notes(&self) -> bool {
        match *self {}
    }

    pub fn resolve(self, _: &[u8], _: &Document, _: &mut FileReport) -> Preview {
        match self {}
    }
}

/// Renders `doc` into an image with the preset of `args` (see [`prepare`]).
#[cfg(feature = "render")]
pub fn render_image(
    args: &RenderArgs,
    path: &Path,
    root: Option<&Path>,
    source: &[u8],
    doc: Option<&Document>,
    report: &mut FileReport,
) -> Result<image::RgbaImage, String> {
    preview(
        args,
        args.quality.settings(),
        path,
        root,
        source,
        doc,
        report,
    )?
    .draw()
}

/// The [`Preview`] of `doc` with explicit [`Settings`] instead of a quality preset (the
/// benchmark measures the presets against a heavily supersampled reference this way).
#[cfg(feature = "render")]
pub fn preview(
    args: &RenderArgs,
    settings: Settings,
    path: &Path,
    root: Option<&Path>,
    source: &[u8],
    doc: Option<&Document>,
    report: &mut FileReport,
) -> Result<Preview, String> {
    let doc = doc.ok_or_else(|| no_scene(path))?;
    Ok(unresolved(args, settings, path, root, doc)?.resolve(source, doc, report))
}

#[cfg(feature = "render")]
fn no_scene(path: &Path) -> String {
    format!("{}: no scene to render", path.display())
}

/// The [`Unresolved`] preview of `doc` with explicit [`Settings`].
#[cfg(feature = "render")]
fn unresolved(
    args: &RenderArgs,
    settings: Settings,
    path: &Path,
    root: Option<&Path>,
    doc: &Document,
) -> Result<Unresolved, String> {
    let base_dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
        .to_path_buf();
    let options = flatten::Options {
        camera: flatten::CameraChoice::parse(&args.camera),
        root: root.map_or_else(|| base_dir.clone(), Path::to_path_buf),
        base_dir,
        x3d_version_3: doc
            .version_text
            .as_ref()
            .is_some_and(|v| v.text.starts_with('3')),
        primitive_budget: flatten::primitive_budget(args.size.width, args.size.height),
        image: (args.size.width, args.size.height),
    };
    let flattened = flatten::flatten(doc, &options)?;
    let notes: Vec<Diagnostic> = flattened
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
    Ok(Unresolved {
        preview: Preview {
            list: flattened.list,
            width: args.size.width,
            height: args.size.height,
            settings,
            out: args.render.clone(),
        },
        notes,
    })
}

/// Mesa's software drivers complain on stderr ("XDG_RUNTIME_DIR is invalid or not set")
/// when the variable is missing, as on CI machines and containers; it then points at the
/// temporary directory. Call it before any thread starts.
pub fn prepare_environment() {
    #[cfg(feature = "render")]
    if std::env::var_os("XDG_RUNTIME_DIR").is_none_or(|v| v.is_empty()) {
        // Sound here: the caller runs this while the process has one thread.
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
}
