//! The typed scene graph both readers produce: an arena of nodes addressed by [`NodeId`],
//! each with its type, the fields the document set (typed values with their spans) and its
//! children per node field. `USE` is a second [`ChildRef`] to the DEF'd node, never a copy.
//! Defaults are not stored: they come from the schema when asked for.

pub mod bounds;
pub mod builder;
pub mod data_url;
pub mod draft;
pub mod faces;
mod fields;
mod header;
mod instantiate;
pub mod rules;
pub mod text;
pub mod texture_mapping;
pub mod units;
mod value;

pub use crate::diagnostic::{NodeId, Span};
pub use builder::Builder;
pub use header::{
    is_namespace_declaration, record, statement_attributes, statement_name, HeaderPart,
    IgnoredContent, UnknownAttribute,
};
pub use instantiate::{instantiate_with, is_instantiation_limit, ExternalPrototypes, LibraryFile};
pub use value::{range_applies, ChildRef, Image, Sink, Summarized, Summarizer, Summary, Value};

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::schema::{AccessType, FieldDef, FieldType, NodeDef, Version};

/// Inputs are addressed with u32 offsets; larger files are refused with a diagnostic.
pub use crate::limits::MAX_INPUT_BYTES;

#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Encoding {
    Xml,
    Json,
    /// ISO/IEC 19776-2 (`#X3D V3.x utf8`), serialized `"classicvrml"`.
    ClassicVrml,
    /// ISO/IEC 14772-1 (`#VRML V2.0 utf8`), serialized `"vrml97"`.
    Vrml97,
}

/// A name or other text as written, with its place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Named {
    pub text: String,
    pub span: Span,
}

/// What a node is.
#[derive(Clone, Debug)]
pub enum NodeKind {
    /// A node type of the schema. `version` is the version whose table defined it: the
    /// document's own, or (for a node that only exists in another version) that one.
    Known {
        def: &'static NodeDef,
        version: Version,
    },
    /// `ProtoInstance name='…'`; `proto` is its declaration in the same scope, if any.
    ProtoInstance { name: String, proto: Option<usize> },
    /// A name no version of the schema knows.
    Unknown { name: String },
}

impl NodeKind {
    /// The schema type, for a known node.
    pub fn def(&self) -> Option<&'static NodeDef> {
        match self {
            NodeKind::Known { def, .. } => Some(*def),
            _ => None,
        }
    }
}

/// Whether an XML attribute or JSON `@` member of this name on a node of type `def` is one
/// of the HTML attributes any X3D 4 element may carry (`class`, `id`, `style`; 19776-1 and
/// -5) and no field. `style` is also a field, of FontStyle and ScreenFontStyle (15.4.1,
/// 36.4.4): there it is the field.
pub fn is_html_attribute(def: Option<&NodeDef>, name: &str) -> bool {
    matches!(name, "class" | "id" | "style") && def.is_none_or(|d| d.field(name).is_none())
}

/// Where a node was defined: the Scene, a ProtoBody, a ProtoInterface field's initial
/// value, or a node field of its parent.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Place {
    Scene,
    ProtoBody {
        proto: usize,
    },
    ProtoField {
        proto: usize,
        field: u32,
    },
    Field {
        parent: NodeId,
        entry: u32,
    },
    /// A top-level node of a ProtoBody as one ProtoInstance builds it (a copy that holds
    /// the instance's values).
    Instance {
        instance: NodeId,
    },
}

/// The DEF name scope a node lives in: the scene, or one ProtoBody (19775-1 4.4.7).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Scope {
    Scene,
    Proto(usize),
}

#[derive(Clone, Debug)]
pub struct Node {
    pub kind: NodeKind,
    /// The whole element (XML) or object (JSON) that defines the node.
    pub span: Span,
    /// The element name or JSON key naming the node type.
    pub name_span: Span,
    pub def_name: Option<Named>,
    pub place: Place,
    pub scope: Scope,
    /// The fields the document set, in document order.
    pub fields: Vec<FieldEntry>,
    /// Fields declared by the node itself (Script, shaders): `<field>` children.
    pub declared: Vec<FieldDecl>,
    /// `IS`/`connect` statements inside a ProtoBody.
    pub connects: Vec<IsConnect>,
    /// Source text (Script, ShaderPart CDATA or `#sourceCode`); not checked.
    pub source_code: Option<Span>,
    /// The longest chain of node references below this node (0 for a leaf).
    pub height: u32,
    /// How many node instances this node stands for with every USE expanded, itself
    /// included (saturating). DEF/USE can make this exponential in the file size, so
    /// whatever visits instances (bounds, the renderer) checks it first.
    pub instances: u64,
    /// For a node made by instantiating a prototype: which body node it copies, for which
    /// ProtoInstance (see [`Instantiation`]).
    pub copy_of: Option<Copied>,
    /// For a ProtoInstance of a ProtoDeclare: its index in [`Document::instantiations`].
    pub instantiation: Option<u32>,
}

/// A ProtoBody node copied for an instance, so that its fields hold the instance's values.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Copied {
    /// The body node copied: of this document, or of the library file `library` names.
    pub original: NodeId,
    /// The first ProtoInstance built with these values.
    pub instance: NodeId,
    /// For a node of an external prototype's body (another file): where it is written.
    pub library: Option<LibraryPlace>,
}

/// Where a node copied from a library file's prototype body is written: the body
/// ([`Document::library_bodies`] names it) and the line in that file. The copy's spans are
/// those of its instance in this document: a place in another file is never shown against
/// this one's text.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct LibraryPlace {
    pub body: u32,
    pub line: u32,
    /// The version of the library file, which its body's nodes are written for.
    pub version: Version,
}

/// A prototype body in a library file that copies were made from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LibraryBody {
    /// How notes name it: `` `Lamp` in lib/lamps.x3d ``.
    pub label: String,
    /// The file it is written in, as it was read: the base of the relative urls its nodes
    /// hold.
    pub path: PathBuf,
}

/// What the ProtoInstances of one ProtoDeclare with the same values build (19775-1
/// 4.4.4): the body's top-level nodes, where each node that takes a value through `IS`
/// (or holds such a node) is a copy with that value, and every other node is the body's
/// own, shared as `USE` shares.
#[derive(Clone, Debug)]
pub struct Instantiation {
    /// The prototype of this document instantiated (for an external prototype, the
    /// ExternProtoDeclare); None for a prototype of a library file instantiated in an
    /// external prototype's body.
    pub proto: Option<usize>,
    /// The body's top-level nodes; the first is the node the instance stands for.
    pub roots: Vec<ChildRef>,
    /// The first ProtoInstance built with these values.
    pub instance: NodeId,
    /// How many ProtoInstance nodes share it (identical values build once).
    pub count: u64,
}

impl Node {
    pub fn def(&self) -> Option<&'static NodeDef> {
        self.kind.def()
    }

    /// The type name as the document wrote it.
    pub fn type_name(&self) -> &str {
        match &self.kind {
            NodeKind::Known { def, .. } => def.name,
            NodeKind::ProtoInstance { .. } => "ProtoInstance",
            NodeKind::Unknown { name } => name,
        }
    }

    /// Whether this node is of type `type_name` or inherits it (`X3DMaterialNode`).
    pub fn is_a(&self, type_name: &str) -> bool {
        self.def().is_some_and(|d| d.is_a(type_name))
    }

    /// Whether a field of a node inside a ProtoBody takes its value from the instance
    /// through `IS`, so that what the document writes there is not what is used.
    pub fn is_connected(&self, field: &str) -> bool {
        self.connects.iter().any(|c| c.node_field.text == field)
    }

    pub fn entry(&self, name: &str) -> Option<&FieldEntry> {
        self.fields.iter().find(|f| f.name() == name)
    }

    /// The value the document set for `name`, if it set one that parsed.
    pub fn value(&self, name: &str) -> Option<&Value> {
        self.entry(name)
            .map(|e| &e.value)
            .filter(|v| !matches!(v, Value::Unparsed(_)))
    }

    /// The nodes of a node field (empty when unset or NULL).
    pub fn children(&self, name: &str) -> &[ChildRef] {
        self.value(name).and_then(Value::as_nodes).unwrap_or(&[])
    }

    /// The first node of an SFNode field.
    pub fn child(&self, name: &str) -> Option<NodeId> {
        self.children(name).first().map(|c| c.node)
    }
}

/// How a field got its value.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    /// An XML attribute.
    Attribute,
    /// Child elements, placed by `containerField` or the type's default.
    Children,
    /// A `fieldValue` statement of a ProtoInstance.
    FieldValue,
    /// A JSON member (`@name` or `-name`), or a ClassicVRML field named in a node's body.
    Member,
    /// In a prototype's instantiation: the value an `IS` passes in (the instance's
    /// fieldValue or the interface default). The entry's spans are the IS/connect's; in a
    /// copy of a library file's body, every field is of this origin and its spans are the
    /// instance's (the value is not written in this document's text).
    Is,
}

/// Which field an entry sets.
#[derive(Clone, Debug)]
pub enum FieldRef {
    /// A field of the schema. `version` is the version whose table defined it.
    Schema {
        def: &'static FieldDef,
        version: Version,
    },
    /// A field declared by the document: a ProtoInstance's fieldValue, typed by the
    /// ProtoDeclare when known.
    Declared { name: String, ty: Option<FieldType> },
    /// A name the node's type does not have in any version.
    Unknown { name: String },
}

impl FieldRef {
    /// The field's type, where it is known.
    pub fn field_type(&self) -> Option<FieldType> {
        match self {
            FieldRef::Schema { def, .. } => Some(def.ty),
            FieldRef::Declared { ty, .. } => *ty,
            FieldRef::Unknown { .. } => None,
        }
    }
}

#[derive(Clone, Debug)]
pub struct FieldEntry {
    pub field: FieldRef,
    /// The attribute name, JSON key, `fieldValue` element or first child element.
    pub name_span: Span,
    /// The value: attribute value, JSON value, or the first child element.
    pub span: Span,
    pub origin: Origin,
    pub value: Value,
}

impl FieldEntry {
    pub fn name(&self) -> &str {
        match &self.field {
            FieldRef::Schema { def, .. } => def.name,
            FieldRef::Declared { name, .. } | FieldRef::Unknown { name } => name,
        }
    }

    pub fn schema_def(&self) -> Option<&'static FieldDef> {
        match self.field {
            FieldRef::Schema { def, .. } => Some(def),
            _ => None,
        }
    }

    pub fn field_type(&self) -> Option<FieldType> {
        self.field.field_type()
    }
}

/// A `field` declaration: in ProtoInterface, ExternProtoDeclare, Script or a shader node.
#[derive(Clone, Debug)]
pub struct FieldDecl {
    pub name: Named,
    pub ty: Option<FieldType>,
    pub access: Option<AccessType>,
    pub span: Span,
    /// The initial value, where one was given.
    pub value: Option<(Value, Span)>,
}

#[derive(Clone, Debug)]
pub struct IsConnect {
    pub node_field: Named,
    pub proto_field: Named,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct ProtoDecl {
    pub name: Named,
    pub span: Span,
    pub external: bool,
    /// Where the declaration stands: the scene, or the body of the prototype it is nested
    /// in (it is visible there only, 4.4.4.3). Set by [`Builder::declare_proto`].
    pub scope: Scope,
    pub interface: Vec<FieldDecl>,
    /// The ProtoBody's top-level nodes (empty for ExternProtoDeclare).
    pub body: Vec<ChildRef>,
    pub url: Vec<String>,
}

#[derive(Clone, Debug)]
pub struct Route {
    pub from_node: Named,
    pub from_field: Named,
    pub to_node: Named,
    pub to_field: Named,
    pub span: Span,
    pub scope: Scope,
    /// VRML97 only: the nodes `from_node` and `to_node` named where the ROUTE is written,
    /// since a later DEF may take a name over (14772-1 4.6.2). Set by
    /// [`Builder::add_route`](builder::Builder::add_route); readers leave it `None`.
    pub vrml97_ends: Option<[Option<NodeId>; 2]>,
}

/// The two ends of a ROUTE.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum RouteEnd {
    From,
    To,
}

impl Route {
    /// The name written for `end`.
    pub fn node_name(&self, end: RouteEnd) -> &Named {
        match end {
            RouteEnd::From => &self.from_node,
            RouteEnd::To => &self.to_node,
        }
    }

    /// The node `end` names in this document: in VRML97 the nearest DEF before the ROUTE,
    /// else the DEF of that name in the ROUTE's scope. None: no such DEF here (an IMPORT
    /// may still bring the node in).
    pub fn node_id(&self, doc: &Document, end: RouteEnd) -> Option<NodeId> {
        let index = match end {
            RouteEnd::From => 0,
            RouteEnd::To => 1,
        };
        self.vrml97_ends.and_then(|ends| ends[index]).or_else(|| {
            doc.defs
                .get(&(self.scope, self.node_name(end).text.clone()))
                .copied()
        })
    }
}

/// An IMPORT statement (19775-1 4.9.2): `IMPORT inlineDEF.importedDEF AS name`, the XML
/// and JSON `IMPORT` with `inlineDEF`, `importedDEF` and `AS`.
#[derive(Clone, Debug)]
pub struct Import {
    /// The DEF name of the Inline whose file exports the node.
    pub inline_def: Named,
    /// The name the inlined file exports the node under.
    pub imported_def: Named,
    pub as_name: Option<Named>,
    pub span: Span,
    pub scope: Scope,
}

impl Import {
    /// The name the node takes in this scene: `AS`, else `importedDEF`.
    pub fn local_name(&self) -> &Named {
        self.as_name.as_ref().unwrap_or(&self.imported_def)
    }
}

/// An EXPORT statement (19775-1 4.9.3): `EXPORT localDEF AS name`, the XML and JSON
/// `EXPORT` with `localDEF` and `AS`.
#[derive(Clone, Debug)]
pub struct Export {
    /// The DEF name of the exported node in this file.
    pub local_def: Named,
    pub as_name: Option<Named>,
    pub span: Span,
    pub scope: Scope,
}

impl Export {
    /// The name importing scenes name the node by: `AS`, else `localDEF`.
    pub fn exported_name(&self) -> &Named {
        self.as_name.as_ref().unwrap_or(&self.local_def)
    }
}

#[derive(Clone, Debug)]
pub struct ComponentStatement {
    pub name: Named,
    pub level: Option<(i32, Span)>,
    pub span: Span,
}

/// A `unit` statement (19775-1 7.2.5.5): its attributes as written, with their places.
#[derive(Clone, Debug)]
pub struct UnitStatement {
    pub category: Option<Named>,
    pub name: Option<Named>,
    /// The factor as read (None where it is missing or did not parse) and its place.
    pub conversion_factor: Option<(Option<f64>, Span)>,
    pub span: Span,
}

#[derive(Clone, Debug, Default)]
pub struct Head {
    pub components: Vec<ComponentStatement>,
    pub units: Vec<UnitStatement>,
    pub metas: usize,
    /// Attributes of head, component, unit and meta that they do not have.
    pub unknown_attributes: Vec<UnknownAttribute>,
}

/// A comment addressed to x3dcheck (`x3dcheck: …`) as a reader found it, with the part of
/// the document it applies to. What it says is read where findings are gathered
/// (`crate::suppress`), not here: readers and the model only place it.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Directive {
    /// The comment (XML, ClassicVRML) or the `#comment` string (JSON).
    pub span: Span,
    /// The text after `x3dcheck:`, as written in the input.
    pub text: Span,
    /// What it applies to: the element, node or statement that follows it (in JSON, also
    /// the object that holds it); an empty span when nothing follows in its parent; None
    /// for the whole file.
    pub scope: Option<Span>,
}

/// One parsed document.
#[derive(Clone, Debug)]
pub struct Document {
    pub encoding: Encoding,
    /// The `version` attribute as written.
    pub version_text: Option<Named>,
    /// The version it names, when it names a known one; without a `version`, the one a
    /// [`VersionHint`] names.
    pub version: Option<Version>,
    /// The version the DOCTYPE or the schema location names, if any.
    pub version_hint: Option<VersionHint>,
    pub profile: Option<Named>,
    pub head: Head,
    /// The root element or `"X3D"` object.
    pub root_span: Span,
    pub scene_span: Option<Span>,
    /// Read from an X3D island of an HTML page (X3DOM, X_ITE), which needs no `version` or
    /// `profile`.
    pub in_page: bool,
    /// In a page that is a server's template, the attribute values that are placeholders
    /// (`{{ model.inline }}`), left out.
    pub template_values: Vec<Span>,
    /// In a page, the elements of the library's own nodes (X3DOM's `<plane>`), left out:
    /// a Shape holding one may have its geometry there.
    pub library_nodes: Vec<Span>,
    pub nodes: Vec<Node>,
    /// The Scene's top-level nodes.
    pub scene: Vec<ChildRef>,
    pub routes: Vec<Route>,
    pub protos: Vec<ProtoDecl>,
    /// IMPORT statements, in document order.
    pub imports: Vec<Import>,
    /// EXPORT statements, in document order.
    pub exports: Vec<Export>,
    /// Content of the X3D root and head that X3D gives no meaning (not read further).
    pub ignored: Vec<IgnoredContent>,
    /// DEF names per scope, each with the first node that took it.
    pub defs: HashMap<(Scope, String), NodeId>,
    /// How many of the last nodes are copies made by instantiating prototypes; the nodes
    /// before them are those the document writes, in the order their elements start.
    pub copies: usize,
    /// The prototype instantiations, shared by ProtoInstances with identical values.
    pub instantiations: Vec<Instantiation>,
    /// The library prototype bodies copies were made from; see [`LibraryPlace`].
    pub library_bodies: Vec<LibraryBody>,
    /// The comments addressed to x3dcheck, in document order.
    pub directives: Vec<Directive>,
}

/// A version that a document without `version` names elsewhere: its DOCTYPE's public or
/// system id (`ISO//Web3D//DTD X3D 3.0//EN`, `x3d-3.0.dtd`) or its schema location
/// (`x3d-3.0.xsd`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct VersionHint {
    pub version: Version,
    /// "DOCTYPE" or "schema location".
    pub source: &'static str,
}

impl VersionHint {
    /// The X3D version a DOCTYPE or schema location text names: `X3D 3.0` or `x3d-3.0`
    /// followed by anything but a digit or a dot.
    pub fn find(text: &str, source: &'static str) -> Option<VersionHint> {
        let lower = text.to_ascii_lowercase();
        ["x3d-", "x3d "].iter().find_map(|prefix| {
            lower.match_indices(prefix).find_map(|(at, _)| {
                let rest = &lower[at + prefix.len()..];
                let end = rest
                    .find(|c: char| !(c.is_ascii_digit() || c == '.'))
                    .unwrap_or(rest.len());
                let number = rest[..end].trim_end_matches('.');
                Version::parse(number).map(|version| VersionHint { version, source })
            })
        })
    }
}

impl Document {
    /// Without a `version`, takes the hint's version for the schema (the document is
    /// still reported as having no `version`).
    pub fn apply_version_hint(&mut self) {
        if self.version_text.is_none() && self.version.is_none() {
            self.version = self.version_hint.map(|hint| hint.version);
        }
    }

    pub fn new(encoding: Encoding) -> Document {
        Document {
            encoding,
            version_text: None,
            version: None,
            version_hint: None,
            profile: None,
            head: Head::default(),
            root_span: Span::default(),
            scene_span: None,
            in_page: false,
            template_values: Vec::new(),
            library_nodes: Vec::new(),
            nodes: Vec::new(),
            scene: Vec::new(),
            routes: Vec::new(),
            protos: Vec::new(),
            imports: Vec::new(),
            exports: Vec::new(),
            ignored: Vec::new(),
            defs: HashMap::new(),
            copies: 0,
            instantiations: Vec::new(),
            library_bodies: Vec::new(),
            directives: Vec::new(),
        }
    }

    /// The library file `node` is written in, when it is a copy of a node of an external
    /// prototype's body (None for the document's own nodes and for nodes an instance
    /// passes in).
    pub fn library_file_of(&self, node: NodeId) -> Option<&Path> {
        let place = self.nodes.get(node.index())?.copy_of?.library?;
        let body = self.library_bodies.get(place.body as usize)?;
        Some(&body.path)
    }

    /// The nodes the document writes, without the copies instantiation made.
    pub fn written_nodes(&self) -> &[Node] {
        &self.nodes[..self.nodes.len().saturating_sub(self.copies)]
    }

    /// The instantiation a ProtoInstance builds, if it was built.
    pub fn instantiation_of(&self, id: NodeId) -> Option<&Instantiation> {
        let index = self.node(id).instantiation?;
        self.instantiations.get(index as usize)
    }

    /// The node a reference stands for: itself, or for a ProtoInstance the first node
    /// its instantiation builds (through nested instances). None for an instance that
    /// builds nothing (an external or unknown prototype, an empty body, a limit).
    pub fn built(&self, id: NodeId) -> Option<NodeId> {
        let mut current = id;
        for _ in 0..=crate::limits::MAX_PROTO_NESTING {
            if !matches!(self.node(current).kind, NodeKind::ProtoInstance { .. }) {
                return Some(current);
            }
            current = self.instantiation_of(current)?.roots.first()?.node;
        }
        None
    }

    /// The version whose schema applies: the document's, or the latest when it names none.
    pub fn schema_version(&self) -> Version {
        self.version.unwrap_or(Version::LATEST)
    }

    pub fn node(&self, id: NodeId) -> &Node {
        &self.nodes[id.index()]
    }

    /// Every node with its id, in document order.
    pub fn iter(&self) -> impl Iterator<Item = (NodeId, &Node)> {
        self.nodes
            .iter()
            .enumerate()
            .map(|(i, n)| (NodeId(i as u32), n))
    }

    pub fn node_ids(&self) -> impl Iterator<Item = NodeId> {
        (0..self.nodes.len() as u32).map(NodeId)
    }

    /// Node instances in the scene with every USE expanded and every prototype instance
    /// counted as the nodes its instantiation builds (saturating).
    pub fn instances(&self) -> u64 {
        let mut counted = HashMap::new();
        self.scene.iter().fold(0u64, |sum, c| {
            sum.saturating_add(self.instances_below(c.node, &mut counted))
        })
    }

    /// The instances `root` stands for, memoized over the DAG in `counted`, with an
    /// explicit stack (a scene may be deep). A prototype instance counts as its built root;
    /// the nodes below a node count through each of its node fields. A node met again
    /// while it is being counted (only an instantiation gone wrong could do that) counts 1.
    fn instances_below(&self, root: NodeId, counted: &mut HashMap<NodeId, u64>) -> u64 {
        let below = |id: NodeId| -> Vec<NodeId> {
            let node = self.node(id);
            if matches!(node.kind, NodeKind::ProtoInstance { .. }) {
                return self.built(id).into_iter().collect();
            }
            node.fields
                .iter()
                .filter_map(|f| f.value.as_nodes())
                .flatten()
                .map(|c| c.node)
                .collect()
        };
        let mut open = std::collections::HashSet::new();
        let mut stack = vec![(root, false)];
        while let Some((id, children_counted)) = stack.pop() {
            if counted.contains_key(&id) {
                continue;
            }
            let children = below(id);
            if children_counted {
                open.remove(&id);
                let own = u64::from(!matches!(
                    self.node(id).kind,
                    NodeKind::ProtoInstance { .. }
                ));
                let count = children.iter().fold(own, |sum, c| {
                    sum.saturating_add(counted.get(c).copied().unwrap_or(1))
                });
                counted.insert(id, count);
            } else if open.insert(id) {
                stack.push((id, true));
                stack.extend(
                    children
                        .into_iter()
                        .filter(|c| !counted.contains_key(c) && !open.contains(c))
                        .map(|c| (c, false)),
                );
            }
        }
        counted.get(&root).copied().unwrap_or(1)
    }

    /// Nodes of a given concrete type, in document order.
    pub fn nodes_of_type<'a>(&'a self, type_name: &'a str) -> impl Iterator<Item = NodeId> + 'a {
        self.node_ids()
            .filter(move |id| self.node(*id).def().is_some_and(|d| d.name == type_name))
    }
}

#[cfg(test)]
mod tests {
    use super::VersionHint;
    use crate::schema::Version;

    #[test]
    fn version_hints_read_dtd_and_schema_names() {
        let find = |text| VersionHint::find(text, "test").map(|h| h.version);
        assert_eq!(
            find(r#"X3D PUBLIC "ISO//Web3D//DTD X3D 3.0//EN" "x3d-3.0.dtd""#),
            Some(Version::V3_0)
        );
        assert_eq!(
            find("https://www.web3d.org/specifications/x3d-4.0.xsd"),
            Some(Version::V4_0)
        );
        assert_eq!(
            find("x3d-3.3-Web3dExtensionsPublic.xsd"),
            Some(Version::V3_3)
        );
        assert_eq!(
            find("https://www.web3d.org/specifications/x3d-4.1-JSONSchema.json"),
            Some(Version::V4_1)
        );
        assert_eq!(find("x3d-9.9.xsd"), None);
        assert_eq!(find("x3d-3.xsd"), None);
        assert_eq!(find("scene.xsd"), None);
    }
}
