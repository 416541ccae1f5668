//! X3D names for the names an HTML parser gives: it lower-cases every element and
//! attribute name, and X3DOM and X_ITE find the X3D name again without regard to case.
//! X3DOM matches element names case-insensitively against its node types and reads fields
//! with the DOM's `getAttribute`, which ignores case on HTML elements; X_ITE maps
//! upper-cased type names and lower-cased field names of every node type back to their
//! X3D spelling (its `Parser/HTMLSupport.js`). Both are the lookups here, built from the
//! schema tables of every version.

use std::collections::HashMap;
use std::sync::LazyLock;

use crate::model::statement_attributes;
use crate::schema::{schema, FieldDef, NodeDef, Version};

/// The elements of the XML encoding (19776-1) that are not node types.
const STATEMENTS: &[&str] = &[
    "X3D",
    "head",
    "Scene",
    "component",
    "unit",
    "meta",
    "ROUTE",
    "IMPORT",
    "EXPORT",
    "ProtoDeclare",
    "ExternProtoDeclare",
    "ProtoInterface",
    "ProtoBody",
    "ProtoInstance",
    "field",
    "fieldValue",
    "IS",
    "connect",
];

/// Attributes of the XML encoding that are not fields, beyond those of the head
/// statements ([`statement_attributes`]).
const XML_ATTRIBUTES: &[&str] = &[
    "DEF",
    "USE",
    "containerField",
    "version",
    "profile",
    "fromNode",
    "fromField",
    "toNode",
    "toField",
    "type",
    "accessType",
    "value",
    "appinfo",
    "documentation",
    "url",
    "nodeField",
    "protoField",
    "inlineDEF",
    "importedDEF",
    "AS",
    "localDEF",
];

static ELEMENTS: LazyLock<HashMap<String, &'static str>> = LazyLock::new(|| {
    let nodes = Version::ALL
        .iter()
        .flat_map(|&v| schema(v).nodes.iter().map(|n| n.name));
    nodes
        .chain(STATEMENTS.iter().copied())
        .map(|name| (name.to_ascii_lowercase(), name))
        .collect()
});

/// Every field name of every node type, and the XML attributes, by their lower case.
static ATTRIBUTES: LazyLock<HashMap<String, &'static str>> = LazyLock::new(|| {
    let fields = Version::ALL.iter().flat_map(|&v| {
        schema(v)
            .nodes
            .iter()
            .flat_map(|n| n.fields.iter().map(|f| f.name))
    });
    let statements = ["head", "component", "unit", "meta"]
        .into_iter()
        .flat_map(|s| statement_attributes(s).unwrap_or(&[]).iter().copied());
    fields
        .chain(statements)
        .chain(XML_ATTRIBUTES.iter().copied())
        .map(|name| (name.to_ascii_lowercase(), name))
        .collect()
});

/// The X3D element name written `name` in any case.
pub fn element(name: &str) -> Option<&'static str> {
    ELEMENTS.get(&name.to_ascii_lowercase()).copied()
}

/// The X3D attribute name written `name` in any case on an element `element` (an X3D
/// name): the node type's own field first, so that a name two types spell differently
/// takes the spelling of this one, then any field or XML attribute.
pub fn attribute(element: &str, name: &str) -> Option<&'static str> {
    own_field(element, name)
        .map(|f| f.name)
        .or_else(|| ATTRIBUTES.get(&name.to_ascii_lowercase()).copied())
}

/// The field of node type `element` written `name` in any case, in the newest version
/// that has the type.
pub fn own_field(element: &str, name: &str) -> Option<&'static FieldDef> {
    newest_def(element)?
        .fields
        .iter()
        .find(|f| f.name.eq_ignore_ascii_case(name))
        .copied()
}

fn newest_def(node: &str) -> Option<&'static NodeDef> {
    Version::ALL
        .iter()
        .rev()
        .find_map(|&v| schema(v).node(node))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lower_case_names_find_their_x3d_spelling() {
        assert_eq!(element("indexedfaceset"), Some("IndexedFaceSet"));
        assert_eq!(element("SCENE"), Some("Scene"));
        assert_eq!(element("protoinstance"), Some("ProtoInstance"));
        assert_eq!(element("div"), None);
        assert_eq!(attribute("Material", "diffusecolor"), Some("diffuseColor"));
        assert_eq!(attribute("Shape", "def"), Some("DEF"));
        assert_eq!(attribute("ROUTE", "fromnode"), Some("fromNode"));
        assert_eq!(attribute("Transform", "notafield"), None);
    }
}
