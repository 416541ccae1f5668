//! VRML97's schema table against ISO/IEC 14772-1:1997 clause 6: every node, and every
//! field's type, access type, default and range, from the interfaces transcribed in
//! `tests/data/vrml97_interfaces.txt`.

use std::collections::BTreeSet;

use x3dcheck::schema::{schema, AccessType, Bound, FieldType, Version};

const INTERFACES: &str = include_str!("data/vrml97_interfaces.txt");

/// Ranges the table keeps as X3D's table has them (`docs/vrml97-vs-x3d.md`, "Left as X3D
/// has it"): 14772-1 prints the same as 19775-1 and the difference is the UOM's.
const NO_MIN_MAX: &[&str] = &[
    // "(0,∞) or -1,-1,-1" is no min/max range.
    "Anchor.bboxSize",
    "Billboard.bboxSize",
    "Collision.bboxSize",
    "Group.bboxSize",
    "Inline.bboxSize",
    "Transform.bboxSize",
];
/// π written to four or five digits (1.5708, 3.1416, 6.2832, 0.7854), and as exclusive
/// bounds for CylinderSensor's angles.
const PI_ROUNDED: &[&str] = &[
    "Background.groundAngle",
    "Background.skyAngle",
    "CylinderSensor.maxAngle",
    "CylinderSensor.minAngle",
    "Viewpoint.fieldOfView",
];

struct Line<'a> {
    subclause: &'a str,
    node: &'a str,
    kind: &'a str,
    ty: &'a str,
    name: &'a str,
    default: String,
    range: &'a str,
}

fn lines() -> Vec<Line<'static>> {
    INTERFACES
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (head, range) = l.split_once(" # ").unwrap_or((l, ""));
            let words: Vec<&str> = head.split_whitespace().collect();
            Line {
                subclause: words[0],
                node: words[1],
                kind: words[2],
                ty: words[3],
                name: words[4],
                default: words[5..].join(" "),
                range: range.trim(),
            }
        })
        .collect()
}

fn access(kind: &str) -> AccessType {
    match kind {
        "eventIn" => AccessType::InputOnly,
        "eventOut" => AccessType::OutputOnly,
        "field" => AccessType::InitializeOnly,
        "exposedField" => AccessType::InputOutput,
        _ => panic!("no such kind {kind}"),
    }
}

/// A default in either syntax as comparable words: brackets and commas dropped, TRUE and
/// FALSE in XML's case, an SFString's quotes dropped (the XML encoding has none).
fn words(default: &str, ty: FieldType) -> Vec<String> {
    let text = default.trim();
    let text = if ty == FieldType::SFString {
        text.trim_matches('"')
    } else {
        text
    };
    text.replace(['[', ']', ','], " ")
        .split_whitespace()
        .map(|w| match w {
            "TRUE" => "true".to_string(),
            "FALSE" => "false".to_string(),
            _ => w.to_string(),
        })
        .collect()
}

fn same_default(expected: &[String], actual: &[String], tolerance: f64) -> bool {
    expected.len() == actual.len()
        && expected
            .iter()
            .zip(actual)
            .all(|(e, a)| match (e.parse::<f64>(), a.parse::<f64>()) {
                (Ok(e), Ok(a)) => (e - a).abs() <= tolerance,
                _ => e == a,
            })
}

fn number(text: &str) -> f64 {
    use std::f64::consts::PI;
    match text {
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        "pi" => PI,
        "pi/2" => PI / 2.0,
        "2pi" => 2.0 * PI,
        "-2pi" => -2.0 * PI,
        _ => text.parse().unwrap_or_else(|_| panic!("bound {text}")),
    }
}

/// "[0,1]", "(0,inf)", "[-1,1],(-inf,inf)" (a rotation: the axis part is not a bound)
/// as (min, max); unbounded ends are None.
fn bounds(range: &str) -> (Option<Bound>, Option<Bound>) {
    if range.is_empty() {
        return (None, None);
    }
    let range = range.strip_prefix("[-1,1],").unwrap_or(range);
    let (lo, hi) = range[1..range.len() - 1].split_once(',').unwrap();
    let (lo, hi) = (number(lo), number(hi));
    let min = lo.is_finite().then(|| Bound {
        value: lo,
        inclusive: range.starts_with('['),
    });
    let max = hi.is_finite().then(|| Bound {
        value: hi,
        inclusive: range.ends_with(']'),
    });
    (min, max)
}

fn same_bound(expected: Option<Bound>, actual: Option<Bound>, rounded: bool) -> bool {
    match (expected, actual) {
        (None, None) => true,
        (Some(e), Some(a)) if rounded => (e.value - a.value).abs() < 1e-4,
        (Some(e), Some(a)) => e.value == a.value && e.inclusive == a.inclusive,
        _ => false,
    }
}

#[test]
fn every_field_is_as_14772_1_prints_it() {
    let vrml97 = schema(Version::Vrml97);
    let mut problems = Vec::new();
    let lines = lines();
    for line in &lines {
        let key = format!("{}.{}", line.node, line.name);
        let at = format!("14772-1 {} {key}", line.subclause);
        let Some(field) = vrml97.node(line.node).and_then(|n| n.field(line.name)) else {
            problems.push(format!("{at}: missing"));
            continue;
        };
        if field.ty.as_str() != line.ty {
            problems.push(format!("{at}: type {} not {}", field.ty, line.ty));
        }
        if field.access != access(line.kind) {
            problems.push(format!("{at}: access {:?} not {}", field.access, line.kind));
        }
        let rounded = PI_ROUNDED.contains(&key.as_str());
        if field.access.is_initializable() {
            let tolerance = if rounded { 1e-4 } else { 0.0 };
            let (expected, actual) = (
                words(&line.default, field.ty),
                words(field.default, field.ty),
            );
            if !same_default(&expected, &actual, tolerance) {
                problems.push(format!(
                    "{at}: default {:?} not {:?}",
                    field.default, line.default
                ));
            }
            let (min, max) = if NO_MIN_MAX.contains(&key.as_str()) {
                (None, None)
            } else {
                bounds(line.range)
            };
            if !same_bound(min, field.min, rounded) || !same_bound(max, field.max, rounded) {
                problems.push(format!(
                    "{at}: range {:?}..{:?} not {}",
                    field.min, field.max, line.range
                ));
            }
        }
    }
    // No field beyond those 14772-1 lists.
    for node in vrml97.nodes {
        for field in node.fields {
            if !lines
                .iter()
                .any(|l| l.node == node.name && l.name == field.name)
            {
                problems.push(format!("{}.{}: not in 14772-1", node.name, field.name));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_54_nodes_and_no_other() {
    let listed: BTreeSet<&str> = lines().iter().map(|l| l.node).collect();
    let table: BTreeSet<&str> = schema(Version::Vrml97)
        .nodes
        .iter()
        .map(|n| n.name)
        .collect();
    assert_eq!(listed.len(), 54);
    assert_eq!(listed, table);
}

#[test]
fn nodes_x3d_added_are_absent() {
    for name in [
        "TriangleSet",
        "IndexedTriangleSet",
        "LineSet",
        "ColorRGBA",
        "StaticGroup",
        "KeySensor",
        "StringSensor",
        "BooleanFilter",
        "MetadataString",
        "TextureBackground",
        "Arc2D",
        "FillProperties",
        "MultiTexture",
    ] {
        assert!(schema(Version::Vrml97).node(name).is_none(), "{name}");
        assert!(schema(Version::V3_0).node(name).is_some(), "{name}");
    }
}

#[test]
fn renamed_fields_have_their_vrml97_names() {
    let node = |name| schema(Version::Vrml97).node(name).unwrap();
    let collide = node("Collision").field("collide").unwrap();
    assert_eq!(
        (collide.ty, collide.access, collide.default),
        (FieldType::SFBool, AccessType::InputOutput, "true")
    );
    assert!(node("Collision").field("enabled").is_none());
    assert!(node("Collision").field("isActive").is_none());
    let level = node("LOD").field("level").unwrap();
    assert_eq!(
        (level.ty, level.access),
        (FieldType::MFNode, AccessType::InputOutput)
    );
    assert!(node("LOD").field("children").is_none());
    assert!(node("Switch").field("choice").is_some());
    assert!(node("Switch").field("children").is_none());
    // X3D 3.0 the other way round.
    let x3d = |name| schema(Version::V3_0).node(name).unwrap();
    assert!(x3d("Collision").field("enabled").is_some());
    assert!(x3d("Collision").field("collide").is_none());
}

#[test]
fn defaults_ranges_and_access_of_vrml97() {
    let field = |node, name| {
        schema(Version::Vrml97)
            .node(node)
            .and_then(|n| n.field(name))
            .unwrap()
    };
    let exclusive_zero = Some(Bound {
        value: 0.0,
        inclusive: false,
    });
    assert_eq!(field("SpotLight", "beamWidth").default, "1.570796");
    assert_eq!(field("SpotLight", "cutOffAngle").default, "0.785398");
    assert_eq!(field("NavigationInfo", "type").default, "\"WALK\" \"ANY\"");
    assert_eq!(field("ElevationGrid", "xDimension").default, "0");
    // X3D 3.0's table has no bound on Transform scale; VRML97 says (0,∞).
    assert_eq!(field("Transform", "scale").min, exclusive_zero);
    assert_eq!(field("LOD", "range").min, exclusive_zero);
    assert_eq!(field("TimeSensor", "cycleInterval").min, exclusive_zero);
    assert_eq!(field("Normal", "vector").max, None);
    assert_eq!(
        field("Material", "shininess").max.map(|b| b.value),
        Some(1.0)
    );
    assert_eq!(
        field("Viewpoint", "description").access,
        AccessType::InitializeOnly
    );
    assert_eq!(
        field("PointLight", "radius").access,
        AccessType::InputOutput
    );
    assert!(schema(Version::Vrml97)
        .nodes
        .iter()
        .all(|n| n.field("metadata").is_none()));
}

#[test]
fn vrml97_is_a_version_before_x3d_3_0() {
    assert_eq!(Version::ALL[0], Version::Vrml97);
    assert!(Version::Vrml97 < Version::V3_0 && !Version::Vrml97.is_4x());
    assert!(!Version::X3D.contains(&Version::Vrml97));
    // An X3D document's version attribute never names VRML97.
    assert_eq!(Version::parse("VRML97"), None);
    assert_eq!(Version::parse("3.0"), Some(Version::V3_0));
    assert_eq!(Version::Vrml97.name(), "VRML97");
    assert_eq!(Version::V3_3.name(), "X3D 3.3");
}
