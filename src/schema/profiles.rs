//! The X3D profiles: for each version, the components and levels a `profile` attribute
//! provides (ISO/IEC 19775-1 Annexes A–F, H and L: "Table x.2 — Components and levels").
//! The UOM does not give these in structured form, so they are written out here.
//!
//! Sources and checks (see the tests): the tables are those of the published profile
//! annexes, 3.2/3.3 and 4.0 (the 3.0 FDIS differs, see `INTERACTIVE`); every level named
//! exists in the generated component tables; and every node the UOM's `profileNameChoices`
//! text lists for a profile is allowed by the table, except for the few listed in the test
//! `uom_profile_node_lists_agree`, where the annex and the UOM's list disagree and the annex
//! is kept. Checked against the 1,306 scenes of `../shared/corpus`: 63 exceed their
//! profile and component statements, nearly all plainly (HAnim under Immersive, Inline or
//! Switch under Interchange, Box under CADInterchange, …); see `docs/spec-vs-uom.md`.

use super::types::{ComponentLevel, Version};

/// What a profile provides.
#[derive(Debug)]
pub enum Components {
    /// These components at these levels, sorted by component name.
    Listed(&'static [ComponentLevel]),
    /// Every component of the version at its highest level (the Full profile).
    All,
}

#[derive(Debug)]
pub struct Profile {
    /// As written in the `profile` attribute.
    pub name: &'static str,
    /// The versions this entry is for. A profile whose table changed between versions has
    /// one entry per table.
    pub versions: &'static [Version],
    pub components: Components,
    /// The annex of ISO/IEC 19775-1 that defines the profile.
    pub clause: &'static str,
}

impl Profile {
    /// The level of `component` the profile provides in `version`; 0 when it has none of it.
    pub fn level(&self, version: Version, component: &str) -> u8 {
        match self.components {
            Components::Listed(levels) => levels
                .binary_search_by(|c| c.component.cmp(component))
                .map_or(0, |i| levels[i].level),
            Components::All => super::schema(version)
                .component(component)
                .map_or(0, |c| c.max_level),
        }
    }

    /// Every component and level the profile provides in `version`, sorted by name.
    pub fn component_levels(&self, version: Version) -> Vec<ComponentLevel> {
        match self.components {
            Components::Listed(levels) => levels.to_vec(),
            Components::All => super::schema(version)
                .components
                .iter()
                .map(|c| ComponentLevel {
                    component: c.name,
                    level: c.max_level,
                })
                .collect(),
        }
    }
}

/// The profile `name` as `version` defines it; None for a name that version does not know
/// (CADInterchange before 3.1, MedicalInterchange before 3.3, any misspelling), and for
/// VRML97, which has no profiles.
pub fn profile(version: Version, name: &str) -> Option<&'static Profile> {
    PROFILES
        .iter()
        .find(|p| p.name == name && p.versions.contains(&version))
}

/// Every profile name of any version.
pub const PROFILE_NAMES: [&str; 8] = [
    "Core",
    "Interchange",
    "CADInterchange",
    "Interactive",
    "Immersive",
    "MedicalInterchange",
    "MPEG4Interactive",
    "Full",
];

const ALL: &[Version] = &Version::X3D;
const V3_1_TO_3_3: &[Version] = &[Version::V3_1, Version::V3_2, Version::V3_3];
const V4: &[Version] = &[Version::V4_0, Version::V4_1];
const V3_3_ON: &[Version] = &[Version::V3_3, Version::V4_0, Version::V4_1];

const fn c(component: &'static str, level: u8) -> ComponentLevel {
    ComponentLevel { component, level }
}

/// Table A.2, the same in every version.
const CORE: &[ComponentLevel] = &[c("Core", 1)];

/// Table B.2, the same in every version (3.0 FDIS, 3.3 and 4.0 pages agree).
const INTERCHANGE: &[ComponentLevel] = &[
    c("Core", 1),
    c("EnvironmentalEffects", 1),
    c("Geometry3D", 2),
    c("Grouping", 1),
    c("Interpolation", 2),
    c("Lighting", 1),
    c("Navigation", 1),
    c("Networking", 1),
    c("Rendering", 3),
    c("Shape", 1),
    c("Texturing", 2),
    c("Time", 1),
];

/// Table C.2 of 3.2, 3.3 and 4.0. The 3.0 FDIS text has Networking 1 and Rendering 2, which
/// would leave out Anchor and Inline (Networking 2, and named by the UOM's 3.0 list for this
/// profile) and IndexedTriangleSet and friends (Rendering 3, which Interchange has): that
/// reads as an error the later editions fixed, so 3.0 and 3.1 get the corrected table too.
/// KeyDeviceSensor 1 and EnvironmentalSensor 1 leave out StringSensor and VisibilitySensor,
/// which the UOM's list names: the annex is kept.
const INTERACTIVE: &[ComponentLevel] = &[
    c("Core", 1),
    c("EnvironmentalEffects", 1),
    c("EnvironmentalSensor", 1),
    c("EventUtilities", 1),
    c("Geometry3D", 3),
    c("Grouping", 2),
    c("Interpolation", 2),
    c("KeyDeviceSensor", 1),
    c("Lighting", 2),
    c("Navigation", 1),
    c("Networking", 2),
    c("PointingDeviceSensor", 1),
    c("Rendering", 3),
    c("Shape", 1),
    c("Texturing", 2),
    c("Time", 1),
];

/// Table D.2, the same in every version. Geometry3D 2 leaves out ElevationGrid
/// (Geometry3D 3), which the UOM's list names: the annex is kept (3.x and 4.0 drafts agree).
const MPEG4_INTERACTIVE: &[ComponentLevel] = &[
    c("Core", 1),
    c("EnvironmentalEffects", 1),
    c("EnvironmentalSensor", 1),
    c("Geometry3D", 2),
    c("Grouping", 2),
    c("Interpolation", 2),
    c("Lighting", 2),
    c("Navigation", 1),
    c("Networking", 2),
    c("PointingDeviceSensor", 1),
    c("Rendering", 1),
    c("Shape", 1),
    c("Texturing", 1),
    c("Time", 1),
];

/// Table E.2 of 3.3 and 4.0. The 3.0 FDIS says Sound 2, a level Sound did not have in 3.0
/// (the 3.0 UOM knows only Sound 1); Sound 1 throughout.
const IMMERSIVE: &[ComponentLevel] = &[
    c("Core", 2),
    c("EnvironmentalEffects", 2),
    c("EnvironmentalSensor", 2),
    c("EventUtilities", 1),
    c("Geometry2D", 1),
    c("Geometry3D", 4),
    c("Grouping", 2),
    c("Interpolation", 2),
    c("KeyDeviceSensor", 2),
    c("Lighting", 2),
    c("Navigation", 2),
    c("Networking", 3),
    c("PointingDeviceSensor", 1),
    c("Rendering", 3),
    c("Scripting", 1),
    c("Shape", 2),
    c("Sound", 1),
    c("Text", 1),
    c("Texturing", 3),
    c("Time", 1),
];

/// Table H.2 of 3.x: Networking 1, so Anchor and Inline (Networking 2, named by the UOM's
/// list) are left out until 4.0 raises it to 2. No Geometry3D: CAD scenes use
/// IndexedQuadSet, QuadSet and the Rendering triangle sets.
const CAD_INTERCHANGE_3: &[ComponentLevel] = &[
    c("CADGeometry", 2),
    c("Core", 1),
    c("Grouping", 1),
    c("Lighting", 1),
    c("Navigation", 2),
    c("Networking", 1),
    c("Rendering", 4),
    c("Shaders", 1),
    c("Shape", 2),
    c("Texturing", 2),
];

/// Table H.2 of 4.x: as in 3.x with Networking 2.
const CAD_INTERCHANGE_4: &[ComponentLevel] = &[
    c("CADGeometry", 2),
    c("Core", 1),
    c("Grouping", 1),
    c("Lighting", 1),
    c("Navigation", 2),
    c("Networking", 2),
    c("Rendering", 4),
    c("Shaders", 1),
    c("Shape", 2),
    c("Texturing", 2),
];

/// Table L.2 (new in 3.3; the same in 4.x). The 3.3 UOM's list also names CoordinateDouble,
/// which 3.3 puts in NURBS 1, a component this table lacks (4.0 moves it to Rendering).
const MEDICAL_INTERCHANGE: &[ComponentLevel] = &[
    c("Core", 1),
    c("EnvironmentalEffects", 1),
    c("EventUtilities", 1),
    c("Geometry2D", 2),
    c("Geometry3D", 2),
    c("Grouping", 3),
    c("Interpolation", 2),
    c("Lighting", 1),
    c("Navigation", 3),
    c("Networking", 2),
    c("Rendering", 5),
    c("Shape", 3),
    c("Text", 1),
    c("Texturing", 2),
    c("Texturing3D", 2),
    c("Time", 1),
    c("VolumeRendering", 4),
];

pub static PROFILES: &[Profile] = &[
    Profile {
        name: "Core",
        versions: ALL,
        components: Components::Listed(CORE),
        clause: "Annex A (Table A.2)",
    },
    Profile {
        name: "Interchange",
        versions: ALL,
        components: Components::Listed(INTERCHANGE),
        clause: "Annex B (Table B.2)",
    },
    Profile {
        name: "CADInterchange",
        versions: V3_1_TO_3_3,
        components: Components::Listed(CAD_INTERCHANGE_3),
        clause: "Annex H (Table H.2)",
    },
    Profile {
        name: "CADInterchange",
        versions: V4,
        components: Components::Listed(CAD_INTERCHANGE_4),
        clause: "Annex H (Table H.2)",
    },
    Profile {
        name: "Interactive",
        versions: ALL,
        components: Components::Listed(INTERACTIVE),
        clause: "Annex C (Table C.2)",
    },
    Profile {
        name: "Immersive",
        versions: ALL,
        components: Components::Listed(IMMERSIVE),
        clause: "Annex E (Table E.2)",
    },
    Profile {
        name: "MedicalInterchange",
        versions: V3_3_ON,
        components: Components::Listed(MEDICAL_INTERCHANGE),
        clause: "Annex L (Table L.2; Annex M in 4.x)",
    },
    Profile {
        name: "MPEG4Interactive",
        versions: ALL,
        components: Components::Listed(MPEG4_INTERACTIVE),
        clause: "Annex D (Table D.2)",
    },
    Profile {
        name: "Full",
        versions: ALL,
        components: Components::All,
        clause: "Annex F (Table F.2)",
    },
];

#[cfg(test)]
mod tests {
    use std::fs;
    use std::path::PathBuf;

    use super::*;
    use crate::schema::schema;

    fn listed(profile: &Profile) -> &'static [ComponentLevel] {
        match profile.components {
            Components::Listed(levels) => levels,
            Components::All => &[],
        }
    }

    #[test]
    fn levels_exist_in_the_generated_components() {
        for profile in PROFILES {
            let levels = listed(profile);
            assert!(
                levels.windows(2).all(|w| w[0].component < w[1].component),
                "{} is not sorted by component name",
                profile.name
            );
            for &version in profile.versions {
                for level in levels {
                    let component = schema(version).component(level.component);
                    let max = component.map_or(0, |c| c.max_level);
                    assert!(
                        max >= level.level && level.level >= 1,
                        "{version} {}: {} {} (the component's highest level is {max})",
                        profile.name,
                        level.component,
                        level.level
                    );
                }
            }
        }
    }

    #[test]
    fn one_entry_per_name_and_version() {
        for version in Version::X3D {
            for name in PROFILE_NAMES {
                let count = PROFILES
                    .iter()
                    .filter(|p| p.name == name && p.versions.contains(&version))
                    .count();
                assert!(count <= 1, "{version} {name} has {count} entries");
            }
        }
        assert!(profile(Version::V3_0, "CADInterchange").is_none());
        // VRML97 has no profiles (14772-1 has no PROFILE statement).
        assert!(PROFILE_NAMES
            .iter()
            .all(|name| profile(Version::Vrml97, name).is_none()));
        assert!(profile(Version::V3_2, "MedicalInterchange").is_none());
        assert!(profile(Version::V4_1, "Medical").is_none());
        assert_eq!(
            profile(Version::V3_3, "CADInterchange")
                .unwrap()
                .level(Version::V3_3, "Networking"),
            1
        );
        assert_eq!(
            profile(Version::V4_0, "CADInterchange")
                .unwrap()
                .level(Version::V4_0, "Networking"),
            2
        );
    }

    /// The level of the node's component that `profile` provides covers the node.
    fn allows(version: Version, profile: &str, node: &str) -> bool {
        let node = schema(version).node(node).unwrap();
        let profile = profile_of(version, profile);
        profile.level(version, node.component.component) >= node.component.level
    }

    fn profile_of(version: Version, name: &str) -> &'static Profile {
        profile(version, name).unwrap_or_else(|| panic!("{version} has no profile {name}"))
    }

    #[test]
    fn profiles_hold_the_nodes_they_are_for() {
        for version in Version::X3D {
            for node in [
                "Shape",
                "Appearance",
                "Material",
                "IndexedFaceSet",
                "Transform",
            ] {
                assert!(allows(version, "Interchange", node), "{version} {node}");
            }
            assert!(!allows(version, "Interchange", "Inline"), "{version}");
            assert!(allows(version, "Interactive", "TouchSensor"), "{version}");
            assert!(allows(version, "Interactive", "Anchor"), "{version}");
            assert!(!allows(version, "Interactive", "Script"), "{version}");
            assert!(allows(version, "Immersive", "Script"), "{version}");
            assert!(allows(version, "Immersive", "Extrusion"), "{version}");
            assert!(!allows(version, "Core", "Shape"), "{version}");
        }
        for version in [Version::V4_0, Version::V4_1] {
            assert!(allows(version, "Interchange", "UnlitMaterial"));
            assert!(!allows(version, "Interchange", "PhysicalMaterial"));
            assert!(allows(version, "Immersive", "PhysicalMaterial"));
            assert!(!allows(version, "Immersive", "TwoSidedMaterial"));
        }
        assert!(allows(
            Version::V4_1,
            "MedicalInterchange",
            "TwoSidedMaterial"
        ));
        assert!(!allows(
            Version::V4_0,
            "MedicalInterchange",
            "TwoSidedMaterial"
        ));
        assert!(allows(Version::V3_3, "MedicalInterchange", "VolumeData"));
        assert!(allows(Version::V3_1, "CADInterchange", "CADAssembly"));
    }

    #[test]
    fn profiles_nest() {
        let nested = [
            ("Core", "Interchange"),
            ("Interchange", "Interactive"),
            ("Interactive", "Immersive"),
            ("Interchange", "MedicalInterchange"),
            ("Immersive", "Full"),
            ("MedicalInterchange", "Full"),
            ("CADInterchange", "Full"),
            ("MPEG4Interactive", "Full"),
        ];
        for version in Version::X3D {
            for (small, big) in nested {
                let (Some(small), Some(big)) = (profile(version, small), profile(version, big))
                else {
                    continue;
                };
                for level in small.component_levels(version) {
                    assert!(
                        big.level(version, level.component) >= level.level,
                        "{version}: {} {} {} is not in {}",
                        small.name,
                        level.component,
                        level.level,
                        big.name
                    );
                }
            }
        }
    }

    #[test]
    fn full_is_every_component_at_its_highest_level() {
        for version in Version::X3D {
            let full = profile_of(version, "Full");
            for component in schema(version).components {
                assert_eq!(full.level(version, component.name), component.max_level);
            }
            assert_eq!(full.level(version, "NoSuchComponent"), 0);
        }
    }

    fn oracle(version: Version) -> String {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../shared/oracle")
            .join(format!("X3dUnifiedObjectModel-{version}.xml"));
        fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    }

    /// `(profile name, appinfo text)` of each `<enumeration>` of `profileNameChoices`.
    fn uom_profiles(text: &str) -> Vec<(String, String)> {
        let start = text
            .find(r#"<SimpleType name="profileNameChoices""#)
            .expect("profileNameChoices");
        let body = &text[start..start + text[start..].find("</SimpleType>").unwrap()];
        let attr = |element: &str, name: &str| {
            let key = format!("{name}=\"");
            element.find(&key).map(|i| {
                let value = &element[i + key.len()..];
                value[..value.find('"').unwrap()].to_owned()
            })
        };
        body.split("<enumeration")
            .skip(1)
            .map(|e| {
                (
                    attr(e, "value").unwrap(),
                    attr(e, "appinfo").unwrap_or_default(),
                )
            })
            .collect()
    }

    #[test]
    fn every_uom_profile_name_is_covered() {
        for version in Version::X3D {
            for (name, _) in uom_profiles(&oracle(version)) {
                assert!(
                    profile(version, &name).is_some(),
                    "{version}: the UOM names profile {name}"
                );
                assert!(PROFILE_NAMES.contains(&name.as_str()));
            }
        }
    }

    /// Nodes a UOM profile list names although the annex's table leaves them out (the
    /// table is kept; see the comments on the tables above and on MultiTexture/MovieTexture
    /// in overrides.rs, whose 4.0 levels come from clause 18).
    const KNOWN_DISAGREEMENTS: &[(&[Version], &str, &str)] = &[
        (ALL, "Interactive", "StringSensor"),
        (ALL, "Interactive", "VisibilitySensor"),
        (ALL, "MPEG4Interactive", "ElevationGrid"),
        (V3_1_TO_3_3, "CADInterchange", "Anchor"),
        (V3_1_TO_3_3, "CADInterchange", "Inline"),
        (&[Version::V3_3], "MedicalInterchange", "CoordinateDouble"),
        (&[Version::V4_0], "Interchange", "MultiTexture"),
        (&[Version::V4_0], "Interactive", "MultiTexture"),
        (&[Version::V4_0], "CADInterchange", "MultiTexture"),
        (&[Version::V4_0], "MedicalInterchange", "MultiTexture"),
        (&[Version::V4_0], "Immersive", "MovieTexture"),
    ];

    #[test]
    fn uom_profile_node_lists_agree() {
        const MARKER: &str = "Allowed X3D nodes for this profile are:";
        for version in Version::X3D {
            for (name, appinfo) in uom_profiles(&oracle(version)) {
                let Some(list) = appinfo.split(MARKER).nth(1) else {
                    continue; // Full: "All X3D nodes and statements are allowed"
                };
                for node in list.split_whitespace().map(|n| n.trim_end_matches('.')) {
                    // The lists carry some names no UOM node has (MetadataBoolean in 3.x,
                    // IndexedTriangleFan, Shader, …); they cannot be checked.
                    if schema(version).node(node).is_none() {
                        continue;
                    }
                    let known = KNOWN_DISAGREEMENTS.iter().any(|(versions, p, n)| {
                        versions.contains(&version) && *p == name && *n == node
                    });
                    assert_eq!(
                        allows(version, &name, node),
                        !known,
                        "{version} {name}: {node} (listed by the UOM)"
                    );
                }
            }
        }
    }
}
