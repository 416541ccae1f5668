//! Texture mapping specified in material nodes (19775-1 12.2.4): which texture coordinates
//! and which texture transformation a material's `xxxTexture` uses. One implementation for
//! the validator and the renderer.
//!
//! # The lists (12.2.4.1, 12.2.4.2)
//! - [`texture_coordinates`] of a geometry: empty when its type has no `texCoord` field (Box,
//!   Sphere…) or the field is NULL; the node itself when it is an
//!   X3DSingleTextureCoordinateNode; `MultiTextureCoordinate.texCoord`'s nodes otherwise (so a
//!   MultiTextureCoordinate with one child is that child, and an empty one is an empty list).
//!   A NurbsTextureCoordinate (the only other node NURBS surfaces accept) is listed like a
//!   single node; it has no `mapping` field, so its mapping reads as empty.
//! - [`texture_transforms`] of an Appearance: empty without an Appearance or with
//!   `textureTransform` NULL; the node itself when it is an X3DSingleTextureTransformNode;
//!   `MultiTextureTransform.textureTransform`'s nodes otherwise.
//!
//! Each entry is the [`ChildRef`] as written, so a node USE'd twice in a MultiTexture… list
//! is two entries. A list is [`MappingList::opaque`] when the mapping of some entry (or the
//! list itself) cannot be read: a prototype instance, an unknown node type, or a field
//! connected by `IS` inside a ProtoBody.
//!
//! # Resolving an `xxxTextureMapping` against a list ([`MappingList::resolve`])
//! - Empty mapping: never a match (12.2.4 note: empty names are the default and must not
//!   match by accident). The texture uses the **first** entry of the list whatever its
//!   mapping; with an empty list, the geometry's default texture coordinates, or no
//!   transformation ([`Resolution::NoMapping`]).
//! - Non-empty mapping: the first entry whose `mapping` equals it, compared exactly (case
//!   and spaces count) ([`Resolution::Matched`]). X3D 4.1 says "the one that is first found
//!   on the list … is used" when several share it; X3D 4.0 forbids duplicates on the
//!   coordinate list ("must have a different mapping value") and says nothing for
//!   transforms, so taking the first is also the only defined reading there.
//! - Non-empty mapping that names no entry ([`Resolution::Unresolved`]): an error in X3D 4.0
//!   ("it must refer to a corresponding … node"); X3D 4.1 turns "must" into "should" and
//!   states the fallback: "as if xxxTextureMapping would be empty", that is the first entry
//!   or, with an empty list, the default coordinates / no transformation. A renderer uses
//!   that fallback in both versions.

use std::collections::HashMap;

use super::{ChildRef, Document, NodeId};

/// A geometry's list of texture coordinates or an Appearance's list of texture
/// transformations, in the order 12.2.4 defines.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MappingList {
    pub items: Vec<ChildRef>,
    /// Some entry's mapping, or the list itself, cannot be known from the document (see
    /// the module docs): a failed resolution may be an artefact, so checks stay silent.
    pub opaque: bool,
}

/// What a texture with a given `xxxTextureMapping` uses from a [`MappingList`].
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Resolution {
    /// The mapping is empty: the first entry (regardless of its mapping), or `None` for an
    /// empty list, meaning the geometry's default texture coordinates / no transformation.
    NoMapping { first: Option<NodeId> },
    /// The first entry whose `mapping` equals the non-empty mapping.
    Matched(NodeId),
    /// No entry has this non-empty mapping (an error in 4.0, a warning in 4.1). `fallback`
    /// is what 4.1 says a browser uses: the same as for an empty mapping.
    Unresolved { fallback: Option<NodeId> },
}

impl Resolution {
    /// The node a renderer uses: `None` means default texture coordinates / identity.
    pub fn used(self) -> Option<NodeId> {
        match self {
            Resolution::NoMapping { first } | Resolution::Unresolved { fallback: first } => first,
            Resolution::Matched(node) => Some(node),
        }
    }
}

impl MappingList {
    /// Resolves a material's `xxxTextureMapping` value against this list (12.2.4.1/2).
    pub fn resolve(&self, doc: &Document, mapping: &str) -> Resolution {
        let first = self.items.first().map(|c| c.node);
        if mapping.is_empty() {
            return Resolution::NoMapping { first };
        }
        match self
            .items
            .iter()
            .find(|c| mapping_of(doc, c.node).as_deref() == Some(mapping))
        {
            Some(item) => Resolution::Matched(item.node),
            None => Resolution::Unresolved { fallback: first },
        }
    }

    /// Entries that repeat an earlier entry's non-empty mapping, as (index of the first
    /// entry with that mapping, index of the repeat), in list order.
    pub fn duplicates(&self, doc: &Document) -> Vec<(usize, usize)> {
        let mut first_with: HashMap<String, usize> = HashMap::new();
        let mut repeats = Vec::new();
        for (i, item) in self.items.iter().enumerate() {
            let Some(mapping) = mapping_of(doc, item.node) else {
                continue;
            };
            if mapping.is_empty() {
                continue;
            }
            match first_with.get(&mapping) {
                Some(&first) => repeats.push((first, i)),
                None => {
                    first_with.insert(mapping, i);
                }
            }
        }
        repeats
    }
}

/// The `mapping` of a texture coordinate or transform node: its value or default, `""`
/// for a type without the field (NurbsTextureCoordinate, any 3.x node), `None` when the
/// node's type is not known (prototype instance, unknown name) or the field is IS-connected.
pub fn mapping_of(doc: &Document, node: NodeId) -> Option<String> {
    let n = doc.node(node);
    let def = n.def()?;
    if def.field("mapping").is_none() {
        return Some(String::new());
    }
    if n.connects.iter().any(|c| c.node_field.text == "mapping") {
        return None;
    }
    doc.string_of(node, "mapping")
}

/// The list of texture coordinates of a geometry node (12.2.4.1).
pub fn texture_coordinates(doc: &Document, geometry: NodeId) -> MappingList {
    let node = doc.node(geometry);
    match node.def() {
        Some(def) if def.field("texCoord").is_none() => MappingList::default(),
        Some(_) => flatten(
            doc,
            geometry,
            "texCoord",
            "MultiTextureCoordinate",
            "texCoord",
        ),
        None => MappingList {
            items: Vec::new(),
            opaque: true,
        },
    }
}

/// The list of texture transformations of an Appearance (12.2.4.2); `None` (a Shape
/// without Appearance) gives the empty list.
pub fn texture_transforms(doc: &Document, appearance: Option<NodeId>) -> MappingList {
    let Some(appearance) = appearance else {
        return MappingList::default();
    };
    if doc.node(appearance).def().is_none() {
        return MappingList {
            items: Vec::new(),
            opaque: true,
        };
    }
    flatten(
        doc,
        appearance,
        "textureTransform",
        "MultiTextureTransform",
        "textureTransform",
    )
}

/// The shared shape of both definitions: a holder's single-node field that is NULL, one
/// single node, or a Multi… node whose list field gives the entries.
fn flatten(
    doc: &Document,
    holder: NodeId,
    field: &str,
    multi_type: &str,
    multi_field: &str,
) -> MappingList {
    let holder_node = doc.node(holder);
    let connected = |id: NodeId, name: &str| {
        doc.node(id)
            .connects
            .iter()
            .any(|c| c.node_field.text == name)
    };
    let Some(&child) = holder_node.children(field).first() else {
        return MappingList {
            items: Vec::new(),
            opaque: connected(holder, field),
        };
    };
    let child_node = doc.node(child.node);
    if child_node.is_a(multi_type) {
        let items = child_node.children(multi_field).to_vec();
        let opaque = connected(child.node, multi_field)
            || items.iter().any(|c| mapping_of(doc, c.node).is_none());
        return MappingList { items, opaque };
    }
    // A single node (X3DSingle…, or another known type the field holds, such as
    // NurbsTextureCoordinate). An unknown type might be a Multi… node in disguise.
    MappingList {
        items: vec![child],
        opaque: mapping_of(doc, child.node).is_none(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn doc(scene: &str, version: &str) -> Document {
        let source =
            format!("<X3D version='{version}' profile='Full'><Scene>{scene}</Scene></X3D>");
        parse::read(source.as_bytes()).document.unwrap()
    }

    fn only(doc: &Document, type_name: &str) -> NodeId {
        doc.nodes_of_type(type_name).next().unwrap()
    }

    fn by_def(doc: &Document, name: &str) -> NodeId {
        *doc.defs
            .iter()
            .find(|((_, n), _)| n == name)
            .map(|(_, id)| id)
            .unwrap()
    }

    #[test]
    fn geometries_without_tex_coord_have_an_empty_list() {
        let d = doc("<Shape><Box/></Shape>", "4.0");
        let list = texture_coordinates(&d, only(&d, "Box"));
        assert_eq!(list, MappingList::default());
        assert_eq!(
            list.resolve(&d, "uv"),
            Resolution::Unresolved { fallback: None }
        );
        assert_eq!(list.resolve(&d, ""), Resolution::NoMapping { first: None });
    }

    #[test]
    fn a_single_coordinate_node_is_the_list() {
        let d = doc(
            "<Shape><IndexedFaceSet><TextureCoordinate DEF='A' mapping='uv'/></IndexedFaceSet></Shape>",
            "4.0",
        );
        let list = texture_coordinates(&d, only(&d, "IndexedFaceSet"));
        let a = by_def(&d, "A");
        assert_eq!(list.items.len(), 1);
        assert!(!list.opaque);
        assert_eq!(list.resolve(&d, "uv"), Resolution::Matched(a));
        assert_eq!(
            list.resolve(&d, "UV"),
            Resolution::Unresolved { fallback: Some(a) }
        );
        assert_eq!(list.resolve(&d, "UV").used(), Some(a));
    }

    #[test]
    fn multi_texture_coordinate_lists_its_children_and_the_first_duplicate_wins() {
        let d = doc(
            "<Shape><IndexedFaceSet><MultiTextureCoordinate>\
               <TextureCoordinate DEF='A'/>\
               <TextureCoordinate DEF='B' mapping='uv'/>\
               <TextureCoordinateGenerator DEF='C' mapping='uv'/>\
               <TextureCoordinate DEF='D'/>\
             </MultiTextureCoordinate></IndexedFaceSet></Shape>",
            "4.1",
        );
        let list = texture_coordinates(&d, only(&d, "IndexedFaceSet"));
        assert_eq!(list.items.len(), 4);
        assert_eq!(list.resolve(&d, "uv"), Resolution::Matched(by_def(&d, "B")));
        // An empty mapping takes the first entry, whatever its mapping; empty never matches.
        assert_eq!(
            list.resolve(&d, ""),
            Resolution::NoMapping {
                first: Some(by_def(&d, "A"))
            }
        );
        // Only non-empty mappings are duplicates (A and D are both empty).
        assert_eq!(list.duplicates(&d), vec![(1, 2)]);
    }

    #[test]
    fn an_empty_multi_texture_coordinate_is_an_empty_list() {
        let d = doc(
            "<Shape><IndexedFaceSet><MultiTextureCoordinate/></IndexedFaceSet></Shape>",
            "4.0",
        );
        let list = texture_coordinates(&d, only(&d, "IndexedFaceSet"));
        assert!(list.items.is_empty() && !list.opaque);
        assert_eq!(list.resolve(&d, "").used(), None);
    }

    #[test]
    fn a_use_is_an_entry_of_its_own() {
        let d = doc(
            "<Shape><IndexedFaceSet><MultiTextureCoordinate>\
               <TextureCoordinate DEF='A' mapping='m'/><TextureCoordinate USE='A'/>\
             </MultiTextureCoordinate></IndexedFaceSet></Shape>",
            "4.0",
        );
        let list = texture_coordinates(&d, only(&d, "IndexedFaceSet"));
        assert_eq!(list.items.len(), 2);
        assert!(list.items[1].is_use);
        assert_eq!(list.duplicates(&d), vec![(0, 1)]);
    }

    #[test]
    fn texture_transforms_come_from_the_appearance() {
        let d = doc(
            "<Shape><Appearance><MultiTextureTransform>\
               <TextureTransform DEF='T1' mapping='a'/><TextureTransform DEF='T2' mapping='b'/>\
             </MultiTextureTransform></Appearance><Box/></Shape>",
            "4.0",
        );
        let appearance = only(&d, "Appearance");
        let list = texture_transforms(&d, Some(appearance));
        assert_eq!(list.resolve(&d, "b"), Resolution::Matched(by_def(&d, "T2")));
        assert_eq!(
            list.resolve(&d, "c"),
            Resolution::Unresolved {
                fallback: Some(by_def(&d, "T1"))
            }
        );
        assert_eq!(texture_transforms(&d, None), MappingList::default());
    }

    #[test]
    fn prototype_instances_make_the_list_opaque() {
        let d = doc(
            "<ProtoDeclare name='UV'><ProtoBody><TextureCoordinate/></ProtoBody></ProtoDeclare>\
             <Shape><IndexedFaceSet><MultiTextureCoordinate>\
               <ProtoInstance name='UV' containerField='texCoord'/>\
             </MultiTextureCoordinate></IndexedFaceSet></Shape>",
            "4.0",
        );
        let list = texture_coordinates(&d, only(&d, "IndexedFaceSet"));
        assert!(list.opaque);
        assert!(list.duplicates(&d).is_empty());
    }

    #[test]
    fn nodes_without_a_mapping_field_read_as_empty() {
        let d = doc(
            "<Shape><IndexedFaceSet><TextureCoordinate DEF='A'/></IndexedFaceSet></Shape>",
            "3.3",
        );
        let a = by_def(&d, "A");
        assert_eq!(mapping_of(&d, a).as_deref(), Some(""));
        let list = texture_coordinates(&d, only(&d, "IndexedFaceSet"));
        assert!(!list.opaque);
        assert_eq!(
            list.resolve(&d, "x"),
            Resolution::Unresolved { fallback: Some(a) }
        );
    }
}
