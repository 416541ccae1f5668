//! The comparison 12.2.3 item 2 asks for: the xxxTexture and xxxTextureMapping fields of
//! an Appearance's material and backMaterial. Shared by the three rules that report on it.

use super::analysis::{appearances, back_material, texture_fields};
use crate::model::{ChildRef, Document, NodeId, Value};

/// How deep texture nodes' children (TextureProperties, ComposedCubeMapTexture faces…) are
/// compared before two nodes are taken as different.
const MAX_CONTENT_DEPTH: usize = 16;

/// A material/backMaterial pair of the same node class, as two distinct nodes.
pub struct MaterialPair {
    pub front: ChildRef,
    pub back: ChildRef,
    /// The xxxTexture/xxxTextureMapping field names of their class.
    pub fields: Vec<(&'static str, &'static str)>,
}

/// The Appearances of a 4.x scene whose material and backMaterial are distinct nodes of
/// one X3DOneSidedMaterialNode class, with the texture fields to compare. Fields
/// connected by `IS` on either side are left out: the document does not say their values.
pub fn material_pairs(doc: &Document) -> Vec<MaterialPair> {
    let mut pairs = Vec::new();
    for (_, node) in appearances(doc) {
        let (Some(&front), Some(back)) =
            (node.children("material").first(), back_material(doc, node))
        else {
            continue;
        };
        let (front_node, back_node) = (doc.node(front.node), doc.node(back.node));
        let (Some(def), Some(back_def)) = (front_node.def(), back_node.def()) else {
            continue;
        };
        if front.node == back.node
            || def.name != back_def.name
            || !def.is_a("X3DOneSidedMaterialNode")
        {
            continue;
        }
        let fields = texture_fields(def)
            .into_iter()
            .filter(|(texture, mapping)| {
                ![texture, mapping]
                    .iter()
                    .any(|f| front_node.is_connected(f) || back_node.is_connected(f))
            })
            .collect();
        pairs.push(MaterialPair {
            front,
            back,
            fields,
        });
    }
    pairs
}

/// Whether two texture nodes are copies of each other: the same node, or two nodes of one
/// known type whose every field but `metadata` has the same effective value (set or
/// default; `url` lists element by element; numbers by `==`, so NaN differs from itself),
/// with node-valued fields (TextureProperties, cube map faces) compared the same way.
/// Fields connected by `IS` or values that did not parse make nodes differ: their content
/// is not known.
pub fn equal_content(doc: &Document, a: NodeId, b: NodeId) -> bool {
    equal_at(doc, a, b, 0)
}

fn equal_at(doc: &Document, a: NodeId, b: NodeId, depth: usize) -> bool {
    if a == b {
        return true;
    }
    let (node_a, node_b) = (doc.node(a), doc.node(b));
    let (Some(def), Some(def_b)) = (node_a.def(), node_b.def()) else {
        return false;
    };
    if def.name != def_b.name
        || depth >= MAX_CONTENT_DEPTH
        || !node_a.connects.is_empty()
        || !node_b.connects.is_empty()
    {
        return false;
    }
    let unparsed = |id: NodeId, name: &str| {
        matches!(
            doc.node(id).entry(name).map(|e| &e.value),
            Some(Value::Unparsed(_))
        )
    };
    def.fields.iter().filter(|f| f.name != "metadata").all(|f| {
        if unparsed(a, f.name) || unparsed(b, f.name) {
            return false;
        }
        match (doc.value_of(a, f.name), doc.value_of(b, f.name)) {
            (None, None) => true,
            (Some(va), Some(vb)) => match (va.as_nodes(), vb.as_nodes()) {
                (Some(na), Some(nb)) => {
                    na.len() == nb.len()
                        && na
                            .iter()
                            .zip(nb)
                            .all(|(x, y)| equal_at(doc, x.node, y.node, depth + 1))
                }
                _ => va == vb,
            },
            _ => false,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn textures(scene: &str) -> (Document, NodeId, NodeId) {
        let source = format!("<X3D version='4.0' profile='Full'><Scene>{scene}</Scene></X3D>");
        let doc = parse::read(source.as_bytes()).document.unwrap();
        let ids: Vec<NodeId> = doc
            .iter()
            .filter(|(_, n)| n.is_a("X3DTextureNode"))
            .map(|(id, _)| id)
            .collect();
        (doc, ids[0], ids[1])
    }

    #[test]
    fn defaults_count_as_values() {
        let (d, a, b) = textures(
            "<ImageTexture url='\"a.png\"' repeatS='true'/><ImageTexture url='\"a.png\"'/>",
        );
        assert!(equal_content(&d, a, b));
    }

    #[test]
    fn url_lists_and_child_nodes_are_compared() {
        let (d, a, b) =
            textures("<ImageTexture url='\"a.png\" \"b.png\"'/><ImageTexture url='\"a.png\"'/>");
        assert!(!equal_content(&d, a, b));
        let (d, a, b) = textures(
            "<ImageTexture><TextureProperties anisotropicDegree='2'/></ImageTexture>\
             <ImageTexture><TextureProperties anisotropicDegree='2.0'/></ImageTexture>",
        );
        assert!(equal_content(&d, a, b));
        let (d, a, b) = textures(
            "<ImageTexture><TextureProperties anisotropicDegree='2'/></ImageTexture>\
             <ImageTexture><TextureProperties/></ImageTexture>",
        );
        assert!(!equal_content(&d, a, b));
    }

    #[test]
    fn numbers_compare_as_numbers() {
        let (d, a, b) = textures(
            "<ImageTexture><TextureProperties borderWidth='-0'/></ImageTexture>\
             <ImageTexture><TextureProperties borderWidth='0'/></ImageTexture>",
        );
        assert!(equal_content(&d, a, b), "-0 equals 0");
        let (d, a, b) = textures(
            "<ImageTexture><TextureProperties anisotropicDegree='NaN'/></ImageTexture>\
             <ImageTexture><TextureProperties anisotropicDegree='NaN'/></ImageTexture>",
        );
        assert!(!equal_content(&d, a, b), "NaN equals nothing");
    }

    #[test]
    fn types_and_metadata() {
        let (d, a, b) = textures("<ImageTexture/><PixelTexture/>");
        assert!(!equal_content(&d, a, b));
        let (d, a, b) = textures(
            "<PixelTexture image='1 1 1 0xFF'><MetadataString name='x'/></PixelTexture>\
             <PixelTexture image='1 1 1 255'/>",
        );
        assert!(
            equal_content(&d, a, b),
            "metadata is not content; 0xFF is 255"
        );
    }
}
