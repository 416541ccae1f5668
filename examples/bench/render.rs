//! The render half of the benchmark: what each quality preset costs and how far its image
//! is from a heavily supersampled one.
//!
//! - Cost: `x3dcheck SCENE --render OUT.png --quality P --size WxH` on the generated
//!   scene, a child process timed like the checks (wall clock, peak RSS), and, when it is
//!   installed, view3dscene's screenshot of the same file (DESIGN.md's peer) under a
//!   private Xvfb server started once beforehand, so that the server's start is not
//!   counted against view3dscene.
//! - Accuracy: every render case of `corpus/render/` and the generated scene, drawn in
//!   this process with each preset and with [`REFERENCE`] (64 samples per pixel); the
//!   mean absolute error and the PSNR of each preset's image against the reference's.
//! - What the renderer keeps: the normals, tangents and texture coordinates in the draw
//!   lists, against those attributes for every vertex.

use std::ffi::OsStr;
use std::fmt::Write as _;
use std::fs;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Instant;

use image::RgbaImage;
use x3dcheck::config::CheckConfig;
use x3dcheck::model::Document;
use x3dcheck::render::draw_list::DrawList;
use x3dcheck::render::{preview, Gpu, ImageSize, Quality, RenderArgs, Settings, Shading};
use x3dcheck::report::FileReport;

use super::measure::{self, median_wall, on_path, peak_bytes, wall_range, Sample, Timer};
use super::{mb, memory_na, seconds, seconds_bare, speed_ratio, Args};

const PRESETS: [Quality; 3] = [Quality::Fast, Quality::Balanced, Quality::Accurate];

/// What every preset is measured against: per-pixel lighting with every material texture,
/// 4× multisampling of an image 4× larger on each side, averaged down: 64 samples per pixel.
const REFERENCE: Settings = Settings {
    shading: Shading::Phong,
    msaa_samples: 4,
    supersampling: 4,
};

/// The size the render cases are drawn at (their tests use 160×120).
const CASE_SIZE: ImageSize = ImageSize {
    width: 320,
    height: 240,
};

const CASES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/corpus/render");

fn name(quality: Quality) -> &'static str {
    match quality {
        Quality::Fast => "fast",
        Quality::Balanced => "balanced",
        Quality::Accurate => "accurate",
    }
}

fn samples_per_pixel(settings: Settings) -> u32 {
    settings.msaa_samples * settings.supersampling * settings.supersampling
}

fn lighting(settings: Settings) -> &'static str {
    match settings.shading {
        Shading::Gouraud => "per vertex (Gouraud), main texture only",
        Shading::Phong => "per pixel (Phong), every material texture",
    }
}

fn size_text(size: ImageSize) -> String {
    format!("{}x{}", size.width, size.height)
}

/// Times `x3dcheck SCENE --render` per preset and view3dscene's screenshot of the scene.
pub fn speed(
    out: &mut String,
    args: &Args,
    timer: &Timer,
    x3dcheck: &Path,
    scene: &Path,
    runs: usize,
    scratch: &Path,
) -> Result<(), String> {
    let size = args.render_size;
    let image = scratch.join("render.png");
    let stderr = scratch.join("render-stderr.txt");
    let size_arg = size_text(size);
    let mut rows: Vec<(String, Vec<Sample>)> = Vec::new();
    for quality in PRESETS {
        eprintln!(
            "x3dcheck-bench: x3dcheck --render --quality {} ×{runs}",
            name(quality)
        );
        let argv: Vec<&OsStr> = [
            scene.as_os_str(),
            OsStr::new("--render"),
            image.as_os_str(),
            OsStr::new("--quality"),
            OsStr::new(name(quality)),
            OsStr::new("--size"),
            OsStr::new(&size_arg),
            OsStr::new("--format"),
            OsStr::new("concise"),
        ]
        .to_vec();
        let _ = fs::remove_file(&image);
        let samples = timed(timer, x3dcheck.as_os_str(), &argv, &stderr, runs, || {
            image.is_file()
        })
        .map_err(|e| format!("x3dcheck --render --quality {}: {e}", name(quality)))?;
        rows.push((
            format!("`x3dcheck --render --quality {}`", name(quality)),
            samples,
        ));
    }

    let mut notes = Vec::new();
    let peer = if !args.no_peers {
        view3dscene(timer, scene, size, runs, scratch, &mut notes)
    } else {
        notes.push("view3dscene: not run (--no-peers)".to_string());
        None
    };
    let peer_median = peer.as_ref().map(|s| median_wall(s));
    let presets = rows.len();
    if let Some(samples) = peer {
        rows.push((
            "`view3dscene --screenshot` (Xvfb, Mesa GL)".to_string(),
            samples,
        ));
    }

    let _ = writeln!(
        out,
        "\n### Rendering the generated scene ({}×{}, the CLI as a child process)\n",
        size.width, size.height
    );
    let _ = writeln!(
        out,
        "| what | time (median) | min–max | peak RSS | RSS / file size (target < 2×) | vs view3dscene |"
    );
    let _ = writeln!(out, "|---|--:|--:|--:|--:|--:|");
    let file_size = fs::metadata(scene)
        .map_err(|e| format!("{}: {e}", scene.display()))?
        .len();
    let ratio_of = |samples: &[Sample]| peak_bytes(samples).map(|p| p as f64 / file_size as f64);
    for (i, (what, samples)) in rows.iter().enumerate() {
        let median = median_wall(samples);
        let (low, high) = wall_range(samples);
        let ratio = match peer_median {
            Some(_) if i == presets => "1× (itself)".to_string(),
            Some(reference) => speed_ratio(reference, median),
            None => "—".to_string(),
        };
        let _ = writeln!(
            out,
            "| {what} | {} | {}–{} | {} | {} | {ratio} |",
            seconds(median),
            seconds_bare(low),
            seconds_bare(high),
            peak_bytes(samples).map_or(memory_na(timer), |p| format!("{:.0} MB", mb(p))),
            ratio_of(samples).map_or(memory_na(timer), |r| format!("{r:.2}×")),
        );
    }
    let _ = writeln!(
        out,
        "\nMedian wall clock of {runs} run{} after one warm-up run, each a whole `x3dcheck` run \
         (read, check at the standard level, draw, write the PNG); peak RSS as above.",
        if runs == 1 { "" } else { "s" }
    );
    let balanced = PRESETS
        .iter()
        .position(|&q| q == Quality::Balanced)
        .map_or(f64::NAN, |i| median_wall(&rows[i].1));
    match peer_median {
        Some(reference) => {
            let ratio = reference / balanced;
            let _ = writeln!(
                out,
                "- {} `--render` (balanced, the default) under a fifth of view3dscene's time: {ratio:.1}× faster",
                if ratio >= 5.0 { "✓" } else { "✗" }
            );
        }
        None => {
            let _ = writeln!(
                out,
                "- – `--render` under a fifth of view3dscene's time: not measured"
            );
        }
    }
    let ratios: Vec<Option<f64>> = rows[..presets].iter().map(|(_, s)| ratio_of(s)).collect();
    if ratios.iter().all(Option::is_some) {
        let listed: Vec<String> = PRESETS
            .iter()
            .zip(&ratios)
            .map(|(&q, r)| format!("{} {:.2}×", name(q), r.unwrap_or(f64::NAN)))
            .collect();
        let _ = writeln!(
            out,
            "- {} `--render` peak memory < 2× file size at every preset: {}",
            if ratios.iter().all(|r| r.is_some_and(|r| r < 2.0)) {
                "✓"
            } else {
                "✗"
            },
            listed.join(", ")
        );
    } else {
        let _ = writeln!(
            out,
            "- – `--render` peak memory < 2× file size: not measured"
        );
    }
    for note in notes {
        let _ = writeln!(out, "- {note}");
    }
    Ok(())
}

/// A warm-up run that must exit 0 or 1 and leave `made()` true, then `runs` timed runs.
fn timed(
    timer: &Timer,
    program: &OsStr,
    argv: &[&OsStr],
    stderr: &Path,
    runs: usize,
    made: impl Fn() -> bool,
) -> Result<Vec<Sample>, String> {
    let run = || {
        timer
            .run(program, argv, Some(stderr))
            .map_err(|e| format!("cannot run {}: {e}", program.to_string_lossy()))
    };
    let warm = run()?;
    if !matches!(warm.code, Some(0 | 1)) || !made() {
        return Err(format!(
            "exit code {:?}, no image: {}",
            warm.code,
            measure::head(stderr, 3)
        ));
    }
    (0..runs).map(|_| run()).collect()
}

/// view3dscene's screenshot of `scene`, when view3dscene and Xvfb are installed.
fn view3dscene(
    timer: &Timer,
    scene: &Path,
    size: ImageSize,
    runs: usize,
    scratch: &Path,
    notes: &mut Vec<String>,
) -> Option<Vec<Sample>> {
    let (Some(view3dscene), Some(xvfb)) = (on_path("view3dscene"), on_path("Xvfb")) else {
        notes.push(
            "view3dscene: not measured (needs the Debian packages `view3dscene` and `xvfb`)"
                .to_string(),
        );
        return None;
    };
    let server = match XServer::start(&xvfb, size) {
        Ok(server) => server,
        Err(e) => {
            notes.push(format!("view3dscene: not measured (Xvfb: {e})"));
            return None;
        }
    };
    // view3dscene names its image format by the file's extension.
    let image = scratch.join("view3dscene.png");
    let stderr = scratch.join("view3dscene-stderr.txt");
    let display = format!("DISPLAY=:{}", server.display);
    let geometry = size_text(size);
    let argv: Vec<&OsStr> = [
        OsStr::new(&display),
        view3dscene.as_os_str(),
        scene.as_os_str(),
        OsStr::new("--screenshot"),
        OsStr::new("0"),
        image.as_os_str(),
        OsStr::new("--geometry"),
        OsStr::new(&geometry),
    ]
    .to_vec();
    eprintln!("x3dcheck-bench: view3dscene --screenshot ×{runs} (slow)");
    let _ = fs::remove_file(&image);
    // `env` execs view3dscene, so GNU time measures view3dscene itself.
    match timed(timer, OsStr::new("env"), &argv, &stderr, runs, || {
        image.is_file()
    }) {
        Ok(samples) => {
            let version = Command::new(&view3dscene)
                .arg("--version")
                .output()
                .ok()
                .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
                .unwrap_or_default();
            notes.push(format!(
                "view3dscene {version}: `view3dscene SCENE --screenshot 0 OUT.png --geometry {geometry}` \
                 on a private Xvfb display started before the runs (Mesa's software OpenGL)"
            ));
            Some(samples)
        }
        Err(e) => {
            notes.push(format!("view3dscene: failed ({e})"));
            None
        }
    }
}

/// An Xvfb server for the peer's window, stopped when dropped.
struct XServer {
    child: Child,
    display: u32,
}

impl XServer {
    fn start(xvfb: &Path, size: ImageSize) -> Result<XServer, String> {
        let screen = format!("{}x{}x24", size.width + 64, size.height + 64);
        // -displayfd: Xvfb picks a free display and writes its number once it accepts
        // connections.
        let mut child = Command::new(xvfb)
            .args([
                "-displayfd",
                "1",
                "-nolisten",
                "tcp",
                "-screen",
                "0",
                &screen,
            ])
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", xvfb.display()))?;
        let mut line = String::new();
        let read = child
            .stdout
            .take()
            .map(|stdout| BufReader::new(stdout).read_line(&mut line));
        match (read, line.trim().parse::<u32>()) {
            (Some(Ok(_)), Ok(display)) => Ok(XServer { child, display }),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                Err("it did not say which display it opened".to_string())
            }
        }
    }
}

impl Drop for XServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A scene read and checked once, drawn many times.
struct Loaded {
    name: String,
    path: PathBuf,
    source: Vec<u8>,
    doc: Document,
    /// The check's report, which the renderer's notes would join.
    report: FileReport,
    camera: String,
}

impl Loaded {
    fn read(name: String, path: PathBuf, camera: String) -> Result<Loaded, String> {
        let source = fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let x3dcheck::check::Checked {
            report,
            document: doc,
            ..
        } = x3dcheck::check::check_document(
            &path.display().to_string(),
            &source,
            &CheckConfig::default(),
        );
        let doc = doc.ok_or_else(|| format!("{}: no scene", path.display()))?;
        Ok(Loaded {
            name,
            path,
            source,
            doc,
            report,
            camera,
        })
    }

    /// The image for `settings` and the seconds it took (the draw list, the GPU work and
    /// the read-back); what the draw list holds is added to `attributes`.
    fn draw(
        &self,
        gpu: &Gpu,
        size: ImageSize,
        settings: Settings,
        attributes: Option<&mut Attributes>,
    ) -> Result<(f64, RgbaImage), String> {
        let args = RenderArgs {
            render: None,
            size,
            quality: Quality::Balanced,
            camera: self.camera.clone(),
            island: 1,
        };
        let mut report = self.report.clone();
        let started = Instant::now();
        let preview = preview(
            &args,
            settings,
            &self.path,
            None,
            &self.source,
            Some(&self.doc),
            &mut report,
        )?;
        let flattened = started.elapsed();
        if let Some(attributes) = attributes {
            attributes.add(preview.list());
        }
        let drawing = Instant::now();
        let image = preview.draw_on(gpu)?;
        Ok(((flattened + drawing.elapsed()).as_secs_f64(), image))
    }
}

/// The render cases of `corpus/render/`, with the camera their `render.toml` names.
fn render_cases() -> Result<Vec<Loaded>, String> {
    let mut dirs: Vec<PathBuf> = fs::read_dir(CASES)
        .map_err(|e| format!("{CASES}: {e}"))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.join("scene.x3d").is_file())
        .collect();
    dirs.sort();
    dirs.into_iter()
        .map(|dir| {
            let camera = fs::read_to_string(dir.join("render.toml"))
                .ok()
                .and_then(|t| t.parse::<toml::Table>().ok())
                .and_then(|t| t.get("camera").and_then(|c| c.as_str()).map(str::to_string))
                .unwrap_or_else(|| "auto".to_string());
            let name = dir
                .file_name()
                .map_or(String::new(), |n| n.to_string_lossy().into_owned());
            Loaded::read(name, dir.join("scene.x3d"), camera)
        })
        .collect()
}

/// How far one image is from another, over the red, green and blue channels (0–255).
#[derive(Copy, Clone, Debug, Default)]
struct ImageError {
    absolute: f64,
    squared: f64,
    channels: f64,
}

impl ImageError {
    fn between(image: &RgbaImage, reference: &RgbaImage) -> ImageError {
        let mut error = ImageError::default();
        for (a, b) in image.pixels().zip(reference.pixels()) {
            for c in 0..3 {
                let d = f64::from(a[c]) - f64::from(b[c]);
                error.absolute += d.abs();
                error.squared += d * d;
            }
        }
        error.channels = f64::from(image.width() * image.height() * 3);
        error
    }

    fn mae(&self) -> f64 {
        self.absolute / self.channels
    }

    fn mse(&self) -> f64 {
        self.squared / self.channels
    }
}

/// PSNR in dB of a mean squared error on 0–255 channels.
fn psnr(mse: f64) -> String {
    if mse == 0.0 {
        "∞".to_string()
    } else {
        format!("{:.1} dB", 10.0 * (255.0 * 255.0 / mse).log10())
    }
}

/// One setting over a set of scenes: per scene, the median seconds and the error.
#[derive(Default)]
struct Measured {
    seconds: Vec<f64>,
    errors: Vec<(String, ImageError)>,
}

impl Measured {
    fn total_seconds(&self) -> f64 {
        self.seconds.iter().sum()
    }

    /// The mean MAE over the scenes ("—" for the reference, which has no error).
    fn mae(&self) -> String {
        if self.errors.is_empty() {
            return "—".to_string();
        }
        let sum: f64 = self.errors.iter().map(|(_, e)| e.mae()).sum();
        format!("{:.2}", sum / self.errors.len() as f64)
    }

    /// The PSNR of the mean MSE over the scenes.
    fn psnr(&self) -> String {
        if self.errors.is_empty() {
            return "—".to_string();
        }
        let sum: f64 = self.errors.iter().map(|(_, e)| e.mse()).sum();
        psnr(sum / self.errors.len() as f64)
    }

    fn worst(&self) -> Option<&(String, ImageError)> {
        self.errors
            .iter()
            .max_by(|a, b| a.1.mae().total_cmp(&b.1.mae()))
    }
}

/// What the draw lists hold, against normals, tangents and texture coordinates for every
/// vertex.
#[derive(Default)]
struct Attributes {
    meshes: usize,
    vertices: u64,
    with_normals: usize,
    with_tangents: usize,
    tex_coord_sets: usize,
    bytes: u64,
}

impl Attributes {
    /// Normals (12 bytes), tangents (16) and one texture coordinate set (8) per vertex.
    const EVERYTHING: u64 = 12 + 16 + 8;

    fn add(&mut self, list: &DrawList) {
        for mesh in list.meshes() {
            let n = mesh.positions.len() as u64;
            self.meshes += 1;
            self.vertices += n;
            self.with_normals += usize::from(mesh.normals.is_some());
            self.with_tangents += usize::from(mesh.tangents.is_some());
            self.tex_coord_sets += mesh.tex_coords.len();
            self.bytes += n
                * (12 * u64::from(mesh.normals.is_some())
                    + 16 * u64::from(mesh.tangents.is_some())
                    + 8 * mesh.tex_coords.len() as u64);
        }
    }

    fn line(&self, what: &str) -> String {
        format!(
            "{what}: {} meshes, {} vertices; normals in {}, tangents in {}, {} texture coordinate \
             set{}: {:.2} MB, against {:.2} MB for normals, tangents and one texture coordinate \
             set at every vertex ({:.0}%)",
            self.meshes,
            self.vertices,
            self.with_normals,
            self.with_tangents,
            self.tex_coord_sets,
            if self.tex_coord_sets == 1 { "" } else { "s" },
            mb(self.bytes),
            mb(self.vertices * Self::EVERYTHING),
            100.0 * self.bytes as f64 / (self.vertices * Self::EVERYTHING).max(1) as f64
        )
    }
}

/// Draws `scenes` `runs` times per preset and once with the reference.
fn measure_scenes(
    gpu: &Gpu,
    scenes: &[Loaded],
    size: ImageSize,
    runs: usize,
    attributes: &mut Attributes,
) -> Result<(Measured, [Measured; 3]), String> {
    let mut reference = Measured::default();
    let mut presets: [Measured; 3] = Default::default();
    for scene in scenes {
        eprintln!(
            "x3dcheck-bench: rendering {} (reference and presets)",
            scene.name
        );
        let (seconds, truth) = scene.draw(gpu, size, REFERENCE, Some(&mut *attributes))?;
        reference.seconds.push(seconds);
        for (quality, measured) in PRESETS.iter().zip(presets.iter_mut()) {
            let mut times = Vec::with_capacity(runs);
            let mut image = None;
            for _ in 0..runs {
                let (seconds, drawn) = scene.draw(gpu, size, quality.settings(), None)?;
                times.push(seconds);
                image = Some(drawn);
            }
            measured.seconds.push(measure::median(times));
            // Every draw of a preset is the same image: the last one is measured.
            let error = image.map_or_else(ImageError::default, |image| {
                ImageError::between(&image, &truth)
            });
            measured.errors.push((scene.name.clone(), error));
        }
    }
    Ok((reference, presets))
}

/// The presets against the reference, over the render cases and the generated scene.
pub fn accuracy(
    out: &mut String,
    scene: &Path,
    size: ImageSize,
    runs: usize,
) -> Result<(), String> {
    let gpu = Gpu::open().map_err(|e| e.to_string())?;
    let cases = render_cases()?;
    let mut case_attributes = Attributes::default();
    let (case_reference, case_presets) =
        measure_scenes(&gpu, &cases, CASE_SIZE, runs, &mut case_attributes)?;
    drop(cases);
    let generated = Loaded::read(
        "generated scene".to_string(),
        scene.to_path_buf(),
        "auto".to_string(),
    )?;
    let mut scene_attributes = Attributes::default();
    let (scene_reference, scene_presets) = measure_scenes(
        &gpu,
        std::slice::from_ref(&generated),
        size,
        runs,
        &mut scene_attributes,
    )?;
    drop(generated);

    let count = case_reference.seconds.len();
    let _ = writeln!(
        out,
        "\n### Render quality presets against a {}-samples-per-pixel reference\n",
        samples_per_pixel(REFERENCE)
    );
    let _ = writeln!(
        out,
        "| preset | lighting | samples per pixel | {count} render cases ({}×{}): time | MAE | PSNR | worst case (MAE, PSNR) | generated scene ({}×{}): time | MAE | PSNR |",
        CASE_SIZE.width, CASE_SIZE.height, size.width, size.height
    );
    let _ = writeln!(out, "|---|---|--:|--:|--:|--:|---|--:|--:|--:|");
    let rows = PRESETS
        .iter()
        .map(|q| (name(*q), q.settings()))
        .zip(case_presets.iter().zip(scene_presets.iter()))
        .chain(std::iter::once((
            ("reference", REFERENCE),
            (&case_reference, &scene_reference),
        )));
    for ((preset, settings), (cases, scene)) in rows {
        let worst = cases.worst().map_or("—".to_string(), |(name, e)| {
            format!("{name} ({:.2}, {})", e.mae(), psnr(e.mse()))
        });
        let _ = writeln!(
            out,
            "| {preset} | {} | {} | {} | {} | {} | {worst} | {} | {} | {} |",
            lighting(settings),
            samples_per_pixel(settings),
            seconds(cases.total_seconds()),
            cases.mae(),
            cases.psnr(),
            seconds(scene.total_seconds()),
            scene.mae(),
            scene.psnr(),
        );
    }
    let _ = writeln!(
        out,
        "\nDrawn in this process on the adapter wgpu picks (`WGPU_BACKEND` chooses), from a \
         document read once, on one device opened beforehand: time is the sum over the scenes \
         of the median of {runs} draw{} (draw list, GPU work, read-back; the reference: one \
         draw). MAE: mean absolute \
         difference from the reference's image per red, green and blue channel, on 0–255, \
         averaged over the scenes; PSNR: from the mean squared difference averaged over the \
         scenes; worst case: the scene with the largest MAE. The reference draws per pixel \
         with 4× multisampling at 4× the size on each side, averaged down.",
        if runs == 1 { "" } else { "s" }
    );
    let _ = writeln!(
        out,
        "\nWhat the draw lists hold (only what a scene uses, see src/render/draw_list.rs):\n\
         - {}\n- {}",
        case_attributes.line("render cases"),
        scene_attributes.line("generated scene"),
    );
    Ok(())
}
