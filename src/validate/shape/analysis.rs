//! What the Shape rules share: the Appearance × geometry pairs the scene forms, the
//! materials of an Appearance, and the xxxTexture/xxxTextureMapping field pairs of a
//! material class, read from the schema so that every X3DOneSidedMaterialNode is covered.

use std::collections::HashSet;

use crate::model::texture_mapping::{mapping_of, MappingList};
use crate::model::{ChildRef, Document, Node, NodeId};
use crate::schema::NodeDef;

/// One Appearance × geometry pair, with the first Shape that forms it.
pub struct ShapePair {
    pub shape: NodeId,
    /// The Shape's reference to its geometry (the element or the USE).
    pub geometry_ref: ChildRef,
    pub geometry: NodeId,
    /// `None`: the Shape has no Appearance.
    pub appearance: Option<NodeId>,
}

/// Every distinct Appearance × geometry pair formed by an X3DShapeNode, in document order,
/// each with the first Shape forming it. Left out are pairs whose parts the document does
/// not determine: an unknown-type geometry or Appearance (prototype instances), an
/// Appearance with `IS` connections, or `appearance`/`geometry` fields connected by `IS`.
pub fn shape_pairs(doc: &Document) -> Vec<ShapePair> {
    let mut seen = HashSet::new();
    let mut pairs = Vec::new();
    for (shape, node) in doc.iter() {
        if !node.is_a("X3DShapeNode")
            || node.is_connected("appearance")
            || node.is_connected("geometry")
        {
            continue;
        }
        let Some(&geometry_ref) = node.children("geometry").first() else {
            continue;
        };
        let appearance = node.child("appearance");
        let determined = |id: NodeId| {
            let n = doc.node(id);
            n.def().is_some() && n.connects.is_empty()
        };
        if !doc.node(geometry_ref.node).is_a("X3DGeometryNode")
            || appearance.is_some_and(|a| !determined(a) || !doc.node(a).is_a("Appearance"))
        {
            continue;
        }
        if seen.insert((appearance, geometry_ref.node)) {
            pairs.push(ShapePair {
                shape,
                geometry_ref,
                geometry: geometry_ref.node,
                appearance,
            });
        }
    }
    pairs
}

/// The Appearance nodes of the document whose fields the document determines (no `IS`).
pub fn appearances(doc: &Document) -> impl Iterator<Item = (NodeId, &Node)> {
    doc.iter()
        .filter(|(_, n)| n.is_a("Appearance") && n.connects.is_empty())
}

/// A material slot of an Appearance: `material` or `backMaterial`, with the reference.
pub struct MaterialRef {
    pub field: &'static str,
    pub child: ChildRef,
    pub def: &'static NodeDef,
}

/// The one-sided materials (Material, PhysicalMaterial, UnlitMaterial, …) an Appearance
/// holds in `material` and `backMaterial`, the same node once.
pub fn one_sided_materials(doc: &Document, appearance: NodeId) -> Vec<MaterialRef> {
    let node = doc.node(appearance);
    let mut found: Vec<MaterialRef> = Vec::new();
    for field in ["material", "backMaterial"] {
        let Some(&child) = node.children(field).first() else {
            continue;
        };
        let Some(def) = doc.node(child.node).def() else {
            continue;
        };
        if def.is_a("X3DOneSidedMaterialNode") && found.iter().all(|m| m.child.node != child.node) {
            found.push(MaterialRef { field, child, def });
        }
    }
    found
}

/// The `xxxTexture` fields of a material class that have a matching `xxxTextureMapping`
/// field (12.2.4), as (texture field, mapping field), in name order.
pub fn texture_fields(def: &'static NodeDef) -> Vec<(&'static str, &'static str)> {
    def.fields
        .iter()
        .filter(|f| f.name.ends_with("Texture"))
        .filter_map(|f| {
            let mapping = def.field(&format!("{}Mapping", f.name))?;
            Some((f.name, mapping.name))
        })
        .collect()
}

/// A node of a MultiTextureCoordinate or MultiTextureTransform list whose non-empty mapping
/// repeats an earlier one's.
pub struct RepeatedMapping {
    /// The MultiTextureCoordinate or MultiTextureTransform.
    pub list: NodeId,
    pub first: ChildRef,
    pub repeat: ChildRef,
    /// The repeat's position in the list.
    pub index: usize,
    pub mapping: String,
}

/// The repeated mappings of every `node_type` node's `field` list (12.2.4.1, 12.2.4.2).
pub fn repeated_mappings(doc: &Document, node_type: &str, field: &str) -> Vec<RepeatedMapping> {
    let mut found = Vec::new();
    for list_node in doc.nodes_of_type(node_type) {
        let list = MappingList {
            items: doc.node(list_node).children(field).to_vec(),
            opaque: false,
        };
        for (first, repeat) in list.duplicates(doc) {
            found.push(RepeatedMapping {
                list: list_node,
                first: list.items[first],
                repeat: list.items[repeat],
                index: repeat,
                mapping: mapping_of(doc, list.items[repeat].node).unwrap_or_default(),
            });
        }
    }
    found
}

/// An Appearance's backMaterial, unless it is of a type the field does not accept (a
/// TwoSidedMaterial): NODE_TYPE_NOT_ALLOWED reports that, and a browser ignores it, so no
/// backMaterial rule has anything more to say about it.
pub fn back_material(doc: &Document, appearance: &Node) -> Option<ChildRef> {
    let back = *appearance.children("backMaterial").first()?;
    let accepted = appearance
        .entry("backMaterial")
        .and_then(|e| e.schema_def());
    if let (Some(field), Some(def)) = (accepted, doc.node(back.node).def()) {
        if !field.acceptable.is_empty() && !field.acceptable.iter().any(|a| def.is_a(a)) {
            return None;
        }
    }
    Some(back)
}

/// Appearances that have both a material and a backMaterial ([`back_material`]):
/// (Appearance, material, backMaterial), in document order.
pub fn front_and_back(doc: &Document) -> impl Iterator<Item = (NodeId, ChildRef, ChildRef)> + '_ {
    appearances(doc).filter_map(|(appearance, node)| {
        let front = *node.children("material").first()?;
        Some((appearance, front, back_material(doc, node)?))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;
    use crate::schema::{schema, Version};

    #[test]
    fn texture_fields_come_from_the_schema_for_every_material_class() {
        let s = schema(Version::V4_1);
        let names = |n: &str| texture_fields(s.node(n).unwrap());
        assert_eq!(
            names("UnlitMaterial"),
            vec![
                ("emissiveTexture", "emissiveTextureMapping"),
                ("normalTexture", "normalTextureMapping")
            ]
        );
        assert_eq!(names("PhysicalMaterial").len(), 5);
        assert_eq!(names("Material").len(), 7);
        assert!(names("TwoSidedMaterial").is_empty());
    }

    #[test]
    fn pairs_are_distinct_and_skip_undetermined_parts() {
        let source = br#"<X3D version='4.0' profile='Full'><Scene>
            <Shape><Appearance DEF='A'/><Box DEF='B'/></Shape>
            <Shape><Appearance USE='A'/><Box USE='B'/></Shape>
            <Shape><Appearance USE='A'/><Sphere/></Shape>
            <Shape><Box/></Shape>
            <Shape><Appearance/></Shape>
            </Scene></X3D>"#;
        let doc = parse::read(source).document.unwrap();
        let pairs = shape_pairs(&doc);
        assert_eq!(pairs.len(), 3);
        assert!(pairs[0].appearance.is_some() && pairs[2].appearance.is_none());
        assert!(pairs[1].geometry_ref.span != pairs[0].geometry_ref.span);
    }
}
