//! One model, three encodings (issue 11 item 5): the scenes of `corpus/encodings/`, each
//! written by the project in XML (`.x3d`), JSON (`.x3dj`) and ClassicVRML (`.x3dv`), read
//! into the same model (compared through the canonical summary of tests/common/summary.rs)
//! and give the same report apart from positions: the same diagnostics (code, severity,
//! message, structural path, value) and the same stats. The scenes cover every field type,
//! DEF/USE, PROTO with IS, EXTERNPROTO, ROUTE, IMPORT/EXPORT and META/UNIT/COMPONENT.
//!
//! The real pair of `../shared/corpus` (Castle's Fox, the same scene exported as `.x3d`
//! and `.x3dv`) is compared the same way.

mod common;

use std::path::{Path, PathBuf};

use common::summary::{first_difference, Summary};
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;
use x3dcheck::model::Encoding;
use x3dcheck::report::FileReport;

fn scenes() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/encodings");
    let mut stems: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "x3d"))
        .map(|p| p.with_extension(""))
        .collect();
    stems.sort();
    stems
}

fn check(path: &Path) -> FileReport {
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let source = std::fs::read(path).unwrap();
    x3dcheck::check_source(&path.display().to_string(), &source, &config)
}

/// The codes whose messages name prototypes, IS and ROUTE in the encoding's own words
/// (`src/validate/terms.rs`): ClassicVRML says `PROTO`, `a IS b`, `ROUTE from field` where
/// XML and JSON say `ProtoDeclare`, `connect`, `fromField`.
const WORDED: &[&str] = &[
    "IS_FIELD_UNKNOWN",
    "IS_OUTSIDE_PROTO",
    "IS_TYPE_MISMATCH",
    "PROTO_CYCLE",
    "PROTO_FIELD_UNKNOWN",
    "ROUTE_FIELD_UNKNOWN",
];

/// The report without positions: one line per diagnostic, sorted, and the stats. Without
/// `words`, a diagnostic of a [`WORDED`] code is compared without its message.
fn positionless(report: &FileReport, words: bool) -> (Vec<String>, String) {
    let mut lines: Vec<String> = report
        .diagnostics
        .iter()
        .map(|d| {
            let worded = WORDED.contains(&d.code);
            let message = if words || !worded {
                d.message.as_str()
            } else {
                ""
            };
            format!(
                "{} {:?} {message} at {} value {:?} ×{}",
                d.code, d.severity, d.path, d.value, d.count
            )
        })
        .collect();
    lines.sort();
    (lines, format!("{:?}", report.stats))
}

/// The differences between two encodings of one scene: model, then report.
fn compare(name: &str, a: (&str, &Path), b: (&str, &Path)) -> Vec<String> {
    let mut problems = Vec::new();
    let read = |path: &Path| x3dcheck::parse::read(&std::fs::read(path).unwrap());
    let (pa, pb) = (read(a.1), read(b.1));
    let (Some(da), Some(db)) = (&pa.document, &pb.document) else {
        return vec![format!(
            "{name}: a side did not read ({}: {:?}, {}: {:?})",
            a.0,
            pa.diagnostics.first().map(|d| &d.message),
            b.0,
            pb.diagnostics.first().map(|d| &d.message)
        )];
    };
    if let Some(difference) = first_difference((a.0, &Summary::of(da)), (b.0, &Summary::of(db))) {
        problems.push(format!("{name}: the models differ\n{difference}"));
    }
    // XML and JSON share their words; ClassicVRML has its own.
    let words = a.0 != "classic" && b.0 != "classic";
    let (ra, rb) = (
        positionless(&check(a.1), words),
        positionless(&check(b.1), words),
    );
    if ra != rb {
        problems.push(format!(
            "{name}: the reports differ\n      {}: {:#?}\n      {}: {:#?}",
            a.0, ra, b.0, rb
        ));
    }
    problems
}

#[test]
fn the_project_scenes_give_one_model_in_three_encodings() {
    let stems = scenes();
    assert!(
        stems.len() >= 3,
        "corpus/encodings has {} scenes",
        stems.len()
    );
    let mut problems = Vec::new();
    for stem in &stems {
        let name = stem.file_name().unwrap().to_string_lossy().into_owned();
        let xml = stem.with_extension("x3d");
        let json = stem.with_extension("x3dj");
        let classic = stem.with_extension("x3dv");
        problems.extend(compare(&name, ("xml", &xml), ("json", &json)));
        problems.extend(compare(&name, ("xml", &xml), ("classic", &classic)));
        let parsed = x3dcheck::parse::read(&std::fs::read(&classic).unwrap());
        assert_eq!(parsed.encoding, Some(Encoding::ClassicVrml), "{name}");
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The scenes are clean in every encoding, so that the comparison above compares models
/// and not error recovery.
#[test]
fn the_project_scenes_have_no_reader_findings() {
    for stem in scenes() {
        for extension in ["x3d", "x3dj", "x3dv"] {
            let path = stem.with_extension(extension);
            let parsed = x3dcheck::parse::read(&std::fs::read(&path).unwrap());
            let codes: Vec<_> = parsed.diagnostics.iter().map(|d| d.rule.code).collect();
            assert!(codes.is_empty(), "{}: {codes:?}", path.display());
        }
    }
}

#[test]
fn the_real_pairs_give_one_model() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    let fox = "animation/gltf_skinned_animation/fox_from_khronos/Fox";
    let xml = root
        .join("castle-demo-models")
        .join(fox)
        .with_extension("x3d");
    let classic = root
        .join("castle-demo-models-classic")
        .join(fox)
        .with_extension("x3dv");
    let problems = compare("Fox", ("xml", &xml), ("classic", &classic));
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// FontStyle's `style` field (15.4.1) is a field in every encoding, where the XML and JSON
/// readers drop the HTML attribute `style` of other nodes (19776-1, -5).
#[test]
fn font_style_style_arrives_from_every_encoding() {
    let xml = br#"<X3D profile='Immersive' version='4.0'><Scene>
<Transform style='color: red'><Shape><Text string='"a"'>
<FontStyle style='BOLDITALIC'/></Text></Shape></Transform></Scene></X3D>"#;
    let json = br#"{"X3D": {"@profile": "Immersive", "@version": "4.0", "Scene": {"-children": [
{"Transform": {"@style": "color: red", "-children": [{"Shape": {"-geometry": {"Text": {
"@string": ["a"], "-fontStyle": {"FontStyle": {"@style": "BOLDITALIC"}}}}}}]}}]}}}"#;
    let classic = br#"#X3D V4.0 utf8
PROFILE Immersive
Transform { children Shape { geometry Text { string "a"
fontStyle FontStyle { style "BOLDITALIC" } } } }"#;
    for (name, source) in [
        ("XML", &xml[..]),
        ("JSON", &json[..]),
        ("ClassicVRML", &classic[..]),
    ] {
        let parsed = x3dcheck::parse::read(source);
        let doc = parsed
            .document
            .unwrap_or_else(|| panic!("{name} reads: {:?}", parsed.diagnostics));
        let font_style = doc.nodes_of_type("FontStyle").next().expect("a FontStyle");
        assert_eq!(
            doc.string_of(font_style, "style").as_deref(),
            Some("BOLDITALIC"),
            "{name}"
        );
        let transform = doc.nodes_of_type("Transform").next().expect("a Transform");
        assert!(doc.node(transform).entry("style").is_none(), "{name}");
        assert!(
            parsed.diagnostics.is_empty(),
            "{name}: {:?}",
            parsed.diagnostics
        );
    }
}
