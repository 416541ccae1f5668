//! What a field name means on a node for events: a ROUTE end or an `IS`/`connect` nodeField.
//!
//! A node's fields are its schema fields, the fields it declares itself (Script, shader
//! nodes: `node.declared`) or, for a ProtoInstance, its ProtoDeclare/ExternProtoDeclare's
//! interface. An inputOutput field `x` may also be named `set_x` (its input) and
//! `x_changed` (its output) (19775-1 4.4.2.2). Nodes whose fields cannot be known (unknown
//! types, instances of undeclared prototypes) resolve to [`Lookup::Unchecked`].

use crate::library::Library;
use crate::model::{Document, NodeId, NodeKind, Route, RouteEnd, Scope};
use crate::schema::{self, AccessType, FieldType, Version};
use crate::validate::Ctx;

/// Which way an event flows through a field.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Direction {
    /// Read by a ROUTE (`fromField`): outputOnly or inputOutput.
    Out,
    /// Written by a ROUTE (`toField`): inputOnly or inputOutput.
    In,
}

impl Direction {
    fn accepts(self, access: AccessType) -> bool {
        match self {
            Direction::Out => access.is_output(),
            Direction::In => access.is_input(),
        }
    }
}

/// A field found by name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Field {
    /// The field's own name (`translation` for `set_translation`).
    pub name: String,
    pub ty: Option<FieldType>,
    /// `None` for a declaration without a (valid) accessType.
    pub access: Option<AccessType>,
    /// How the name reached it: `Some(Direction::In)` for `set_x`, `Some(Direction::Out)`
    /// for `x_changed`, `None` for the plain name.
    pub alias: Option<Direction>,
}

impl Field {
    /// Whether a ROUTE may use the field, as named, in this direction.
    pub fn allows(&self, direction: Direction) -> bool {
        match self.alias {
            Some(alias) => alias == direction,
            None => self.access.is_none_or(|a| direction.accepts(a)),
        }
    }

    /// Why the field cannot be used in this direction, for messages.
    pub fn access_text(&self) -> String {
        match (self.alias, self.access) {
            (Some(Direction::In), _) => format!("the input of inputOutput `{}`", self.name),
            (Some(Direction::Out), _) => format!("the output of inputOutput `{}`", self.name),
            (None, Some(access)) => access.as_str().to_string(),
            (None, None) => "of unknown access".to_string(),
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Lookup {
    Found(Field),
    /// No such field; `only_in` lists the versions whose table has it (none: no version).
    Missing {
        candidates: Vec<String>,
        only_in: Vec<Version>,
        /// For `set_x`/`x_changed` where `x` exists but is not inputOutput: `x`'s access.
        not_input_output: Option<(String, AccessType)>,
    },
    /// The node's fields are not known.
    Unchecked,
}

/// The node a ROUTE end names in the ROUTE's scope.
pub fn route_node(doc: &Document, scope: Scope, name: &str) -> Option<NodeId> {
    doc.defs.get(&(scope, name.to_string())).copied()
}

/// The node a ROUTE end names: DEF'd in this document, or (deep level) a node of an
/// inlined file that an IMPORT of the ROUTE's scope brings in (19775-1 4.9.2).
pub struct End<'a> {
    pub doc: &'a Document,
    pub node: NodeId,
    /// The version of the document the node is in.
    pub version: Version,
    /// The inlined file an imported node is in.
    pub imported_from: Option<&'a Library>,
}

impl End<'_> {
    /// The node, for a diagnostic's path: None for an imported node (it is in another file).
    pub fn local(&self) -> Option<NodeId> {
        self.imported_from.is_none().then_some(self.node)
    }

    /// The node's type for messages, saying where an imported node is from.
    pub fn label(&self) -> String {
        let label = type_label(self.doc, self.node);
        match self.imported_from {
            None => label,
            Some(library) => {
                let file = library.path.file_name().unwrap_or_default();
                format!("{label} (imported from {})", file.to_string_lossy())
            }
        }
    }

    /// What `name` means on the node.
    pub fn lookup(&self, name: &str) -> Lookup {
        lookup(self.doc, self.version, self.node, name)
    }
}

/// The node end `end` of `route` stands for: DEF'd here, or imported.
pub fn route_end<'a>(ctx: &'a Ctx, route: &Route, end: RouteEnd) -> Option<End<'a>> {
    if let Some(node) = route.node_id(ctx.doc, end) {
        return Some(End {
            doc: ctx.doc,
            node,
            version: ctx.version,
            imported_from: None,
        });
    }
    let name = &route.node_name(end).text;
    let (library, doc, node) = ctx.imports.node(ctx.doc, route.scope, name)?;
    Some(End {
        doc,
        node,
        version: doc.schema_version(),
        imported_from: Some(library),
    })
}

/// Both ends of a ROUTE, when both resolve.
pub fn route_ends<'a>(ctx: &'a Ctx, route: &Route) -> Option<(End<'a>, End<'a>)> {
    Some((
        route_end(ctx, route, RouteEnd::From)?,
        route_end(ctx, route, RouteEnd::To)?,
    ))
}

/// What `name` means on `node` in a document of `version`.
pub fn lookup(doc: &Document, version: Version, node: NodeId, name: &str) -> Lookup {
    let plain = |n: &str| find(doc, version, node, n);
    let mut missing = match plain(name) {
        None => return Lookup::Unchecked,
        Some(Lookup::Found(field)) => return Lookup::Found(field),
        Some(missing) => missing,
    };
    let aliases = [
        (name.strip_prefix("set_"), Direction::In),
        (name.strip_suffix("_changed"), Direction::Out),
    ];
    for (base, alias) in aliases {
        let Some(base) = base.filter(|b| !b.is_empty()) else {
            continue;
        };
        if let Some(Lookup::Found(field)) = plain(base) {
            if field.access == Some(AccessType::InputOutput) {
                return Lookup::Found(Field {
                    alias: Some(alias),
                    ..field
                });
            }
            if let (
                Lookup::Missing {
                    not_input_output, ..
                },
                Some(access),
            ) = (&mut missing, field.access)
            {
                *not_input_output = Some((field.name, access));
            }
        }
    }
    missing
}

/// The field of exactly that name, `Missing` with the candidates, or `None` when the
/// node's fields are not known.
fn find(doc: &Document, version: Version, node: NodeId, name: &str) -> Option<Lookup> {
    let node = doc.node(node);
    if let Some(decl) = node.declared.iter().find(|d| d.name.text == name) {
        return Some(found(name, decl.ty, decl.access));
    }
    let declared = node.declared.iter().map(|d| d.name.text.clone());
    match &node.kind {
        NodeKind::Known { def, .. } => {
            let in_version = schema::schema(version).node(def.name).unwrap_or(def);
            if let Some(field) = in_version.field(name) {
                return Some(found(name, Some(field.ty), Some(field.access)));
            }
            let only_in = Version::ALL
                .into_iter()
                .filter(|v| {
                    schema::schema(*v)
                        .node(def.name)
                        .is_some_and(|d| d.field(name).is_some())
                })
                .collect();
            let candidates = declared
                .chain(in_version.fields.iter().map(|f| f.name.to_string()))
                .collect();
            Some(Lookup::Missing {
                candidates,
                only_in,
                not_input_output: None,
            })
        }
        NodeKind::ProtoInstance { proto: Some(p), .. } => {
            let interface = &doc.protos.get(*p)?.interface;
            if let Some(decl) = interface.iter().find(|d| d.name.text == name) {
                return Some(found(name, decl.ty, decl.access));
            }
            let candidates = interface.iter().map(|d| d.name.text.clone()).collect();
            Some(Lookup::Missing {
                candidates,
                only_in: Vec::new(),
                not_input_output: None,
            })
        }
        NodeKind::ProtoInstance { proto: None, .. } | NodeKind::Unknown { .. } => None,
    }
}

fn found(name: &str, ty: Option<FieldType>, access: Option<AccessType>) -> Lookup {
    Lookup::Found(Field {
        name: name.to_string(),
        ty,
        access,
        alias: None,
    })
}

/// The node's type for messages: `TimeSensor`, or the prototype's name for an instance.
pub fn type_label(doc: &Document, node: NodeId) -> String {
    match &doc.node(node).kind {
        NodeKind::ProtoInstance { name, .. } => format!("ProtoInstance `{name}`"),
        _ => doc.node(node).type_name().to_string(),
    }
}

/// `did you mean `x`?` among `candidates`: the `x_changed` or `set_x` field of its own
/// (EspduTransform's `articulationParameterValue0_changed`), else the nearest name.
pub fn did_you_mean(name: &str, candidates: &[String]) -> Option<String> {
    let forms = [format!("{name}_changed"), format!("set_{name}")];
    if let Some(form) = forms.iter().find(|f| candidates.contains(f)) {
        return Some(format!("did you mean `{form}`?"));
    }
    let names = candidates.iter().map(String::as_str);
    crate::validate::suggest::did_you_mean(name, names).map(|c| format!("did you mean `{c}`?"))
}

/// Why a `set_x`/`x_changed` name means nothing, when `x` exists.
pub fn not_input_output_text(not_input_output: &Option<(String, AccessType)>) -> String {
    match not_input_output {
        Some((base, access)) => format!(
            " (`{base}` is {}: only inputOutput fields have `set_` and `_changed` forms)",
            access.as_str()
        ),
        None => String::new(),
    }
}

/// ` (it exists in X3D 4.0, 4.1)` for a field of other versions only.
pub fn only_in_text(only_in: &[Version]) -> String {
    if only_in.is_empty() {
        return String::new();
    }
    let x3d: Vec<&str> = only_in
        .iter()
        .filter(|v| **v != Version::Vrml97)
        .map(|v| v.as_str())
        .collect();
    let mut parts = Vec::new();
    if only_in.contains(&Version::Vrml97) {
        parts.push("VRML97".to_string());
    }
    if !x3d.is_empty() {
        parts.push(format!("X3D {}", x3d.join(", ")));
    }
    format!(" (it exists only in {})", parts.join(" and "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc(scene: &str) -> Document {
        let text = format!("<X3D profile='Full' version='4.0'><Scene>{scene}</Scene></X3D>");
        crate::parse::read(text.as_bytes()).document.unwrap()
    }

    fn field(doc: &Document, def: &str, name: &str) -> Lookup {
        let node = route_node(doc, Scope::Scene, def).unwrap();
        lookup(doc, Version::V4_0, node, name)
    }

    #[test]
    fn input_output_aliases() {
        let d = doc("<Transform DEF='T'/>");
        let Lookup::Found(set) = field(&d, "T", "set_translation") else {
            panic!()
        };
        assert_eq!(set.name, "translation");
        assert!(set.allows(Direction::In) && !set.allows(Direction::Out));
        let Lookup::Found(changed) = field(&d, "T", "translation_changed") else {
            panic!()
        };
        assert!(changed.allows(Direction::Out) && !changed.allows(Direction::In));
        let Lookup::Found(plain) = field(&d, "T", "translation") else {
            panic!()
        };
        assert!(plain.allows(Direction::Out) && plain.allows(Direction::In));
        // `children` is inputOutput too; `set_` alone or `_changed` alone name nothing.
        assert!(matches!(field(&d, "T", "set_"), Lookup::Missing { .. }));
        assert!(matches!(field(&d, "T", "_changed"), Lookup::Missing { .. }));
    }

    #[test]
    fn aliases_need_input_output() {
        let d = doc("<TimeSensor DEF='C'/><Box DEF='B'/>");
        // fraction_changed is a field of its own (outputOnly), not an alias.
        let Lookup::Found(f) = field(&d, "C", "fraction_changed") else {
            panic!()
        };
        assert_eq!((f.name.as_str(), f.alias), ("fraction_changed", None));
        // Box.size is initializeOnly: neither set_size nor size_changed exists.
        let Lookup::Missing {
            not_input_output, ..
        } = field(&d, "B", "set_size")
        else {
            panic!()
        };
        assert_eq!(
            not_input_output,
            Some(("size".to_string(), AccessType::InitializeOnly))
        );
        let Lookup::Found(size) = field(&d, "B", "size") else {
            panic!()
        };
        assert!(!size.allows(Direction::In) && !size.allows(Direction::Out));
    }

    #[test]
    fn script_fields_and_unknown_nodes() {
        let d = doc(
            "<Script DEF='S'><field name='out' type='SFFloat' accessType='outputOnly'/></Script>\
             <Frobnicator DEF='U'/>",
        );
        let Lookup::Found(out) = field(&d, "S", "out") else {
            panic!()
        };
        assert_eq!(out.ty, Some(FieldType::SFFloat));
        assert!(out.allows(Direction::Out) && !out.allows(Direction::In));
        let Lookup::Missing { candidates, .. } = field(&d, "S", "outt") else {
            panic!()
        };
        assert_eq!(
            did_you_mean("outt", &candidates).as_deref(),
            Some("did you mean `out`?")
        );
        assert_eq!(field(&d, "U", "anything"), Lookup::Unchecked);
    }
}
