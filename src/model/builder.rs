//! Builds a [`Document`] from reader events. Both readers (XML and JSON) drive it, so DEF
//! names and their scopes, USE resolution, node-type and field lookup across versions, and
//! the diagnostics of those steps exist once.

use super::draft::{Draft, Limit};
use super::rules::{DEF_DUPLICATE, FIELD_DUPLICATE, USE_CYCLE, USE_TYPE_MISMATCH, USE_UNDEFINED};
use super::*;
use crate::diagnostic::{Diagnostic, Severity};
use crate::schema::Version;

/// Where a node being added goes.
#[derive(Copy, Clone, Debug)]
pub enum Parent<'a> {
    /// The Scene, or the ProtoBody being read (the builder knows which by its scope).
    TopLevel,
    /// The initial value of a ProtoInterface field of node type.
    ProtoField { proto: usize, field: &'a str },
    /// A node field of an open node, by name (the containerField or JSON `-name`).
    Field {
        node: NodeId,
        field: &'a str,
        field_span: Span,
        origin: Origin,
    },
}

pub struct Builder {
    /// The document and the findings so far.
    draft: Draft,
    /// The scope new nodes and DEFs go in: the scene, or the innermost open ProtoBody.
    scopes: Vec<Scope>,
    /// Nodes whose element is still open, innermost last: a USE of one of them is a cycle.
    open: Vec<NodeId>,
}

/// The deepest chain of nodes (through USE too) the model holds.
pub use crate::limits::MAX_DEPTH;
use crate::limits::{MAX_FIELDS_PER_NODE, MAX_FIELD_VALUES, MAX_NODES};

impl Builder {
    pub fn new(encoding: Encoding) -> Builder {
        Builder {
            draft: Draft::new(encoding),
            scopes: vec![Scope::Scene],
            open: Vec::new(),
        }
    }

    pub fn doc(&self) -> &Document {
        self.draft.doc()
    }

    pub fn doc_mut(&mut self) -> &mut Document {
        self.draft.doc_mut()
    }

    /// Keeps a finding, as [`Draft::report`] does.
    pub fn report(&mut self, diagnostic: Diagnostic) {
        self.draft.report(diagnostic);
    }

    /// Reports a limit of [`crate::limits`] at `span`, once per document and kind.
    pub fn exceeded(&mut self, limit: Limit, span: Span, message: String) {
        self.draft.exceeded(limit, span, message);
    }

    /// The version whose schema applies (set the document's version first).
    pub fn version(&self) -> Version {
        self.draft.version()
    }

    /// What a node type name means, as [`Draft::node_kind`] tells.
    pub fn node_kind(&self, name: &str) -> NodeKind {
        self.draft.node_kind(name)
    }

    /// What a field name means on a node, as [`Draft::field_ref`] tells.
    pub fn field_ref(&self, node: NodeId, name: &str) -> FieldRef {
        self.draft.field_ref(node, name)
    }

    fn scope(&self) -> Scope {
        *self.scopes.last().expect("the scene scope is never popped")
    }

    /// The ProtoDeclare or ExternProtoDeclare of that name visible here, if any.
    pub fn find_proto(&self, name: &str) -> Option<usize> {
        self.draft
            .doc
            .protos
            .iter()
            .rposition(|p| p.name.text == name)
    }

    /// Adds a new node under `parent` and opens it; close it with [`Builder::end_node`].
    /// None when the node would stand deeper than [`MAX_DEPTH`] or be one more than
    /// [`MAX_NODES`]: the reader then skips it and everything inside it.
    pub fn begin_node(
        &mut self,
        kind: NodeKind,
        name_span: Span,
        parent: Parent,
    ) -> Option<NodeId> {
        if self.open.len() >= MAX_DEPTH {
            self.too_deep(name_span);
            return None;
        }
        if self.draft.doc.nodes.len() >= MAX_NODES {
            let message =
                format!("the document has more than {MAX_NODES} nodes; the rest are not read");
            self.exceeded(Limit::Nodes, name_span, message);
            return None;
        }
        let id = NodeId(self.draft.doc.nodes.len() as u32);
        let span = Span {
            start: name_span.start,
            end: name_span.end,
        };
        let place = self.attach(
            parent,
            ChildRef {
                node: id,
                span,
                is_use: false,
            },
        )?;
        self.draft.doc.nodes.push(Node {
            kind,
            span,
            name_span,
            def_name: None,
            place,
            scope: self.scope(),
            fields: Vec::new(),
            declared: Vec::new(),
            connects: Vec::new(),
            source_code: None,
            height: 0,
            instances: 1,
            copy_of: None,
            instantiation: None,
        });
        self.open.push(id);
        Some(id)
    }

    fn too_deep(&mut self, span: Span) {
        let message = format!(
            "the scene graph is nested deeper than {MAX_DEPTH} nodes here; deeper nodes are not read"
        );
        self.exceeded(Limit::Depth, span, message);
    }

    /// Whether `node` may get one more field; reports the limit when not.
    fn has_room_for_field(&mut self, node: NodeId, span: Span) -> bool {
        if self.draft.doc.nodes[node.index()].fields.len() < MAX_FIELDS_PER_NODE {
            return true;
        }
        let message =
            format!("a node with more than {MAX_FIELDS_PER_NODE} fields; the rest are not read");
        self.exceeded(Limit::FieldsPerNode, span, message);
        false
    }

    /// Closes the innermost open node; `span` is its whole element or object.
    pub fn end_node(&mut self, id: NodeId, span: Span) {
        debug_assert_eq!(self.open.last(), Some(&id));
        self.open.pop();
        // Every child is closed by now (a USE names an earlier, closed node), so the
        // height and the instance count below this node are final.
        let (mut height, mut instances) = (0u32, 1u64);
        for child in self.draft.doc.nodes[id.index()]
            .fields
            .iter()
            .filter_map(|f| f.value.as_nodes())
            .flatten()
        {
            let child = &self.draft.doc.nodes[child.node.index()];
            height = height.max(child.height + 1);
            instances = instances.saturating_add(child.instances);
        }
        self.report_duplicate_declarations(id);
        let node = &mut self.draft.doc.nodes[id.index()];
        node.height = height;
        node.instances = instances;
        node.span = span;
        // The reference in the parent was made at the start tag; give it the whole span.
        let siblings: &mut [ChildRef] = match node.place {
            Place::Scene => &mut self.draft.doc.scene,
            Place::ProtoBody { proto } => &mut self.draft.doc.protos[proto].body,
            Place::ProtoField { proto, field } => {
                match &mut self.draft.doc.protos[proto].interface[field as usize].value {
                    Some((Value::Nodes(children), _)) => children,
                    _ => &mut [],
                }
            }
            Place::Field { parent, entry } => {
                match &mut self.draft.doc.nodes[parent.index()].fields[entry as usize].value {
                    Value::Nodes(children) => children,
                    _ => &mut [],
                }
            }
            // Only instantiation makes such nodes, after every node is closed.
            Place::Instance { .. } => &mut [],
        };
        if let Some(child) = siblings
            .iter_mut()
            .rev()
            .find(|c| c.node == id && !c.is_use)
        {
            child.span = span;
        }
    }

    /// Reports a `field` declared twice on a Script or shader node (all its declarations
    /// are read once the node closes). An error, unlike other repeats of a field: "Name
    /// shall be an identifier that is unique for this Script node" (29.4.1), and the same
    /// "for this shader node" (31, X3DProgrammableShaderObject).
    fn report_duplicate_declarations(&mut self, id: NodeId) {
        let mut first_spans: std::collections::HashMap<&str, Span> = Default::default();
        let mut duplicates = Vec::new();
        for decl in &self.draft.doc.nodes[id.index()].declared {
            let Some(&first) = first_spans.get(decl.name.text.as_str()) else {
                first_spans.insert(&decl.name.text, decl.name.span);
                continue;
            };
            let diagnostic = Diagnostic::new(
                &FIELD_DUPLICATE,
                decl.name.span,
                format!("field `{}` is declared twice on this node", decl.name.text),
            )
            .severity(Severity::Error)
            .node(id)
            .related(first, "first declared here");
            duplicates.push(diagnostic);
        }
        for diagnostic in duplicates {
            self.report(diagnostic);
        }
    }

    /// Records `DEF` on a node. In X3D a name already defined in this scope keeps its
    /// first node (an error); in VRML97 the later DEF takes the name over (a warning),
    /// since a USE there names the most recent DEF (14772-1 4.6.2).
    pub fn define(&mut self, id: NodeId, name: Named) {
        let key = (self.scope(), name.text.clone());
        if let Some(&first) = self.draft.doc.defs.get(&key) {
            let vrml97 = self.draft.doc.encoding == Encoding::Vrml97;
            let first_span = self.draft.doc.node(first).def_name.as_ref().map(|d| d.span);
            let mut diagnostic = if vrml97 {
                Diagnostic::new(
                    &DEF_DUPLICATE,
                    name.span,
                    format!(
                        "DEF name `{}` is already defined in this scope: VRML97 lets this DEF take it over for what follows, X3D does not",
                        name.text
                    ),
                )
                .severity(Severity::Warning)
            } else {
                Diagnostic::new(
                    &DEF_DUPLICATE,
                    name.span,
                    format!("DEF name `{}` is already defined in this scope", name.text),
                )
            }
            .node(id)
            .value(name.text.clone());
            if let Some(first_span) = first_span {
                diagnostic = diagnostic.related(first_span, "first defined here");
            }
            self.report(diagnostic);
            if vrml97 {
                self.draft.doc.defs.insert(key, id);
            }
        } else {
            self.draft.doc.defs.insert(key, id);
        }
        self.draft.doc.nodes[id.index()].def_name = Some(name);
    }

    /// Adds a `USE` of a DEF'd node under `parent`. `element_type` is the node type the
    /// document names at the USE site (XML element name; JSON object key), if any.
    pub fn use_node(
        &mut self,
        name: &Named,
        element_type: Option<&str>,
        site: Span,
        parent: Parent,
    ) -> Option<NodeId> {
        let Some(&target) = self.draft.doc.defs.get(&(self.scope(), name.text.clone())) else {
            let in_other_scope = self.draft.doc.defs.keys().any(|(_, n)| *n == name.text);
            let diagnostic = Diagnostic::new(
                &USE_UNDEFINED,
                name.span,
                format!("USE `{}` names no DEF defined before it", name.text),
            )
            .value(name.text.clone())
            .help_opt(in_other_scope.then(|| {
                "a node of that name is DEF'd in another scope (scene or ProtoBody) or after this USE"
                    .to_string()
            }));
            self.report(diagnostic);
            return None;
        };
        if self.open.contains(&target) {
            // A Script (or shader) field may hold its own Script or an ancestor: scripts
            // reach nodes through such fields, which the scene graph does not traverse
            // (19775-1 clause 29 Scripting; the VRML97 Annex C example
            // `field SFNode myself USE Example`).
            // The reference is left out of the model all the same, so it stays acyclic.
            if let Parent::Field { node, field, .. } = parent {
                if matches!(self.field_ref(node, field), FieldRef::Declared { .. }) {
                    return None;
                }
            }
            self.report(
                Diagnostic::new(
                    &USE_CYCLE,
                    name.span,
                    format!(
                        "USE `{}` stands inside the node it names: the scene graph would be cyclic",
                        name.text
                    ),
                )
                .node(target)
                .value(name.text.clone()),
            );
            return None;
        }
        if self.open.len() + 1 + self.draft.doc.node(target).height as usize > MAX_DEPTH {
            self.too_deep(name.span);
            return None;
        }
        let target_type = self.draft.doc.node(target).type_name().to_string();
        if let Some(element_type) = element_type {
            if element_type != target_type {
                self.report(
                    Diagnostic::new(
                        &USE_TYPE_MISMATCH,
                        name.span,
                        format!(
                            "`{element_type}` USE `{}` refers to a {target_type}",
                            name.text
                        ),
                    )
                    .node(target)
                    .value(name.text.clone()),
                );
            }
        }
        self.attach(
            parent,
            ChildRef {
                node: target,
                span: site,
                is_use: true,
            },
        )?;
        Some(target)
    }

    /// Puts a child reference into its parent and says where it went; None when the
    /// parent has no room for another field.
    fn attach(&mut self, parent: Parent, child: ChildRef) -> Option<Place> {
        let place = match parent {
            Parent::TopLevel => match self.scope() {
                Scope::Scene => {
                    self.draft.doc.scene.push(child);
                    Place::Scene
                }
                Scope::Proto(proto) => {
                    self.draft.doc.protos[proto].body.push(child);
                    Place::ProtoBody { proto }
                }
            },
            Parent::ProtoField { proto, field } => {
                let interface = &mut self.draft.doc.protos[proto].interface;
                let index = match interface.iter().rposition(|f| f.name.text == field) {
                    Some(index) => index,
                    None => return Some(Place::Scene),
                };
                let (value, _) = interface[index]
                    .value
                    .get_or_insert((Value::Nodes(Vec::new()), child.span));
                if !matches!(value, Value::Nodes(_)) {
                    *value = Value::Nodes(Vec::new());
                }
                if let Value::Nodes(children) = value {
                    children.push(child);
                }
                Place::ProtoField {
                    proto,
                    field: index as u32,
                }
            }
            Parent::Field {
                node,
                field,
                field_span,
                origin,
            } => {
                let entry = self.node_field_entry(node, field, field_span, origin, child.span)?;
                if let Value::Nodes(children) =
                    &mut self.draft.doc.nodes[node.index()].fields[entry].value
                {
                    children.push(child);
                }
                Place::Field {
                    parent: node,
                    entry: entry as u32,
                }
            }
        };
        Some(place)
    }

    /// The entry of a node field that children accumulate in, made on first use.
    fn node_field_entry(
        &mut self,
        node: NodeId,
        field: &str,
        field_span: Span,
        origin: Origin,
        first_child: Span,
    ) -> Option<usize> {
        let fields = &self.draft.doc.nodes[node.index()].fields;
        if let Some(i) = fields.iter().position(|e| {
            e.name() == field && matches!(e.value, Value::Nodes(_)) && e.origin == origin
        }) {
            return Some(i);
        }
        if !self.has_room_for_field(node, field_span) {
            return None;
        }
        let fields = &self.draft.doc.nodes[node.index()].fields;
        if let Some(first) = fields.iter().find(|e| e.name() == field) {
            let diagnostic = Diagnostic::new(
                &FIELD_DUPLICATE,
                field_span,
                format!("field `{field}` is given twice"),
            )
            .node(node)
            .related(first.name_span, "first given here");
            self.report(diagnostic);
        }
        let field_ref = self.field_ref(node, field);
        let fields = &mut self.draft.doc.nodes[node.index()].fields;
        fields.push(FieldEntry {
            field: field_ref,
            name_span: field_span,
            span: first_child,
            origin,
            value: Value::Nodes(Vec::new()),
        });
        Some(fields.len() - 1)
    }

    /// Sets a field from a value the reader parsed. A field already set keeps its first
    /// value and the repeat is reported. A value of more than [`MAX_FIELD_VALUES`] values
    /// is not kept (the field stays, unparsed, so that the rules skip it).
    pub fn add_field(&mut self, node: NodeId, mut entry: FieldEntry) {
        if entry.value.len() > MAX_FIELD_VALUES {
            let message = format!(
                "`{}` holds {} values, more than {MAX_FIELD_VALUES}; it is not read",
                entry.name(),
                entry.value.len()
            );
            self.exceeded(Limit::FieldValues, entry.span, message);
            entry.value = Value::Unparsed(String::new());
        }
        if !self.has_room_for_field(node, entry.name_span) {
            return;
        }
        let fields = &self.draft.doc.nodes[node.index()].fields;
        if let Some(first) = fields.iter().find(|f| f.name() == entry.name()) {
            let diagnostic = Diagnostic::new(
                &FIELD_DUPLICATE,
                entry.name_span,
                format!(
                    "field `{}` is given twice; the first value is kept",
                    entry.name()
                ),
            )
            .node(node)
            .related(first.name_span, "first given here");
            self.report(diagnostic);
            return;
        }
        self.draft.doc.nodes[node.index()].fields.push(entry);
    }

    /// Starts a ProtoDeclare or ExternProtoDeclare in the current scope; its index names it.
    pub fn declare_proto(&mut self, mut proto: ProtoDecl) -> usize {
        proto.scope = self.scope();
        self.draft.doc.protos.push(proto);
        self.draft.doc.protos.len() - 1
    }

    /// Opens a ProtoBody: a DEF name scope of its own.
    pub fn begin_proto_body(&mut self, proto: usize) {
        self.scopes.push(Scope::Proto(proto));
    }

    pub fn end_proto_body(&mut self) {
        if self.scopes.len() > 1 {
            self.scopes.pop();
        }
    }

    /// Adds a ROUTE in the current scope.
    pub fn add_route(&mut self, mut route: Route) {
        route.scope = self.scope();
        if self.draft.doc.encoding == Encoding::Vrml97 {
            let bound = |name: &Named| {
                self.draft
                    .doc
                    .defs
                    .get(&(route.scope, name.text.clone()))
                    .copied()
            };
            route.vrml97_ends = Some([bound(&route.from_node), bound(&route.to_node)]);
        }
        self.draft.doc.routes.push(route);
    }

    /// Adds an IMPORT statement in the current scope.
    pub fn add_import(&mut self, mut import: Import) {
        import.scope = self.scope();
        self.draft.doc.imports.push(import);
    }

    /// Adds an EXPORT statement in the current scope.
    pub fn add_export(&mut self, mut export: Export) {
        export.scope = self.scope();
        self.draft.doc.exports.push(export);
    }

    /// The nodes still open, innermost last (for readers that stop early on bad input).
    pub fn open_nodes(&self) -> &[NodeId] {
        &self.open
    }

    /// The document, with its prototype instances instantiated, and the findings.
    pub fn finish(mut self) -> (Document, Vec<Diagnostic>) {
        let none = super::instantiate::ExternalPrototypes::default();
        super::instantiate::instantiate_all(&mut self.draft, &none);
        self.draft.into_parts()
    }
}

/// For tests that build documents by hand, node by node, as a reader would.
#[cfg(test)]
pub(crate) mod testing {
    use super::*;

    /// The top level, or `(node, field)`: a node field filled by child elements.
    pub fn parent_of(parent: Option<(NodeId, &str)>) -> Parent<'_> {
        match parent {
            None => Parent::TopLevel,
            Some((node, field)) => Parent::Field {
                node,
                field,
                field_span: Span::default(),
                origin: Origin::Children,
            },
        }
    }

    pub fn named(text: &str) -> Named {
        Named {
            text: text.to_string(),
            span: Span::default(),
        }
    }
}
