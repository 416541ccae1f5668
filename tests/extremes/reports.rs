//! No NaN or infinity leaks into a report. Scenes whose every numeric field (taken from
//! the schema, for a set of node types that drive the geometry, lighting, bounds and
//! texture rules) holds numbers at the extremes are checked at the deep level, folded and
//! not, and rendered by every emitter: JSON and SARIF parse, JUnit is well-formed XML, no
//! output spells a non-finite number (`NaN`, `inf`, `Infinity`), and every number in a
//! message is short or written so in the document.
//!
//! The extremes are written as finite text (`1e39` overflows an SFFloat to ∞, `1e-400`
//! underflows to 0), which both encodings accept, so that any `NaN` or `inf` in the output
//! is one the checker made. With `NaN` and `INF` written in the document (XML only), only
//! the rules about the value itself may quote them.

use proptest::prelude::*;
use quick_xml::events::Event;
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::{Level, Severity};
use x3dcheck::report::{concise, github, human, json, junit, sarif, FileReport};
use x3dcheck::schema::{schema, Scalar, Version};
use x3dcheck::validate::RULES;

use crate::support::{check_with, document, has_non_finite_word, El, Encoding, ENCODINGS};

const FLOATS: &[&str] = &[
    "0",
    "-0",
    "1",
    "-1",
    "0.5",
    "2",
    "1.0000001",
    "0.99999994",
    "3.4028235e38",
    "-3.4028235e38",
    "3.4028236e38",
    "1e39",
    "-1e39",
    "1e400",
    "-1e400",
    "1e-400",
    "1e-45",
    "-1e-45",
    "1.1754942e-38",
    "1.7976931348623157e308",
    "-4.9e-324",
    "123456789012345678901234567890",
];

const INTS: &[&str] = &[
    "0",
    "1",
    "2",
    "3",
    "-1",
    "-2",
    "4",
    "2147483647",
    "-2147483648",
    "2147483648",
];

/// Tokens for each numeric field of `node` (in `version`), drawn by `pick` from `floats`
/// and INTS.
fn filled(
    node: &'static str,
    version: Version,
    floats: &[&str],
    pick: &mut impl FnMut(usize) -> usize,
) -> El {
    let def = schema(version)
        .node(node)
        .unwrap_or_else(|| panic!("{node}"));
    let mut el = El::new(node);
    for field in def.fields {
        let pool = match field.ty.scalar() {
            Scalar::Float | Scalar::Double => floats,
            Scalar::Int32 => INTS,
            _ => continue,
        };
        if !field.access.is_initializable() || pick(4) == 0 {
            continue;
        }
        let elements = if field.ty.is_mf() { pick(7) } else { 1 };
        let tokens: Vec<&str> = (0..elements * field.ty.arity())
            .map(|_| pool[pick(pool.len())])
            .collect();
        el = el.field(field.name, tokens);
    }
    el
}

/// A scene of Transforms, a Group, Shapes with polygonal, line, grid and primitive
/// geometry, materials (PhysicalMaterial and PointProperties in 4.x), a texture transform,
/// a PixelTexture and the three lights, each with every numeric field filled from
/// `choices`.
fn scene(version: Version, floats: &[&str], choices: &[usize]) -> El {
    let mut at = 0;
    let mut pick = |n: usize| {
        let c = choices[at % choices.len()] % n;
        at += 1;
        c
    };
    let mut f = |node: &'static str| filled(node, version, floats, &mut pick);
    let coord = f("Coordinate");
    let appearance = f("Appearance")
        .child("material", f("Material"))
        .child("textureTransform", f("TextureTransform"))
        .child("lineProperties", f("LineProperties"));
    let (physical, points) = if version.is_4x() {
        (
            f("Appearance").child("material", f("PhysicalMaterial")),
            f("Appearance").child("pointProperties", f("PointProperties")),
        )
    } else {
        (appearance.clone(), appearance.clone())
    };
    let textured = f("Appearance").child("texture", f("PixelTexture"));
    let geometries = [
        (
            &appearance,
            f("IndexedFaceSet")
                .child("coord", coord.clone())
                .child("normal", f("Normal"))
                .child("color", f("Color"))
                .child("texCoord", f("TextureCoordinate")),
        ),
        (
            &appearance,
            f("IndexedTriangleSet")
                .child("coord", coord.clone())
                .child("normal", f("Normal")),
        ),
        (
            &appearance,
            f("TriangleStripSet").child("coord", coord.clone()),
        ),
        (&appearance, f("ElevationGrid")),
        (&points, f("LineSet").child("coord", coord)),
        (&physical, f("Box")),
        (&physical, f("Sphere")),
        (&appearance, f("Cone")),
        (&appearance, f("Cylinder")),
    ];
    let mut group = f("Group");
    for (appearance, geometry) in geometries {
        group = group.child(
            "children",
            f("Shape")
                .child("appearance", appearance.clone())
                .child("geometry", geometry),
        );
    }
    for light in ["PointLight", "SpotLight", "DirectionalLight"] {
        group = group.child("children", f(light));
    }
    let boxed = f("Shape")
        .child("appearance", textured)
        .child("geometry", f("Box"));
    f("Transform")
        .child("children", group)
        .child("children", f("Transform").child("children", boxed))
}

fn configs() -> [CheckConfig; 2] {
    let deep = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let unfolded = CheckConfig {
        fold: false,
        ..deep.clone()
    };
    [deep, unfolded]
}

/// Every emitter's output for one report.
fn outputs(report: &FileReport, source: &str) -> Vec<(&'static str, String)> {
    let reports = std::slice::from_ref(report);
    vec![
        ("json", json::render(reports, None)),
        ("sarif", sarif::render(reports, &RULES)),
        ("human", human::render(report, source.as_bytes(), false)),
        ("concise", concise::render(report)),
        ("github", github::render(report)),
        ("junit", junit::render(reports, &[Severity::Error])),
    ]
}

/// Numbers in a message longer than this must be the document's own text.
const LONG_NUMBER: usize = 24;

fn long_numbers<'m>(message: &'m str, source: &str) -> Vec<&'m str> {
    message
        .split(|c: char| c.is_whitespace() || ",;:()[]{}'\"`=".contains(c))
        .map(|w| w.trim_end_matches('.'))
        .filter(|w| w.len() > LONG_NUMBER && w.parse::<f64>().is_ok() && !source.contains(w))
        .collect()
}

fn check_outputs(report: &FileReport, source: &str, quoting: &[&str]) -> Result<(), TestCaseError> {
    for (format, mut output) in outputs(report, source) {
        match format {
            "json" | "sarif" => {
                let parsed: Result<serde_json::Value, _> = serde_json::from_str(&output);
                prop_assert!(
                    parsed.is_ok(),
                    "{} does not parse: {:?}",
                    format,
                    parsed.err()
                );
                if format == "sarif" {
                    // The rules' documentation there speaks of NaN; the results must not.
                    output = parsed.unwrap()["runs"][0]["results"].to_string();
                }
            }
            "junit" => {
                let mut reader = quick_xml::Reader::from_str(&output);
                loop {
                    match reader.read_event() {
                        Ok(Event::Eof) => break,
                        Ok(_) => {}
                        Err(e) => prop_assert!(false, "junit: {}", e),
                    }
                }
            }
            _ => {}
        }
        if quoting.is_empty() {
            prop_assert!(!has_non_finite_word(&output), "{}:\n{}", format, output);
        }
    }
    for d in &report.diagnostics {
        if !quoting.contains(&d.code) {
            prop_assert!(
                !has_non_finite_word(&d.message),
                "{}: {}",
                d.code,
                d.message
            );
            if let Some(help) = &d.help {
                prop_assert!(!has_non_finite_word(help), "{}: {}", d.code, help);
            }
        }
        let long = long_numbers(&d.message, source);
        prop_assert!(long.is_empty(), "{}: {} ({:?})", d.code, d.message, long);
    }
    Ok(())
}

proptest! {
    // Rendering SARIF (with every rule's documentation) costs most: few cases suffice, each
    // scene has a hundred or so findings.
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn reports_of_extreme_scenes_hold_no_nan(
        choices in prop::collection::vec(any::<usize>(), 64..256),
        version in prop::sample::select(&[Version::V3_3, Version::V4_0, Version::V4_1][..]),
    ) {
        let scene = scene(version, FLOATS, &choices);
        for encoding in ENCODINGS {
            let source = document(encoding, version, std::slice::from_ref(&scene));
            for config in configs() {
                let report = check_with(&source, &config);
                check_outputs(&report, &source, &[])?;
            }
        }
    }

    /// `NaN` and `INF` written in an XML document: quoted by the rules about the value
    /// itself, never printed by any other.
    #[test]
    fn written_non_finite_values_are_only_quoted(
        choices in prop::collection::vec(any::<usize>(), 64..256),
    ) {
        let version = Version::V4_0;
        let floats = [FLOATS, &["NaN", "INF", "-INF", "nan", "-Infinity"]].concat();
        let source = document(Encoding::Xml, version, &[scene(version, &floats, &choices)]);
        for config in configs() {
            let report = check_with(&source, &config);
            check_outputs(&report, &source, &["FIELD_VALUE_NONFINITE", "FIELD_OUT_OF_RANGE"])?;
        }
    }
}
