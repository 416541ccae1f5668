//! VRML97 (ISO/IEC 14772-1:1997) as a difference from X3D 3.0.
//!
//! There is no UOM for VRML97. X3D 3.0 took over VRML97's nodes and most of their fields,
//! so the generator (`codegen/`, which includes this file by path) makes VRML97's table from
//! the X3D 3.0 table (after `overrides.rs`): it keeps the nodes of [`NODES`] and applies
//! [`DIFFERENCES`]. Each entry names the subclause of 14772-1 clause 6 ("Node reference")
//! whose interface gives VRML97's field and the clause of 19775-1 that defines the node
//! in X3D; the generator fails when an entry no longer matches the 3.0 table, as it does
//! for `overrides.rs`. `docs/vrml97-vs-x3d.md` is the same table for people, with what
//! was left as the X3D table has it and why; `tests/vrml97_schema.rs` compares the result
//! field by field with 14772-1's interfaces.
//!
//! Abstract X3D types (X3DNode, X3DTimeDependentNode, …) name every VRML97 node that
//! inherits them in X3D 3.0. Data only; run `cargo run -p x3dcheck-codegen` after a change.

use super::overrides::{Change, NewField};
use super::types::{AccessType, Bound, FieldType};

/// The 54 nodes of VRML97, with their subclause of 14772-1.
pub static NODES: &[(&str, &str)] = &[
    ("Anchor", "6.2"),
    ("Appearance", "6.3"),
    ("AudioClip", "6.4"),
    ("Background", "6.5"),
    ("Billboard", "6.6"),
    ("Box", "6.7"),
    ("Collision", "6.8"),
    ("Color", "6.9"),
    ("ColorInterpolator", "6.10"),
    ("Cone", "6.11"),
    ("Coordinate", "6.12"),
    ("CoordinateInterpolator", "6.13"),
    ("Cylinder", "6.14"),
    ("CylinderSensor", "6.15"),
    ("DirectionalLight", "6.16"),
    ("ElevationGrid", "6.17"),
    ("Extrusion", "6.18"),
    ("Fog", "6.19"),
    ("FontStyle", "6.20"),
    ("Group", "6.21"),
    ("ImageTexture", "6.22"),
    ("IndexedFaceSet", "6.23"),
    ("IndexedLineSet", "6.24"),
    ("Inline", "6.25"),
    ("LOD", "6.26"),
    ("Material", "6.27"),
    ("MovieTexture", "6.28"),
    ("NavigationInfo", "6.29"),
    ("Normal", "6.30"),
    ("NormalInterpolator", "6.31"),
    ("OrientationInterpolator", "6.32"),
    ("PixelTexture", "6.33"),
    ("PlaneSensor", "6.34"),
    ("PointLight", "6.35"),
    ("PointSet", "6.36"),
    ("PositionInterpolator", "6.37"),
    ("ProximitySensor", "6.38"),
    ("ScalarInterpolator", "6.39"),
    ("Script", "6.40"),
    ("Shape", "6.41"),
    ("Sound", "6.42"),
    ("Sphere", "6.43"),
    ("SphereSensor", "6.44"),
    ("SpotLight", "6.45"),
    ("Switch", "6.46"),
    ("Text", "6.47"),
    ("TextureCoordinate", "6.48"),
    ("TextureTransform", "6.49"),
    ("TimeSensor", "6.50"),
    ("TouchSensor", "6.51"),
    ("Transform", "6.52"),
    ("Viewpoint", "6.53"),
    ("VisibilitySensor", "6.54"),
    ("WorldInfo", "6.55"),
];

/// Where VRML97's field differs from X3D 3.0's.
pub struct Difference {
    /// A VRML97 node, or an X3D abstract type: every VRML97 node inheriting it in X3D 3.0.
    pub node: &'static str,
    pub field: &'static str,
    pub change: Change,
    /// The subclause of 14772-1 with VRML97's interface ("6" for every node).
    pub vrml97: &'static str,
    /// The clause of 19775-1 (X3D 3.0) that defines the node or abstract type.
    pub x3d: &'static str,
}

const fn diff(
    node: &'static str,
    field: &'static str,
    change: Change,
    vrml97: &'static str,
    x3d: &'static str,
) -> Difference {
    Difference {
        node,
        field,
        change,
        vrml97,
        x3d,
    }
}

const fn exclusive(value: f64) -> Option<Bound> {
    Some(Bound {
        value,
        inclusive: false,
    })
}

/// An exposedField of VRML97 that X3D renamed (Collision.collide, LOD.level, Switch.choice).
const fn exposed(
    ty: FieldType,
    default: &'static str,
    acceptable: &'static [&'static str],
) -> Change {
    Change::Add(NewField {
        ty,
        access: AccessType::InputOutput,
        default,
        min: None,
        max: None,
        enumeration: &[],
        enumeration_strict: false,
        acceptable,
    })
}

use AccessType::{InitializeOnly, InputOutput};
use Change::{Access, Default, Max, Min, Remove};

// One row per difference, as a table: rustfmt would spread each over five lines.
#[rustfmt::skip]
pub static DIFFERENCES: &[Difference] = &[
    // ---- fields X3D added to every node or to an abstract type ----
    diff("X3DNode", "metadata", Remove, "6", "7 (X3DNode)"),
    diff("X3DTimeDependentNode", "pauseTime", Remove, "6.4, 6.28, 6.50", "8 (X3DTimeDependentNode)"),
    diff("X3DTimeDependentNode", "resumeTime", Remove, "6.4, 6.28, 6.50", "8 (X3DTimeDependentNode)"),
    diff("X3DTimeDependentNode", "elapsedTime", Remove, "6.4, 6.28, 6.50", "8 (X3DTimeDependentNode)"),
    diff("X3DTimeDependentNode", "isPaused", Remove, "6.4, 6.28, 6.50", "8 (X3DTimeDependentNode)"),
    diff("X3DPointingDeviceSensorNode", "description", Remove, "6.15, 6.34, 6.44, 6.51", "20 (X3DPointingDeviceSensorNode)"),
    // ---- fields X3D renamed ----
    diff("Collision", "enabled", Remove, "6.8", "23 (Collision)"),
    diff("Collision", "collide", exposed(FieldType::SFBool, "true", &[]), "6.8", "23 (Collision)"),
    diff("LOD", "children", Remove, "6.26", "23 (LOD)"),
    diff("LOD", "level", exposed(FieldType::MFNode, "", &["X3DChildNode"]), "6.26", "23 (LOD)"),
    diff("Switch", "children", Remove, "6.46", "10 (Switch)"),
    diff("Switch", "choice", exposed(FieldType::MFNode, "", &["X3DChildNode"]), "6.46", "10 (Switch)"),
    // ---- fields X3D added to one node ----
    diff("Appearance", "fillProperties", Remove, "6.3", "12 (Appearance)"),
    diff("Appearance", "lineProperties", Remove, "6.3", "12 (Appearance)"),
    diff("Background", "bindTime", Remove, "6.5", "24 (Background)"),
    diff("Background", "transparency", Remove, "6.5", "24 (Background)"),
    diff("Box", "solid", Remove, "6.7", "13 (Box)"),
    diff("Collision", "isActive", Remove, "6.8", "23 (Collision)"),
    diff("Cone", "solid", Remove, "6.11", "13 (Cone)"),
    diff("Cylinder", "solid", Remove, "6.14", "13 (Cylinder)"),
    diff("CylinderSensor", "axisRotation", Remove, "6.15", "20 (CylinderSensor)"),
    diff("CylinderSensor", "isOver", Remove, "6.15", "20 (CylinderSensor)"),
    diff("Fog", "bindTime", Remove, "6.19", "24 (Fog)"),
    diff("Inline", "load", Remove, "6.25", "9 (Inline)"),
    diff("LOD", "addChildren", Remove, "6.26", "23 (LOD)"),
    diff("LOD", "removeChildren", Remove, "6.26", "23 (LOD)"),
    diff("LOD", "bboxCenter", Remove, "6.26", "23 (LOD)"),
    diff("LOD", "bboxSize", Remove, "6.26", "23 (LOD)"),
    diff("MovieTexture", "description", Remove, "6.28", "18 (MovieTexture)"),
    diff("MovieTexture", "pitch", Remove, "6.28", "18 (MovieTexture)"),
    diff("NavigationInfo", "bindTime", Remove, "6.29", "23 (NavigationInfo)"),
    diff("NavigationInfo", "transitionType", Remove, "6.29", "23 (NavigationInfo)"),
    diff("NavigationInfo", "transitionTime", Remove, "6.29", "23 (NavigationInfo)"),
    diff("NavigationInfo", "transitionComplete", Remove, "6.29", "23 (NavigationInfo)"),
    diff("PlaneSensor", "axisRotation", Remove, "6.34", "20 (PlaneSensor)"),
    diff("PlaneSensor", "isOver", Remove, "6.34", "20 (PlaneSensor)"),
    diff("ProximitySensor", "centerOfRotation_changed", Remove, "6.38", "22 (ProximitySensor)"),
    // The XML encoding's <field> children, listed as a field in the 3.0 UOM; VRML97
    // declares a Script's fields in its interface (6.40), which readers keep as declarations.
    diff("Script", "field", Remove, "6.40", "29 (Script)"),
    diff("Shape", "bboxCenter", Remove, "6.41", "12 (Shape)"),
    diff("Shape", "bboxSize", Remove, "6.41", "12 (Shape)"),
    diff("Sphere", "solid", Remove, "6.43", "13 (Sphere)"),
    diff("SphereSensor", "isOver", Remove, "6.44", "20 (SphereSensor)"),
    diff("Switch", "addChildren", Remove, "6.46", "10 (Switch)"),
    diff("Switch", "removeChildren", Remove, "6.46", "10 (Switch)"),
    diff("Switch", "bboxCenter", Remove, "6.46", "10 (Switch)"),
    diff("Switch", "bboxSize", Remove, "6.46", "10 (Switch)"),
    diff("Text", "solid", Remove, "6.47", "15 (Text)"),
    diff("Viewpoint", "centerOfRotation", Remove, "6.53", "23 (Viewpoint)"),
    // ---- access types: `field` is initializeOnly, `exposedField` inputOutput ----
    diff("Cone", "bottom", Access(InitializeOnly), "6.11", "13 (Cone)"),
    diff("Cylinder", "bottom", Access(InitializeOnly), "6.14", "13 (Cylinder)"),
    diff("Cylinder", "top", Access(InitializeOnly), "6.14", "13 (Cylinder)"),
    diff("Extrusion", "scale", Access(InitializeOnly), "6.18", "13 (Extrusion)"),
    diff("FontStyle", "family", Access(InitializeOnly), "6.20", "15 (FontStyle)"),
    diff("PointLight", "radius", Access(InputOutput), "6.35", "17 (PointLight)"),
    diff("ProximitySensor", "size", Access(InputOutput), "6.38", "22 (ProximitySensor)"),
    diff("SpotLight", "radius", Access(InputOutput), "6.45", "17 (SpotLight)"),
    diff("Viewpoint", "orientation", Access(InputOutput), "6.53", "23 (Viewpoint)"),
    diff("Viewpoint", "description", Access(InitializeOnly), "6.53", "23 (Viewpoint)"),
    diff("VisibilitySensor", "size", Access(InputOutput), "6.54", "22 (VisibilitySensor)"),
    diff("WorldInfo", "info", Access(InitializeOnly), "6.55", "7 (WorldInfo)"),
    diff("WorldInfo", "title", Access(InitializeOnly), "6.55", "7 (WorldInfo)"),
    // ---- defaults ----
    diff("CylinderSensor", "diskAngle", Default("0.262"), "6.15", "20 (CylinderSensor)"),
    diff("ElevationGrid", "height", Default(""), "6.17", "13 (ElevationGrid)"),
    diff("ElevationGrid", "xDimension", Default("0"), "6.17", "13 (ElevationGrid)"),
    diff("ElevationGrid", "zDimension", Default("0"), "6.17", "13 (ElevationGrid)"),
    diff("NavigationInfo", "type", Default("\"WALK\" \"ANY\""), "6.29", "23 (NavigationInfo)"),
    diff("SpotLight", "beamWidth", Default("1.570796"), "6.45", "17 (SpotLight)"),
    diff("SpotLight", "cutOffAngle", Default("0.785398"), "6.45", "17 (SpotLight)"),
    // ---- ranges ----
    diff("Box", "size", Min(exclusive(0.0)), "6.7", "13 (Box)"),
    diff("CylinderSensor", "diskAngle", Min(exclusive(0.0)), "6.15", "20 (CylinderSensor)"),
    diff("CylinderSensor", "diskAngle", Max(exclusive(std::f64::consts::FRAC_PI_2)), "6.15", "20 (CylinderSensor)"),
    diff("Extrusion", "scale", Min(exclusive(0.0)), "6.18", "13 (Extrusion)"),
    diff("LOD", "range", Min(exclusive(0.0)), "6.26", "23 (LOD)"),
    diff("Normal", "vector", Min(None), "6.30", "11 (Normal)"),
    diff("Normal", "vector", Max(None), "6.30", "11 (Normal)"),
    diff("TimeSensor", "cycleInterval", Min(exclusive(0.0)), "6.50", "8 (TimeSensor)"),
    diff("Transform", "scale", Min(exclusive(0.0)), "6.52", "10 (Transform)"),
];
