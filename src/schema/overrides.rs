//! Corrections to the X3D Unified Object Model, from the specification clauses in
//! `../shared/spec` (they win where the two differ on meaning; see `../shared/spec/README.md`).
//!
//! Membership is not meaning: a node or field is in a version when that version's
//! published UOM or XML Schema has it (`../shared/oracle/README.md`). The texts in
//! `../shared/spec` are drafts (the 4.0 one predates Appearance.alphaMode), so no entry
//! here removes a field, or adds one, on the ground of a draft text alone.
//!
//! Data only: the generator (`codegen/`, which includes this file by path) applies every
//! entry to the tables it reads from the UOM before it writes `generated.rs`, and fails when
//! an entry names a node, type, field or component that the UOM of one of its versions does
//! not have, so an entry cannot silently stop applying. `docs/spec-vs-uom.md` lists every
//! difference found between the clauses' interface tables and the UOM and what became of it.
//!
//! Which clause speaks for which version: `000_` (Shape) is 4.0, `001_` (Shape) is 4.1, and
//! `002_` (Rendering), `003_` (Lighting) and `004_` (Texturing) are 4.0 (`004_` predates
//! 4.1's RenderedTexture). Entries from them name 4.0 only, although the 4.1 UOM repeats
//! most of the 4.0 entries they correct: nothing here speaks for 4.1 there. Exceptions:
//! `003_` shows the 3.x value of light `intensity` next to the 4.x one (those entries change
//! nothing today; they pin the values), and the SpotLight angle bound π/2 is the same in
//! every version (the UOMs all round it down).
//!
//! Not compiled into the checker (nothing there needs it); run `cargo run -p
//! x3dcheck-codegen` after every change here.

use super::types::{AccessType, Bound, ComponentLevel, FieldType, Version};

/// A correction to one field, for the listed versions.
pub struct FieldOverride {
    pub versions: &'static [Version],
    /// A concrete node, or an abstract type: then the entry applies to every concrete node
    /// that inherits it (and has the field, for changes to an existing field).
    pub node: &'static str,
    pub field: &'static str,
    pub change: Change,
    /// The clause (and table) of ISO/IEC 19775-1 the correction comes from.
    pub clause: &'static str,
    pub why: &'static str,
}

pub enum Change {
    /// The node types an SFNode/MFNode field accepts (the `[X3D…Node]` of the table).
    Acceptable(&'static [&'static str]),
    /// The lower bound; None for unbounded.
    Min(Option<Bound>),
    /// The upper bound; None for unbounded.
    Max(Option<Bound>),
    /// The default, in XML encoding syntax.
    Default(&'static str),
    /// The component level the field needs above its node's; None for just the node's.
    Component(Option<ComponentLevel>),
    /// The access type (VRML97's field/exposedField/eventIn/eventOut where X3D differs).
    Access(AccessType),
    /// The field's enumerated values are the only ones allowed (the clause's table is a
    /// closed list) although the UOM marks them as suggestions.
    Strict,
    /// Values the clause gives a meaning to besides the UOM's enumeration (an empty string
    /// the XML Schema's pattern cannot spell, for one), in the UOM's notation: an MFString
    /// value as its quoted strings (`"\"\""` for one empty string).
    AlsoValid(&'static [&'static str]),
    /// The field does not exist in these versions although the UOM lists it.
    Remove,
    /// The field exists in these versions although the UOM does not list it.
    Add(NewField),
}

/// A field the UOM lacks, as the clause's interface table gives it.
pub struct NewField {
    pub ty: FieldType,
    pub access: AccessType,
    pub default: &'static str,
    pub min: Option<Bound>,
    pub max: Option<Bound>,
    pub enumeration: &'static [&'static str],
    pub enumeration_strict: bool,
    pub acceptable: &'static [&'static str],
}

/// The highest level of a component, where the support-level table has a level that no
/// node needs (a level that only makes fields or behaviour mandatory), so the UOM's
/// `componentInfo` entries do not reach it.
pub struct ComponentOverride {
    pub versions: &'static [Version],
    pub component: &'static str,
    pub max_level: u8,
    pub clause: &'static str,
    pub why: &'static str,
}

/// A correction to the component level a concrete node needs (the support-level tables).
pub struct NodeOverride {
    pub versions: &'static [Version],
    pub node: &'static str,
    pub component: ComponentLevel,
    pub clause: &'static str,
    pub why: &'static str,
}

const V3: &[Version] = &[Version::V3_0, Version::V3_1, Version::V3_2, Version::V3_3];
const V4: &[Version] = &[Version::V4_0, Version::V4_1];
const V4_0: &[Version] = &[Version::V4_0];
const V4_1: &[Version] = &[Version::V4_1];
const ALL: &[Version] = &Version::X3D;
const V3_2_ON: &[Version] = &[Version::V3_2, Version::V3_3, Version::V4_0, Version::V4_1];
const V4_1_AND_3_X: &[Version] = &[Version::V3_2, Version::V3_3, Version::V4_1];
const V3_1_TO_3_3: &[Version] = &[Version::V3_1, Version::V3_2, Version::V3_3];

const fn incl(value: f64) -> Option<Bound> {
    Some(Bound {
        value,
        inclusive: true,
    })
}

const fn excl(value: f64) -> Option<Bound> {
    Some(Bound {
        value,
        inclusive: false,
    })
}

const fn level(component: &'static str, level: u8) -> ComponentLevel {
    ComponentLevel { component, level }
}

pub static FIELD_OVERRIDES: &[FieldOverride] = &[
    // ---- 12 Shape ----
    FieldOverride {
        versions: V4,
        node: "Appearance",
        field: "backMaterial",
        change: Change::Acceptable(&["X3DOneSidedMaterialNode"]),
        clause: "12.4.2",
        why: "backMaterial takes Material, PhysicalMaterial or UnlitMaterial, never a TwoSidedMaterial; the UOM says X3DMaterialNode",
    },
    FieldOverride {
        versions: V4_1,
        node: "PointProperties",
        field: "markerType",
        change: Change::Add(NewField {
            ty: FieldType::SFInt32,
            access: AccessType::InputOutput,
            default: "1",
            min: incl(0.0),
            max: None,
            enumeration: &[],
            enumeration_strict: false,
            acceptable: &[],
        }),
        clause: "12.4.7",
        why: "in the 4.1 table (001_); the 4.1 UOM lacks it and the 4.1 XML Schema has it commented out (\"Mantis 1393 … deferred to X3D4.1\"), so kept for 4.1 as the reading that gives no false FIELD_UNKNOWN, and MARKER_TYPE_UNSUPPORTED (RULES.md) needs it",
    },
    FieldOverride {
        versions: V4,
        node: "PointProperties",
        field: "attenuation",
        change: Change::Min(incl(0.0)),
        clause: "12.4.7",
        why: "the table gives [0,∞) (\"attenuation values shall be greater than or equal to zero\"); the UOM leaves it unbounded",
    },
    FieldOverride {
        versions: V4,
        node: "LineProperties",
        field: "linetype",
        change: Change::Min(incl(1.0)),
        clause: "12.4.4",
        why: "the table gives [1,∞) (linetypes are numbered from 1); the UOM says [0,∞)",
    },
    FieldOverride {
        versions: V4_0,
        node: "Appearance",
        field: "pointProperties",
        change: Change::Component(Some(level("Shape", 4))),
        clause: "12.5 (Table 12.4)",
        why: "PointProperties is a Shape level 4 node in 4.0; the UOM says 5",
    },
    FieldOverride {
        versions: V4_1,
        node: "Appearance",
        field: "pointProperties",
        change: Change::Component(Some(level("Shape", 3))),
        clause: "12.5 (Table 12.4)",
        why: "PointProperties is a Shape level 3 node in 4.1; the UOM says 5",
    },
    FieldOverride {
        versions: V4_1,
        node: "Appearance",
        field: "acousticProperties",
        change: Change::Component(Some(level("Shape", 4))),
        clause: "12.5 (Table 12.4)",
        why: "AcousticProperties is a Shape level 4 node in 4.1; the UOM says 5",
    },
    FieldOverride {
        versions: V4,
        node: "Material",
        field: "transparency",
        change: Change::Component(None),
        clause: "12.5 (Table 12.4)",
        why: "level 1 supports every Material field but the ones it lists as optional, and transparency is not among them; the UOM says Shape 2",
    },
    FieldOverride {
        versions: V3,
        node: "FillProperties",
        field: "hatchStyle",
        change: Change::Min(incl(0.0)),
        clause: "12.4.3",
        why: "the 3.x tables give [0,∞), as the 4.x tables and UOMs do; the 3.x UOMs leave it unbounded",
    },
    // ---- 11 Rendering ----
    FieldOverride {
        versions: V4_0,
        node: "Normal",
        field: "vector",
        change: Change::Min(None),
        clause: "11.4 (Normal)",
        why: "the table gives (-∞,∞); unit length is checked by NORMAL_NOT_UNIT with a tolerance, not as a range; the UOM says [-1,1]",
    },
    FieldOverride {
        versions: V4_0,
        node: "Normal",
        field: "vector",
        change: Change::Max(None),
        clause: "11.4 (Normal)",
        why: "the table gives (-∞,∞); the UOM says [-1,1]",
    },
    FieldOverride {
        versions: V3,
        node: "X3DLightNode",
        field: "intensity",
        change: Change::Max(incl(1.0)),
        clause: "17.2.1",
        why: "3.x: light intensity ranges from 0.0 to 1.0 (003_ shows [0,1] for 3.x)",
    },
    FieldOverride {
        versions: V4,
        node: "DirectionalLight",
        field: "intensity",
        change: Change::Max(None),
        clause: "17.2.1",
        why: "4.x: light intensity ranges from 0.0 to infinity (003_ shows [0,∞] for 4.x)",
    },
    FieldOverride {
        versions: V4,
        node: "PointLight",
        field: "intensity",
        change: Change::Max(None),
        clause: "17.2.1",
        why: "4.x: light intensity ranges from 0.0 to infinity (003_ shows [0,∞] for 4.x)",
    },
    FieldOverride {
        versions: V4,
        node: "SpotLight",
        field: "intensity",
        change: Change::Max(None),
        clause: "17.2.1",
        why: "4.x: light intensity ranges from 0.0 to infinity (003_ shows [0,∞] for 4.x)",
    },
    FieldOverride {
        versions: V4_1,
        node: "EnvironmentLight",
        field: "intensity",
        change: Change::Max(None),
        clause: "17.2.1",
        why: "4.x: light intensity ranges from 0.0 to infinity, for every light source",
    },
    FieldOverride {
        versions: ALL,
        node: "SpotLight",
        field: "beamWidth",
        change: Change::Max(incl(std::f64::consts::FRAC_PI_2)),
        clause: "17.4.4",
        why: "(0,π/2]: the UOM's 1.570796 is below π/2, so π/2 written in full (1.570796327) would fail in f32",
    },
    FieldOverride {
        versions: ALL,
        node: "SpotLight",
        field: "cutOffAngle",
        change: Change::Max(incl(std::f64::consts::FRAC_PI_2)),
        clause: "17.4.4",
        why: "(0,π/2]: the UOM's 1.570796 is below π/2, so π/2 written in full (1.570796327) would fail in f32",
    },
    // Defaults the tables print as multiples of π and the UOMs as shortened decimals: the
    // generator writes the float nearest to the multiple (`Change::Default("π/4")`), so a
    // rule that compares with a default compares with what the spec means.
    FieldOverride {
        versions: ALL,
        node: "SpotLight",
        field: "beamWidth",
        change: Change::Default("π/4"),
        clause: "17.4.4",
        why: "the table gives π/4; the 3.x UOMs say 0.7854, the 4.x UOMs 0.589049 (3π/16)",
    },
    FieldOverride {
        versions: ALL,
        node: "SpotLight",
        field: "cutOffAngle",
        change: Change::Default("π/2"),
        clause: "17.4.4",
        why: "the table gives π/2; the UOMs say 1.570796, another f32",
    },
    // ---- 18 Texturing ----
    FieldOverride {
        versions: V4_0,
        node: "TextureProperties",
        field: "borderWidth",
        change: Change::Max(incl(1.0)),
        clause: "18.4.9",
        why: "the table gives [0,1]; the UOM says [0,∞)",
    },
    FieldOverride {
        versions: V4_1_AND_3_X,
        node: "TextureProperties",
        field: "borderWidth",
        change: Change::Max(incl(1.0)),
        clause: "18.4.9",
        why: "the table of every version with TextureProperties (3.2 on) gives [0,1], as 4.0's (004_) does; the UOMs say [0,∞)",
    },
    FieldOverride {
        versions: ALL,
        node: "MultiTexture",
        field: "mode",
        change: Change::Strict,
        clause: "18.4.3 Table 18.3",
        why: "the table lists the valid values of mode; the UOM has the same values but marks them as suggestions",
    },
    FieldOverride {
        versions: ALL,
        node: "MultiTexture",
        field: "source",
        change: Change::Strict,
        clause: "18.4.3 Table 18.4",
        why: "the table lists the valid values of source; the UOM has the same values but marks them as suggestions",
    },
    FieldOverride {
        versions: ALL,
        node: "MultiTexture",
        field: "function",
        change: Change::Strict,
        clause: "18.4.3 Table 18.5",
        why: "the table lists the valid values of function; the UOM has the same values but marks them as suggestions",
    },
    // ---- 13 Geometry3D, 25 Geospatial: grid defaults ----
    // The 3.x UOMs give a 2 × 2 grid of zero heights as the default, which no table of
    // 19775-1 (nor VRML97 6.18) does; the 4.x UOMs have the tables' values.
    FieldOverride {
        versions: V3,
        node: "ElevationGrid",
        field: "height",
        change: Change::Default(""),
        clause: "13.3.4 ElevationGrid",
        why: "the table gives [] (VRML97 6.18 too); the 3.x UOMs say 0 0 0 0, so an unwritten height counted as 4 values",
    },
    FieldOverride {
        versions: V3,
        node: "ElevationGrid",
        field: "xDimension",
        change: Change::Default("0"),
        clause: "13.3.4 ElevationGrid",
        why: "the table gives 0 [0,∞) (VRML97 6.18 too); the 3.x UOMs say 2",
    },
    FieldOverride {
        versions: V3,
        node: "ElevationGrid",
        field: "zDimension",
        change: Change::Default("0"),
        clause: "13.3.4 ElevationGrid",
        why: "the table gives 0 [0,∞) (VRML97 6.18 too); the 3.x UOMs say 2",
    },
    FieldOverride {
        versions: V3,
        node: "GeoElevationGrid",
        field: "height",
        change: Change::Default("0 0"),
        clause: "25.4.5 GeoElevationGrid",
        why: "the table gives [0 0], as the 4.x UOMs do; the 3.x UOMs say 0 0 0 0",
    },
    FieldOverride {
        versions: V3,
        node: "GeoElevationGrid",
        field: "xDimension",
        change: Change::Default("0"),
        clause: "25.4.5 GeoElevationGrid",
        why: "the table gives 0, as the 4.x UOMs do; the 3.x UOMs say 2",
    },
    FieldOverride {
        versions: V3,
        node: "GeoElevationGrid",
        field: "zDimension",
        change: Change::Default("0"),
        clause: "25.4.5 GeoElevationGrid",
        why: "the table gives 0, as the 4.x UOMs do; the 3.x UOMs say 2",
    },
    // ---- Ranges of vector fields (each component; the UOMs give none, or not in every version) ----
    FieldOverride {
        versions: ALL,
        node: "Box",
        field: "size",
        change: Change::Min(excl(0.0)),
        clause: "13.3.1 Box",
        why: "the table gives (0,∞): \"each component value shall be greater than zero\" (VRML97 6.7 too); the UOMs give no range",
    },
    FieldOverride {
        versions: ALL,
        node: "Extrusion",
        field: "scale",
        change: Change::Min(excl(0.0)),
        clause: "13.3.5 Extrusion",
        why: "the table gives (0,∞) for each scale value (VRML97 6.18 too); the UOMs give no range",
    },
    FieldOverride {
        versions: V4,
        node: "Rectangle2D",
        field: "size",
        change: Change::Min(excl(0.0)),
        clause: "14.4.8 Rectangle2D",
        why: "the table gives (0,∞), as the 3.x UOMs do; the 4.x UOMs give no range",
    },
    FieldOverride {
        versions: V3_1_TO_3_3,
        node: "CADPart",
        field: "scale",
        change: Change::Min(excl(0.0)),
        clause: "32.4.4 CADPart",
        why: "the 3.x table gives `scale 1 1 1 (0,∞)`, as for HAnimJoint and GeoTransform (3.2–3.3 UOMs); the UOMs give no range. Not 4.x: the 4.x table was not read, and a copy of the 4.x CADPart prose says scale values may be positive, negative or zero, as Transform's does",
    },
    // ---- 15 Text ----
    FieldOverride {
        versions: ALL,
        node: "X3DFontStyleNode",
        field: "style",
        change: Change::AlsoValid(&[""]),
        clause: "15.2.2.2",
        why: "an empty style value is identical to \"PLAIN\" (as in VRML97 6.20); the UOM's list, like the XML Schema's, lacks it",
    },
    FieldOverride {
        versions: ALL,
        node: "X3DFontStyleNode",
        field: "justify",
        change: Change::AlsoValid(&["\"\""]),
        clause: "15.2.2.3",
        why: "justify values of \"\", \"BEGIN\" and \"BEGIN\" \"FIRST\" are equivalent (as in VRML97 6.20); the UOM's list lacks the empty string",
    },
    // ---- 8 Time ----
    FieldOverride {
        versions: ALL,
        node: "TimeSensor",
        field: "cycleInterval",
        change: Change::Min(excl(0.0)),
        clause: "8.4.1 TimeSensor",
        why: "the table gives (0,∞), as VRML97 6.50 does (a cycle of no length has no fraction); the 3.1–4.1 UOMs say [0,∞)",
    },
    // ---- Defaults printed as multiples of π in other clauses ----
    FieldOverride {
        versions: ALL,
        node: "Viewpoint",
        field: "fieldOfView",
        change: Change::Default("π/4"),
        clause: "23.4 Viewpoint",
        why: "the table gives π/4; the UOMs say 0.7854, another f32",
    },
    FieldOverride {
        versions: ALL,
        node: "GeoViewpoint",
        field: "fieldOfView",
        change: Change::Default("π/4"),
        clause: "25.4 GeoViewpoint",
        why: "the table gives π/4; the UOMs say 0.7854, another f32",
    },
    FieldOverride {
        versions: V4,
        node: "TextureProjector",
        field: "fieldOfView",
        change: Change::Default("π/4"),
        clause: "42.4 TextureProjector",
        why: "the table gives π/4; the UOMs say 0.7854, another f32",
    },
    FieldOverride {
        versions: ALL,
        node: "Arc2D",
        field: "endAngle",
        change: Change::Default("π/2"),
        clause: "14.4 Arc2D",
        why: "the table gives π/2; the UOMs say 1.570796, another f32",
    },
    FieldOverride {
        versions: ALL,
        node: "ArcClose2D",
        field: "endAngle",
        change: Change::Default("π/2"),
        clause: "14.4 ArcClose2D",
        why: "the table gives π/2; the UOMs say 1.570796, another f32",
    },
    FieldOverride {
        versions: ALL,
        node: "CylinderSensor",
        field: "diskAngle",
        change: Change::Default("π/12"),
        clause: "20.4 CylinderSensor",
        why: "the table gives π/12; the UOMs say 0.26179167, another f32",
    },
    FieldOverride {
        versions: V3_2_ON,
        node: "ConeEmitter",
        field: "angle",
        change: Change::Default("π/4"),
        clause: "40.4 ConeEmitter",
        why: "the table gives π/4; the UOMs say 0.7854, another f32",
    },
    FieldOverride {
        versions: V3_2_ON,
        node: "SingleAxisHingeJoint",
        field: "maxAngle",
        change: Change::Default("π"),
        clause: "37.4 SingleAxisHingeJoint",
        why: "the table gives π; the UOMs say 3.141592653 (the same f32, written exactly)",
    },
    FieldOverride {
        versions: V3_2_ON,
        node: "DoubleAxisHingeJoint",
        field: "maxAngle1",
        change: Change::Default("π"),
        clause: "37.4 DoubleAxisHingeJoint",
        why: "the table gives π; the UOMs say 3.141592653 (the same f32, written exactly)",
    },
    // ---- 26 Humanoid animation ----
    FieldOverride {
        versions: V4,
        node: "HAnimJoint",
        field: "children",
        change: Change::Acceptable(&["HAnimJoint", "HAnimSegment", "HAnimSite"]),
        clause: "26.3.3 HAnimJoint (HAnim 2.0, ISO/IEC 19774-1:2019)",
        why: "the 4.1 XML Schema documents HAnimJoint's content model as [HAnimJoint,HAnimSegment,HAnimSite] children although its element list, like the UOM, omits HAnimSite",
    },
];

pub static NODE_OVERRIDES: &[NodeOverride] = &[
    NodeOverride {
        versions: V4_0,
        node: "PointProperties",
        component: level("Shape", 4),
        clause: "12.5 (Table 12.4)",
        why: "Shape level 4 in 4.0; the UOM says 5",
    },
    NodeOverride {
        versions: V4_1,
        node: "PointProperties",
        component: level("Shape", 3),
        clause: "12.5 (Table 12.4)",
        why: "Shape level 3 in 4.1 (support levels regrouped); the UOM says 5",
    },
    NodeOverride {
        versions: V4_1,
        node: "TwoSidedMaterial",
        component: level("Shape", 3),
        clause: "12.5 (Table 12.4)",
        why: "Shape level 3 in 4.1 (support levels regrouped); the UOM says 4",
    },
    NodeOverride {
        versions: V4_1,
        node: "AcousticProperties",
        component: level("Shape", 4),
        clause: "12.5 (Table 12.4)",
        why: "Shape level 4 in 4.1 (support levels regrouped); the UOM says 5",
    },
    NodeOverride {
        versions: V4_0,
        node: "MultiTexture",
        component: level("Texturing", 3),
        clause: "18.5 (Table 18.11)",
        why: "Texturing level 3 in 4.0; the UOM says 2",
    },
    NodeOverride {
        versions: V4_0,
        node: "MovieTexture",
        component: level("Texturing", 4),
        clause: "18.5 (Table 18.11)",
        why: "Texturing level 4 in 4.0; the UOM says 3",
    },
];

pub static COMPONENT_OVERRIDES: &[ComponentOverride] = &[
    ComponentOverride {
        versions: V4_0,
        component: "Lighting",
        max_level: 4,
        clause: "17.6 (Table 17.6)",
        why: "level 4 (all fields and capabilities fully supported) adds no node",
    },
    ComponentOverride {
        versions: &[Version::V3_3, Version::V4_0, Version::V4_1],
        component: "VolumeRendering",
        max_level: 4,
        clause: "41.5; MedicalInterchange profile (Annex L, Table L.2)",
        why: "the MedicalInterchange profile includes VolumeRendering level 4, a level that adds no node",
    },
];
