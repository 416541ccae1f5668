//! Instantiates the ProtoInstances of the document's ProtoDeclares (19775-1 4.4.4), so
//! that the rules and the renderer see the nodes a browser builds, with the values each
//! instance passes through `IS`.
//!
//! Not a deep copy per instance: an instantiation copies only the body nodes that take a
//! value through IS and the nodes above them in the body (path copying); every other body
//! node is shared with the body as written, as `USE` shares it. Instances whose values
//! are identical (same prototype, same fieldValues or defaults) share one instantiation,
//! so 100,000 identical instances cost one copy. A body ProtoInstance that a copy holds is
//! instantiated in turn with the values the copy gives it. The copies are appended to the
//! arena after the written nodes (`Document::copies` counts them), each with [`Copied`] naming the
//! body node it copies and the instance it was made for; their top-level nodes are placed
//! in the instance ([`Place::Instance`]), so a finding in one has the instance in its path.
//! Copies keep the body node's spans and DEF names: each instance is its own DEF name scope.
//!
//! External prototypes (4.4.5) are instantiated when their resolution is handed in
//! ([`ExternalPrototypes`], [`instantiate_with`]): the model reads no file; the caller
//! (the deep level, the renderer) resolves the urls and hands over the library documents.
//! A body in another file cannot be shared with this document, so it is copied whole; its
//! copies take the instance's spans (a place in another file is never shown against this
//! one's text) and say where they are written ([`LibraryPlace`]).
//!
//! Limits ([`MAX_INSTANCE_NODES`] or [`INSTANCE_AMPLIFICATION`] copies per written node,
//! [`MAX_INSTANCE_VALUES`], [`MAX_PROTO_NESTING`]) stop a
//! prototype "billion laughs" with `LIMIT_EXCEEDED`; past one, no more copies are made and
//! the remaining nodes are checked as written.

use std::collections::HashMap;
use std::path::PathBuf;

use super::draft::{Draft, Limit};
use super::*;
use crate::diagnostic::Diagnostic;
use crate::limits::{
    INSTANCE_AMPLIFICATION, MAX_INSTANCE_NODES, MAX_INSTANCE_VALUES, MAX_PROTO_NESTING,
};

/// A prototype library file, as the caller read it.
pub struct LibraryFile<'a> {
    pub doc: &'a Document,
    /// The text its spans are offsets into (for the line numbers of notes).
    pub text: &'a [u8],
    /// Its name in messages (a path relative to the checked document's directory).
    pub name: String,
    /// The path it was read from: its body's relative urls are relative to it.
    pub path: PathBuf,
}

/// What the ExternProtoDeclares of a document and of the library files it reaches resolve
/// to. Files are numbered: 0 is the document instantiated, `k ≥ 1` is `libraries[k - 1]`.
#[derive(Default)]
pub struct ExternalPrototypes<'a> {
    pub libraries: Vec<LibraryFile<'a>>,
    /// Per file, per prototype: the top-level ProtoDeclare an ExternProtoDeclare resolves
    /// to, as (file, prototype index); None for one that does not resolve (and for
    /// ProtoDeclares).
    pub resolved: Vec<Vec<Option<(usize, usize)>>>,
}

impl ExternalPrototypes<'_> {
    fn resolve(&self, file: usize, proto: usize) -> Option<(usize, usize)> {
        self.resolved.get(file)?.get(proto).copied().flatten()
    }

    fn library(&self, file: usize) -> Option<&LibraryFile<'_>> {
        self.libraries.get(file.checked_sub(1)?)
    }
}

const TOO_MANY_COPIES: &str = "instantiating prototypes copies more than";
const NESTED_TOO_DEEP: &str = "prototype instances nest deeper than";

/// Whether `diagnostic` is a LIMIT_EXCEEDED instantiation reports (so that a caller that
/// instantiates again can drop the first one).
pub fn is_instantiation_limit(diagnostic: &Diagnostic) -> bool {
    diagnostic.rule.code == "LIMIT_EXCEEDED"
        && (diagnostic.message.starts_with(TOO_MANY_COPIES)
            || diagnostic.message.starts_with(NESTED_TOO_DEEP))
}

/// Instantiates the document's prototype instances again, this time with the external
/// prototypes `externals` resolves: the copies made when it was read are dropped first.
/// The findings are those of the limits.
pub fn instantiate_with(
    mut doc: Document,
    externals: &ExternalPrototypes,
) -> (Document, Vec<Diagnostic>) {
    let written = doc.written_nodes().len();
    doc.nodes.truncate(written);
    doc.copies = 0;
    doc.instantiations.clear();
    doc.library_bodies.clear();
    for node in &mut doc.nodes {
        node.instantiation = None;
    }
    let mut draft = Draft::of(doc);
    instantiate_all(&mut draft, externals);
    draft.into_parts()
}

/// Instantiates every ProtoInstance of a ProtoDeclare the document holds, and of an
/// ExternProtoDeclare `externals` resolves.
pub(super) fn instantiate_all(draft: &mut Draft, externals: &ExternalPrototypes) {
    let written = draft.doc().nodes.len();
    let doc = draft.doc();
    let mut instanced = vec![false; doc.protos.len()];
    for node in &doc.nodes {
        if let NodeKind::ProtoInstance { proto: Some(p), .. } = node.kind {
            instanced[p] = true;
            if let Some((0, q)) = externals.resolve(0, p) {
                if let Some(q) = instanced.get_mut(q) {
                    *q = true;
                }
            }
        }
    }
    if !instanced.iter().any(|&i| i) {
        return;
    }
    let mut state = State {
        externals,
        budget: MAX_INSTANCE_NODES.max(INSTANCE_AMPLIFICATION.saturating_mul(written)),
        needs: vec![None; written],
        memo: HashMap::new(),
        nodes: 0,
        values: 0,
        open: Vec::new(),
        stopped: false,
        lines: HashMap::new(),
        bodies: HashMap::new(),
    };
    for index in 0..written {
        let id = NodeId(index as u32);
        let node = draft.doc().node(id);
        if !matches!(node.kind, NodeKind::ProtoInstance { proto: Some(_), .. }) {
            continue;
        }
        // A body instance that takes values through IS is instantiated with each copy of
        // it that its own prototype's instances make, not as written.
        if let Scope::Proto(outer) = node.scope {
            if instanced[outer] && state.needs(draft.doc(), id) {
                continue;
            }
        }
        state.instantiate(draft, id, 0);
    }
    let doc = draft.doc_mut();
    doc.copies = doc.nodes.len() - written;
}

/// A prototype of one of the files: (file, index in its protos); file 0 is the document.
type ProtoKey = (usize, usize);

/// An instantiation's prototype and values, for sharing it.
type MemoKey = (ProtoKey, Vec<Option<String>>);

struct State<'e> {
    externals: &'e ExternalPrototypes<'e>,
    /// Nodes that may be copied: relative to the written nodes, at least
    /// [`MAX_INSTANCE_NODES`].
    budget: usize,
    /// Per written node: whether it, or a node below it, takes a value through IS.
    needs: Vec<Option<bool>>,
    /// (prototype, the values as a key) → instantiation.
    memo: HashMap<MemoKey, u32>,
    /// Nodes and field values copied so far.
    nodes: usize,
    values: usize,
    /// The prototypes being instantiated, outermost first.
    open: Vec<ProtoKey>,
    /// A limit was reached: nothing more is copied.
    stopped: bool,
    /// Per library file: the offsets of its line ends, once needed.
    lines: HashMap<usize, Vec<usize>>,
    /// Library prototype → its index in `Document::library_bodies`.
    bodies: HashMap<ProtoKey, u32>,
}

impl State<'_> {
    fn needs(&mut self, doc: &Document, id: NodeId) -> bool {
        let Some(&known) = self.needs.get(id.index()) else {
            return false;
        };
        if let Some(known) = known {
            return known;
        }
        let node = doc.node(id);
        let mut needs = !node.connects.is_empty();
        if !needs {
            let children: Vec<NodeId> = node
                .fields
                .iter()
                .filter_map(|f| f.value.as_nodes())
                .flatten()
                .map(|c| c.node)
                .collect();
            needs = children.into_iter().any(|c| self.needs(doc, c));
        }
        self.needs[id.index()] = Some(needs);
        needs
    }

    fn instantiate(&mut self, draft: &mut Draft, instance: NodeId, depth: usize) {
        let doc = draft.doc();
        let NodeKind::ProtoInstance { proto: Some(p), .. } = doc.node(instance).kind else {
            return;
        };
        let mut p = p;
        if doc.protos[p].external {
            match self.externals.resolve(0, p) {
                Some((0, q)) if doc.protos.get(q).is_some_and(|q| !q.external) => p = q,
                Some((file, q)) if file > 0 => {
                    return self.import(draft, instance, (file, q), Some(p), depth)
                }
                _ => return,
            }
        }
        // A prototype instantiated inside its own instantiation is a cycle (PROTO_CYCLE):
        // it builds nothing.
        if self.stopped || self.open.contains(&(0, p)) || self.too_deep(draft, instance, depth) {
            return;
        }
        let doc = draft.doc();
        let node = doc.node(instance);
        let proto = &doc.protos[p];
        let values: Vec<Option<Value>> = proto
            .interface
            .iter()
            .map(|decl| {
                let given = node.fields.iter().find(|f| {
                    f.name() == decl.name.text && matches!(f.field, FieldRef::Declared { .. })
                });
                given
                    .map(|f| f.value.clone())
                    .or_else(|| decl.value.as_ref().map(|(v, _)| v.clone()))
            })
            .collect();
        let key = (
            (0, p),
            values.iter().map(|v| v.as_ref().map(key_of)).collect(),
        );
        let body = proto.body.clone();
        if self.share(draft, instance, &key) {
            return;
        }
        self.open.push((0, p));
        let mut copies = HashMap::new();
        let mut roots = Vec::with_capacity(body.len());
        for root in body {
            let place = Place::Instance { instance };
            let copy = Copier {
                values: &values,
                proto: p,
                instance,
                depth,
            };
            roots.push(copy.child(self, draft, &mut copies, root, place));
        }
        self.open.pop();
        self.record(draft, instance, Some(p), roots, key);
    }

    /// Whether nesting at `depth` is past [`MAX_PROTO_NESTING`] (reported once).
    fn too_deep(&mut self, draft: &mut Draft, instance: NodeId, depth: usize) -> bool {
        if depth < MAX_PROTO_NESTING {
            return false;
        }
        let message = format!(
            "{NESTED_TOO_DEEP} {MAX_PROTO_NESTING} levels here; deeper ones are checked as written"
        );
        let span = draft.doc().node(instance).name_span;
        draft.exceeded(Limit::Instances, span, message);
        true
    }

    /// Shares the instantiation made with the same values, if there is one.
    fn share(&mut self, draft: &mut Draft, instance: NodeId, key: &MemoKey) -> bool {
        let Some(&shared) = self.memo.get(key) else {
            return false;
        };
        let doc = draft.doc_mut();
        doc.nodes[instance.index()].instantiation = Some(shared);
        let shared = &mut doc.instantiations[shared as usize];
        shared.count = shared.count.saturating_add(1);
        true
    }

    fn record(
        &mut self,
        draft: &mut Draft,
        instance: NodeId,
        proto: Option<usize>,
        roots: Vec<ChildRef>,
        key: MemoKey,
    ) {
        let doc = draft.doc_mut();
        let index = doc.instantiations.len() as u32;
        doc.instantiations.push(Instantiation {
            proto,
            roots,
            instance,
            count: 1,
        });
        doc.nodes[instance.index()].instantiation = Some(index);
        self.memo.insert(key, index);
    }

    /// Whether one more node of `cost` values may be copied; reports the limit when not.
    fn room_for(&mut self, draft: &mut Draft, instance: NodeId, cost: usize) -> bool {
        if self.stopped {
            return false;
        }
        if self.nodes >= self.budget || self.values + cost > MAX_INSTANCE_VALUES {
            self.stopped = true;
            let message = format!(
                "{TOO_MANY_COPIES} {} nodes or {MAX_INSTANCE_VALUES} values; the rest are checked as written",
                self.budget
            );
            let span = draft.doc().node(instance).name_span;
            draft.exceeded(Limit::Instances, span, message);
            return false;
        }
        self.nodes += 1;
        self.values += cost;
        true
    }

    /// Instantiates `instance` (a node of this document) from the body of prototype `key`
    /// of a library file. `proto` is the ExternProtoDeclare of this document it is an
    /// instance of (None for an instance inside a library body).
    fn import(
        &mut self,
        draft: &mut Draft,
        instance: NodeId,
        key: ProtoKey,
        proto: Option<usize>,
        depth: usize,
    ) {
        let externals = self.externals;
        let Some(decl) = externals
            .library(key.0)
            .and_then(|l| l.doc.protos.get(key.1))
        else {
            return;
        };
        if self.stopped || self.open.contains(&key) || self.too_deep(draft, instance, depth) {
            return;
        }
        // The instance's fieldValue, else the ProtoDeclare's default: an
        // ExternProtoDeclare's interface gives no initial values (4.4.5.2).
        let node = draft.doc().node(instance);
        let given: Vec<Option<Value>> = decl
            .interface
            .iter()
            .map(|f| {
                let entry = node.fields.iter().find(|e| {
                    e.name() == f.name.text && matches!(e.field, FieldRef::Declared { .. })
                });
                entry.map(|e| e.value.clone())
            })
            .collect();
        let memo_values = given
            .iter()
            .map(|v| Some(v.as_ref().map_or_else(String::new, |v| key_of(v) + "=")))
            .collect();
        let memo_key = (key, memo_values);
        if self.share(draft, instance, &memo_key) {
            return;
        }
        self.open.push(key);
        let mut copies = HashMap::new();
        let mut importer = Importer {
            file: key.0,
            proto: key.1,
            instance,
            depth,
            body: self.body(draft, key),
            values: Vec::new(),
        };
        // A default of node type is the library's nodes: copied too.
        let mut values = Vec::with_capacity(given.len());
        for (given, field) in given.into_iter().zip(&decl.interface) {
            let value = given.or_else(|| {
                let (default, _) = field.value.as_ref()?;
                let Some(nodes) = default.as_nodes() else {
                    return Some(default.clone());
                };
                let place = Place::Instance { instance };
                let copied = nodes
                    .iter()
                    .filter_map(|&c| importer.copy(self, draft, &mut copies, c, place))
                    .collect();
                Some(Value::Nodes(copied))
            });
            values.push(value);
        }
        importer.values = values;
        let roots = decl
            .body
            .iter()
            .filter_map(|&root| {
                let place = Place::Instance { instance };
                importer.copy(self, draft, &mut copies, root, place)
            })
            .collect();
        self.open.pop();
        self.record(draft, instance, proto, roots, memo_key);
    }

    /// `` `Name` in file ``, as notes name a library body: its index in
    /// `Document::library_bodies`.
    fn body(&mut self, draft: &mut Draft, key: ProtoKey) -> u32 {
        if let Some(&index) = self.bodies.get(&key) {
            return index;
        }
        let library = self.externals.library(key.0).expect("a library file");
        let label = format!(
            "`{}` in {}",
            library.doc.protos[key.1].name.text, library.name
        );
        let bodies = &mut draft.doc_mut().library_bodies;
        bodies.push(LibraryBody {
            label,
            path: library.path.clone(),
        });
        let index = (bodies.len() - 1) as u32;
        self.bodies.insert(key, index);
        index
    }

    /// The 1-based line of `span` in library `file`.
    fn line(&mut self, file: usize, span: Span) -> u32 {
        let externals = self.externals;
        let Some(library) = externals.library(file) else {
            return 0;
        };
        let ends = self.lines.entry(file).or_insert_with(|| {
            let text = library.text.iter().enumerate();
            text.filter(|&(_, &b)| b == b'\n').map(|(i, _)| i).collect()
        });
        (ends.partition_point(|&end| end < span.start as usize) + 1) as u32
    }
}

/// What identifies a value for sharing instantiations: its nodes by identity (the same
/// node passed twice builds the same), any other value by its contents.
fn key_of(value: &Value) -> String {
    match value {
        Value::Nodes(refs) => refs
            .iter()
            .map(|c| c.node.0.to_string())
            .collect::<Vec<_>>()
            .join(" "),
        other => format!("{other:?}"),
    }
}

/// The entry an `IS` gives a copy: `value` (of the prototype field's type `proto_type`)
/// for node field `field`. None when the node field takes no initial value (inputOnly,
/// outputOnly) or is one the document's version lacks (IS_FIELD_UNKNOWN's concern, not
/// one to report again in every instance).
fn passed_entry(
    doc: &Document,
    field: FieldRef,
    value: &Value,
    proto_type: Option<FieldType>,
    name_span: Span,
    span: Span,
) -> Option<FieldEntry> {
    let initializable = match &field {
        FieldRef::Schema { def, version } => {
            *version == doc.schema_version()
                && matches!(
                    def.access,
                    AccessType::InitializeOnly | AccessType::InputOutput
                )
        }
        FieldRef::Declared { .. } => true,
        FieldRef::Unknown { .. } => false,
    };
    if !initializable {
        return None;
    }
    // A value of another type (IS_TYPE_MISMATCH) is not one the node's rules can read.
    let value = if field.field_type().is_some() && field.field_type() == proto_type {
        value.clone()
    } else {
        Value::Unparsed(String::new())
    };
    Some(FieldEntry {
        field,
        name_span,
        span,
        origin: Origin::Is,
        value,
    })
}

/// Sets the entry an `IS` passes on a copy, in place of what the body wrote.
fn set_entry(node: &mut Node, entry: FieldEntry) {
    match node.fields.iter().position(|f| f.name() == entry.name()) {
        Some(at) => node.fields[at] = entry,
        None => node.fields.push(entry),
    }
}

/// Copies the body nodes of one instantiation.
struct Copier<'v> {
    /// Per interface field: the instance's value, or the default.
    values: &'v [Option<Value>],
    proto: usize,
    instance: NodeId,
    depth: usize,
}

impl Copier<'_> {
    /// The reference `child` (of the body) becomes in this instantiation: a copy when a
    /// node at or below it takes a value through IS, else the body's node itself.
    fn child(
        &self,
        state: &mut State,
        draft: &mut Draft,
        copies: &mut HashMap<NodeId, NodeId>,
        child: ChildRef,
        place: Place,
    ) -> ChildRef {
        let original = child.node;
        if let Some(&copy) = copies.get(&original) {
            return ChildRef {
                node: copy,
                ..child
            };
        }
        if !state.needs(draft.doc(), original) || state.stopped {
            return child;
        }
        let mut node = draft.doc().node(original).clone();
        let cost: usize = node.fields.iter().map(|f| f.value.len()).sum();
        if !state.room_for(draft, self.instance, cost) {
            return child;
        }
        let id = NodeId(draft.doc().nodes.len() as u32);
        copies.insert(original, id);
        node.place = place;
        node.copy_of = Some(Copied {
            original,
            instance: self.instance,
            library: None,
        });
        node.instantiation = None;
        for connect in std::mem::take(&mut node.connects) {
            if let Some(entry) = self.passed(draft, original, &connect) {
                set_entry(&mut node, entry);
            }
        }
        draft.doc_mut().nodes.push(node);
        let field_count = draft.doc().node(id).fields.len();
        for entry in 0..field_count {
            let field = &draft.doc().node(id).fields[entry];
            // A value passed in through IS is the instance's (or the interface's): shared.
            if field.origin == Origin::Is {
                continue;
            }
            let Some(children) = field.value.as_nodes().map(<[ChildRef]>::to_vec) else {
                continue;
            };
            let place = Place::Field {
                parent: id,
                entry: entry as u32,
            };
            let copied: Vec<ChildRef> = children
                .into_iter()
                .map(|c| self.child(state, draft, copies, c, place))
                .collect();
            draft.doc_mut().nodes[id.index()].fields[entry].value = Value::Nodes(copied);
        }
        if matches!(
            draft.doc().node(id).kind,
            NodeKind::ProtoInstance { proto: Some(_), .. }
        ) {
            state.instantiate(draft, id, self.depth + 1);
        }
        ChildRef { node: id, ..child }
    }

    /// The entry a `connect` gives the copy of `original`: the instance's value for the
    /// prototype field, typed as the node's field.
    fn passed(&self, draft: &Draft, original: NodeId, connect: &IsConnect) -> Option<FieldEntry> {
        let doc = draft.doc();
        let interface = &doc.protos[self.proto].interface;
        let at = interface
            .iter()
            .position(|f| f.name.text == connect.proto_field.text)?;
        let value = self.values[at].as_ref()?;
        let field = draft.field_ref(original, &connect.node_field.text);
        let (name_span, span) = (connect.node_field.span, connect.span);
        passed_entry(doc, field, value, interface[at].ty, name_span, span)
    }
}

/// Copies the body nodes of one instantiation of a library file's prototype: every node,
/// since none can be shared with this document.
struct Importer {
    file: usize,
    proto: usize,
    instance: NodeId,
    depth: usize,
    /// The body's index in `Document::library_bodies`.
    body: u32,
    /// Per interface field: the instance's value, or the default.
    values: Vec<Option<Value>>,
}

impl Importer {
    /// The copy of library node `child` under `place`; None past a limit.
    fn copy(
        &self,
        state: &mut State,
        draft: &mut Draft,
        copies: &mut HashMap<NodeId, NodeId>,
        child: ChildRef,
        place: Place,
    ) -> Option<ChildRef> {
        let at = draft.doc().node(self.instance).name_span;
        let copied = |node| ChildRef {
            node,
            span: at,
            is_use: child.is_use,
        };
        if let Some(&copy) = copies.get(&child.node) {
            return Some(copied(copy));
        }
        let externals = state.externals;
        let library = externals.library(self.file)?.doc;
        let original = library.nodes.get(child.node.index())?;
        let cost: usize = original.fields.iter().map(|f| f.value.len()).sum();
        if !state.room_for(draft, self.instance, cost) {
            return None;
        }
        let line = state.line(self.file, original.name_span);
        let mut node = original.clone();
        let id = NodeId(draft.doc().nodes.len() as u32);
        copies.insert(child.node, id);
        node.span = at;
        node.name_span = at;
        if let Some(def) = &mut node.def_name {
            def.span = at;
        }
        node.place = place;
        node.scope = draft.doc().node(self.instance).scope;
        node.source_code = None;
        node.instantiation = None;
        node.copy_of = Some(Copied {
            original: child.node,
            instance: self.instance,
            library: Some(LibraryPlace {
                body: self.body,
                line,
                version: library.schema_version(),
            }),
        });
        // An instance of a library prototype: instantiated below from the library, never
        // taken for an instance of this document's prototype of that index.
        let nested = match &mut node.kind {
            NodeKind::ProtoInstance { proto, .. } => proto.take(),
            _ => None,
        };
        for decl in &mut node.declared {
            decl.span = at;
            decl.name.span = at;
            match &mut decl.value {
                Some((Value::Nodes(_), _)) => decl.value = None,
                Some((_, span)) => *span = at,
                None => {}
            }
        }
        for entry in &mut node.fields {
            entry.span = at;
            entry.name_span = at;
            entry.origin = Origin::Is;
        }
        // The library's node types and fields, as this document's version has them (the
        // library's own version is the library's concern).
        if let NodeKind::Known { def, .. } = node.kind {
            node.kind = draft.node_kind(def.name);
        }
        let connects = std::mem::take(&mut node.connects);
        draft.doc_mut().nodes.push(node);
        let field_count = draft.doc().node(id).fields.len();
        for entry in 0..field_count {
            let field = &draft.doc().node(id).fields[entry];
            if let FieldRef::Schema { def, .. } = field.field {
                let field = draft.field_ref(id, def.name);
                draft.doc_mut().nodes[id.index()].fields[entry].field = field;
            }
            let field = &draft.doc().node(id).fields[entry];
            let Some(children) = field.value.as_nodes().map(<[ChildRef]>::to_vec) else {
                continue;
            };
            let place = Place::Field {
                parent: id,
                entry: entry as u32,
            };
            let children: Vec<ChildRef> = children
                .into_iter()
                .filter_map(|c| self.copy(state, draft, copies, c, place))
                .collect();
            draft.doc_mut().nodes[id.index()].fields[entry].value = Value::Nodes(children);
        }
        for connect in &connects {
            if let Some(entry) = self.passed(state, draft, id, nested, connect) {
                set_entry(&mut draft.doc_mut().nodes[id.index()], entry);
            }
        }
        if let Some(nested) = nested {
            let target = if library.protos.get(nested)?.external {
                externals.resolve(self.file, nested)
            } else {
                Some((self.file, nested))
            };
            // A url back to the checked document names it as a library file: never file 0.
            if let Some(target) = target.filter(|t| t.0 > 0) {
                state.import(draft, id, target, None, self.depth + 1);
            }
        }
        Some(copied(id))
    }

    /// The entry a `connect` of the library body gives the copy `id`: the instance's value
    /// for the prototype field, typed as the node's field. `nested` is the library
    /// prototype the copy is an instance of, if it is one.
    fn passed(
        &self,
        state: &State,
        draft: &Draft,
        id: NodeId,
        nested: Option<usize>,
        connect: &IsConnect,
    ) -> Option<FieldEntry> {
        let library = state.externals.library(self.file)?.doc;
        let interface = &library.protos.get(self.proto)?.interface;
        let at = interface
            .iter()
            .position(|f| f.name.text == connect.proto_field.text)?;
        let value = self.values.get(at)?.as_ref()?;
        let name = &connect.node_field.text;
        let field = match nested {
            Some(nested) => {
                let declared = library.protos.get(nested)?.interface.iter();
                FieldRef::Declared {
                    name: name.clone(),
                    ty: declared
                        .clone()
                        .find(|f| &f.name.text == name)
                        .and_then(|f| f.ty),
                }
            }
            None => draft.field_ref(id, name),
        };
        let span = draft.doc().node(self.instance).name_span;
        passed_entry(draft.doc(), field, value, interface[at].ty, span, span)
    }
}

#[cfg(test)]
mod tests {
    use crate::model::{Document, NodeId, NodeKind, Place};
    use crate::parse;

    fn doc(scene: &str) -> Document {
        let source = format!(
            "<X3D profile='Immersive' version='4.0'><Scene>
            <ProtoDeclare name='Ball'>
              <ProtoInterface>
                <field name='s' type='SFFloat' accessType='inputOutput' value='0.2'/>
              </ProtoInterface>
              <ProtoBody>
                <Shape>
                  <Appearance><Material><IS><connect nodeField='shininess' protoField='s'/></IS></Material></Appearance>
                  <Box/>
                </Shape>
              </ProtoBody>
            </ProtoDeclare>{scene}</Scene></X3D>"
        );
        parse::read(source.as_bytes()).document.unwrap()
    }

    fn instances(doc: &Document) -> Vec<NodeId> {
        doc.node_ids()
            .filter(|&id| matches!(doc.node(id).kind, NodeKind::ProtoInstance { .. }))
            .collect()
    }

    #[test]
    fn copies_the_path_to_connected_fields_and_shares_the_rest() {
        let doc =
            doc("<ProtoInstance name='Ball'><fieldValue name='s' value='0.7'/></ProtoInstance>");
        // Shape, Appearance and Material are copied; the Box is the body's own.
        assert_eq!(doc.copies, 3);
        let instance = instances(&doc)[0];
        let shape = doc.built(instance).unwrap();
        assert!(shape.index() >= doc.written_nodes().len());
        assert_eq!(doc.node(shape).place, Place::Instance { instance });
        let material = doc.child_of(doc.child_of(shape, "appearance").unwrap(), "material");
        let material = material.unwrap();
        assert_eq!(doc.f32_of(material, "shininess"), Some(0.7));
        assert!(doc.node(material).connects.is_empty());
        let body_shape = doc.node(shape).copy_of.unwrap().original;
        assert_eq!(
            doc.child_of(shape, "geometry"),
            doc.child_of(body_shape, "geometry")
        );
    }

    #[test]
    fn identical_instances_share_one_instantiation() {
        let same = "<ProtoInstance name='Ball'><fieldValue name='s' value='0.5'/></ProtoInstance>";
        let doc = doc(&format!(
            "{}<ProtoInstance name='Ball'/><ProtoInstance name='Ball'><fieldValue name='s' value='0.2'/></ProtoInstance>",
            same.repeat(100)
        ));
        // 0.5 a hundred times; the default and an explicit 0.2 are two more values.
        assert_eq!(doc.instantiations.len(), 2);
        assert_eq!(doc.instantiations[0].count, 100);
        assert_eq!(doc.instantiations[1].count, 2);
        assert_eq!(doc.copies, 6);
    }

    #[test]
    fn instances_count_what_prototype_instances_build() {
        // P_k's body is a Group of ten P_(k-1); nine levels over one Box make 10^9
        // Boxes, built from one shared instantiation per level.
        let mut scene = String::from(
            "<ProtoDeclare name='P0'><ProtoBody><Shape><Box/></Shape></ProtoBody></ProtoDeclare>",
        );
        for k in 1..10 {
            let body = format!("<ProtoInstance name='P{}'/>", k - 1).repeat(10);
            scene += &format!(
                "<ProtoDeclare name='P{k}'><ProtoBody><Group>{body}</Group></ProtoBody></ProtoDeclare>"
            );
        }
        scene += "<ProtoInstance name='P9'/>";
        let source = format!("<X3D profile='Immersive' version='4.0'><Scene>{scene}</Scene></X3D>");
        let doc = parse::read(source.as_bytes()).document.unwrap();
        // Per level k ≥ 1 a Group; below each P0 a Shape and a Box.
        let groups: u64 = (0..9).map(|k| 10u64.pow(k)).sum();
        assert_eq!(doc.instances(), groups + 2 * 10u64.pow(9));
    }

    #[test]
    fn a_prototype_billion_laughs_stops_at_the_limit() {
        // P_k's body holds ten instances of P_(k-1), each setting its own field k and
        // passing the others on: 10^7 distinct instantiations of P0.
        let n = 8;
        let fields: String = (0..n)
            .map(|i| {
                format!("<field name='f{i}' type='SFFloat' accessType='initializeOnly' value='0'/>")
            })
            .collect();
        let mut scene = format!(
            "<ProtoDeclare name='P0'><ProtoInterface>{fields}</ProtoInterface><ProtoBody><Material><IS><connect nodeField='shininess' protoField='f0'/></IS></Material></ProtoBody></ProtoDeclare>"
        );
        for k in 1..n {
            let connects: String = (0..n)
                .filter(|&i| i != k)
                .map(|i| format!("<connect nodeField='f{i}' protoField='f{i}'/>"))
                .collect();
            let body: String = (0..10)
                .map(|j| format!("<ProtoInstance name='P{}'><fieldValue name='f{k}' value='0.{j}'/><IS>{connects}</IS></ProtoInstance>", k - 1))
                .collect();
            scene += &format!("<ProtoDeclare name='P{k}'><ProtoInterface>{fields}</ProtoInterface><ProtoBody><Group>{body}</Group></ProtoBody></ProtoDeclare>");
        }
        scene += &format!("<ProtoInstance name='P{}'/>", n - 1);
        let source = format!("<X3D profile='Immersive' version='4.0'><Scene>{scene}</Scene></X3D>");
        let parsed = parse::read(source.as_bytes());
        assert!(parsed.document.unwrap().copies <= crate::limits::MAX_INSTANCE_NODES);
        assert!(parsed
            .diagnostics
            .iter()
            .any(|d| d.code() == "LIMIT_EXCEEDED" && d.message.contains("instantiating")));
    }
}
