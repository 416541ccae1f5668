//! Applies the corrections of `src/schema/overrides.rs` to the tables read from one UOM, and
//! refuses any entry that no longer matches what the UOM says, so that an entry whose node
//! or field was renamed or dropped fails the build instead of silently doing nothing.

use crate::overrides::{Change, ComponentOverride, NewField, NodeOverride};
use crate::overrides::{COMPONENT_OVERRIDES, FIELD_OVERRIDES, NODE_OVERRIDES};
use crate::types::{ComponentLevel, Version};
use crate::uom::{self, Component, Field, Schema};
use crate::vrml97;

/// What applying the overrides did, over all versions, for the stderr summary.
#[derive(Default)]
pub struct Applied {
    /// Node or field entries of the tables that an override changed.
    pub changes: usize,
    /// `version node.field (clause)` of entries that matched but changed nothing: the UOM
    /// already says what the clause says (kept on purpose, to pin the value).
    pub no_ops: Vec<String>,
}

pub fn apply(schema: &mut Schema, applied: &mut Applied) -> Result<(), String> {
    let version = schema.version;
    for entry in FIELD_OVERRIDES
        .iter()
        .filter(|o| o.versions.contains(&version))
    {
        apply_field(
            schema,
            entry.node,
            entry.field,
            &entry.change,
            entry.clause,
            applied,
        )
        .map_err(|e| {
            format!(
                "src/schema/overrides.rs: {version} {}.{} ({}): {e}",
                entry.node, entry.field, entry.clause
            )
        })?;
    }
    for entry in NODE_OVERRIDES
        .iter()
        .filter(|o| o.versions.contains(&version))
    {
        apply_node(schema, entry, applied).map_err(|e| {
            format!(
                "src/schema/overrides.rs: {version} {} ({}): {e}",
                entry.node, entry.clause
            )
        })?;
    }
    // Levels may have moved: the highest level of each component is taken afresh.
    schema.components = uom::component_levels(&schema.nodes);
    for entry in COMPONENT_OVERRIDES
        .iter()
        .filter(|o| o.versions.contains(&version))
    {
        apply_component(schema, entry, applied).map_err(|e| {
            format!(
                "src/schema/overrides.rs: {version} component {} ({}): {e}",
                entry.component, entry.clause
            )
        })?;
    }
    Ok(())
}

/// VRML97's table: the nodes of `src/schema/vrml97.rs` taken from X3D 3.0's table (with
/// its overrides applied), changed by that file's differences.
pub fn vrml97(x3d_3_0: &Schema, applied: &mut Applied) -> Result<Schema, String> {
    let mut schema = x3d_3_0.clone();
    schema.version = Version::Vrml97;
    for (name, clause) in vrml97::NODES {
        if !schema.nodes.iter().any(|n| n.name == *name) {
            return Err(format!(
                "src/schema/vrml97.rs: {name} (14772-1 {clause}) is not a node of X3D 3.0"
            ));
        }
    }
    schema
        .nodes
        .retain(|n| vrml97::NODES.iter().any(|(name, _)| n.name == *name));
    for entry in vrml97::DIFFERENCES {
        let clause = format!("14772-1 {}", entry.vrml97);
        apply_field(
            &mut schema,
            entry.node,
            entry.field,
            &entry.change,
            &clause,
            applied,
        )
        .map_err(|e| {
            format!(
                "src/schema/vrml97.rs: {}.{} ({clause}): {e}",
                entry.node, entry.field
            )
        })?;
    }
    schema.components = uom::component_levels(&schema.nodes);
    Ok(schema)
}

fn apply_component(
    schema: &mut Schema,
    entry: &ComponentOverride,
    applied: &mut Applied,
) -> Result<(), String> {
    let max = schema
        .components
        .get_mut(entry.component)
        .ok_or("no node of this version belongs to the component")?;
    if *max > entry.max_level {
        return Err(format!(
            "nodes or fields need level {max}, above the stated highest level"
        ));
    }
    if *max == entry.max_level {
        applied.no_ops.push(format!(
            "{} component {} ({})",
            schema.version, entry.component, entry.clause
        ));
    } else {
        *max = entry.max_level;
        applied.changes += 1;
    }
    Ok(())
}

/// Applies `change` to the field `field` of `node` (a concrete node, or every concrete
/// node inheriting that abstract type); `clause` names the source in the no-op list.
fn apply_field(
    schema: &mut Schema,
    node: &str,
    field: &str,
    change: &Change,
    clause: &str,
    applied: &mut Applied,
) -> Result<(), String> {
    let version = schema.version;
    let targets: Vec<usize> = (0..schema.nodes.len())
        .filter(|&i| {
            let n = &schema.nodes[i];
            n.name == node || n.ancestors.iter().any(|a| a == node)
        })
        .collect();
    if targets.is_empty() {
        return Err(format!("no node of this version is or inherits {node}"));
    }
    if let Change::Add(new) = change {
        for &i in &targets {
            let node = &mut schema.nodes[i];
            if node.fields.iter().any(|f| f.name == field) {
                return Err(format!(
                    "{} already has this field in the UOM: drop or change the override",
                    node.name
                ));
            }
            node.fields.push(new_field(field, new));
            node.fields.sort_by(|a, b| a.name.cmp(&b.name));
            applied.changes += 1;
        }
        return Ok(());
    }

    let mut found = 0;
    let mut changed = 0;
    for &i in &targets {
        let n = &mut schema.nodes[i];
        let Some(position) = n.fields.iter().position(|f| f.name == field) else {
            continue;
        };
        found += 1;
        if modify(&mut n.fields, position, change) {
            changed += 1;
        }
    }
    if found == 0 {
        return Err(format!("no node that is or inherits {node} has this field"));
    }
    if changed == 0 {
        applied
            .no_ops
            .push(format!("{version} {node}.{field} ({clause})"));
    }
    applied.changes += changed;
    Ok(())
}

/// Applies `change` to `fields[position]`; true when that changed anything.
fn modify(fields: &mut Vec<Field>, position: usize, change: &Change) -> bool {
    let field = &mut fields[position];
    match change {
        Change::Acceptable(types) => {
            let types: Vec<String> = types.iter().map(|t| t.to_string()).collect();
            replace(&mut field.acceptable, types)
        }
        Change::Min(bound) => replace(&mut field.min, *bound),
        Change::Max(bound) => replace(&mut field.max, *bound),
        Change::Default(default) => {
            let exact = exact_default(default, field.ty);
            replace(&mut field.default, exact)
        }
        Change::Component(level) => {
            let new = level.map(component);
            let same = match (&field.component, &new) {
                (None, None) => true,
                (Some(a), Some(b)) => a.name == b.name && a.level == b.level,
                _ => false,
            };
            field.component = new;
            !same
        }
        Change::Access(access) => replace(&mut field.access, *access),
        Change::Strict => replace(&mut field.enumeration_strict, true),
        Change::AlsoValid(values) => {
            let before = field.enumeration.len();
            for value in *values {
                if !field.enumeration.iter().any(|v| v == value) {
                    field.enumeration.push(value.to_string());
                }
            }
            field.enumeration.len() != before
        }
        Change::Remove => {
            fields.remove(position);
            true
        }
        Change::Add(_) => unreachable!("handled by apply_field"),
    }
}

fn replace<T: PartialEq>(slot: &mut T, value: T) -> bool {
    let changed = *slot != value;
    *slot = value;
    changed
}

fn apply_node(
    schema: &mut Schema,
    entry: &NodeOverride,
    applied: &mut Applied,
) -> Result<(), String> {
    let node = schema
        .nodes
        .iter_mut()
        .find(|n| n.name == entry.node)
        .ok_or("no such concrete node in this version")?;
    let new = component(entry.component);
    if node.component.name == new.name && node.component.level == new.level {
        applied.no_ops.push(format!(
            "{} {} ({})",
            schema.version, entry.node, entry.clause
        ));
    } else {
        node.component = new;
        applied.changes += 1;
    }
    Ok(())
}

fn component(level: ComponentLevel) -> Component {
    Component {
        name: level.component.to_owned(),
        level: level.level,
    }
}

fn new_field(name: &str, new: &NewField) -> Field {
    let strings = |items: &[&str]| items.iter().map(|s| s.to_string()).collect();
    Field {
        name: name.to_owned(),
        ty: new.ty,
        access: new.access,
        default: new.default.to_owned(),
        min: new.min,
        max: new.max,
        enumeration: strings(new.enumeration),
        enumeration_strict: new.enumeration_strict,
        acceptable: strings(new.acceptable),
        component: None,
    }
}

/// A default as the interface table prints it, in XML encoding syntax. A multiple of π
/// (`π/4`, `π`, `2π`) becomes the shortest text of the float nearest to it at the field's
/// precision (`0.7853982` for an SFFloat, `0.7853981633974483` for an SFDouble), where the
/// UOM prints a shortened decimal (`0.7854`) that rounds to another float.
fn exact_default(default: &str, ty: crate::types::FieldType) -> String {
    let Some(value) = pi_multiple(default) else {
        return default.to_string();
    };
    match ty.scalar() {
        crate::types::Scalar::Float => format!("{}", value as f32),
        _ => format!("{value}"),
    }
}

/// The value of `kπ/n` as written in the tables (`π`, `π/4`, `2π`, `3π/16`).
fn pi_multiple(text: &str) -> Option<f64> {
    let (numerator, denominator) = match text.split_once('/') {
        Some((a, b)) => (a, b.parse::<f64>().ok()?),
        None => (text, 1.0),
    };
    let k = numerator.strip_suffix('π')?;
    let k = if k.is_empty() {
        1.0
    } else {
        k.parse::<f64>().ok()?
    };
    Some(k * std::f64::consts::PI / denominator)
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;
    use crate::overrides::FieldOverride;
    use crate::types::{AccessType, Bound, FieldType};
    use crate::uom::Node;

    fn apply_entry(
        schema: &mut Schema,
        entry: &FieldOverride,
        applied: &mut Applied,
    ) -> Result<(), String> {
        let FieldOverride {
            node,
            field,
            change,
            clause,
            ..
        } = entry;
        apply_field(schema, node, field, change, clause, applied)
    }

    fn schema() -> Schema {
        let field = |name: &str| Field {
            name: name.to_owned(),
            ty: FieldType::SFFloat,
            access: AccessType::InputOutput,
            default: "1".to_owned(),
            min: None,
            max: None,
            enumeration: Vec::new(),
            enumeration_strict: false,
            acceptable: Vec::new(),
            component: None,
        };
        Schema {
            version: Version::V4_0,
            nodes: vec![Node {
                name: "SpotLight".to_owned(),
                component: Component {
                    name: "Lighting".to_owned(),
                    level: 2,
                },
                container_field: "children".to_owned(),
                ancestors: vec!["X3DLightNode".to_owned()],
                fields: vec![field("beamWidth"), field("intensity")],
            }],
            components: BTreeMap::new(),
        }
    }

    fn entry(node: &'static str, field: &'static str, change: Change) -> FieldOverride {
        FieldOverride {
            versions: &[Version::V4_0],
            node,
            field,
            change,
            clause: "test",
            why: "test",
        }
    }

    const HALF_PI: Option<Bound> = Some(Bound {
        value: std::f64::consts::FRAC_PI_2,
        inclusive: true,
    });

    #[test]
    fn applies_through_an_abstract_type() {
        let mut schema = schema();
        let mut applied = Applied::default();
        let max = entry("X3DLightNode", "beamWidth", Change::Max(HALF_PI));
        apply_entry(&mut schema, &max, &mut applied).unwrap();
        assert_eq!(schema.nodes[0].fields[0].max, HALF_PI);
        assert_eq!(applied.changes, 1);
        // The same again changes nothing and is reported as such.
        apply_entry(&mut schema, &max, &mut applied).unwrap();
        assert_eq!(applied.no_ops.len(), 1);
    }

    #[test]
    fn also_valid_appends_values_once() {
        let mut schema = schema();
        schema.nodes[0].fields[0].enumeration = vec!["PLAIN".to_owned()];
        let mut applied = Applied::default();
        let empty = entry("SpotLight", "beamWidth", Change::AlsoValid(&[""]));
        apply_entry(&mut schema, &empty, &mut applied).unwrap();
        assert_eq!(schema.nodes[0].fields[0].enumeration, ["PLAIN", ""]);
        apply_entry(&mut schema, &empty, &mut applied).unwrap();
        assert_eq!(schema.nodes[0].fields[0].enumeration, ["PLAIN", ""]);
        assert_eq!(applied.no_ops.len(), 1);
    }

    #[test]
    fn refuses_entries_that_match_nothing() {
        let mut applied = Applied::default();
        let unknown_node = entry("SpotLite", "beamWidth", Change::Remove);
        assert!(apply_entry(&mut schema(), &unknown_node, &mut applied).is_err());
        let unknown_field = entry("SpotLight", "beamwidth", Change::Remove);
        assert!(apply_entry(&mut schema(), &unknown_field, &mut applied).is_err());
        let added_twice = entry(
            "SpotLight",
            "intensity",
            Change::Add(NewField {
                ty: FieldType::SFFloat,
                access: AccessType::InputOutput,
                default: "1",
                min: None,
                max: None,
                enumeration: &[],
                enumeration_strict: false,
                acceptable: &[],
            }),
        );
        assert!(apply_entry(&mut schema(), &added_twice, &mut applied).is_err());
        let node = NodeOverride {
            versions: &[Version::V4_0],
            node: "X3DLightNode",
            component: ComponentLevel {
                component: "Lighting",
                level: 1,
            },
            clause: "test",
            why: "test",
        };
        assert!(apply_node(&mut schema(), &node, &mut applied).is_err());
    }

    #[test]
    fn removes_and_adds_keeping_fields_sorted() {
        let mut schema = schema();
        let mut applied = Applied::default();
        let remove = entry("SpotLight", "beamWidth", Change::Remove);
        apply_entry(&mut schema, &remove, &mut applied).unwrap();
        let add = entry(
            "SpotLight",
            "attenuation",
            Change::Add(NewField {
                ty: FieldType::SFVec3f,
                access: AccessType::InputOutput,
                default: "1 0 0",
                min: None,
                max: None,
                enumeration: &[],
                enumeration_strict: false,
                acceptable: &[],
            }),
        );
        apply_entry(&mut schema, &add, &mut applied).unwrap();
        let names: Vec<&str> = schema.nodes[0]
            .fields
            .iter()
            .map(|f| f.name.as_str())
            .collect();
        assert_eq!(names, ["attenuation", "intensity"]);
    }
}
