//! The subclause of ISO/IEC 19775-1 that defines each node type, derived from the schema
//! tables rather than typed per rule: a component's chapter (the one table below, from the
//! standard's contents) and the node's place in the alphabetical list of that component's
//! node types in the version at hand. The standard numbers a component's node reference
//! that way: 12.4.1 AcousticProperties … 12.4.10 UnlitMaterial and 18.4.1 ImageTexture …
//! 18.4.10 TextureTransform in the seed texts (the tests check both lists against them),
//! 32.4.5 IndexedQuadSet and 32.4.6 QuadSet, 17.4.4 SpotLight in 4.1 (after
//! EnvironmentLight) but 17.4.3 in 4.0.

use std::collections::HashMap;
use std::sync::LazyLock;

use super::{schema, Version};

/// Per component the rules report on: its chapter and the subclause of its node
/// reference — 4, after the abstract types of subclause 3, or 3 for a component that
/// defines no abstract type (Geometry3D).
const CHAPTERS: &[(&str, u32, u32)] = &[
    ("CADGeometry", 32, 4),
    ("Geometry3D", 13, 3),
    ("Lighting", 17, 4),
    ("Rendering", 11, 4),
    ("Shape", 12, 4),
    ("Texturing", 18, 4),
];

/// Per version: node type → subclause, for the components of [`CHAPTERS`].
static SUBCLAUSES: LazyLock<HashMap<Version, HashMap<&'static str, String>>> =
    LazyLock::new(|| {
        let mut tables = HashMap::new();
        for version in Version::ALL {
            let table: &mut HashMap<&'static str, String> = tables.entry(version).or_default();
            for &(component, chapter, section) in CHAPTERS {
                // `nodes` is sorted by name, so the n-th of the component is its n-th subclause.
                let nodes = schema(version).nodes.iter();
                let of_component = nodes.filter(|n| n.component.component == component);
                for (n, node) in of_component.enumerate() {
                    table.insert(node.name, format!("{chapter}.{section}.{}", n + 1));
                }
            }
        }
        tables
    });

/// The subclause that defines `node` in `version`; None for a node type of a component
/// outside `CHAPTERS` or not in that version.
pub fn node_subclause(version: Version, node: &str) -> Option<&'static str> {
    SUBCLAUSES.get(&version)?.get(node).map(String::as_str)
}

/// The clause a sequencer's decreasing key cites: 30.3.1 X3DSequencerNode, which says of
/// the sequencers' keys what 19.2.2 says of the interpolators'.
pub const SEQUENCER_KEYS: &str = "30.3.1";

/// `clause` as the table holds it, for a report read back (`x3dcheck merge`): the clause
/// a finding on some node type cited.
pub fn known_subclause(clause: &str) -> Option<&'static str> {
    SUBCLAUSES
        .values()
        .flat_map(|table| table.values())
        .find(|known| *known == clause)
        .map(String::as_str)
}

/// Whether `clause` is a node subclause of a component of `CHAPTERS` (or that
/// component's whole node reference, "11.4"): a rule citing one states what a node
/// type's definition requires, so its finding on another node type cites that type's.
pub fn is_node_subclause(clause: &str) -> bool {
    let mut parts = clause.split('.');
    let (Some(chapter), Some(section)) = (parts.next(), parts.next()) else {
        return false;
    };
    let rest: Vec<&str> = parts.collect();
    let numeric = rest.len() <= 1 && rest.iter().all(|p| p.parse::<u32>().is_ok());
    numeric
        && CHAPTERS
            .iter()
            .any(|&(_, c, s)| chapter.parse() == Ok(c) && section.parse() == Ok(s))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The "12.4.1 AcousticProperties" headings of a seed text.
    fn headings(file: &str, prefix: &str) -> Vec<(String, String)> {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/spec/");
        let text = std::fs::read_to_string(format!("{dir}{file}")).expect("the seed text");
        let mut found: Vec<(String, String)> = text
            .lines()
            .filter_map(|line| {
                let mut words = line.split_whitespace();
                let number = words.next()?;
                let name = words.next()?;
                let is_heading = number.starts_with(prefix)
                    && number[prefix.len()..].parse::<u32>().is_ok()
                    && name.chars().next().is_some_and(char::is_uppercase)
                    && words.next().is_none_or(|w| w == "(deprecated)");
                is_heading.then(|| (number.to_string(), name.to_string()))
            })
            .collect();
        found.sort();
        found.dedup();
        found
    }

    #[test]
    fn numbering_matches_the_seed_texts() {
        for (file, prefix, version) in [
            ("000_254d2750502b8f13.txt", "12.4.", Version::V4_0),
            ("004_c3bde948b81b61c3.txt", "18.4.", Version::V4_0),
        ] {
            let found = headings(file, prefix);
            assert!(found.len() >= 10, "{file}: {found:?}");
            for (number, name) in found {
                assert_eq!(
                    node_subclause(version, &name),
                    Some(number.as_str()),
                    "{name}"
                );
            }
        }
    }

    #[test]
    fn each_node_cites_its_own_component_and_version() {
        assert_eq!(node_subclause(Version::V4_0, "QuadSet"), Some("32.4.6"));
        assert_eq!(
            node_subclause(Version::V4_0, "IndexedQuadSet"),
            Some("32.4.5")
        );
        assert_eq!(node_subclause(Version::V4_1, "SpotLight"), Some("17.4.4"));
        assert_eq!(node_subclause(Version::V4_0, "SpotLight"), Some("17.4.3"));
        assert_eq!(
            node_subclause(Version::V4_1, "IndexedFaceSet"),
            Some("13.3.6")
        );
        assert_eq!(node_subclause(Version::V4_1, "Transform"), None);
        assert!(is_node_subclause("11.4") && is_node_subclause("17.4.1"));
        assert!(!is_node_subclause("12.2.3") && !is_node_subclause("4.4.3"));
        assert!(!is_node_subclause("7.2.5.4") && !is_node_subclause("11.4.2.1"));
    }
}
