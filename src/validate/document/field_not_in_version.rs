//! FIELD_NOT_IN_VERSION: a field of the node's type in another X3D version only (or one
//! X3D added to a VRML97 node).

use super::node_not_in_version::first_with;
use crate::diagnostic::Diagnostic;
use crate::model::{FieldRef, NodeKind};
use crate::schema::{self, versions, Version};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a field that the node's type has in another X3D version but not in the
    /// document's, as the published UOM and XML Schema of each version say (not the
    /// drafts): `backMaterial`, `alphaMode`, `alphaCutoff`, `castShadow` in 3.x;
    /// PointProperties `markerType` in 4.0. In a VRML97 file, every field X3D added or
    /// renamed: `metadata`, Collision `enabled` (VRML97's `collide`), LOD and Switch
    /// `children` (VRML97's `level` and `choice`), TimeSensor `pauseTime`, and the others
    /// `docs/vrml97-vs-x3d.md` lists; in an X3D file, those three VRML97 names. A node
    /// field holding only nodes that are not in the document's version either
    /// (Appearance.shaders with a ComposedShader in 3.0) is left to NODE_NOT_IN_VERSION,
    /// which reports those nodes at the same place. The message names the versions that
    /// have the field: the first, and every run of versions where it is not contiguous.
    ///
    /// ## Why it matters
    /// A browser of the declared version ignores the field, so the scene looks different
    /// from what its author saw in a newer browser.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='3.3' profile='Interchange'>
    ///   <Scene><Shape><Appearance alphaMode='BLEND'/><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Clause
    /// The node's interface table in the version that defines the field; 7.2.5.2;
    /// for VRML97 files, the node's interface in 14772-1 clause 6.
    /// A field the version does not define is functionality none of the version's components
    /// has at any level, so the document cannot declare it (VRML97: 14772-1 clause 6 gives
    /// each node's fields). The sentence was added to 7.2.5.4 by 19775-1 V3.1 (Amendment 1),
    /// read on the web3d.org V3.1 `core.html` page.
    /// > "A user shall declare all components and levels for the nodes and/or functionality being used either explicitly through the use of the COMPONENT statement or implicitly through the PROFILE statement" (19775-1 V3.1 7.2.5.4)
    pub static FIELD_NOT_IN_VERSION = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for (id, node) in ctx.doc.iter() {
        // A node of another version is NODE_NOT_IN_VERSION; its fields go with it.
        if matches!(node.kind, NodeKind::Known { version, .. } if version != ctx.version) {
            continue;
        }
        for entry in &node.fields {
            let FieldRef::Schema { def, version } = entry.field else {
                continue;
            };
            // A node field whose nodes are all of another version (ComposedShader in
            // Appearance.shaders of a 3.0 file) is NODE_NOT_IN_VERSION's finding, at the
            // same place: the field came with the nodes.
            let nodes = entry.value.as_nodes().unwrap_or_default();
            let nodes_of_other_version = !nodes.is_empty()
                && nodes.iter().all(|child| {
                    matches!(ctx.doc.node(child.node).kind,
                        NodeKind::Known { version, .. } if version != ctx.version)
                });
            if version != ctx.version && !nodes_of_other_version {
                let type_name = node.type_name();
                let message = if ctx.version == Version::Vrml97 {
                    let added = first_with(|v| {
                        let node = schema::schema(v).node(type_name);
                        node.is_some_and(|n| n.field(def.name).is_some())
                    });
                    format!(
                        "VRML97 has no field {type_name}.{}; {} added it",
                        def.name,
                        added.name()
                    )
                } else {
                    format!(
                        "{type_name}.{} is not in {}; it is in {}",
                        def.name,
                        ctx.version.name(),
                        versions::describe(&versions::with_field(type_name, def.name))
                    )
                };
                ctx.report(
                    Diagnostic::new(&FIELD_NOT_IN_VERSION, entry.name_span, message).node(id),
                );
            }
        }
    }
}

/// VRML97 documents built node by node as the ClassicVRML reader builds them, through the
/// model's Builder (the reader itself is another branch's).
#[cfg(test)]
mod tests {
    use crate::config::CheckConfig;
    use crate::model::builder::testing::parent_of;
    use crate::model::{Builder, Encoding, FieldEntry, FieldRef, NodeKind, Origin, Span, Value};
    use crate::schema::Version;

    /// Checks a scene of top-level nodes, each with its fields, read as a `version`
    /// document; the (code, message) pairs, sorted.
    fn check(version: Version, nodes: &[(&str, Vec<(&str, Value)>)]) -> Vec<(String, String)> {
        let mut builder = Builder::new(Encoding::Xml);
        builder.doc_mut().version = Some(version);
        for (ty, fields) in nodes {
            let kind = builder.node_kind(ty);
            let id = builder
                .begin_node(kind, Span::default(), parent_of(None))
                .unwrap();
            for (name, value) in fields {
                let entry = FieldEntry {
                    field: builder.field_ref(id, name),
                    name_span: Span::default(),
                    span: Span::default(),
                    origin: Origin::Attribute,
                    value: value.clone(),
                };
                builder.add_field(id, entry);
            }
            builder.end_node(id, Span::default());
        }
        let (doc, _) = builder.finish();
        let mut found: Vec<(String, String)> =
            crate::validate::check(&doc, b"", None, &CheckConfig::default())
                .into_iter()
                .map(|d| (d.rule.code.to_string(), d.message))
                .collect();
        found.sort();
        found
    }

    fn pair(code: &str, message: &str) -> (String, String) {
        (code.to_string(), message.to_string())
    }

    #[test]
    fn x3d_nodes_and_fields_in_vrml97_name_vrml97() {
        let found = check(
            Version::Vrml97,
            &[
                ("TriangleSet", vec![]),
                ("Collision", vec![("enabled", Value::Bools(vec![false]))]),
                ("TimeSensor", vec![("pauseTime", Value::Doubles(vec![1.0]))]),
                (
                    "Transform",
                    vec![("scale", Value::Floats(vec![-1.0, 1.0, 1.0]))],
                ),
            ],
        );
        // The value's text comes from the source, which this hand-built scene has none of.
        let range = "Transform.scale component 0 =  is outside (0,∞) in VRML97";
        let expected = [
            pair(
                "FIELD_NOT_IN_VERSION",
                "VRML97 has no field Collision.enabled; X3D 3.0 added it",
            ),
            pair(
                "FIELD_NOT_IN_VERSION",
                "VRML97 has no field TimeSensor.pauseTime; X3D 3.0 added it",
            ),
            pair("FIELD_OUT_OF_RANGE", range),
            pair(
                "NODE_NOT_IN_VERSION",
                "VRML97 has no node TriangleSet; X3D 3.0 added it",
            ),
        ];
        for finding in &expected {
            assert!(found.contains(finding), "{finding:?} not in {found:?}");
        }
    }

    #[test]
    fn a_valid_vrml97_scene_passes_without_profile() {
        let found = check(
            Version::Vrml97,
            &[
                ("Collision", vec![("collide", Value::Bools(vec![false]))]),
                // No levels, so no ranges either (LOD_LEVEL_COUNT_MISMATCH).
                ("LOD", vec![("range", Value::Floats(vec![]))]),
                ("SpotLight", vec![("radius", Value::Floats(vec![5.0]))]),
                (
                    "Viewpoint",
                    vec![("description", Value::Strings(vec!["v".into()]))],
                ),
            ],
        );
        assert_eq!(found, []);
    }

    #[test]
    fn vrml97_names_in_x3d_are_fields_of_another_version() {
        let found = check(
            Version::V3_3,
            &[("Collision", vec![("collide", Value::Bools(vec![false]))])],
        );
        assert!(
            found.contains(&pair(
                "FIELD_NOT_IN_VERSION",
                "Collision.collide is not in X3D 3.3; it is in VRML97 only"
            )),
            "{found:?}"
        );
    }

    #[test]
    fn the_builder_resolves_names_against_vrml97() {
        let mut builder = Builder::new(Encoding::Xml);
        builder.doc_mut().version = Some(Version::Vrml97);
        let NodeKind::Known { version, .. } = builder.node_kind("Collision") else {
            panic!("Collision is a VRML97 node");
        };
        assert_eq!(version, Version::Vrml97);
        let kind = builder.node_kind("Collision");
        let id = builder
            .begin_node(kind, Span::default(), parent_of(None))
            .unwrap();
        let FieldRef::Schema { version, .. } = builder.field_ref(id, "collide") else {
            panic!("collide is a VRML97 field");
        };
        assert_eq!(version, Version::Vrml97);
        let FieldRef::Schema { version, .. } = builder.field_ref(id, "enabled") else {
            panic!("enabled is an X3D field");
        };
        assert_eq!(version, Version::LATEST);
    }
}
