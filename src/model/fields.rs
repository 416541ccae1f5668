//! Typed access to field values with the schema's defaults: what the rules and the
//! renderer read. A value the document set wins; otherwise the default of the node type's
//! field in the document's version, parsed from the schema's XML-encoding text.

use std::borrow::Cow;

use super::{Document, NodeId, Value};
use crate::model::text::xml_value;

impl Document {
    /// The value of a field: as set in the document, else its default. None for a field
    /// the node's type does not have, or a value that did not parse.
    pub fn value_of(&self, node: NodeId, name: &str) -> Option<Cow<'_, Value>> {
        let node_ref = self.node(node);
        if let Some(entry) = node_ref.entry(name) {
            return match &entry.value {
                Value::Unparsed(_) => None,
                value => Some(Cow::Borrowed(value)),
            };
        }
        let field = node_ref.def()?.field(name)?;
        xml_value::parse_value(field.ty, field.default)
            .ok()
            .map(Cow::Owned)
    }

    pub fn bool_of(&self, node: NodeId, name: &str) -> Option<bool> {
        self.value_of(node, name)?.as_bools()?.first().copied()
    }

    pub fn f32_of(&self, node: NodeId, name: &str) -> Option<f32> {
        self.value_of(node, name)?.as_floats()?.first().copied()
    }

    pub fn i32_of(&self, node: NodeId, name: &str) -> Option<i32> {
        self.value_of(node, name)?.as_int32s()?.first().copied()
    }

    pub fn string_of(&self, node: NodeId, name: &str) -> Option<String> {
        self.value_of(node, name)?.as_strings()?.first().cloned()
    }

    /// The first node of an SFNode field (defaults are NULL, so only set values count).
    pub fn child_of(&self, node: NodeId, name: &str) -> Option<NodeId> {
        self.node(node).child(name)
    }
}

#[cfg(test)]
mod tests {
    use crate::parse;

    #[test]
    fn set_values_win_and_defaults_fill_in() {
        let source = br#"<X3D version='4.0' profile='Interchange'><Scene>
            <Shape><IndexedFaceSet solid='false'/></Shape></Scene></X3D>"#;
        let doc = parse::read(source).document.unwrap();
        let ifs = doc.nodes_of_type("IndexedFaceSet").next().unwrap();
        assert_eq!(doc.bool_of(ifs, "solid"), Some(false));
        assert_eq!(doc.bool_of(ifs, "ccw"), Some(true));
        assert_eq!(doc.f32_of(ifs, "creaseAngle"), Some(0.0));
        assert!(doc.value_of(ifs, "coordIndex").unwrap().is_empty());
        assert_eq!(doc.bool_of(ifs, "noSuchField"), None);
    }
}
