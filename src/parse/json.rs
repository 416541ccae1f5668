//! The JSON encoding (ISO/IEC 19776-5) read into the same scene model as the XML reader.
//!
//! The input is scanned once by [`tree`] into a flat tree with the span of every key and
//! value (the scalars inside arrays, nearly all of a large scene, are read back from the
//! text rather than kept), then walked with an explicit stack (no recursion: nesting is
//! bounded only by the scanner's depth cap) while driving the [`Builder`] exactly as the
//! XML reader does, so that both encodings of one scene give equal documents.
//!
//! The shapes read (as the Web3D X3dToJson stylesheet writes them):
//! - `{ "X3D": { "@version", "@profile", "head": { "component": […], "meta": […],
//!   "unit": […] }, "Scene": { "-children": […] } } }`;
//! - a node is an object with one member named after its type, whose value holds its
//!   fields: `@name` members are field values, `-name` members node fields (one node
//!   object for SFNode, an array of them for MFNode; the key *is* the field, so no
//!   containerField is needed and `@containerField` is ignored), `@DEF`, `@USE`, `IS` with
//!   `connect` arrays, `field` declarations (Script, shaders), `fieldValue` (ProtoInstance),
//!   `#sourceCode` (a string or an array of lines) and `#comment`;
//! - statements in the same arrays as nodes: `ROUTE`, `ProtoDeclare` (`ProtoInterface`
//!   with `field` arrays, `ProtoBody` with `-children`), `ExternProtoDeclare`, `IMPORT`,
//!   `EXPORT`, `#comment`.
//!
//! A node object's `@` members are read before its other members, as an XML element's
//! attributes come before its children, whatever the member order.
//!
//! Variants real exporters write, read as the XML reader reads their XML counterparts:
//! `#sourceText` (an older name of `#sourceCode`), `IS` inside a `fieldValue` (connects
//! the ProtoInstance), a lone string for an MFString (a list of one). Duplicate keys are
//! kept by the scanner and reported (FIELD_DUPLICATE); values that do not fit their
//! field's type are reported (FIELD_VALUE_SYNTAX) and kept unparsed.

#[path = "json_tree.rs"]
pub mod tree;
#[path = "json_value.rs"]
pub mod value;

use std::borrow::Cow;

use tree::{Elements, Kind, Members, Tree, ValueRef};

use super::behind::{self, Pass, Progress};
use super::rules::{FIELD_VALUE_SYNTAX, JSON_MALFORMED, ROOT_NOT_X3D, USE_WITH_FIELDS};
use super::Parsed;
use crate::diagnostic::Diagnostic;
use crate::limits::MAX_FIELDS_PER_NODE;
use crate::model::builder::Parent;
use crate::model::draft::Limit;
use crate::model::rules::FIELD_DUPLICATE;
use crate::model::*;
use crate::parse::KeepValues;
use crate::schema::{AccessType, FieldType, NodeDef, Scalar, Version};

/// Reads an X3D JSON document.
pub fn read(source: &[u8]) -> Parsed {
    read_with(source, KeepValues::All, &())
}

/// Reads an X3D JSON document, keeping numeric MF values whole or as summaries, telling
/// `progress` how far each of its passes (UTF-8 check, scan, walk) has got.
pub fn read_with(source: &[u8], keep: KeepValues, progress: &dyn Progress) -> Parsed {
    let failed = |diagnostic: Diagnostic| Parsed {
        encoding: Some(Encoding::Json),
        document: None,
        diagnostics: vec![diagnostic],
    };
    if source.len() > MAX_INPUT_BYTES {
        return failed(malformed(0, 0, "the input is larger than 4 GiB"));
    }
    let text = match behind::utf8(source, progress) {
        Ok(text) => text,
        Err(error) => {
            let at = error.valid_up_to;
            let len = error.error_len.unwrap_or(source.len() - at);
            return failed(malformed(
                at,
                len,
                &format!("invalid UTF-8 at byte {at}: JSON text is UTF-8"),
            ));
        }
    };
    // Arrays of plain numbers are checked as their numbers are read; when one is not JSON
    // (or the scan stops at an error, which may come after one of them), the document is
    // scanned again whole, which reports the first error as it always has.
    if let Ok(tree) = tree::parse_deferring(text, progress) {
        let parsed = read_tree(&tree, source, keep, progress);
        if tree.deferred_are_json() {
            return parsed;
        }
    }
    match tree::parse_with_progress(text, progress) {
        Ok(tree) => read_tree(&tree, source, keep, progress),
        Err(error) => failed(malformed(error.at, error.len, &error.message)),
    }
}

/// The document of a scanned JSON text.
fn read_tree(tree: &Tree, source: &[u8], keep: KeepValues, progress: &dyn Progress) -> Parsed {
    let x3d = match root(tree) {
        Ok(x3d) => x3d,
        Err(diagnostic) => {
            return Parsed {
                encoding: Some(Encoding::Json),
                document: None,
                diagnostics: vec![diagnostic],
            }
        }
    };
    let mut reader = JsonReader {
        t: tree,
        pass: Pass::new(source, progress),
        builder: Builder::new(Encoding::Json),
        stack: Vec::new(),
        keep,
    };
    reader.x3d(x3d);
    reader.run();
    // As in the XML reader: the pieces' vectors are kept for this document only.
    crate::model::text::split::scratch::release();
    let (mut document, diagnostics) = reader.builder.finish();
    document.directives = super::directive::place_json(tree, progress);
    Parsed {
        encoding: Some(Encoding::Json),
        document: Some(document),
        diagnostics,
    }
}

fn malformed(at: usize, len: usize, message: &str) -> Diagnostic {
    Diagnostic::new(
        &JSON_MALFORMED,
        Span::new(at, at + len),
        format!("not valid JSON: {message}"),
    )
}

/// The top-level value in the [`Tree`].
const TOP: usize = 0;

/// The `"X3D"` member of the top-level object: its key and value.
#[allow(clippy::result_large_err)]
fn root(t: &Tree) -> Result<(usize, usize), Diagnostic> {
    let top = TOP;
    let not_x3d = |message: String| {
        Err(Diagnostic::new(
            &ROOT_NOT_X3D,
            span(t.full_span(top)),
            message,
        ))
    };
    if t.kind(top) != Kind::Object {
        return not_x3d(format!(
            "the top-level JSON value is {}, not an object with an `X3D` member",
            value::describe(t, top)
        ));
    }
    let Some((key, value)) = t.get(top, "X3D") else {
        let keys: Vec<String> = t
            .members(top)
            .take(3)
            .map(|(k, _)| format!("`{}`", t.str(k)))
            .collect();
        let found = if keys.is_empty() {
            "no member".to_string()
        } else {
            keys.join(", ")
        };
        return not_x3d(format!(
            "the top-level object has no `X3D` member (found {found})"
        ));
    };
    if t.kind(value) != Kind::Object {
        return Err(Diagnostic::new(
            &ROOT_NOT_X3D,
            span(t.full_span(value)),
            format!(
                "`X3D` must be an object, found {}",
                value::describe(t, value)
            ),
        ));
    }
    Ok((key, value))
}

fn span((start, end): (usize, usize)) -> Span {
    Span::new(start, end)
}

/// Where nodes read in a context go.
#[derive(Clone)]
enum Ctx<'s> {
    /// The Scene or the open ProtoBody (the builder knows which by its scope).
    TopLevel,
    /// A node field of a node: `-name`, a `field` declaration's or a `fieldValue`'s nodes.
    Field {
        node: NodeId,
        field: Cow<'s, str>,
        field_span: Span,
        origin: Origin,
    },
    /// The initial value of a ProtoInterface field.
    ProtoField { proto: usize, field: Cow<'s, str> },
}

impl<'s> Ctx<'s> {
    fn parent(&self) -> Parent<'_> {
        match self {
            Ctx::TopLevel => Parent::TopLevel,
            Ctx::Field {
                node,
                field,
                field_span,
                origin,
            } => Parent::Field {
                node: *node,
                field,
                field_span: *field_span,
                origin: *origin,
            },
            Ctx::ProtoField { proto, field } => Parent::ProtoField {
                proto: *proto,
                field,
            },
        }
    }

    /// How the place is called in messages.
    fn describe(&self) -> String {
        match self {
            Ctx::TopLevel => "`-children`".to_string(),
            Ctx::Field {
                field,
                origin: Origin::Member,
                ..
            } => format!("`-{field}`"),
            Ctx::Field { field, .. } | Ctx::ProtoField { field, .. } => {
                format!("the nodes of `{field}`")
            }
        }
    }
}

#[derive(Copy, Clone)]
enum DeclOwner {
    Node(NodeId),
    Proto(usize),
}

/// What the members of an object on the walk's stack are and what to do with them.
#[derive(Clone)]
enum ObjectTask<'s> {
    /// Members of one statement object: nodes, ROUTE, protos, comments.
    Statements(Ctx<'s>),
    /// A node object's members other than its fields (`-name`, `field`, `IS`, …); the
    /// node is closed when they are done.
    Node { id: NodeId, span: Span },
    /// Members of a ProtoDeclare or ExternProtoDeclare.
    Proto { proto: usize, external: bool },
    /// Members of a ProtoInterface.
    ProtoInterface { proto: usize },
    /// Members of a ProtoBody; its scope is closed when they are done.
    ProtoBody,
}

/// What the elements of an array on the walk's stack are and what to do with them.
#[derive(Clone)]
enum ArrayTask<'s> {
    /// Elements of an array of statement objects (`-children`, `-name`, …).
    List(Ctx<'s>),
    /// Elements of a `field` array.
    Decls(DeclOwner),
    /// Elements of a `fieldValue` array.
    FieldValues(NodeId),
}

/// An object or array of the walk, with the members or elements still to read.
enum Frame<'t, 's> {
    Object(ObjectTask<'s>, Members<'t, 's>),
    Array(ArrayTask<'s>, Elements<'t, 's>),
}

struct JsonReader<'t, 's> {
    t: &'t Tree<'s>,
    pass: Pass<'t>,
    builder: Builder,
    stack: Vec<Frame<'t, 's>>,
    /// Whether numeric MF values of schema fields are kept or summarized.
    keep: KeepValues,
}

/// Node object members that are not node fields: read by the reader itself, so their
/// repeats are reported here (repeated fields are reported by the builder).
fn is_node_statement_key(key: &str) -> bool {
    matches!(
        key,
        "@DEF" | "@USE" | "@containerField" | "IS" | "field" | "fieldValue" | "#sourceCode"
    )
}

impl<'t, 's> JsonReader<'t, 's> {
    fn report(&mut self, diagnostic: Diagnostic) {
        self.builder.report(diagnostic);
    }

    fn syntax(&mut self, at: (usize, usize), message: String) {
        self.report(Diagnostic::new(&FIELD_VALUE_SYNTAX, span(at), message));
    }

    /// The span of a member: its key (with quotes) through its value.
    fn member_span(&self, key: usize, value: usize) -> Span {
        Span::new(self.t.full_span(key).0, self.t.full_span(value).1)
    }

    /// The span a value is reported at: a string's content (as an XML attribute value's),
    /// any other value's whole token.
    fn value_span(&self, value: usize) -> Span {
        if self.t.kind(value) == Kind::String {
            span(self.t.span(value))
        } else {
            span(self.t.full_span(value))
        }
    }

    fn push_object(&mut self, task: ObjectTask<'s>, object: usize) {
        self.stack.push(Frame::Object(task, self.t.members(object)));
    }

    fn push_array(&mut self, task: ArrayTask<'s>, array: usize) {
        self.stack.push(Frame::Array(task, self.t.elements(array)));
    }

    /// Pushes the nodes of a node-valued member: one node object, or an array of them.
    fn push_nodes(&mut self, ctx: Ctx<'s>, value: usize, what: &str) {
        match self.t.kind(value) {
            Kind::Object => {
                self.duplicate_keys(value, |_| true);
                self.push_object(ObjectTask::Statements(ctx), value);
            }
            Kind::Array => self.push_array(ArrayTask::List(ctx), value),
            _ => {
                let found = value::describe(self.t, value);
                self.syntax(
                    self.t.full_span(value),
                    format!(
                        "{what} takes a node object or an array of node objects, found {found}"
                    ),
                );
            }
        }
    }

    /// Reports the repeated keys of object `object` that `filter` selects.
    fn duplicate_keys(&mut self, object: usize, filter: impl Fn(&str) -> bool) {
        let t = self.t;
        let count = t.item(object).len as usize;
        if count < 2 {
            return;
        }
        let selected = |k: usize| {
            let name = t.str(k);
            (!name.starts_with("#comment") && filter(&name)).then_some(name)
        };
        // Small objects (nearly all) are compared pairwise, without allocating.
        let mut repeats: Vec<(usize, usize)> = Vec::new();
        if count <= 16 {
            for (j, (key, _)) in t.members(object).enumerate() {
                let Some(name) = selected(key) else { continue };
                let first = t
                    .members(object)
                    .take(j)
                    .map(|(k, _)| k)
                    .find(|&k| t.key_is(k, &name));
                if let Some(first) = first {
                    repeats.push((first, key));
                }
            }
        } else {
            let mut seen: std::collections::HashMap<Cow<'s, str>, usize> =
                std::collections::HashMap::new();
            for (key, _) in t.members(object) {
                let Some(name) = selected(key) else { continue };
                match seen.get(&name) {
                    Some(&first) => repeats.push((first, key)),
                    None => {
                        seen.insert(name, key);
                    }
                }
            }
        }
        for (first, key) in repeats {
            let name = t.str(key);
            self.report(
                Diagnostic::new(
                    &FIELD_DUPLICATE,
                    span(t.span(key)),
                    format!(
                        "`{name}` is given twice in one object; JSON parsers keep only one of them"
                    ),
                )
                .value(name.to_string())
                .related(span(t.span(first)), "first given here"),
            );
        }
    }

    /// A string member's text and place, or a report that it is not a string.
    fn string_member(&mut self, key: usize, value: usize) -> Option<Named> {
        if self.t.kind(value) == Kind::String {
            return Some(Named {
                text: self.t.str(value).into_owned(),
                span: span(self.t.span(value)),
            });
        }
        let found = value::describe(self.t, value);
        let key_name = self.t.str(key);
        self.syntax(
            self.t.full_span(value),
            format!("`{key_name}` takes a string, found {found}"),
        );
        None
    }

    /// The first member `name` of object `object`, as a string.
    fn named(&mut self, object: usize, name: &str) -> Option<Named> {
        let (key, value) = self.t.get(object, name)?;
        self.string_member(key, value)
    }

    // ----- the document -----

    fn x3d(&mut self, (key, x3d): (usize, usize)) {
        let t = self.t;
        self.builder.doc_mut().root_span = self.member_span(key, x3d);
        // A second top-level `X3D` (the first is read) is lost as a repeated Scene is.
        self.duplicate_keys(TOP, |_| true);
        self.duplicate_keys(x3d, |_| true);
        // Version and profile first: node and field lookup depend on the version.
        for (key, value) in t.members(x3d) {
            let text = || match t.kind(value) {
                Kind::String => Some(Named {
                    text: t.str(value).into_owned(),
                    span: span(t.span(value)),
                }),
                Kind::Number => Some(Named {
                    text: t.raw(value).to_string(),
                    span: span(t.span(value)),
                }),
                _ => None,
            };
            if t.key_is(key, "@version") && self.builder.doc().version_text.is_none() {
                match text() {
                    Some(named) => {
                        let doc = self.builder.doc_mut();
                        doc.version = Version::parse(named.text.trim());
                        doc.version_text = Some(named);
                    }
                    None => {
                        self.string_member(key, value);
                    }
                }
            } else if t.key_is(key, "@profile") && self.builder.doc().profile.is_none() {
                match text() {
                    Some(named) => self.builder.doc_mut().profile = Some(named),
                    None => {
                        self.string_member(key, value);
                    }
                }
            }
        }
        if let Some((_, location)) = t.get(x3d, "@xsd:noNamespaceSchemaLocation") {
            if t.kind(location) == Kind::String {
                let hint = VersionHint::find(&t.str(location), "schema location");
                self.builder.doc_mut().version_hint = hint;
            }
        }
        self.builder.doc_mut().apply_version_hint();
        for (key, value) in t.members(x3d) {
            if t.key_is(key, "head") && t.kind(value) == Kind::Object {
                self.head(value);
            }
        }
        self.header_content(x3d, HeaderPart::Root);
        // The Scene last, on the stack; a repeated Scene is reported and read too.
        let scenes: Vec<(usize, usize)> = t
            .members(x3d)
            .filter(|&(k, _)| t.key_is(k, "Scene"))
            .collect();
        for &(_, scene) in scenes.iter().rev() {
            if t.kind(scene) != Kind::Object {
                let found = value::describe(t, scene);
                self.syntax(
                    t.full_span(scene),
                    format!("`Scene` must be an object, found {found}"),
                );
                continue;
            }
            self.duplicate_keys(scene, |_| true);
            if let Some((_, children)) = t.get(scene, "-children") {
                self.push_nodes(Ctx::TopLevel, children, "`-children`");
            }
        }
        if let Some(&(key, scene)) = scenes.first() {
            let scene_span = self.member_span(key, scene);
            self.builder.doc_mut().scene_span = Some(scene_span);
        }
    }

    /// Records the members of the X3D object or of head (`part`) that X3D gives no
    /// meaning there: besides `@` attributes (the head's own are checked), comments and
    /// a `-children` array of comments (the JSON schema's `-childStatements`), X3D holds
    /// `encoding`, `JSON schema`, head and Scene; head holds component, unit and meta.
    fn header_content(&mut self, object: usize, part: HeaderPart) {
        let t = self.t;
        if part == HeaderPart::Head {
            self.statement_attributes("head", object);
        }
        for (key, value) in t.members(object) {
            let name = t.str(key);
            let known = match part {
                HeaderPart::Root => &["encoding", "JSON schema", "head", "Scene"][..],
                HeaderPart::Head => &["component", "unit", "meta"][..],
            };
            if name.starts_with('@') || name.starts_with("#comment") || known.contains(&&*name) {
                continue;
            }
            if name == "-children" && t.kind(value) == Kind::Array {
                let statements = t.elements(value).filter_map(|e| t.object(e));
                for statement in statements {
                    for (key, _) in t.members(statement) {
                        if !t.str(key).starts_with("#comment") {
                            self.ignore(key, part);
                        }
                    }
                }
                continue;
            }
            self.ignore(key, part);
        }
    }

    fn ignore(&mut self, key: usize, part: HeaderPart) {
        let name = Named {
            text: self.t.str(key).into_owned(),
            span: span(self.t.span(key)),
        };
        record(
            &mut self.builder.doc_mut().ignored,
            IgnoredContent { name, part },
        );
    }

    /// Records the `@` members that head statement `statement` (its object) does not
    /// have, and the other members of component, unit and meta but comments and
    /// `-children`; past
    /// [`MAX_FIELDS_PER_NODE`] members the rest are not read.
    fn statement_attributes(&mut self, statement: &'static str, object: usize) {
        let t = self.t;
        let known = statement_attributes(statement).unwrap_or(&[]);
        for (count, (key, _)) in t.members(object).enumerate() {
            if count == MAX_FIELDS_PER_NODE {
                let message = format!(
                    "an object with more than {MAX_FIELDS_PER_NODE} members; the rest are not read"
                );
                self.builder
                    .exceeded(Limit::FieldsPerNode, span(t.span(key)), message);
                break;
            }
            let written = t.str(key);
            let attribute = written.strip_prefix('@');
            // head's other members are its content (`header_content`).
            let fine = match attribute {
                Some(name) => known.contains(&name),
                None => {
                    statement == "head" || written.starts_with("#comment") || written == "-children"
                }
            };
            if !fine {
                let name = Named {
                    text: attribute.unwrap_or(&written).to_string(),
                    span: span(t.span(key)),
                };
                record(
                    &mut self.builder.doc_mut().head.unknown_attributes,
                    UnknownAttribute { statement, name },
                );
            }
        }
    }

    fn head(&mut self, head: usize) {
        let t = self.t;
        self.duplicate_keys(head, |_| true);
        self.header_content(head, HeaderPart::Head);
        for (key, value) in t.members(head) {
            let objects: Vec<usize> = match t.kind(value) {
                Kind::Array => t.elements(value).filter_map(|e| t.object(e)).collect(),
                Kind::Object => vec![value],
                _ => Vec::new(),
            };
            if let Some(statement) = statement_name(&t.str(key)).filter(|&s| s != "head") {
                for &object in &objects {
                    self.statement_attributes(statement, object);
                }
            }
            match t.str(key).as_ref() {
                "component" => {
                    for object in objects {
                        self.component(object);
                    }
                }
                "unit" => {
                    for object in objects {
                        self.unit(object);
                    }
                }
                "meta" => self.builder.doc_mut().head.metas += objects.len(),
                _ => {}
            }
        }
    }

    fn unit(&mut self, object: usize) {
        let t = self.t;
        self.duplicate_keys(object, |_| true);
        let conversion_factor = t.get(object, "@conversionFactor").map(|(_, value)| {
            let factor = match self.convert(FieldType::SFDouble, value, "`@conversionFactor`", None)
            {
                Value::Doubles(v) => v.first().copied(),
                _ => None,
            };
            (factor, self.value_span(value))
        });
        let unit = UnitStatement {
            category: self.named(object, "@category"),
            name: self.named(object, "@name"),
            conversion_factor,
            span: span(t.full_span(object)),
        };
        self.builder.doc_mut().head.units.push(unit);
    }

    fn component(&mut self, object: usize) {
        let t = self.t;
        self.duplicate_keys(object, |_| true);
        let object_span = span(t.full_span(object));
        let name = self.named(object, "@name").unwrap_or(Named {
            text: String::new(),
            span: object_span,
        });
        let level = t.get(object, "@level").and_then(|(_, v)| {
            let text = match t.kind(v) {
                Kind::Number | Kind::String => t.raw(v).trim(),
                _ => return None,
            };
            text.parse::<i32>().ok().map(|l| (l, span(t.span(v))))
        });
        self.builder
            .doc_mut()
            .head
            .components
            .push(ComponentStatement {
                name,
                level,
                span: object_span,
            });
    }

    // ----- the walk -----

    fn run(&mut self) {
        while let Some(frame) = self.stack.last_mut() {
            match frame {
                Frame::Object(task, members) => match members.next() {
                    Some((key, value)) => {
                        let task = task.clone();
                        self.pass.reached(self.t.items[key].start as usize);
                        self.member(task, key, value);
                    }
                    None => {
                        if let Some(Frame::Object(task, _)) = self.stack.pop() {
                            self.finish(task);
                        }
                    }
                },
                Frame::Array(task, elements) => match elements.next() {
                    Some(element) => {
                        let task = task.clone();
                        self.pass.reached(self.t.item(element).start as usize);
                        self.element(task, element);
                    }
                    None => {
                        self.stack.pop();
                    }
                },
            }
        }
    }

    fn member(&mut self, task: ObjectTask<'s>, key: usize, value: usize) {
        match task {
            ObjectTask::Statements(ctx) => self.statement(&ctx, key, value),
            ObjectTask::Node { id, .. } => self.node_member(id, key, value),
            ObjectTask::Proto { proto, external } => self.proto_member(proto, external, key, value),
            ObjectTask::ProtoInterface { proto } => {
                if self.t.key_is(key, "field") {
                    self.push_decls(DeclOwner::Proto(proto), key, value);
                }
            }
            ObjectTask::ProtoBody => {
                if self.t.key_is(key, "-children") {
                    self.push_nodes(Ctx::TopLevel, value, "`-children`");
                }
            }
        }
    }

    fn element(&mut self, task: ArrayTask<'s>, element: ValueRef) {
        match task {
            ArrayTask::List(ctx) => self.list_element(ctx, element),
            ArrayTask::Decls(owner) => self.field_decl(owner, element),
            ArrayTask::FieldValues(node) => self.field_value(node, element),
        }
    }

    fn finish(&mut self, task: ObjectTask) {
        match task {
            ObjectTask::Node { id, span } => self.builder.end_node(id, span),
            ObjectTask::ProtoBody => self.builder.end_proto_body(),
            _ => {}
        }
    }

    /// An element of a node array: an object holding one node (or statement, or comment).
    fn list_element(&mut self, ctx: Ctx<'s>, element: ValueRef) {
        if let Some(object) = self.t.object(element) {
            self.duplicate_keys(object, |_| true);
            self.push_object(ObjectTask::Statements(ctx), object);
        } else {
            let found = value::describe(self.t, element);
            let place = ctx.describe();
            self.syntax(
                self.t.full_span(element),
                format!("{place} holds objects naming a node, like {{\"Transform\": {{…}}}}, found {found}"),
            );
        }
    }

    /// One member of a statement object: a node, ROUTE, a proto declaration, a comment.
    fn statement(&mut self, ctx: &Ctx<'s>, key: usize, value: usize) {
        let t = self.t;
        let name = t.str(key);
        match name.as_ref() {
            "ROUTE" => self.route(key, value),
            "ProtoDeclare" => self.proto_declare(key, value, false),
            "ExternProtoDeclare" => self.proto_declare(key, value, true),
            "IMPORT" | "EXPORT" => self.import_export(key, value),
            n if n.starts_with('#') => {}
            n if n.starts_with('@') || n.starts_with('-') => {
                let place = ctx.describe();
                self.syntax(
                    t.span(key),
                    format!("`{n}` is a field, not a node: {place} holds objects naming a node, like {{\"Transform\": {{…}}}}"),
                );
            }
            _ => self.node(ctx, key, value),
        }
    }

    fn route(&mut self, key: usize, value: usize) {
        let route_span = self.member_span(key, value);
        if self.t.kind(value) != Kind::Object {
            let found = value::describe(self.t, value);
            self.syntax(
                self.t.full_span(value),
                format!("`ROUTE` takes an object, found {found}"),
            );
            return;
        }
        self.duplicate_keys(value, |_| true);
        let mut get = |name: &str| {
            self.named(value, name).unwrap_or(Named {
                text: String::new(),
                span: route_span,
            })
        };
        let route = Route {
            from_node: get("@fromNode"),
            from_field: get("@fromField"),
            to_node: get("@toNode"),
            to_field: get("@toField"),
            span: route_span,
            scope: Scope::Scene,
            vrml97_ends: None,
        };
        self.builder.add_route(route);
    }

    /// `{"IMPORT": {"@inlineDEF", "@importedDEF", "@AS"}}` and `{"EXPORT": {"@localDEF",
    /// "@AS"}}` (19776-5).
    fn import_export(&mut self, key: usize, value: usize) {
        let span = self.member_span(key, value);
        let statement = self.t.str(key).into_owned();
        if self.t.kind(value) != Kind::Object {
            let found = value::describe(self.t, value);
            self.syntax(
                self.t.full_span(value),
                format!("`{statement}` takes an object, found {found}"),
            );
            return;
        }
        self.duplicate_keys(value, |_| true);
        let mut get = |name: &str| {
            self.named(value, name).unwrap_or(Named {
                text: String::new(),
                span,
            })
        };
        if statement == "IMPORT" {
            let inline_def = get("@inlineDEF");
            let imported_def = get("@importedDEF");
            let as_name = self.named(value, "@AS");
            self.builder.add_import(Import {
                inline_def,
                imported_def,
                as_name,
                span,
                scope: Scope::Scene,
            });
        } else {
            let local_def = get("@localDEF");
            let as_name = self.named(value, "@AS");
            self.builder.add_export(Export {
                local_def,
                as_name,
                span,
                scope: Scope::Scene,
            });
        }
    }

    fn proto_declare(&mut self, key: usize, value: usize, external: bool) {
        let t = self.t;
        let proto_span = self.member_span(key, value);
        if t.kind(value) != Kind::Object {
            let found = value::describe(t, value);
            let name = t.str(key);
            self.syntax(
                t.full_span(value),
                format!("`{name}` takes an object, found {found}"),
            );
            return;
        }
        self.duplicate_keys(value, |_| true);
        let name = self.named(value, "@name").unwrap_or(Named {
            text: String::new(),
            span: proto_span,
        });
        let url = t
            .get(value, "@url")
            .and_then(|(_, v)| value::convert(t, v, FieldType::MFString).ok())
            .and_then(|v| match v {
                Value::Strings(s) => Some(s),
                _ => None,
            })
            .unwrap_or_default();
        let proto = self.builder.declare_proto(ProtoDecl {
            name,
            span: proto_span,
            external,
            scope: Scope::Scene,
            interface: Vec::new(),
            body: Vec::new(),
            url,
        });
        self.push_object(ObjectTask::Proto { proto, external }, value);
    }

    fn proto_member(&mut self, proto: usize, external: bool, key: usize, value: usize) {
        let t = self.t;
        let name = t.str(key);
        match (name.as_ref(), external) {
            ("ProtoInterface", false) if t.kind(value) == Kind::Object => {
                self.duplicate_keys(value, |_| true);
                self.push_object(ObjectTask::ProtoInterface { proto }, value);
            }
            ("ProtoBody", false) if t.kind(value) == Kind::Object => {
                self.duplicate_keys(value, |_| true);
                self.builder.begin_proto_body(proto);
                self.push_object(ObjectTask::ProtoBody, value);
            }
            ("field", true) => self.push_decls(DeclOwner::Proto(proto), key, value),
            _ => {}
        }
    }

    fn push_decls(&mut self, owner: DeclOwner, key: usize, value: usize) {
        match self.t.kind(value) {
            Kind::Array => self.push_array(ArrayTask::Decls(owner), value),
            _ => {
                let found = value::describe(self.t, value);
                let name = self.t.str(key);
                self.syntax(
                    self.t.full_span(value),
                    format!("`{name}` takes an array of field declarations, found {found}"),
                );
            }
        }
    }

    // ----- nodes -----

    /// A node: `key` names its type, `value` holds its fields.
    fn node(&mut self, ctx: &Ctx<'s>, key: usize, value: usize) {
        let t = self.t;
        let name = t.str(key);
        let name_span = span(t.span(key));
        let node_span = self.member_span(key, value);
        if t.kind(value) != Kind::Object {
            let found = value::describe(t, value);
            self.syntax(
                t.full_span(value),
                format!("`{name}` takes an object of its fields (`{{}}` for none), found {found}"),
            );
            return;
        }
        let is_proto_instance = name == "ProtoInstance";
        let kind = if is_proto_instance {
            let proto_name = t
                .get(value, "@name")
                .filter(|&(_, v)| t.kind(v) == Kind::String)
                .map(|(_, v)| t.str(v).into_owned())
                .unwrap_or_default();
            NodeKind::ProtoInstance {
                proto: self.builder.find_proto(&proto_name),
                name: proto_name,
            }
        } else {
            self.builder.node_kind(&name)
        };
        let def = kind.def();
        let html_attribute = |k: &str| {
            k.strip_prefix('@')
                .is_some_and(|a| is_html_attribute(def, a))
        };
        self.duplicate_keys(value, |k| {
            !k.starts_with('@') || is_node_statement_key(k) || html_attribute(k)
        });

        if let Some((use_key, use_value)) = t.get(value, "@USE") {
            let Some(use_name) = self.string_member(use_key, use_value) else {
                return;
            };
            self.use_extras(value, use_key, &use_name, is_proto_instance, def);
            let element_type = (!is_proto_instance).then_some(name.as_ref());
            self.builder
                .use_node(&use_name, element_type, node_span, ctx.parent());
            return;
        }

        let Some(id) = self.builder.begin_node(kind, name_span, ctx.parent()) else {
            return;
        };
        let mut defined = false;
        for (k, v) in t.members(value) {
            let member = t.str(k);
            match member.as_ref() {
                "@DEF" if !defined => {
                    defined = true;
                    if let Some(def) = self.string_member(k, v) {
                        self.builder.define(id, def);
                    }
                }
                // A repeated `@DEF` is reported as a duplicate key; the first one names.
                "@DEF" | "@containerField" => {}
                m if html_attribute(m) => {}
                "@name" if is_proto_instance => {
                    self.string_member(k, v);
                }
                m if m.starts_with('@') => self.field_member(id, k, v, &m[1..]),
                _ => {}
            }
        }
        self.push_object(
            ObjectTask::Node {
                id,
                span: node_span,
            },
            value,
        );
    }

    /// Reports what a USE node object holds besides `@USE`, as the XML reader does: its
    /// fields in one diagnostic (`@containerField`, the HTML attributes `@class`, `@id`, `@style` and a
    /// ProtoInstance's `@name` allowed), then each node or statement it holds (comments
    /// allowed).
    fn use_extras(
        &mut self,
        object: usize,
        use_key: usize,
        use_name: &Named,
        is_proto_instance: bool,
        def: Option<&NodeDef>,
    ) {
        let t = self.t;
        let mut fields: Vec<(Cow<'s, str>, Span)> = Vec::new();
        let mut children: Vec<(Cow<'s, str>, Span)> = Vec::new();
        let nodes_of = |value: usize, out: &mut Vec<(Cow<'s, str>, Span)>| {
            let wrappers: Vec<ValueRef> = match t.kind(value) {
                Kind::Array => t.elements(value).collect(),
                _ => vec![value.into()],
            };
            for wrapper in wrappers {
                let Some(wrapper) = t.object(wrapper) else {
                    out.push((
                        Cow::Owned(value::describe(t, wrapper)),
                        span(t.full_span(wrapper)),
                    ));
                    continue;
                };
                for (k, _) in t.members(wrapper) {
                    let name = t.str(k);
                    if !name.starts_with('#') {
                        out.push((name, span(t.span(k))));
                    }
                }
            }
        };
        for (k, v) in t.members(object) {
            if k == use_key {
                continue;
            }
            let member = t.str(k);
            match member.as_ref() {
                "@containerField" => {}
                m if m
                    .strip_prefix('@')
                    .is_some_and(|a| is_html_attribute(def, a)) => {}
                "@name" if is_proto_instance => {}
                m if m.starts_with('@') => fields.push((member, span(t.span(k)))),
                m if m.starts_with('-') => nodes_of(v, &mut children),
                m if m.starts_with('#') => {}
                "field" | "fieldValue" if t.kind(v) == Kind::Array => {
                    for e in t.elements(v) {
                        children.push((member.clone(), span(t.full_span(e))));
                    }
                }
                _ => children.push((member, span(t.span(k)))),
            }
        }
        if let Some((_, first)) = fields.first() {
            let names: Vec<String> = fields.iter().map(|(n, _)| format!("`{n}`")).collect();
            self.report(
                Diagnostic::new(
                    &USE_WITH_FIELDS,
                    *first,
                    format!(
                        "USE `{}` also sets {}: a USE takes no fields",
                        use_name.text,
                        names.join(", ")
                    ),
                )
                .help("a USE is the DEF'd node itself; set the values on the DEF"),
            );
        }
        for (name, at) in children {
            self.report(Diagnostic::new(
                &USE_WITH_FIELDS,
                at,
                format!(
                    "USE `{}` holds `{name}`: a USE takes no children or fields",
                    use_name.text
                ),
            ));
        }
    }

    /// A node object's member other than its `@` fields, in document order.
    fn node_member(&mut self, id: NodeId, key: usize, value: usize) {
        let t = self.t;
        let member = t.str(key);
        match member.as_ref() {
            m if m.starts_with('@') => {}
            m if m.starts_with('-') && m.len() > 1 => {
                let field = match &member {
                    Cow::Borrowed(b) => Cow::Borrowed(&b[1..]),
                    Cow::Owned(o) => Cow::Owned(o[1..].to_string()),
                };
                let ctx = Ctx::Field {
                    node: id,
                    field,
                    field_span: span(t.span(key)),
                    origin: Origin::Member,
                };
                let what = format!("`{m}`");
                self.push_nodes(ctx, value, &what);
            }
            "field" => self.push_decls(DeclOwner::Node(id), key, value),
            "fieldValue" => match t.kind(value) {
                Kind::Array => self.push_array(ArrayTask::FieldValues(id), value),
                _ => {
                    let found = value::describe(t, value);
                    self.syntax(
                        t.full_span(value),
                        format!("`fieldValue` takes an array, found {found}"),
                    );
                }
            },
            "IS" => self.is(id, value),
            // `#sourceText` is an older exporter's name for it.
            "#sourceCode" | "#sourceText" => {
                let is_text = match t.kind(value) {
                    Kind::String => true,
                    Kind::Array => t.elements(value).all(|e| t.kind(e) == Kind::String),
                    _ => false,
                };
                if is_text {
                    let code = span(t.full_span(value));
                    self.builder.doc_mut().nodes[id.index()].source_code = Some(code);
                } else {
                    let found = value::describe(t, value);
                    self.syntax(
                        t.full_span(value),
                        format!("`{member}` takes a string or an array of strings, found {found}"),
                    );
                }
            }
            m if m.starts_with('#') => {}
            m => {
                let help = format!("`@{m}` for a value, `-{m}` for nodes");
                self.report(
                    Diagnostic::new(
                        &FIELD_VALUE_SYNTAX,
                        span(t.span(key)),
                        format!("`{m}` is not a member a node can have: field names start with `@` (values) or `-` (nodes)"),
                    )
                    .help(help),
                );
            }
        }
    }

    /// An `@name` member of a node: a field value.
    fn field_member(&mut self, id: NodeId, key: usize, value: usize, name: &str) {
        let field = self.builder.field_ref(id, name);
        let label = format!("`@{name}`");
        let parsed = match &field {
            FieldRef::Schema { def, .. }
                if self.keep == KeepValues::Summaries && Summary::applies_to(def.ty) =>
            {
                let t = self.t;
                let converted = value::convert_summary(t, value, self.builder.doc().node(id), def);
                self.converted_or_reported(converted, value, &label)
            }
            FieldRef::Schema { def, .. } => self.convert(def.ty, value, &label, Some(name)),
            FieldRef::Declared { ty: Some(ty), .. } => self.convert(*ty, value, &label, Some(name)),
            _ => Value::Unparsed(self.t.raw_full(value).to_string()),
        };
        let entry = FieldEntry {
            field,
            name_span: span(self.t.span(key)),
            span: self.value_span(value),
            origin: Origin::Member,
            value: parsed,
        };
        self.builder.add_field(id, entry);
    }

    /// Converts a value, reporting a syntax error at its place (then it is kept unparsed).
    /// `node_field` names the `-name` form for node-typed fields.
    fn convert(
        &mut self,
        ty: FieldType,
        value: usize,
        label: &str,
        node_field: Option<&str>,
    ) -> Value {
        let t = self.t;
        if ty.scalar() == Scalar::Node {
            let hint = match node_field {
                Some(name) => format!("give its nodes as `-{name}`"),
                None => "give its nodes in `-children`".to_string(),
            };
            self.syntax(
                t.full_span(value),
                format!("{label} is an {ty} field: {hint}, not as a value"),
            );
            return Value::Unparsed(t.raw_full(value).to_string());
        }
        let converted = value::convert(t, value, ty);
        self.converted_or_reported(converted, value, label)
    }

    /// The value converted, or the error reported at its place (and the text kept).
    fn converted_or_reported(
        &mut self,
        converted: Result<Value, value::ValueError>,
        value: usize,
        label: &str,
    ) -> Value {
        let t = self.t;
        match converted {
            Ok(parsed) => parsed,
            Err(error) => {
                let mut diagnostic = Diagnostic::new(
                    &FIELD_VALUE_SYNTAX,
                    span(error.span),
                    format!("{label}: {}", error.message),
                )
                .value(truncate(t.raw_full(value), 80))
                .help_opt(error.help);
                if let Some(index) = error.index {
                    diagnostic = diagnostic.index(index);
                }
                self.report(diagnostic);
                Value::Unparsed(t.raw_full(value).to_string())
            }
        }
    }

    /// A `field` declaration (ProtoInterface, ExternProtoDeclare, Script, shaders).
    fn field_decl(&mut self, owner: DeclOwner, element: ValueRef) {
        let t = self.t;
        let Some(object) = t.object(element) else {
            let found = value::describe(t, element);
            self.syntax(
                t.full_span(element),
                format!("a `field` declaration is an object, found {found}"),
            );
            return;
        };
        self.duplicate_keys(object, |_| true);
        let decl_span = span(t.full_span(object));
        let name = self.named(object, "@name").unwrap_or(Named {
            text: String::new(),
            span: decl_span,
        });
        let mut ty = None;
        if let Some((key, value)) = t.get(object, "@type") {
            if let Some(text) = self.string_member(key, value) {
                ty = FieldType::parse(text.text.trim());
                if ty.is_none() {
                    self.syntax(
                        t.span(value),
                        format!("`{}` is not an X3D field type", text.text),
                    );
                }
            }
        }
        let access = t
            .get(object, "@accessType")
            .filter(|&(_, v)| t.kind(v) == Kind::String)
            .and_then(|(_, v)| AccessType::parse(t.str(v).trim()));
        let value = t.get(object, "@value").map(|(_, v)| {
            let parsed = match ty {
                Some(ty) => {
                    self.convert(ty, v, &format!("`@value` of field `{}`", name.text), None)
                }
                None => Value::Unparsed(t.raw_full(v).to_string()),
            };
            (parsed, self.value_span(v))
        });
        let field = name.text.clone();
        let decl = FieldDecl {
            name,
            ty,
            access,
            span: decl_span,
            value,
        };
        match owner {
            DeclOwner::Node(node) => self.builder.doc_mut().nodes[node.index()]
                .declared
                .push(decl),
            DeclOwner::Proto(proto) => self.builder.doc_mut().protos[proto].interface.push(decl),
        }
        if let Some((key, children)) = t.get(object, "-children") {
            let ctx = match owner {
                DeclOwner::Node(node) => Ctx::Field {
                    node,
                    field: Cow::Owned(field),
                    field_span: span(t.span(key)),
                    origin: Origin::Member,
                },
                DeclOwner::Proto(proto) => Ctx::ProtoField {
                    proto,
                    field: Cow::Owned(field),
                },
            };
            self.push_nodes(ctx, children, "`-children`");
        }
    }

    /// A ProtoInstance's `fieldValue`: typed by the ProtoDeclare when it is known.
    fn field_value(&mut self, node: NodeId, element: ValueRef) {
        let t = self.t;
        let Some(object) = t.object(element) else {
            let found = value::describe(t, element);
            self.syntax(
                t.full_span(element),
                format!("a `fieldValue` is an object, found {found}"),
            );
            return;
        };
        self.duplicate_keys(object, |_| true);
        let Some(name) = self.named(object, "@name") else {
            return;
        };
        if let Some((_, value)) = t.get(object, "@value") {
            let field = self.builder.field_ref(node, &name.text);
            let parsed = match &field {
                FieldRef::Declared { ty: Some(ty), .. } => self.convert(
                    *ty,
                    value,
                    &format!("`@value` of fieldValue `{}`", name.text),
                    None,
                ),
                _ => Value::Unparsed(t.raw_full(value).to_string()),
            };
            let entry = FieldEntry {
                field,
                name_span: name.span,
                span: self.value_span(value),
                origin: Origin::FieldValue,
                value: parsed,
            };
            self.builder.add_field(node, entry);
        }
        // `IS` inside a fieldValue (written by some exporters) connects the instance.
        if let Some((_, is)) = t.get(object, "IS") {
            self.is(node, is);
        }
        if let Some((_, children)) = t.get(object, "-children") {
            let ctx = Ctx::Field {
                node,
                field: Cow::Owned(name.text),
                field_span: name.span,
                origin: Origin::FieldValue,
            };
            self.push_nodes(ctx, children, "`-children`");
        }
    }

    /// `"IS": { "connect": [ { "@nodeField", "@protoField" }, … ] }`.
    fn is(&mut self, node: NodeId, object: usize) {
        let t = self.t;
        if t.kind(object) != Kind::Object {
            let found = value::describe(t, object);
            self.syntax(
                t.full_span(object),
                format!("`IS` takes an object with a `connect` array, found {found}"),
            );
            return;
        }
        self.duplicate_keys(object, |_| true);
        // A repeated `connect` key is reported above; both are read.
        for (key, value) in t.members(object) {
            if !t.key_is(key, "connect") {
                continue;
            }
            let connects: Vec<ValueRef> = match t.kind(value) {
                Kind::Array => t.elements(value).collect(),
                Kind::Object => vec![value.into()],
                _ => {
                    let found = value::describe(t, value);
                    self.syntax(
                        t.full_span(value),
                        format!("`connect` takes an array, found {found}"),
                    );
                    continue;
                }
            };
            for connect in connects {
                let connect_span = span(t.full_span(connect));
                let Some(connect) = t.object(connect) else {
                    let found = value::describe(t, connect);
                    self.syntax(
                        t.full_span(connect),
                        format!("a `connect` is an object, found {found}"),
                    );
                    continue;
                };
                self.duplicate_keys(connect, |_| true);
                let mut get = |name: &str| {
                    self.named(connect, name).unwrap_or(Named {
                        text: String::new(),
                        span: connect_span,
                    })
                };
                let connect = IsConnect {
                    node_field: get("@nodeField"),
                    proto_field: get("@protoField"),
                    span: connect_span,
                };
                self.builder.doc_mut().nodes[node.index()]
                    .connects
                    .push(connect);
            }
        }
    }
}

fn truncate(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_str(source: &str) -> Parsed {
        read(source.as_bytes())
    }

    /// `(code, text at the span)` of every diagnostic.
    fn findings(source: &str) -> Vec<(&'static str, String)> {
        read_str(source)
            .diagnostics
            .iter()
            .map(|d| {
                (
                    d.rule.code,
                    source
                        .get(d.span.range())
                        .unwrap_or("<bad span>")
                        .to_string(),
                )
            })
            .collect()
    }

    fn messages(parsed: &Parsed) -> Vec<&str> {
        parsed
            .diagnostics
            .iter()
            .map(|d| d.message.as_str())
            .collect()
    }

    fn scene(children: &str) -> String {
        format!(
            r##"{{ "X3D": {{ "@profile": "Immersive", "@version": "4.0", "head": {{}}, "Scene": {{ "-children": [ {children} ] }} }} }}"##
        )
    }

    fn doc(source: &str) -> Document {
        let parsed = read_str(source);
        assert!(parsed.diagnostics.is_empty(), "{:?}", parsed.diagnostics);
        parsed.document.expect("a document")
    }

    #[test]
    fn reads_a_scene() {
        let source = scene(
            r##"{ "Shape": { "@DEF": "S", "-appearance": { "Appearance": { "-material": { "Material": { "@diffuseColor": [1,0,0], "@transparency": 0.5 } } } }, "-geometry": { "Box": {} } } },
               { "Shape": { "@USE": "S" } },
               { "ROUTE": { "@fromNode": "A", "@fromField": "b", "@toNode": "C", "@toField": "d" } },
               { "#comment": "ignored" }"##,
        );
        let d = doc(&source);
        assert_eq!(d.encoding, Encoding::Json);
        assert_eq!(d.version, Some(Version::V4_0));
        assert_eq!(d.profile.as_ref().unwrap().text, "Immersive");
        let types: Vec<&str> = d.nodes.iter().map(|n| n.type_name()).collect();
        assert_eq!(types, ["Shape", "Appearance", "Material", "Box"]);
        assert_eq!(d.scene.len(), 2);
        assert!(d.scene[1].is_use && d.scene[1].node == d.scene[0].node);
        let shape = d.node(d.scene[0].node);
        assert_eq!(shape.def_name.as_ref().unwrap().text, "S");
        let material = d.node(d.nodes_of_type("Material").next().unwrap());
        assert_eq!(
            material.value("diffuseColor"),
            Some(&Value::Floats(vec![1.0, 0.0, 0.0]))
        );
        assert_eq!(
            material.value("transparency"),
            Some(&Value::Floats(vec![0.5]))
        );
        let entry = material.entry("diffuseColor").unwrap();
        assert_eq!(&source[entry.name_span.range()], "@diffuseColor");
        assert_eq!(&source[entry.span.range()], "[1,0,0]");
        assert_eq!(entry.origin, Origin::Member);
        // Spans: a node from its key to the end of its object; its name is the key.
        assert!(source[shape.span.range()].starts_with("\"Shape\": {"));
        assert!(source[shape.span.range()].ends_with('}'));
        assert_eq!(&source[shape.name_span.range()], "Shape");
        assert_eq!(d.scene[0].span, shape.span);
        assert_eq!(
            &source[d.scene[1].span.range()],
            r##""Shape": { "@USE": "S" }"##
        );
        assert_eq!(d.routes.len(), 1);
        assert_eq!(&source[d.routes[0].to_field.span.range()], "d");
        assert!(source[d.root_span.range()].starts_with("\"X3D\""));
        assert!(source[d.scene_span.unwrap().range()].starts_with("\"Scene\""));
    }

    #[test]
    fn members_come_in_any_order_as_xml_attributes_do() {
        // DEF after the children: still defined before them, as an XML attribute would be.
        let d = doc(&scene(
            r##"{ "Transform": { "-children": [ { "Shape": {} } ], "@translation": [1,2,3], "@DEF": "T" } }"##,
        ));
        let transform = d.node(d.scene[0].node);
        assert_eq!(transform.def_name.as_ref().unwrap().text, "T");
        let names: Vec<&str> = transform.fields.iter().map(|f| f.name()).collect();
        assert_eq!(names, ["translation", "children"]);
    }

    #[test]
    fn head_and_statements() {
        let source = r##"{ "X3D": { "encoding": "UTF-8", "@profile": "Interchange", "@version": "3.3",
            "head": { "component": [ { "@name": "Shape", "@level": 4 } ], "unit": [ {"@category": "length"} ], "meta": [ {}, {} ] },
            "Scene": { "-children": [ { "IMPORT": { "@inlineDEF": "I", "@importedDEF": "E", "@AS": "N" } }, { "EXPORT": {} } ] } } }"##;
        let d = doc(source);
        assert_eq!(d.version, Some(Version::V3_3));
        assert_eq!(d.head.components.len(), 1);
        assert_eq!(d.head.components[0].name.text, "Shape");
        assert_eq!(d.head.components[0].level.map(|l| l.0), Some(4));
        assert_eq!((d.head.units.len(), d.head.metas), (1, 2));
        assert_eq!(d.imports.len(), 1);
        let import = &d.imports[0];
        assert_eq!(
            (
                import.inline_def.text.as_str(),
                import.local_name().text.as_str()
            ),
            ("I", "N")
        );
        assert_eq!(d.exports.len(), 1);
        assert_eq!(d.exports[0].exported_name().text, "");
    }

    #[test]
    fn protos_fields_and_instances() {
        let source = scene(
            r##"{ "ProtoDeclare": { "@name": "P",
                  "ProtoInterface": { "field": [
                    { "@name": "c", "@accessType": "inputOutput", "@type": "SFColor", "@value": [1,0,0] },
                    { "@name": "n", "@accessType": "initializeOnly", "@type": "SFNode", "-children": [ { "Box": {} } ] } ] },
                  "ProtoBody": { "-children": [ { "Material": { "@DEF": "M", "IS": { "connect": [ { "@nodeField": "diffuseColor", "@protoField": "c" } ] } } } ] } } },
               { "ExternProtoDeclare": { "@name": "E", "@url": ["e.x3d#E", "f.x3d"], "field": [ { "@name": "x", "@type": "SFFloat", "@accessType": "inputOutput" } ] } },
               { "ProtoInstance": { "@name": "P", "@DEF": "I", "fieldValue": [
                   { "@name": "c", "@value": [0,1,0] },
                   { "@name": "n", "-children": [ { "Sphere": {} } ] } ] } },
               { "Script": { "@DEF": "Sc", "field": [ { "@name": "t", "@type": "SFTime", "@accessType": "inputOnly" },
                   { "@name": "k", "@type": "MFNode", "@accessType": "initializeOnly", "-children": [ { "Group": {} } ] } ],
                   "#sourceCode": ["ecmascript:", "function t() {}"] } }"##,
        );
        let d = doc(&source);
        assert_eq!(d.protos.len(), 2);
        let p = &d.protos[0];
        assert_eq!(p.name.text, "P");
        assert_eq!(p.interface.len(), 2);
        assert_eq!(
            p.interface[0].value.as_ref().unwrap().0,
            Value::Floats(vec![1.0, 0.0, 0.0])
        );
        assert!(matches!(&p.interface[1].value, Some((Value::Nodes(n), _)) if n.len() == 1));
        assert_eq!(p.body.len(), 1);
        let material = d.node(p.body[0].node);
        assert_eq!(material.scope, Scope::Proto(0));
        assert_eq!(material.connects.len(), 1);
        assert_eq!(material.connects[0].proto_field.text, "c");
        assert!(d.protos[1].external);
        assert_eq!(d.protos[1].url, ["e.x3d#E", "f.x3d"]);
        assert_eq!(d.protos[1].interface[0].ty, Some(FieldType::SFFloat));
        let instance = d.node(d.scene[0].node);
        assert!(
            matches!(&instance.kind, NodeKind::ProtoInstance { name, proto: Some(0) } if name == "P")
        );
        assert_eq!(
            instance.value("c"),
            Some(&Value::Floats(vec![0.0, 1.0, 0.0]))
        );
        assert_eq!(instance.entry("c").unwrap().origin, Origin::FieldValue);
        assert_eq!(instance.children("n").len(), 1);
        let script = d.node(d.scene[1].node);
        assert_eq!(script.declared.len(), 2);
        assert_eq!(script.children("k").len(), 1);
        assert!(source[script.source_code.unwrap().range()].starts_with("[\"ecmascript:\""));
        assert_eq!(d.scope_count(), 2);
    }

    trait ScopeCount {
        fn scope_count(&self) -> usize;
    }

    impl ScopeCount for Document {
        fn scope_count(&self) -> usize {
            let mut scopes: Vec<Scope> = self.nodes.iter().map(|n| n.scope).collect();
            scopes.dedup();
            scopes.sort_by_key(|s| match s {
                Scope::Scene => 0,
                Scope::Proto(p) => p + 1,
            });
            scopes.dedup();
            scopes.len()
        }
    }

    #[test]
    fn unknown_nodes_and_fields_are_kept_for_the_rules() {
        let d = doc(&scene(
            r##"{ "Materiall": { "@x": 1 } }, { "Box": { "@sizee": [1,2,3], "-metadataa": { "MetadataString": {} } } }"##,
        ));
        assert!(matches!(&d.nodes[0].kind, NodeKind::Unknown { name } if name == "Materiall"));
        assert!(matches!(&d.nodes[0].fields[0].field, FieldRef::Unknown { name } if name == "x"));
        assert_eq!(d.nodes[0].fields[0].value, Value::Unparsed("1".into()));
        let b = &d.nodes[1];
        assert!(matches!(&b.fields[0].field, FieldRef::Unknown { name } if name == "sizee"));
        assert_eq!(b.fields[0].value, Value::Unparsed("[1,2,3]".into()));
        assert!(matches!(&b.fields[1].field, FieldRef::Unknown { name } if name == "metadataa"));
        assert_eq!(b.fields[1].value.len(), 1);
    }

    #[test]
    fn syntax_errors_point_at_the_value() {
        let source = scene(
            r##"{ "Material": { "@diffuseColor": [1, 0], "@transparency": "0.5", "@shininess": null } },
               { "IndexedFaceSet": { "@coordIndex": [0, 1, 2.5, -1], "@solid": "false" } },
               { "Coordinate": { "@point": [0,0,0, 1,0] } }"##,
        );
        let f = findings(&source);
        assert_eq!(
            f,
            vec![
                ("FIELD_VALUE_SYNTAX", "[1, 0]".to_string()),
                ("FIELD_VALUE_SYNTAX", "\"0.5\"".to_string()),
                ("FIELD_VALUE_SYNTAX", "null".to_string()),
                ("FIELD_VALUE_SYNTAX", "2.5".to_string()),
                ("FIELD_VALUE_SYNTAX", "\"false\"".to_string()),
                ("FIELD_VALUE_SYNTAX", "1,0".to_string()),
            ]
        );
        let parsed = read_str(&source);
        let messages = messages(&parsed);
        assert_eq!(
            messages[0],
            "`@diffuseColor`: SFColor takes 3 numbers, found 2"
        );
        assert_eq!(
            messages[1],
            "`@transparency`: SFFloat takes a number, found the string \"0.5\""
        );
        assert_eq!(
            parsed.diagnostics[1].help.as_deref(),
            Some("JSON numbers are written without quotes")
        );
        assert!(messages[3].starts_with("`@coordIndex`: MFInt32 takes whole numbers"));
        assert_eq!(parsed.diagnostics[3].index, Some(2));
        assert_eq!(
            messages[5],
            "`@point`: MFVec3f takes a multiple of 3 numbers, found 5"
        );
        // The values that did not parse are kept unparsed: the document is still there.
        let d = parsed.document.unwrap();
        assert!(matches!(
            d.nodes[0].entry("diffuseColor").unwrap().value,
            Value::Unparsed(_)
        ));
    }

    #[test]
    fn huge_numbers_are_values_not_errors() {
        let d = doc(&scene(
            r##"{ "Material": { "@transparency": 1e39, "@shininess": -1e400 } }, { "TimeSensor": { "@cycleInterval": 1e400 } }"##,
        ));
        assert_eq!(
            d.nodes[0].value("transparency"),
            Some(&Value::Floats(vec![f32::INFINITY]))
        );
        assert_eq!(
            d.nodes[0].value("shininess"),
            Some(&Value::Floats(vec![f32::NEG_INFINITY]))
        );
        assert_eq!(
            d.nodes[1].value("cycleInterval"),
            Some(&Value::Doubles(vec![f64::INFINITY]))
        );
    }

    #[test]
    fn json_slips_in_structure() {
        let source = scene(
            r##"{ "Shape": { "-geometry": 5, "appearance": {}, "-children": [ "x" ] } },
               { "@DEF": "X" },
               { "Box": [] },
               { "Material": { "@material": {} } },
               { "Appearance": { "@material": [] } }"##,
        );
        let f = findings(&source);
        let codes: Vec<&str> = f.iter().map(|(c, _)| *c).collect();
        assert!(codes.iter().all(|c| *c == "FIELD_VALUE_SYNTAX"), "{f:?}");
        let places: Vec<&str> = f.iter().map(|(_, t)| t.as_str()).collect();
        // Material has no `material` field: that one is an unknown field for a rule to report.
        assert_eq!(places, ["5", "appearance", "\"x\"", "@DEF", "[]", "[]"]);
        let parsed = read_str(&source);
        assert!(
            parsed.diagnostics[5]
                .message
                .contains("give its nodes as `-material`"),
            "{}",
            parsed.diagnostics[5].message
        );
    }

    #[test]
    fn use_with_fields() {
        let source = scene(
            r##"{ "Material": { "@DEF": "M" } },
               { "Material": { "@USE": "M", "@containerField": "material", "@class": "c", "#comment": "ok" } },
               { "Material": { "@USE": "M", "@transparency": 0.5, "@DEF": "N" } },
               { "Group": { "@DEF": "G" } },
               { "Group": { "@USE": "G", "-children": [ { "#comment": "fine" } ] } },
               { "Group": { "@USE": "G", "-children": [ { "Shape": {} }, { "Box": {} } ] } },
               { "ProtoInstance": { "@USE": "G", "@name": "Group" } }"##,
        );
        let f = findings(&source);
        assert_eq!(
            f,
            vec![
                ("USE_WITH_FIELDS", "@transparency".to_string()),
                ("USE_WITH_FIELDS", "Shape".to_string()),
                ("USE_WITH_FIELDS", "Box".to_string()),
            ]
        );
        let parsed = read_str(&source);
        assert_eq!(
            parsed.diagnostics[0].message,
            "USE `M` also sets `@transparency`, `@DEF`: a USE takes no fields"
        );
        // The USEs still refer to their nodes.
        let d = parsed.document.unwrap();
        assert_eq!(d.scene.iter().filter(|c| c.is_use).count(), 5);
    }

    #[test]
    fn def_use_diagnostics_come_from_the_builder() {
        let f = findings(&scene(
            r##"{ "Group": { "@DEF": "A", "-children": [ { "Group": { "@USE": "A" } } ] } },
               { "Box": { "@USE": "Nope" } },
               { "Box": { "@DEF": "A" } },
               { "Sphere": { "@DEF": "S" } }, { "Box": { "@USE": "S" } }"##,
        ));
        let codes: Vec<&str> = f.iter().map(|(c, _)| *c).collect();
        assert_eq!(
            codes,
            [
                "USE_CYCLE",
                "USE_UNDEFINED",
                "DEF_DUPLICATE",
                "USE_TYPE_MISMATCH"
            ]
        );
        assert_eq!(f[1].1, "Nope");
    }

    #[test]
    fn duplicates() {
        let source = scene(
            r##"{ "Material": { "@diffuseColor": [1,0,0], "@diffuseColor": [0,1,0] } },
               { "Group": { "-children": [], "-children": [ { "Box": {} } ], "@DEF": "G", "@DEF": "H" } },
               { "Appearance": { "@material": null, "-material": { "Material": {} } } },
               { "Script": { "IS": { "connect": [], "connect": [] } } }"##,
        );
        let f = findings(&source);
        assert_eq!(
            f,
            vec![
                ("FIELD_DUPLICATE", "@diffuseColor".to_string()),
                ("FIELD_DUPLICATE", "-children".to_string()),
                ("FIELD_DUPLICATE", "@DEF".to_string()),
                ("FIELD_VALUE_SYNTAX", "null".to_string()),
                ("FIELD_DUPLICATE", "-material".to_string()),
                ("FIELD_DUPLICATE", "connect".to_string()),
            ]
        );
        let d = read_str(&source).document.unwrap();
        // The first value is kept; both `-children` members give their nodes; the first DEF names.
        assert_eq!(
            d.nodes[0].value("diffuseColor"),
            Some(&Value::Floats(vec![1.0, 0.0, 0.0]))
        );
        assert_eq!(d.nodes[1].children("children").len(), 1);
        assert_eq!(d.nodes[1].def_name.as_ref().unwrap().text, "G");
    }

    /// Scalars in arrays have no items of their own: where nodes or objects belong, each
    /// is still reported at its own text, in document order among the nodes around it.
    #[test]
    fn scalars_where_objects_belong_are_reported_at_their_place() {
        let source = scene(
            r##"{ "Box": {} }, 5, "x", { "Group": { "@DEF": "A", "@DEF": "B", "-children": [ null, { "Sphere": {} } ] } },
               { "Script": { "field": [ 1, { "@name": "f", "@type": "MFVec3f", "@accessType": "initializeOnly", "@value": [0,0,0, 1,"0",0] } ],
                             "IS": { "connect": [ false ] }, "#sourceCode": ["a", 2] } },
               { "ProtoInstance": { "@name": "P", "fieldValue": [ "v" ] } },
               { "Group": { "@USE": "A", "-children": [ 7 ] } },
               { "Coordinate": { "@point": [0,0,0, [1,0,0]] } }"##,
        );
        let f = findings(&source);
        assert_eq!(
            f,
            vec![
                ("FIELD_VALUE_SYNTAX", "5".to_string()),
                ("FIELD_VALUE_SYNTAX", "\"x\"".to_string()),
                ("FIELD_DUPLICATE", "@DEF".to_string()),
                ("FIELD_VALUE_SYNTAX", "null".to_string()),
                ("FIELD_VALUE_SYNTAX", "1".to_string()),
                ("FIELD_VALUE_SYNTAX", "\"0\"".to_string()),
                ("FIELD_VALUE_SYNTAX", "false".to_string()),
                ("FIELD_VALUE_SYNTAX", "[\"a\", 2]".to_string()),
                ("FIELD_VALUE_SYNTAX", "\"v\"".to_string()),
                ("USE_WITH_FIELDS", "7".to_string()),
                ("FIELD_VALUE_SYNTAX", "[1,0,0]".to_string()),
            ]
        );
        let parsed = read_str(&source);
        let messages = messages(&parsed);
        assert_eq!(
            messages[0],
            "`-children` holds objects naming a node, like {\"Transform\": {…}}, found the number 5"
        );
        assert_eq!(
            messages[4],
            "a `field` declaration is an object, found the number 1"
        );
        assert_eq!(parsed.diagnostics[5].index, Some(1));
        assert_eq!(messages[6], "a `connect` is an object, found `false`");
        assert_eq!(
            messages[8],
            "a `fieldValue` is an object, found the string \"v\""
        );
        assert_eq!(
            messages[9],
            "USE `A` holds `the number 7`: a USE takes no children or fields"
        );
        assert_eq!(parsed.diagnostics[10].index, Some(1));
        // The nodes around the scalars are read.
        let d = parsed.document.unwrap();
        let types: Vec<&str> = d.nodes.iter().map(|n| n.type_name()).collect();
        assert_eq!(
            types,
            [
                "Box",
                "Group",
                "Sphere",
                "Script",
                "ProtoInstance",
                "Coordinate"
            ]
        );
    }

    #[test]
    fn malformed_json_has_a_position_and_no_document() {
        let source = "{ \"X3D\": {\n  \"Scene\": { \"-children\": [ 1, ] }\n} }";
        let parsed = read_str(source);
        assert!(parsed.document.is_none());
        assert_eq!(parsed.diagnostics.len(), 1);
        let d = &parsed.diagnostics[0];
        assert_eq!(d.rule.code, "JSON_MALFORMED");
        assert_eq!(d.span.start as usize, source.find("]").unwrap());
        assert_eq!(
            d.message,
            "not valid JSON: a trailing comma before `]` is not allowed in JSON"
        );
    }

    /// Arrays of plain numbers are skipped by the scan and checked as they are read: what
    /// is not JSON in them is reported as the whole scan reports it, whichever field (or
    /// none) reads the array, and what is JSON reads as before.
    #[test]
    fn skipped_number_arrays_report_what_the_scan_reports() {
        let arrays = [
            "1,2,3",
            "1,,2",
            ",1",
            "1,2,",
            "01,2",
            "-,1",
            "1.,2",
            "1.5.5,2",
            "-01",
            "1,-",
            "0.5,-0.25,00",
            "1--2",
            "1,2.",
            ".5,1",
            "-.5",
            "1,2 ,3",
            "1.5,2,3.25",
            "-0,0,0.0",
            "7,8,-9.125",
            "1.5e3,2",
            "1,\"a\"",
            "2147483648,1",
            "0.5,1,1.5,2",
        ];
        let fields = ["point", "index", "size", "on", "url", "unknownField"];
        for array in arrays {
            for (node, field) in [
                ("Coordinate", fields[0]),
                ("IndexedFaceSet", fields[1]),
                ("Box", fields[2]),
                ("TimeSensor", fields[3]),
                ("ImageTexture", fields[4]),
                ("Group", fields[5]),
            ] {
                let source = scene(&format!("{{ \"{node}\": {{ \"@{field}\": [{array}] }} }}"));
                let parsed = read_str(&source);
                match tree::parse(&source) {
                    Err(error) => {
                        assert!(parsed.document.is_none(), "{source}");
                        let d = &parsed.diagnostics[0];
                        assert_eq!(parsed.diagnostics.len(), 1, "{source}");
                        assert_eq!(d.rule.code, "JSON_MALFORMED", "{source}");
                        assert_eq!(d.span.start as usize, error.at, "{source}");
                        assert!(d.message.ends_with(&error.message), "{source}");
                    }
                    Ok(_) => assert!(parsed.document.is_some(), "{source}"),
                }
            }
        }
        // And a long one, read in pieces.
        let long = (0..400_000)
            .map(|k| format!("{k}.5"))
            .collect::<Vec<_>>()
            .join(",");
        for (tail, json) in [("", true), (",01", false), (",1.", false), (",,1", false)] {
            let source = scene(&format!(
                "{{ \"Coordinate\": {{ \"@point\": [{long}{tail},1,2] }} }}"
            ));
            let parsed = read_str(&source);
            assert_eq!(parsed.document.is_some(), json, "{tail}");
            assert_eq!(tree::parse(&source).is_ok(), json, "{tail}");
        }
    }

    #[test]
    fn invalid_utf8_is_malformed_at_the_first_bad_byte() {
        let mut source =
            br##"{ "X3D": { "Scene": { "-children": [ { "WorldInfo": { "@title": "x"##.to_vec();
        let at = source.len();
        source.extend_from_slice(b"\xff\xfe\" } } ] } } }");
        let parsed = read(&source);
        assert!(parsed.document.is_none());
        assert_eq!(parsed.diagnostics[0].rule.code, "JSON_MALFORMED");
        assert_eq!(parsed.diagnostics[0].span.start as usize, at);
        assert!(parsed.diagnostics[0].message.contains("UTF-8"));
    }

    #[test]
    fn root_must_be_an_x3d_object() {
        for source in ["[1, 2]", "{\"x3d\": {}}", "{}", "\"X3D\"", "{\"X3D\": []}"] {
            let parsed = read_str(source);
            assert!(parsed.document.is_none(), "{source}");
            assert_eq!(parsed.diagnostics.len(), 1);
            assert_eq!(parsed.diagnostics[0].rule.code, "ROOT_NOT_X3D", "{source}");
        }
        let parsed = read_str("  {\"x3d\": {}}");
        assert_eq!(parsed.diagnostics[0].span, Span::new(2, 13));
        assert!(parsed.diagnostics[0].message.contains("`x3d`"));
    }

    #[test]
    fn a_minimal_document_reads() {
        let d = doc(r##"{"X3D": {}}"##);
        assert!(d.version.is_none() && d.profile.is_none() && d.scene_span.is_none());
        assert!(d.nodes.is_empty());
    }

    /// Nodes nested as deep as the scanner allows are read without deep recursion, on a
    /// thread with the 2 MB stack of the checker's worker threads.
    #[test]
    fn deeply_nested_nodes_do_not_overflow_the_stack() {
        let depth = tree::MAX_DEPTH / 3 - 5;
        let mut source = String::from(r##"{"X3D": {"Scene": {"-children": ["##);
        for _ in 0..depth {
            source.push_str(r##"{"Group": {"-children": ["##);
        }
        source.push_str(&"]}}".repeat(depth));
        source.push_str("]}}}");
        let handle = std::thread::Builder::new()
            .stack_size(2 << 20)
            .spawn(move || {
                let parsed = read(source.as_bytes());
                (
                    parsed.diagnostics.len(),
                    parsed.document.map(|d| d.nodes.len()),
                )
            })
            .unwrap();
        // The scanner reads all of it; the model keeps the first MAX_DEPTH nodes and says so.
        let max_nodes = crate::model::builder::MAX_DEPTH;
        assert_eq!(handle.join().unwrap(), (1, Some(max_nodes)));
        // Deeper than the cap: refused, not overflowed.
        let too_deep = format!(r##"{{"X3D": {}"##, "[".repeat(tree::MAX_DEPTH + 10));
        let parsed = read(too_deep.as_bytes());
        assert!(parsed.diagnostics[0].message.contains("nested too deeply"));
    }

    #[test]
    fn every_prefix_and_byte_flip_of_a_scene_is_handled() {
        let source = scene(
            r##"{ "ProtoDeclare": { "@name": "P", "ProtoInterface": { "field": [ { "@name": "c", "@type": "SFColor", "@accessType": "inputOutput", "@value": [1,0,0] } ] }, "ProtoBody": { "-children": [ { "Material": { "IS": { "connect": [ { "@nodeField": "diffuseColor", "@protoField": "c" } ] } } } ] } } },
               { "Transform": { "@DEF": "T", "@rotation": [0,1,0,1.5e0], "-children": [ { "Shape": { "-geometry": { "IndexedFaceSet": { "@coordIndex": [0,1,2,-1], "-coord": { "Coordinate": { "@point": [0,0,0,1,0,0,0,1,0] } } } } } }, { "PixelTexture": { "@image": [1,1,3,255] } } ] } },
               { "ProtoInstance": { "@name": "P", "fieldValue": [ { "@name": "c", "@value": [0,1,0] } ] } },
               { "Script": { "field": [ { "@name": "x", "@type": "SFNode", "@accessType": "initializeOnly", "-children": [ { "Transform": { "@USE": "T" } } ] } ], "#sourceCode": "ecmascript:" } },
               { "ROUTE": { "@fromNode": "T", "@fromField": "translation_changed", "@toNode": "T", "@toField": "set_translation" } }"##,
        );
        assert!(read_str(&source).document.is_some());
        let bytes = source.as_bytes();
        for cut in 0..bytes.len() {
            let _ = read(&bytes[..cut]);
        }
        let replacements = [
            b'"', b'{', b'}', b'[', b']', b',', b':', b'0', b'-', b'e', b'\\', 0xC3, 0xFF,
        ];
        for i in 0..bytes.len() {
            for &r in &replacements {
                let mut mutated = bytes.to_vec();
                mutated[i] = r;
                let _ = read(&mutated);
            }
        }
    }
}
