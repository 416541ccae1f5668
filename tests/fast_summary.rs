//! The fast level keeps numeric MF values as summaries (`Value::Summary`) instead of their
//! numbers when the document is not rendered. Its report must not change: every real
//! scene's fast-level JSON report (diagnostics and stats) is the same with summaries as
//! with the values kept; hand-made scenes pin the non-finite and range findings at the
//! bounds and the stats of each geometry kind; `--render` at the fast level still draws.

mod common;

use std::path::Path;

use x3dcheck::check::{check_document, Checked};
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;
use x3dcheck::model::{Document, Value};
use x3dcheck::report::{FileReport, Stats};

/// The fast level as the CLI runs it without `--render`: values summarized.
fn fast() -> CheckConfig {
    CheckConfig {
        level: Level::Fast,
        ..CheckConfig::default()
    }
}

/// The fast level with every value kept (as for `--render`).
fn fast_kept() -> CheckConfig {
    CheckConfig {
        render: true,
        ..fast()
    }
}

const X3D_EXTENSIONS: &[&str] = &["x3d", "x3dj", "json"];

fn json(report: &FileReport) -> String {
    x3dcheck::report::json::render(std::slice::from_ref(report), None)
}

/// Numeric MF values of schema fields still kept whole, and summaries, in `doc`.
fn kept_and_summarized(doc: &Document) -> (usize, usize) {
    let (mut kept, mut summarized) = (0, 0);
    // The nodes as written: a prototype instance's copy holds the value the instance
    // passes through IS, a declared field's value, which is kept whole at every level.
    for node in doc.written_nodes() {
        for entry in &node.fields {
            let Some(def) = entry.schema_def() else {
                continue;
            };
            match &entry.value {
                Value::Summary(_) => summarized += 1,
                Value::Floats(_) | Value::Doubles(_) | Value::Int32s(_) if def.ty.is_mf() => {
                    kept += 1
                }
                _ => {}
            }
        }
    }
    (kept, summarized)
}

#[test]
fn every_scene_reports_the_same_at_fast_with_summaries() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = common::files_under(&root.join("corpus"), X3D_EXTENSIONS);
    files.extend(common::corpus_files(X3D_EXTENSIONS));
    assert!(files.len() > 1000, "only {} scenes", files.len());
    let (mut differing, mut summaries) = (Vec::new(), 0);
    for path in &files {
        let source = std::fs::read(path).unwrap();
        let name = path.display().to_string();
        let Checked {
            report: summarized,
            document: doc,
            ..
        } = check_document(&name, &source, &fast());
        let Checked {
            report: kept,
            document: kept_doc,
            ..
        } = check_document(&name, &source, &fast_kept());
        if json(&summarized) != json(&kept) {
            differing.push(name.clone());
        }
        if let (Some(doc), Some(kept_doc)) = (doc, kept_doc) {
            let (whole, summarized) = kept_and_summarized(&doc);
            assert_eq!(whole, 0, "{name}: numeric MF values kept at fast");
            assert_eq!(
                kept_and_summarized(&kept_doc).1,
                0,
                "{name}: summaries kept"
            );
            summaries += summarized;
        }
    }
    assert!(summaries > 10_000, "only {summaries} values summarized");
    assert!(
        differing.is_empty(),
        "{} of {} scenes report differently with summaries:\n{}",
        differing.len(),
        files.len(),
        differing.join("\n")
    );
}

/// (code, index, count, value) of each diagnostic.
fn findings(report: &FileReport) -> Vec<(String, Option<usize>, usize, Option<String>)> {
    report
        .diagnostics
        .iter()
        .map(|d| (d.code.to_string(), d.index, d.count, d.value.clone()))
        .collect()
}

fn finding(
    code: &str,
    index: usize,
    count: usize,
    value: &str,
) -> (String, Option<usize>, usize, Option<String>) {
    (
        code.to_string(),
        Some(index),
        count,
        Some(value.to_string()),
    )
}

/// Checks `source` at fast with summaries and with values kept; the reports must agree,
/// and the summaries must have been made. Returns the summarized report.
fn check_both(name: &str, source: &str) -> FileReport {
    let Checked {
        report,
        document: doc,
        ..
    } = check_document(name, source.as_bytes(), &fast());
    let Checked { report: kept, .. } = check_document(name, source.as_bytes(), &fast_kept());
    assert_eq!(json(&report), json(&kept), "{name}");
    let (whole, summarized) = kept_and_summarized(&doc.expect("a document"));
    assert_eq!(whole, 0);
    assert!(summarized > 0);
    report
}

const HEAD: &str =
    "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Full' version='4.0'><Scene>";
const TAIL: &str = "</Scene></X3D>\n";

#[test]
fn nonfinite_and_out_of_range_first_and_count_at_the_bounds() {
    let body = "<Shape><IndexedFaceSet coordIndex='0 1 2 -1'>\
        <Coordinate point='0 0 0 NaN 1 INF 2 1e39 3'/>\
        <Color color='0 0 0 1.0000001 0 0 NaN 0 1 -1e-45 0 -0 1 1 1'/>\
        </IndexedFaceSet></Shape>\
        <Shape><NurbsCurve order='2' weight='1 0 -0 5e-324 1e309 2'>\
        <Coordinate point='0 0 0 1 1 1 2 2 2 3 3 3 4 4 4 5 5 5'/></NurbsCurve></Shape>\
        <Shape><LineSet vertexCount='2 1 3 -2147483648 2'><Coordinate point='0 0 0'/></LineSet></Shape>";
    let report = check_both("bounds.x3d", &format!("{HEAD}{body}{TAIL}"));
    let mut found = findings(&report);
    found.retain(|f| f.0 == "FIELD_VALUE_NONFINITE" || f.0 == "FIELD_OUT_OF_RANGE");
    assert_eq!(
        found,
        vec![
            // point: NaN, INF and 1e39 (+∞ in f32); no range.
            finding("FIELD_VALUE_NONFINITE", 3, 3, "NaN"),
            // color [0,1]: one ulp above 1 (f32), NaN, the negative denormal; -0 is in.
            finding("FIELD_OUT_OF_RANGE", 1, 3, "1.0000001"),
            finding("FIELD_VALUE_NONFINITE", 6, 1, "NaN"),
            // weight (0,∞) in f64: 0 and -0 are out, the smallest denormal in, +∞ in.
            finding("FIELD_OUT_OF_RANGE", 1, 2, "0"),
            finding("FIELD_VALUE_NONFINITE", 4, 1, "1e309"),
            // vertexCount [2,∞): 1 and the smallest int32.
            finding("FIELD_OUT_OF_RANGE", 1, 2, "1"),
        ]
    );
}

#[test]
fn the_same_findings_from_json() {
    let source = r#"{"X3D": {"@profile": "Full", "@version": "4.0", "Scene": {"-children": [
        {"Shape": {"-geometry": {"IndexedTriangleSet": {"@index": [0, 1, 2, 0, 2, 3, 9],
            "-coord": {"Coordinate": {"@point": [0, 0, 0, 1, 0, 0, 1e39, 1, 0, 0, 1, 0]}},
            "-color": {"ColorRGBA": {"@color": [0, 0, 0, 1, 1.0000001, 0, 0, 1, -0.0, 0, 0, 2]}}}}}}
    ]}}}"#;
    let report = check_both("bounds.x3dj", source);
    let mut found = findings(&report);
    found.retain(|f| f.0 == "FIELD_VALUE_NONFINITE" || f.0 == "FIELD_OUT_OF_RANGE");
    assert_eq!(
        found,
        vec![
            finding("FIELD_VALUE_NONFINITE", 6, 1, "1e39"),
            finding("FIELD_OUT_OF_RANGE", 1, 2, "1.0000001"),
        ]
    );
    // The index field is INDEX_NEGATIVE's (standard), never FIELD_OUT_OF_RANGE's.
    assert_eq!(report.stats.triangles, 2);
}

#[test]
fn stats_of_every_geometry_kind_from_summaries() {
    let body = "\
        <Shape><IndexedFaceSet coordIndex='0 1 2 3 -1 0 1 2 -1 5 6 -1 -1 1 2 3 4 5'><Coordinate point='0 0 0'/></IndexedFaceSet></Shape>\
        <Shape><IndexedTriangleSet index='0 1 2 3 4 5 6'><Coordinate point='0 0 0'/></IndexedTriangleSet></Shape>\
        <Shape><TriangleSet><Coordinate point='0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0'/></TriangleSet></Shape>\
        <Shape><IndexedTriangleStripSet index='0 1 2 3 -1 4 5'><Coordinate point='0 0 0'/></IndexedTriangleStripSet></Shape>\
        <Shape><IndexedTriangleFanSet index='0 1 2 3 4 -1'><Coordinate point='0 0 0'/></IndexedTriangleFanSet></Shape>\
        <Shape><TriangleStripSet stripCount='4 3'><Coordinate point='0 0 0'/></TriangleStripSet></Shape>\
        <Shape><TriangleFanSet fanCount='3 5 -1 2'><Coordinate point='0 0 0'/></TriangleFanSet></Shape>\
        <Shape><ElevationGrid xDimension='3' zDimension='4' height='0 0 0 0 0 0 0 0 0 0 0 0'/></Shape>\
        <Shape><IndexedLineSet coordIndex='0 1 2 -1 3 4 -1 5'><Coordinate point='0 0 0'/></IndexedLineSet></Shape>\
        <Shape><LineSet vertexCount='2 3 -4'><Coordinate point='0 0 0'/></LineSet></Shape>\
        <Shape><PointSet><CoordinateDouble point='0 0 0 0 0 0 0 0 0 0 0 0'/></PointSet></Shape>\
        <Shape><PointSet><Coordinate point='0 0 0 1 1 1'/></PointSet></Shape>";
    let report = check_both("stats.x3d", &format!("{HEAD}{body}{TAIL}"));
    let Stats {
        triangles,
        lines,
        points,
        ..
    } = report.stats;
    // IFS 2+1+0+3; ITS 2; TS 3; ITSS 2; ITFS 3; TSS 2+1; TFS 1+3; EG 12.
    assert_eq!(triangles, 6 + 2 + 3 + 2 + 3 + 3 + 4 + 12);
    // ILS 2+1+0; LS 1+2.
    assert_eq!(lines, 3 + 3);
    assert_eq!(points, 4 + 2);
}

#[cfg(feature = "render")]
#[test]
fn render_at_fast_keeps_the_values_and_draws_what_standard_draws() {
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/render/ifs_concave_face_colors");
    let scene = case.join("scene.x3d");
    let source = std::fs::read(&scene).unwrap();
    let name = scene.display().to_string();
    let draw = |config: &CheckConfig| {
        let Checked {
            mut report,
            document: doc,
            ..
        } = check_document(&name, &source, config);
        let args = x3dcheck::render::RenderArgs {
            render: Some(std::env::temp_dir().join("never-written.png")),
            size: x3dcheck::render::ImageSize {
                width: 160,
                height: 120,
            },
            quality: x3dcheck::render::Quality::Balanced,
            camera: "auto".to_string(),
            island: 1,
        };
        let preview =
            x3dcheck::render::prepare(&args, &scene, None, &source, doc.as_ref(), &mut report)
                .unwrap()
                .unwrap();
        (
            preview.list().meshes().count(),
            format!("{:?}", preview.list()),
        )
    };
    let standard = draw(&CheckConfig::default());
    assert!(standard.0 > 0, "the case draws meshes");
    assert_eq!(draw(&fast_kept()), standard);
    // Without `render`, the fast level's summaries leave nothing to draw: this is what
    // `render: true` is for.
    assert_ne!(draw(&fast()), standard);
}

#[cfg(feature = "render")]
#[test]
fn cli_render_at_fast_draws_the_standard_image() {
    if !x3dcheck::render::adapter_for_test("cli_render_at_fast_draws_the_standard_image") {
        return;
    }
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/render/ifs_concave_face_colors");
    let dir = common::scratch("fast-render", &[]);
    let scene = case.join("scene.x3d");
    let image = |level: &str| {
        let out = dir.join(format!("{level}.png"));
        let output = common::x3dcheck(
            &dir,
            &[
                scene.to_str().unwrap(),
                "--level",
                level,
                "--render",
                out.to_str().unwrap(),
                "--size",
                "160x120",
            ],
        );
        assert!(
            output.status.code() == Some(0) || output.status.code() == Some(1),
            "{level}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        image::open(&out).unwrap().to_rgba8()
    };
    let fast = image("fast");
    let standard = image("standard");
    assert_eq!(fast.dimensions(), standard.dimensions());
    let background = *standard.get_pixel(0, 0);
    assert!(
        standard.pixels().any(|p| *p != background),
        "the standard image shows the geometry"
    );
    assert!(
        fast == standard,
        "the fast-level render differs from the standard one"
    );
}
