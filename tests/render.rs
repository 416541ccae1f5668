//! Render cases: every `corpus/render/<case>/scene.x3d` is rendered at 160×120 (balanced
//! quality, unless a `render.toml` beside it says `quality = "fast"` or `"accurate"`) and
//! compared per channel with `reference.png` beside it. A pixel differs when
//! one channel differs by more than `CHANNEL_TOLERANCE`; a case fails when more than
//! `PIXEL_BUDGET` of its pixels differ (software rasterizers differ slightly at edges).
//! On failure `actual.png` and `diff.png` are written next to the reference.
//!
//! `X3DCHECK_UPDATE_REFERENCES=1` rewrites the references (look at each before
//! committing). On a machine without a graphics adapter each test is skipped with one line
//! saying what to install, unless `X3DCHECK_REQUIRE_GPU=1` (set by CI) makes that a
//! failure ([`x3dcheck::render::adapter_for_test`]); `no_adapter_skips_loudly_or_fails`
//! runs this file's tests with no adapter to see both.
#![cfg(feature = "render")]

use std::path::{Path, PathBuf};

use x3dcheck::config::CheckConfig;
use x3dcheck::limits::{MAX_RENDER_SHAPES, MAX_RENDER_TEXT_CHARACTERS, RENDER_FILL_IMAGES};
use x3dcheck::model::Document;
use x3dcheck::render::{preview, render_image, Gpu, ImageSize, Quality, RenderArgs};
use x3dcheck::report::FileReport;

/// How long a render of a hostile scene may take before it counts as a hang: these cases
/// took minutes before their budgets, and take 2–10 s with them (up to 2× that on the
/// shared 2-core machines under load). A guard, not a speed measure: the benchmarks
/// measure speed.
const HANG_GUARD: std::time::Duration = std::time::Duration::from_secs(60);

const CHANNEL_TOLERANCE: u8 = 24;
const PIXEL_BUDGET: f64 = 0.01;

fn cases() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/render");
    let mut cases: Vec<PathBuf> = std::fs::read_dir(&root)
        .expect("corpus/render exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.join("scene.x3d").is_file())
        .collect();
    cases.sort();
    cases
}

fn args() -> RenderArgs {
    RenderArgs {
        render: None,
        size: ImageSize {
            width: 160,
            height: 120,
        },
        quality: Quality::Balanced,
        camera: "auto".to_string(),
        island: 1,
    }
}

/// A case's scene file, its bytes, and the check's report and document.
fn checked_case(case: &Path) -> (PathBuf, Vec<u8>, FileReport, Option<Document>) {
    let scene = case.join("scene.x3d");
    let source = std::fs::read(&scene).unwrap();
    let x3dcheck::check::Checked {
        report,
        document: doc,
        ..
    } = x3dcheck::check::check_document(
        &scene.display().to_string(),
        &source,
        // As the command line's --render does: values kept, external prototypes resolved.
        &CheckConfig {
            render: true,
            ..CheckConfig::default()
        },
    );
    (scene, source, report, doc)
}

/// The case's arguments: `render.toml` may set `quality` and `camera`.
fn case_args(case: &Path) -> RenderArgs {
    let mut args = args();
    let Ok(text) = std::fs::read_to_string(case.join("render.toml")) else {
        return args;
    };
    let table: toml::Table = text.parse().expect("render.toml parses");
    for (key, value) in table {
        match (key.as_str(), value.as_str()) {
            ("quality", Some("fast")) => args.quality = Quality::Fast,
            ("quality", Some("balanced")) => args.quality = Quality::Balanced,
            ("quality", Some("accurate")) => args.quality = Quality::Accurate,
            ("camera", Some(def)) => args.camera = def.to_string(),
            _ => panic!("{}: unknown render.toml entry {key}", case.display()),
        }
    }
    args
}

#[test]
fn render_cases_match_their_references() {
    if !x3dcheck::render::adapter_for_test("render_cases_match_their_references") {
        return;
    }
    let update = std::env::var_os("X3DCHECK_UPDATE_REFERENCES").is_some_and(|v| v == "1");
    let cases = cases();
    assert!(!cases.is_empty());
    let mut failures = Vec::new();
    for case in &cases {
        let (scene, source, mut report, doc) = checked_case(case);
        let image = render_image(
            &case_args(case),
            &scene,
            None,
            &source,
            doc.as_ref(),
            &mut report,
        )
        .unwrap_or_else(|e| panic!("{}: {e}", case.display()));
        let reference_path = case.join("reference.png");
        if update || !reference_path.exists() {
            image.save(&reference_path).unwrap();
            continue;
        }
        let reference = image::open(&reference_path).unwrap().to_rgba8();
        if let Some(message) = compare(&image, &reference, case) {
            failures.push(message);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `--render` of a web page draws the island `--island` picks (the first by default):
/// both islands of corpus/html/x3dom.html against `corpus/render/html_island_N/
/// reference.png`.
#[test]
fn each_island_of_a_page_renders_like_its_reference() {
    if !x3dcheck::render::adapter_for_test("each_island_of_a_page_renders_like_its_reference") {
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let page = root.join("corpus/html/x3dom.html");
    let source = std::fs::read(&page).unwrap();
    let update = std::env::var_os("X3DCHECK_UPDATE_REFERENCES").is_some_and(|v| v == "1");
    let mut failures = Vec::new();
    for island in [1u32, 2] {
        let x3dcheck::check::Checked {
            mut report,
            document,
            ..
        } = x3dcheck::check::check_document(
            &page.display().to_string(),
            &source,
            &CheckConfig {
                render: true,
                island: island as usize,
                ..CheckConfig::default()
            },
        );
        let args = RenderArgs { island, ..args() };
        let image = render_image(&args, &page, None, &source, document.as_ref(), &mut report)
            .unwrap_or_else(|e| panic!("island {island}: {e}"));
        let case = root.join(format!("corpus/render/html_island_{island}"));
        let reference_path = case.join("reference.png");
        if update || !reference_path.exists() {
            std::fs::create_dir_all(&case).unwrap();
            image.save(&reference_path).unwrap();
            continue;
        }
        let reference = image::open(&reference_path).unwrap().to_rgba8();
        failures.extend(compare(&image, &reference, &case));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// None when the images match; else writes actual.png and diff.png and says how much differs.
fn compare(actual: &image::RgbaImage, reference: &image::RgbaImage, case: &Path) -> Option<String> {
    if actual.dimensions() != reference.dimensions() {
        actual.save(case.join("actual.png")).unwrap();
        return Some(format!(
            "{}: size {:?} ≠ {:?}",
            case.display(),
            actual.dimensions(),
            reference.dimensions()
        ));
    }
    let mut diff = image::RgbaImage::new(actual.width(), actual.height());
    let mut differing = 0usize;
    for (x, y, a) in actual.enumerate_pixels() {
        let r = reference.get_pixel(x, y);
        let worst = (0..4).map(|c| a[c].abs_diff(r[c])).max().unwrap_or(0);
        if worst > CHANNEL_TOLERANCE {
            differing += 1;
            diff.put_pixel(x, y, image::Rgba([255, 0, 0, 255]));
        } else {
            let grey = (u16::from(r[0]) + u16::from(r[1]) + u16::from(r[2])) / 6;
            diff.put_pixel(x, y, image::Rgba([grey as u8, grey as u8, grey as u8, 255]));
        }
    }
    let share = differing as f64 / (actual.width() * actual.height()) as f64;
    if share <= PIXEL_BUDGET {
        return None;
    }
    actual.save(case.join("actual.png")).unwrap();
    diff.save(case.join("diff.png")).unwrap();
    Some(format!(
        "{}: {differing} pixels ({:.1}%) differ; see actual.png and diff.png",
        case.display(),
        share * 100.0
    ))
}

#[test]
fn a_far_away_tiny_box_renders_like_a_big_one_at_the_origin() {
    if !x3dcheck::render::adapter_for_test(
        "a_far_away_tiny_box_renders_like_a_big_one_at_the_origin",
    ) {
        return;
    }
    // The Viewpoint and the box share a Transform placing both at x = 1,000,000; only
    // f64 composition and eye-relative placement keep the 0.0002 box intact. The
    // NavigationInfo brings the near plane (avatarSize / 2, 23.4.4) in front of it.
    let scene = |outer: &str, box_transform: &str| {
        format!(
            "<X3D profile='Interchange' version='4.0'><Scene>\
             <NavigationInfo avatarSize='0.0001'/><Transform translation='{outer}'>\
             <Viewpoint position='0 0 0'/>\
             <Transform {box_transform}><Shape><Appearance><Material diffuseColor='1 0.5 0'/></Appearance>\
             <Box size='1 1 1'/></Shape></Transform></Transform></Scene></X3D>"
        )
    };
    let render = |source: String| {
        let x3dcheck::check::Checked {
            mut report,
            document: doc,
            ..
        } = x3dcheck::check::check_document(
            "scene.x3d",
            source.as_bytes(),
            &CheckConfig::default(),
        );
        render_image(
            &args(),
            Path::new("scene.x3d"),
            None,
            source.as_bytes(),
            doc.as_ref(),
            &mut report,
        )
        .unwrap()
    };
    let tiny = "translation='0 0 -0.002' scale='0.0002 0.0002 0.0002'";
    let near = render(scene("0 0 0", tiny));
    let far = render(scene("1000000 0 0", tiny));
    let big = render(scene("0 0 0", "translation='0 0 -10'"));
    assert!(
        compare(&far, &near, Path::new("target")).is_none(),
        "far box differs from the near one"
    );
    assert!(
        compare(&near, &big, Path::new("target")).is_none(),
        "tiny box differs from the big one"
    );
}

#[test]
fn exponential_use_expansion_renders_quickly_with_a_note() {
    if !x3dcheck::render::adapter_for_test("exponential_use_expansion_renders_quickly_with_a_note")
    {
        return;
    }
    // 2^199 Group instances in 12 KB (as in tests/mutations.rs), then one Box.
    let mut scene =
        String::from("<X3D profile='Interchange' version='4.0'><Scene><Group DEF='L0'/>");
    for i in 1..200 {
        scene.push_str(&format!(
            "<Group DEF='L{i}'><Group USE='L{}'/><Group USE='L{}'/></Group>",
            i - 1,
            i - 1
        ));
    }
    scene.push_str("<Shape><Box/></Shape></Scene></X3D>");
    let (elapsed, report) = check_and_render("laughs.x3d", &scene);
    assert!(elapsed < HANG_GUARD, "took {elapsed:?}");
    assert!(
        report.diagnostics.iter().any(|d| d.message.starts_with(
            "renderer: the scene expands to more than 10^19 node instances; drawn up to the first"
        )),
        "{:#?}",
        report
            .diagnostics
            .iter()
            .map(|d| &d.message)
            .collect::<Vec<_>>()
    );
}

/// Checks and renders a generated scene at 160×120: the time both took and the report's
/// LIMIT_EXCEEDED messages.
fn render_generated(scene: &str) -> (std::time::Duration, Vec<String>) {
    let (elapsed, report) = check_and_render("scene.x3d", scene);
    let limits = report
        .diagnostics
        .iter()
        .filter(|d| d.code == "LIMIT_EXCEEDED")
        .map(|d| d.message.clone())
        .collect();
    (elapsed, limits)
}

/// Checks and renders `scene` as the command line does, with the time both took.
fn check_and_render(name: &str, scene: &str) -> (std::time::Duration, FileReport) {
    let started = std::time::Instant::now();
    let x3dcheck::check::Checked {
        mut report,
        document: doc,
        ..
    } = x3dcheck::check::check_document(name, scene.as_bytes(), &CheckConfig::default());
    render_image(
        &args(),
        Path::new(name),
        None,
        scene.as_bytes(),
        doc.as_ref(),
        &mut report,
    )
    .unwrap();
    (started.elapsed(), report)
}

#[test]
fn shapes_piled_on_one_place_stop_at_the_fill_budget() {
    if !x3dcheck::render::adapter_for_test("shapes_piled_on_one_place_stop_at_the_fill_budget") {
        return;
    }
    // 300,000 unit spheres (7.5 MB), all at the origin: each is a few hundred triangles,
    // but each is shaded wherever it covers the image; drawing them all took minutes.
    let mut scene = String::from("<X3D profile='Interchange' version='4.0'><Scene>");
    for _ in 0..300_000 {
        scene.push_str("<Shape><Sphere/></Shape>");
    }
    scene.push_str("</Scene></X3D>");
    let (elapsed, limits) = render_generated(&scene);
    assert!(elapsed < HANG_GUARD, "took {elapsed:?}");
    assert!(
        limits.iter().any(|m| m.contains(&format!(
            "shapes cover the image more than {RENDER_FILL_IMAGES} times over; drawn up to the first"
        ))),
        "{limits:#?}"
    );
}

#[test]
fn a_text_of_ten_million_characters_stops_at_the_character_budget() {
    if !x3dcheck::render::adapter_for_test(
        "a_text_of_ten_million_characters_stops_at_the_character_budget",
    ) {
        return;
    }
    // Ten million characters (spaces cost layout but no triangles), then a small Text
    // that is still drawn.
    let scene = format!(
        "<X3D profile='Immersive' version='4.0'><Scene>\
         <Shape><Text string='\"{}\"'/></Shape><Shape><Text string='\"drawn\"'/></Shape>\
         </Scene></X3D>",
        "a ".repeat(5_000_000)
    );
    let (elapsed, limits) = render_generated(&scene);
    assert!(elapsed < HANG_GUARD, "took {elapsed:?}");
    assert_eq!(
        limits,
        [format!(
            "renderer: Text of 10000000 characters is not drawn: a scene's Text is drawn up to \
             {MAX_RENDER_TEXT_CHARACTERS} characters"
        )]
    );
}

#[test]
fn nested_uses_of_one_shape_stop_within_seconds() {
    if !x3dcheck::render::adapter_for_test("nested_uses_of_one_shape_stop_within_seconds") {
        return;
    }
    // 60 nested DEFs each USEd twice (3.8 KB, 2^60 paths to one Box): the walk stops at
    // the shape budget, the fill budget at the boxes piled on one another.
    let mut scene = String::from(
        "<X3D profile='Interchange' version='4.0'><Scene><Group DEF='G0'><Shape><Box/></Shape></Group>",
    );
    for i in 1..=60 {
        scene.push_str(&format!(
            "<Group DEF='G{i}'><Group USE='G{}'/><Group USE='G{}'/></Group>",
            i - 1,
            i - 1
        ));
    }
    scene.push_str("</Scene></X3D>");
    stops_at_the_shape_budget_within_seconds(&scene);
}

/// Renders `scene` and checks that it stopped at the shape budget (within [`HANG_GUARD`]); the
/// LIMIT_EXCEEDED messages.
fn stops_at_the_shape_budget_within_seconds(scene: &str) -> Vec<String> {
    let (elapsed, limits) = render_generated(scene);
    assert!(elapsed < HANG_GUARD, "took {elapsed:?}");
    assert!(
        limits
            .iter()
            .any(|m| m.ends_with(&format!("drawn up to {MAX_RENDER_SHAPES} shape instances"))),
        "{limits:#?}"
    );
    limits
}

#[test]
fn many_small_shapes_stop_at_the_shape_budget_within_seconds() {
    if !x3dcheck::render::adapter_for_test(
        "many_small_shapes_stop_at_the_shape_budget_within_seconds",
    ) {
        return;
    }
    // A 256 × 256 grid of Boxes (2^16 shapes, nested USEs moved apart): each covers a
    // pixel or two, so only the shape budget bounds the per-shape cost.
    let mut scene = String::from(
        "<X3D profile='Interchange' version='4.0'><Scene><Group DEF='G0'><Shape><Box/></Shape></Group>",
    );
    for i in 1..=16u32 {
        let step = 3 << ((i - 1) / 2);
        let offset = if i % 2 == 1 {
            format!("{step} 0 0")
        } else {
            format!("0 {step} 0")
        };
        scene.push_str(&format!(
            "<Group DEF='G{i}'><Transform translation='{offset}'><Group USE='G{}'/></Transform>\
             <Group USE='G{}'/></Group>",
            i - 1,
            i - 1
        ));
    }
    scene.push_str("</Scene></X3D>");
    let limits = stops_at_the_shape_budget_within_seconds(&scene);
    assert!(
        !limits.iter().any(|m| m.contains("cover the image")),
        "{limits:#?}"
    );
}

#[test]
fn coordinate_double_far_from_the_origin_keeps_its_precision() {
    if !x3dcheck::render::adapter_for_test(
        "coordinate_double_far_from_the_origin_keeps_its_precision",
    ) {
        return;
    }
    // A 0.001-wide quad made of CoordinateDouble points at x = 10,000,000 (where f32 steps
    // by 1), seen from 0.002 away (a NavigationInfo bringing the near plane closer),
    // renders as the same quad at the origin.
    let scene = |x: f64| {
        let points: Vec<String> = [
            (-0.0005, -0.0005),
            (0.0005, -0.0005),
            (0.0005, 0.0005),
            (-0.0005, 0.0005),
        ]
        .iter()
        .map(|(dx, dy)| format!("{} {dy} 0", x + dx))
        .collect();
        format!(
            "<X3D profile='Full' version='4.0'><Scene><NavigationInfo avatarSize='0.0001'/>\
             <Viewpoint position='{x} 0 0.002'/>\
             <Shape><Appearance><Material diffuseColor='0.2 0.6 1'/></Appearance>\
             <IndexedFaceSet coordIndex='0 1 2 3 -1'><CoordinateDouble point='{}'/></IndexedFaceSet>\
             </Shape></Scene></X3D>",
            points.join(" ")
        )
    };
    let render = |source: String| {
        let x3dcheck::check::Checked {
            mut report,
            document: doc,
            ..
        } = x3dcheck::check::check_document(
            "scene.x3d",
            source.as_bytes(),
            &CheckConfig::default(),
        );
        render_image(
            &args(),
            Path::new("scene.x3d"),
            None,
            source.as_bytes(),
            doc.as_ref(),
            &mut report,
        )
        .unwrap()
    };
    let near = render(scene(0.0));
    let far = render(scene(10_000_000.0));
    // The quad fills the middle of the image.
    let centre = near.get_pixel(80, 60);
    assert!(centre[2] > 100, "the quad is drawn: {centre:?}");
    assert!(
        compare(&far, &near, Path::new("target")).is_none(),
        "the far quad differs from the near one"
    );
}

#[test]
fn one_open_device_draws_several_images_like_a_device_each() {
    if !x3dcheck::render::adapter_for_test(
        "one_open_device_draws_several_images_like_a_device_each",
    ) {
        return;
    }
    // Two different cases in turn on one device: nothing of the first may leak into the
    // second (pipelines, textures and targets are made per image).
    let gpu = Gpu::open().expect("an adapter");
    for name in ["material_textures", "phong_box_headlight"] {
        let case = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("corpus/render")
            .join(name);
        let (scene, source, mut report, doc) = checked_case(&case);
        let args = case_args(&case);
        let own_device =
            render_image(&args, &scene, None, &source, doc.as_ref(), &mut report).unwrap();
        let shared = preview(
            &args,
            args.quality.settings(),
            &scene,
            None,
            &source,
            doc.as_ref(),
            &mut report,
        )
        .and_then(|p| p.draw_on(&gpu))
        .unwrap();
        assert!(
            own_device == shared,
            "{name}: the shared device drew another image"
        );
    }
}

/// With no adapter (Vulkan alone, and no Vulkan driver, as on a machine without Mesa), a
/// drawing test passes with one line saying what to install; under
/// `X3DCHECK_REQUIRE_GPU=1` it fails. Runs this test binary again on one test.
#[test]
fn no_adapter_skips_loudly_or_fails() {
    let run = |require: bool| {
        let mut command = std::process::Command::new(std::env::current_exe().unwrap());
        command
            .args(["--exact", "render_cases_match_their_references"])
            .env("WGPU_BACKEND", "vulkan")
            .env("VK_DRIVER_FILES", "/nonexistent/icd.json")
            .env("VK_ICD_FILENAMES", "/nonexistent/icd.json")
            .env_remove("VK_ADD_DRIVER_FILES");
        if require {
            command.env(x3dcheck::render::REQUIRE_GPU, "1");
        } else {
            command.env_remove(x3dcheck::render::REQUIRE_GPU);
        }
        let output = command.output().unwrap();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        (output.status.success(), text)
    };
    let (passed, text) = run(false);
    assert!(passed, "{text}");
    assert!(text.contains("1 passed"), "{text}");
    let skip_lines: Vec<&str> = text.lines().filter(|l| l.starts_with("SKIPPED")).collect();
    assert_eq!(skip_lines.len(), 1, "{text}");
    assert!(
        skip_lines[0].contains("render_cases_match_their_references: no graphics adapter")
            && skip_lines[0].contains("apt-get install mesa-vulkan-drivers"),
        "{text}"
    );
    let (passed, text) = run(true);
    assert!(!passed, "{text}");
    assert!(
        text.contains("X3DCHECK_REQUIRE_GPU=1 requires one"),
        "{text}"
    );
}

/// The draw list of `scene` (no GPU needed) and the renderer's notes.
fn draw_list_of(scene: &str) -> (x3dcheck::render::draw_list::DrawList, Vec<String>) {
    let x3dcheck::check::Checked {
        mut report,
        document: doc,
        ..
    } = x3dcheck::check::check_document("scene.x3d", scene.as_bytes(), &CheckConfig::default());
    let list = preview(
        &args(),
        Quality::Balanced.settings(),
        Path::new("scene.x3d"),
        None,
        scene.as_bytes(),
        doc.as_ref(),
        &mut report,
    )
    .unwrap()
    .list()
    .clone();
    let notes = report
        .diagnostics
        .iter()
        .filter(|d| d.message.starts_with("renderer:"))
        .map(|d| d.message.clone())
        .collect();
    (list, notes)
}

/// An unlit square of `size` at `x` with emissive colour `rgb`.
fn square(x: f32, size: f32, rgb: &str) -> String {
    format!(
        "<Transform translation='{x} 0 0'><Shape><Appearance><Material diffuseColor='0 0 0' \
         emissiveColor='{rgb}'/></Appearance><Rectangle2D size='{size} {size}'/></Shape></Transform>"
    )
}

#[test]
fn layer_set_order_picks_reorders_and_repeats_layers() {
    // Layers 1, 2, 3 hold one square each (x = 1, 2, 3); the root scene one at x = 0.
    let layers: String = (1..=3)
        .map(|i| format!("<Layer>{}</Layer>", square(i as f32, 1.0, "1 1 1")))
        .collect();
    let scene = |order: &str| {
        format!(
            "<X3D profile='Full' version='4.0'><Scene><Viewpoint position='0 0 10'/>{}\
             <LayerSet {order}>{layers}</LayerSet></Scene></X3D>",
            square(0.0, 1.0, "1 0 0")
        )
    };
    // Each layer's square, told by where it lies relative to its own (framed) eye.
    let squares = |order: &str| {
        let (list, _) = draw_list_of(&scene(order));
        list.layers
            .iter()
            .map(|l| (l.meshes.len(), l.background.is_some()))
            .collect::<Vec<_>>()
    };
    // 35.4.2: 0 is the root scene; 9 and −1 name no layer; a repeated layer is drawn again.
    assert_eq!(
        squares("order='2 0 9 2 -1'"),
        vec![(1, false), (1, true), (1, false)]
    );
    // The default order [0]: only the root scene.
    assert_eq!(squares(""), vec![(1, true)]);
    // An empty order draws nothing.
    assert_eq!(squares("order=''"), vec![]);
    // Without a LayerSet the scene is one layer.
    let (list, _) = draw_list_of(&format!(
        "<X3D profile='Full' version='4.0'><Scene>{}</Scene></X3D>",
        square(0.0, 1.0, "1 0 0")
    ));
    assert_eq!(list.layers.len(), 1);
}

#[test]
fn each_layer_binds_its_own_viewpoint_navigation_and_lights() {
    let scene = "<X3D profile='Full' version='4.0'><Scene>\
        <Viewpoint position='0 0 10'/><PointLight location='0 5 0'/><Shape><Box/></Shape>\
        <LayerSet order='0 1'><Layer><NavigationInfo headlight='false'/>\
        <Viewpoint position='0 0 50'/><Shape><Box/></Shape></Layer></LayerSet>\
        </Scene></X3D>";
    let (list, _) = draw_list_of(scene);
    assert_eq!(list.layers.len(), 2);
    let depth = |layer: usize| {
        let positions = &list.layers[layer].meshes[0].positions;
        positions.iter().map(|p| p[2]).sum::<f32>() / positions.len() as f32
    };
    // Positions are relative to each layer's own eye.
    assert!((depth(0) + 10.0).abs() < 0.01, "{}", depth(0));
    assert!((depth(1) + 50.0).abs() < 0.01, "{}", depth(1));
    // Layer 0: its PointLight and the headlight; layer 1: neither (its NavigationInfo
    // turns the headlight off, and layer 0's light is not its own).
    assert_eq!(list.layers[0].lights.len(), 2);
    assert_eq!(list.layers[1].lights.len(), 0);
}

#[test]
fn viewports_confine_layers_and_cut_their_children() {
    use x3dcheck::render::draw_list::Viewport;
    let scene = "<X3D profile='Full' version='4.0'><Scene><LayerSet order='1'><Layer>\
        <Viewport containerField='viewport' clipBoundary='0.5 1 0 0.5'/>\
        <Viewport containerField='children' clipBoundary='0 0.5 0 1'><Shape><Box/></Shape></Viewport>\
        <Shape><Sphere/></Shape></Layer></LayerSet></Scene></X3D>";
    let (list, _) = draw_list_of(scene);
    let layer = &list.layers[0];
    assert_eq!(
        layer.viewport,
        Viewport {
            left: 0.5,
            right: 1.0,
            bottom: 0.0,
            top: 0.5
        }
    );
    // The Viewport node's rectangle is a part of the layer's.
    let cut: Vec<Option<Viewport>> = layer.meshes.iter().map(|m| m.scissor).collect();
    assert_eq!(
        cut,
        vec![
            Some(Viewport {
                left: 0.5,
                right: 0.75,
                bottom: 0.0,
                top: 0.5
            }),
            None
        ]
    );
}

#[test]
fn what_layering_and_layout_do_not_draw_is_noted() {
    let scene = "<X3D profile='Full' version='4.0'><Scene>\
        <Group><Layer containerField='children'><Shape><Box/></Shape></Layer></Group>\
        <LayoutGroup><Layout size='0.5'/><Shape><Box/></Shape></LayoutGroup>\
        <ScreenGroup><Shape><Box/></Shape></ScreenGroup>\
        <LayerSet order='0 1'><LayoutLayer><Viewpoint/></LayoutLayer></LayerSet>\
        <LayerSet/></Scene></X3D>";
    let (_, notes) = draw_list_of(scene);
    for expected in [
        "renderer: Layer is drawn only in LayerSet.layers (35.2.3)",
        "renderer: LayoutGroup outside a LayoutLayer: drawn as a Group, its Layout is not applied (36.2.1)",
        "renderer: ScreenGroup without a Viewpoint: sized in pixels as seen from the default \
         Viewpoint (0 0 10), not from the framing camera (36.4.5)",
        "renderer: only one LayerSet is allowed (35.2.2): this one is not drawn",
        "renderer: LayoutLayer: its Viewpoint is not used; the layer is drawn in its layout's 2D coordinates (36.2.1)",
    ] {
        assert!(notes.iter().any(|n| n == expected), "{expected}: {notes:#?}");
    }
}

#[test]
fn the_fill_budget_counts_every_layer() {
    // One layer, listed 40 times, whose square covers the whole image: 40 images' worth.
    let order = vec!["1"; 40].join(" ");
    let scene = format!(
        "<X3D profile='Full' version='4.0'><Scene><LayerSet order='{order}'><Layer>\
         <Viewpoint position='0 0 1'/>{}</Layer></LayerSet></Scene></X3D>",
        square(0.0, 100.0, "1 1 1")
    );
    let (list, notes) = draw_list_of(&scene);
    let drawn = list.layers.iter().filter(|l| !l.meshes.is_empty()).count();
    assert!(drawn <= RENDER_FILL_IMAGES as usize, "{drawn} layers drawn");
    assert!(
        notes.iter().any(|m| m.contains(&format!(
            "shapes cover the image more than {RENDER_FILL_IMAGES} times over"
        ))),
        "{notes:#?}"
    );
}
