//! Reads one X3D Unified Object Model document into the node and field tables of one
//! version, noting on the way everything it leaves out so the caller can report it.

use std::collections::{BTreeMap, BTreeSet};

use crate::types::{AccessType, Bound, FieldType, Version};
use crate::xml::Element;

/// Attributes of the XML encoding that the UOM lists as fields inherited from X3DNode
/// although they are not X3D fields. A node's own field of such a name is real: FontStyle
/// and ScreenFontStyle declare `style`, and in 4.x it takes the place of the CSS attribute.
const XML_ATTRIBUTE_FIELDS: [&str; 6] = ["DEF", "USE", "class", "id", "style", "containerField"];

/// The `IS` child element of a node in a prototype body, which the UOM lists as an SFNode
/// field (sometimes not marked as inherited).
const IS_FIELD: &str = "IS";

/// The abstract type the 3.x UOMs give their statements (X3D, Scene, ROUTE, …), which they
/// list among the concrete nodes; 4.x lists them apart as `<Statement>`.
const STATEMENT_TYPE: &str = "SceneGraphStructureStatement";

/// A component and level, as a `<componentInfo name= level=>` states them.
#[derive(Clone)]
pub struct Component {
    pub name: String,
    pub level: u8,
}

#[derive(Clone)]
pub struct Field {
    pub name: String,
    pub ty: FieldType,
    pub access: AccessType,
    pub default: String,
    pub min: Option<Bound>,
    pub max: Option<Bound>,
    pub enumeration: Vec<String>,
    pub enumeration_strict: bool,
    pub acceptable: Vec<String>,
    pub component: Option<Component>,
}

#[derive(Clone)]
pub struct Node {
    pub name: String,
    pub component: Component,
    pub container_field: String,
    pub ancestors: Vec<String>,
    /// Sorted by name.
    pub fields: Vec<Field>,
}

#[derive(Clone)]
pub struct Schema {
    pub version: Version,
    /// Sorted by name.
    pub nodes: Vec<Node>,
    /// Component name to the highest level any node or field of this version needs.
    pub components: BTreeMap<String, u8>,
}

/// What the reader left out or reinterpreted, for the stderr summary.
#[derive(Default)]
pub struct Notes {
    /// Pseudo-field name to how many node entries listed it.
    pub pseudo_fields: BTreeMap<String, usize>,
    /// `version node.field (type)` of fields skipped for a type that is no X3D field type.
    pub untyped_fields: Vec<String>,
    /// `version node.field` of fields whose `xs:NMTOKEN` type was read as SFString.
    pub nmtoken_fields: Vec<String>,
    /// `version node.field attribute="value"` of bounds that are not finite numbers.
    pub bad_bounds: Vec<String>,
    /// `node.field` of fields with a closed enumeration, per version.
    pub strict_enumerations: BTreeMap<Version, Vec<String>>,
}

pub fn read(version: Version, root: &Element, notes: &mut Notes) -> Result<Schema, String> {
    let sections = [
        ("AbstractObjectTypes", "AbstractObjectType"),
        ("AbstractNodeTypes", "AbstractNodeType"),
        ("ConcreteNodes", "ConcreteNode"),
    ];
    let mut bases: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (section, kind) in sections {
        for entry in root
            .children_named(section)
            .flat_map(|s| s.children_named(kind))
        {
            let interface = interface(entry)?;
            // An Inheritance without baseType only relates field types (4.x lists
            // X3DArrayField as an abstract node type inheriting x3dType="X3DField").
            let direct = ["Inheritance", "AdditionalInheritance"]
                .into_iter()
                .flat_map(|tag| interface.children_named(tag))
                .filter_map(|inherit| inherit.attr("baseType"))
                .collect();
            bases.insert(entry.required_attr("name")?, direct);
        }
    }

    let mut nodes = Vec::new();
    let concrete = root
        .children_named("ConcreteNodes")
        .flat_map(|s| s.children_named("ConcreteNode"));
    for entry in concrete {
        let name = entry.required_attr("name")?;
        let ancestors = ancestors(name, &bases);
        if ancestors.iter().any(|a| a == STATEMENT_TYPE) {
            continue;
        }
        let node = read_node(version, name, entry, ancestors, notes)
            .map_err(|e| format!("{version} {name}: {e}"))?;
        nodes.push(node);
    }
    nodes.sort_by(|a, b| a.name.cmp(&b.name));
    // The checker looks nodes up by binary search, which needs names to be unique.
    if let Some(pair) = nodes.windows(2).find(|pair| pair[0].name == pair[1].name) {
        return Err(format!("{version}: node {} is listed twice", pair[0].name));
    }

    let components = component_levels(&nodes);

    let strict = notes.strict_enumerations.entry(version).or_default();
    for node in &nodes {
        for field in node.fields.iter().filter(|f| f.enumeration_strict) {
            strict.push(format!("{}.{}", node.name, field.name));
        }
    }

    Ok(Schema {
        version,
        nodes,
        components,
    })
}

/// Component name to the highest level any node or field of `nodes` needs.
pub fn component_levels(nodes: &[Node]) -> BTreeMap<String, u8> {
    let mut components: BTreeMap<String, u8> = BTreeMap::new();
    for node in nodes {
        let field_components = node.fields.iter().filter_map(|f| f.component.as_ref());
        for component in std::iter::once(&node.component).chain(field_components) {
            let max = components.entry(component.name.clone()).or_default();
            *max = (*max).max(component.level);
        }
    }
    components
}

fn interface(entry: &Element) -> Result<&Element, String> {
    entry.child("InterfaceDefinition").ok_or_else(|| {
        let name = entry.attr("name").unwrap_or("?");
        format!("{name} has no InterfaceDefinition")
    })
}

/// Every type `name` inherits, directly or not, sorted and without repeats.
fn ancestors(name: &str, bases: &BTreeMap<&str, Vec<&str>>) -> Vec<String> {
    let mut seen = BTreeSet::new();
    let mut pending = vec![name];
    while let Some(current) = pending.pop() {
        for &base in bases.get(current).into_iter().flatten() {
            if seen.insert(base) {
                pending.push(base);
            }
        }
    }
    seen.into_iter().map(String::from).collect()
}

fn read_node(
    version: Version,
    name: &str,
    entry: &Element,
    ancestors: Vec<String>,
    notes: &mut Notes,
) -> Result<Node, String> {
    let interface = interface(entry)?;
    let component = interface
        .child("componentInfo")
        .ok_or_else(|| "no componentInfo".to_owned())
        .and_then(read_component)?;
    let container_field = match interface.child("containerField") {
        Some(container) => container.required_attr("default")?,
        None => "children",
    };
    let mut fields = Vec::new();
    for field in interface.children_named("field") {
        let field_name = field.required_attr("name")?;
        let read =
            read_field(version, name, field, notes).map_err(|e| format!("{field_name}: {e}"))?;
        fields.extend(read);
    }
    fields.sort_by(|a, b| a.name.cmp(&b.name));
    if let Some(pair) = fields.windows(2).find(|pair| pair[0].name == pair[1].name) {
        return Err(format!("field {} is listed twice", pair[0].name));
    }
    Ok(Node {
        name: name.to_owned(),
        component,
        container_field: container_field.to_owned(),
        ancestors,
        fields,
    })
}

fn read_component(info: &Element) -> Result<Component, String> {
    let level = info.required_attr("level")?;
    Ok(Component {
        name: info.required_attr("name")?.to_owned(),
        level: level
            .parse()
            .map_err(|_| format!("componentInfo level {level:?} is not a small integer"))?,
    })
}

/// The field as the checker sees it, or None for the fields the tables leave out.
fn read_field(
    version: Version,
    node: &str,
    field: &Element,
    notes: &mut Notes,
) -> Result<Option<Field>, String> {
    let name = field.required_attr("name")?;
    let from_x3d_node = field.attr("inheritedFrom") == Some("X3DNode");
    if name == IS_FIELD || (from_x3d_node && XML_ATTRIBUTE_FIELDS.contains(&name)) {
        *notes.pseudo_fields.entry(name.to_owned()).or_default() += 1;
        return Ok(None);
    }
    let type_text = field.required_attr("type")?;
    let ty = match FieldType::parse(type_text) {
        Some(ty) => ty,
        // The 4.x UOMs give X3DVertexAttributeNode.name the XML Schema type of its
        // attribute; the field itself is SFString (as the 3.x UOMs say).
        None if type_text == "xs:NMTOKEN" => {
            notes
                .nmtoken_fields
                .push(format!("{version} {node}.{name}"));
            FieldType::SFString
        }
        None => {
            let entry = format!("{version} {node}.{name} ({type_text})");
            notes.untyped_fields.push(entry);
            return Ok(None);
        }
    };
    let access_text = field.required_attr("accessType")?;
    let access = AccessType::parse(access_text)
        .ok_or_else(|| format!("unknown accessType {access_text:?}"))?;

    let mut bound = |inclusive_attr: &str, exclusive_attr: &str| {
        let (attr, text, inclusive) = match (field.attr(inclusive_attr), field.attr(exclusive_attr))
        {
            (None, None) => return Ok(None),
            (Some(text), None) => (inclusive_attr, text, true),
            (None, Some(text)) => (exclusive_attr, text, false),
            (Some(_), Some(_)) => {
                return Err(format!("has both {inclusive_attr} and {exclusive_attr}"))
            }
        };
        match text.trim().parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(Some(Bound { value, inclusive })),
            _ => {
                let entry = format!("{version} {node}.{name} {attr}={text:?}");
                notes.bad_bounds.push(entry);
                Ok(None)
            }
        }
    };
    let min = bound("minInclusive", "minExclusive")?;
    let max = bound("maxInclusive", "maxExclusive")?;

    let enumeration: Vec<String> = field
        .children_named("enumeration")
        .map(|e| e.required_attr("value").map(String::from))
        .collect::<Result<_, _>>()?;
    let enumeration_strict = field.attr("additionalEnumerationValuesAllowed") == Some("false");
    // Every UOM so far repeats a simpleType's values inside the field and marks the closed
    // (`…Choices`) ones with additionalEnumerationValuesAllowed="false"; both are relied on.
    if let Some(simple_type) = field.attr("simpleType") {
        if enumeration.is_empty() {
            return Err(format!(
                "simpleType {simple_type} without inline enumeration values"
            ));
        }
        if simple_type.ends_with("Choices") != enumeration_strict {
            return Err(format!(
                "simpleType {simple_type} disagrees with additionalEnumerationValuesAllowed"
            ));
        }
    }

    let acceptable = field
        .attr("acceptableNodeTypes")
        .map(|types| types.split('|').map(String::from).collect())
        .unwrap_or_default();
    let component = field
        .child("componentInfo")
        .map(read_component)
        .transpose()?;

    Ok(Some(Field {
        name: name.to_owned(),
        ty,
        access,
        default: field.attr("default").unwrap_or("").to_owned(),
        min,
        max,
        enumeration,
        enumeration_strict,
        acceptable,
        component,
    }))
}
