//! The X3D schema tables: node types, their fields and components, and the profiles, per version.

pub mod clauses;
pub mod profiles;
mod range;
pub mod types;
pub mod versions;
// Generated and checked for freshness byte for byte, so rustfmt must leave it alone.
#[rustfmt::skip]
pub mod generated;
// Generated like `generated`, and for the same reason left alone by rustfmt.
#[rustfmt::skip]
mod descriptions;

pub use generated::schema;
pub use range::{in_range_f32, in_range_f64, range_text};
pub use types::*;

/// The X3D Unified Object Model's description of a node type, at the wording of the newest
/// version that has the type.
pub fn node_description(node: &str) -> Option<&'static str> {
    let table = descriptions::NODES;
    let found = table.binary_search_by(|(name, _)| name.cmp(&node)).ok()?;
    Some(table[found].1)
}

/// The X3D Unified Object Model's description of a node type's field, at the wording of the
/// newest version that has it.
pub fn field_description(node: &str, field: &str) -> Option<&'static str> {
    let table = descriptions::FIELDS;
    let found = table
        .binary_search_by(|(n, f, _)| (*n, *f).cmp(&(node, field)))
        .ok()?;
    Some(table[found].2)
}

/// The X3D Unified Object Model's description of one of a field's enumeration values.
pub fn value_description(node: &str, field: &str, value: &str) -> Option<&'static str> {
    let table = descriptions::VALUES;
    let found = table
        .binary_search_by(|(n, f, v, _)| (*n, *f, *v).cmp(&(node, field, value)))
        .ok()?;
    Some(table[found].3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn description_tables_are_sorted_for_binary_search() {
        assert!(descriptions::NODES.windows(2).all(|w| w[0].0 < w[1].0));
        assert!(descriptions::FIELDS
            .windows(2)
            .all(|w| (w[0].0, w[0].1) < (w[1].0, w[1].1)));
        assert!(descriptions::VALUES
            .windows(2)
            .all(|w| (w[0].0, w[0].1, w[0].2) < (w[1].0, w[1].1, w[1].2)));
    }

    #[test]
    fn descriptions_of_nodes_fields_and_values() {
        let material = node_description("Material").unwrap();
        assert!(material.starts_with("Material specifies surface rendering"));
        let transparency = field_description("Material", "transparency").unwrap();
        assert!(
            transparency.contains("how \"clear\" an object is"),
            "{transparency}"
        );
        // Inherited from X3DNode, described on every concrete node.
        assert!(field_description("Box", "metadata").is_some());
        let linear = value_description("Fog", "fogType", "LINEAR").unwrap();
        assert!(linear.contains("linear blending"), "{linear}");
        assert_eq!(value_description("Fog", "fogType", "CUBIC"), None);
        assert_eq!(node_description("NoSuchNode"), None);
        assert_eq!(field_description("Material", "noSuchField"), None);
    }

    #[test]
    fn every_x3d_4_1_node_has_a_description() {
        let missing: Vec<&str> = schema(Version::V4_1)
            .nodes
            .iter()
            .map(|n| n.name)
            .filter(|name| node_description(name).is_none())
            .collect();
        assert!(missing.is_empty(), "no description: {missing:?}");
    }
}
