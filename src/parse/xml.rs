//! The XML encoding (ISO/IEC 19776-1) read with quick-xml straight from the input bytes
//! into the scene model. Element and attribute positions are byte offsets into the input;
//! field values are parsed from the attribute text by [`xml_value`].

use std::borrow::Cow;

use quick_xml::events::attributes::Attribute;
use quick_xml::events::{BytesStart, Event};
use quick_xml::name::QName;
use quick_xml::Reader;

use super::behind::{Pass, Progress, STEP};
use super::directive::{addressed, Following};
use super::rules::{FIELD_VALUE_SYNTAX, ROOT_NOT_X3D, USE_WITH_FIELDS, XML_MALFORMED};
use super::xml_entities::{Entities, ExpandError};
use crate::diagnostic::Diagnostic;
use crate::limits::{MAX_FIELDS_PER_NODE, MAX_INPUT_BYTES};
use crate::model::builder::Parent;
use crate::model::draft::Limit;
use crate::model::text::xml_value;
use crate::model::*;
use crate::parse::{KeepValues, Parsed};
use crate::schema::{AccessType, FieldDef, FieldType, NodeDef, Scalar};

/// Reads an X3D XML document.
pub fn read(source: &[u8]) -> Parsed {
    read_with(source, KeepValues::All, &())
}

/// Reads an X3D XML document, keeping numeric MF values whole or as summaries, telling
/// `progress` how far it has got.
pub fn read_with(source: &[u8], keep: KeepValues, progress: &dyn Progress) -> Parsed {
    let mut reader = XmlReader::new(source, keep, progress);
    let result = reader.run();
    reader.finish(result)
}

/// The first character that XML 1.0's Char production (2.2) leaves out, looked for a
/// [`STEP`] ahead of the reader rather than over the whole input first, so that the input
/// is read once, in order (see [`behind`](super::behind)).
struct ForbiddenChars {
    /// How much of the input was looked at.
    scanned: usize,
    first: Option<usize>,
}

impl ForbiddenChars {
    /// The offset of the first forbidden character before `end`.
    #[inline]
    fn before(&mut self, source: &[u8], end: usize) -> Option<usize> {
        while self.first.is_none() && self.scanned < end.min(source.len()) {
            let to = (self.scanned + STEP).max(end).min(source.len());
            self.first = first_forbidden_char(source, self.scanned..to);
            self.scanned = to;
        }
        self.first.filter(|&bad| bad < end)
    }
}

/// The offset of the first character in `source[range]` that XML 1.0's Char production
/// (2.2) leaves out: a C0 control other than tab, line feed and carriage return (NUL among
/// them), or U+FFFE, U+FFFF. The input is UTF-8, whose encoding of surrogates quick-xml
/// refuses, so these are the characters left to find. Each chunk is first tested as a
/// whole, with no early exit and one byte-wide flag per byte, which the compiler turns into
/// vector code (35% fewer instructions than a fold of `bool`s, measured on the
/// benchmark scene); only a chunk with a suspect byte is looked at byte by byte.
fn first_forbidden_char(source: &[u8], range: std::ops::Range<usize>) -> Option<usize> {
    const CHUNK: usize = 64;
    let suspect = |b: u8| (b < 0x20 && !matches!(b, b'\t' | b'\n' | b'\r')) || b == 0xEF;
    // A character starting in the range is judged whole, whatever follows the range.
    let forbidden_at = |at: usize| match source[at] {
        0xEF => matches!(source.get(at + 1..at + 3), Some([0xBF, 0xBE | 0xBF])),
        _ => true,
    };
    let first_in = |base: usize, bytes: &[u8]| {
        (0..bytes.len())
            .filter(|&i| suspect(bytes[i]))
            .map(|i| base + i)
            .find(|&at| forbidden_at(at))
    };
    let mut chunks = source[range.clone()].chunks_exact(CHUNK);
    let mut base = range.start;
    for chunk in &mut chunks {
        let chunk: &[u8; CHUNK] = chunk.try_into().expect("chunks_exact gives whole chunks");
        let mut any = 0u8;
        for &b in chunk {
            let control = (b < 0x20) as u8;
            let space = ((b == b'\t') | (b == b'\n') | (b == b'\r')) as u8;
            any |= (control & !space) | (b == 0xEF) as u8;
        }
        if any != 0 {
            if let Some(at) = first_in(base, chunk) {
                return Some(at);
            }
        }
        base += CHUNK;
    }
    first_in(base, chunks.remainder())
}

/// The attributes of a start tag (`raw`: what follows its name) when each is written
/// `name="value"` or `name='value'`, with only whitespace around them, no name twice and
/// at most 32 of them: the names and values quick-xml's iterator gives, with each value's
/// end found by memchr instead of its byte-by-byte search (16% of the standard level's
/// instructions on a scene of long coordinate lists). `None` for anything else, which
/// quick-xml's iterator then reads, errors and all.
fn plain_attributes(raw: &str) -> Option<Vec<Attribute<'_>>> {
    // Beyond this many names, quick-xml hashes them to find a duplicate; so does nobody here.
    const MOST: usize = 32;
    let is_space = |b: u8| matches!(b, b' ' | b'\t' | b'\n' | b'\r');
    let bytes = raw.as_bytes();
    let mut out: Vec<Attribute> = Vec::new();
    let mut i = 0;
    loop {
        while bytes.get(i).copied().is_some_and(is_space) {
            i += 1;
        }
        if i == bytes.len() {
            return Some(out);
        }
        // As in quick-xml, the name's first byte is taken whatever it is.
        let name_end = i
            + 1
            + bytes[i + 1..]
                .iter()
                .position(|&b| b == b'=' || is_space(b))?;
        let quote = match bytes.get(name_end..name_end + 2)? {
            [b'=', quote @ (b'"' | b'\'')] => *quote,
            _ => return None,
        };
        let value_start = name_end + 2;
        let value_end = value_start + memchr::memchr(quote, &bytes[value_start..])?;
        let name = &raw[i..name_end];
        if out.len() == MOST || out.iter().any(|a: &Attribute| a.key.0 == name) {
            return None;
        }
        out.push(Attribute {
            key: QName(name),
            value: Cow::Borrowed(&raw[value_start..value_end]),
        });
        i = value_end + 1;
    }
}

/// Names the character at the start of `bytes` (one [`first_forbidden_char`] found).
fn forbidden_message(bytes: &[u8]) -> String {
    let code = match bytes {
        [0xEF, 0xBF, last, ..] => 0xFF00 | u32::from(*last),
        [b, ..] => u32::from(*b),
        [] => 0,
    };
    format!("character U+{code:04X} is not allowed in an XML document (XML 1.0 2.2 Char)")
}

/// What an open element is, so that its children and end tag are handled right.
enum Frame {
    Root,
    Head,
    Scene,
    Node {
        id: NodeId,
        start: usize,
    },
    /// A USE element: its children are reported and otherwise ignored.
    Use,
    ProtoDeclare {
        proto: usize,
    },
    ProtoInterface {
        proto: usize,
    },
    ProtoBody,
    ExternProtoDeclare {
        proto: usize,
    },
    /// A `field` declaration whose nodes (for SFNode/MFNode) form its initial value.
    FieldDecl {
        owner: DeclOwner,
        field: String,
    },
    /// A ProtoInstance `fieldValue` whose nodes form the value.
    FieldValue {
        node: NodeId,
        field: String,
        name_span: Span,
    },
    Is {
        node: NodeId,
    },
    /// Anything whose content is not part of the scene model (meta, ROUTE, unknown statements).
    Other,
}

#[derive(Copy, Clone)]
enum DeclOwner {
    Node(NodeId),
    Proto(usize),
}

/// Builds the model from elements, attributes and text: fed by quick-xml's events here and by
/// the HTML tree of a page's X3D island in [`html`](super::html), so that both read the same.
pub(super) struct XmlReader<'s> {
    source: &'s [u8],
    pass: Pass<'s>,
    /// Whether numeric MF values of schema fields are kept or summarized.
    keep: KeepValues,
    builder: Builder,
    stack: Vec<Frame>,
    root_closed: bool,
    /// Declared in the DOCTYPE's internal subset.
    entities: Entities,
    /// The comments addressed to x3dcheck, placed on the elements that follow them.
    directives: Following,
}

/// An attribute's name and value as text, with the value's place in the input.
pub(super) struct Attr<'a> {
    pub(super) name: &'a str,
    pub(super) name_span: Span,
    pub(super) value: Cow<'a, str>,
    pub(super) value_span: Span,
    /// Whether `value` is the input text itself (no entity was replaced), so offsets into
    /// it are offsets into the input.
    pub(super) verbatim: bool,
}

impl<'s> XmlReader<'s> {
    pub(super) fn new(source: &'s [u8], keep: KeepValues, progress: &'s dyn Progress) -> Self {
        XmlReader {
            source,
            pass: Pass::new(source, progress),
            keep,
            builder: Builder::new(Encoding::Xml),
            stack: Vec::new(),
            root_closed: false,
            entities: Entities::default(),
            directives: Following::default(),
        }
    }

    /// The document built, or none when reading stopped at `result`'s error.
    pub(super) fn finish(self, result: Result<(), Box<Diagnostic>>) -> Parsed {
        // The pieces' vectors pay off from one long value to the next; after the document
        // (a render follows, or other files) they would only hold memory.
        crate::model::text::split::scratch::release();
        let (mut document, mut diagnostics) = self.builder.finish();
        match result {
            Ok(()) => {
                document.directives = self.directives.finish(self.source.len());
                Parsed {
                    encoding: Some(Encoding::Xml),
                    document: Some(document),
                    diagnostics,
                }
            }
            Err(stop) => {
                diagnostics.push(*stop);
                Parsed {
                    encoding: Some(Encoding::Xml),
                    document: None,
                    diagnostics,
                }
            }
        }
    }

    fn run(&mut self) -> Result<(), Box<Diagnostic>> {
        if self.source.len() > MAX_INPUT_BYTES {
            return Err(self.malformed(0, "the input is larger than 4 GiB"));
        }
        let mut reader = Reader::from_reader(self.source);
        reader.config_mut().check_end_names = true;
        // quick-xml does not check XML's Char production: the first character outside it
        // is an error once the reader reaches it (an earlier error is reported first).
        let mut forbidden = ForbiddenChars {
            scanned: 0,
            first: None,
        };
        loop {
            let start = reader.buffer_position() as usize;
            self.pass.reached(start);
            let event = match reader.read_event() {
                Ok(event) => event,
                Err(error) => {
                    let at = reader.error_position() as usize;
                    return Err(match forbidden.before(self.source, at.saturating_add(1)) {
                        Some(bad) => self.forbidden_char(bad),
                        None => self.malformed(at, &error.to_string()),
                    });
                }
            };
            let end = reader.buffer_position() as usize;
            if let Some(bad) = forbidden.before(self.source, end) {
                return Err(self.forbidden_char(bad));
            }
            match event {
                Event::Start(element) => self.start(&element, start, end, false)?,
                Event::Empty(element) => {
                    self.start(&element, start, end, true)?;
                    self.end(end);
                }
                Event::End(_) => self.end(end),
                Event::Comment(_) => self.comment(start, end),
                Event::CData(_) => self.text(start, end, true)?,
                Event::Text(_) | Event::GeneralRef(_) => self.text(start, end, false)?,
                Event::Eof => break,
                Event::DocType(doctype) => {
                    self.builder.doc_mut().version_hint = VersionHint::find(&doctype, "DOCTYPE");
                    self.entities.declare(&doctype);
                }
                Event::Decl(_) | Event::PI(_) => {}
            }
        }
        if !self.stack.is_empty() {
            return Err(self.malformed(
                self.source.len(),
                "the document ends before its elements are closed",
            ));
        }
        if !self.root_closed {
            return Err(self.malformed(0, "no root element"));
        }
        Ok(())
    }

    fn malformed(&self, at: usize, message: &str) -> Box<Diagnostic> {
        let at = at.min(self.source.len());
        Box::new(Diagnostic::new(
            &XML_MALFORMED,
            Span::new(at, at),
            format!("not well-formed XML: {message}"),
        ))
    }

    fn forbidden_char(&self, at: usize) -> Box<Diagnostic> {
        self.malformed(at, &forbidden_message(&self.source[at..]))
    }

    fn span_of(&self, bytes: &[u8]) -> Option<Span> {
        let base = self.source.as_ptr() as usize;
        let at = bytes.as_ptr() as usize;
        (at >= base && at + bytes.len() <= base + self.source.len())
            .then(|| Span::new(at - base, at - base + bytes.len()))
    }

    /// Text and CDATA: source code for Script and shader parts; elsewhere only whitespace
    /// is expected, and the root must be followed by nothing but whitespace.
    pub(super) fn text(
        &mut self,
        start: usize,
        end: usize,
        cdata: bool,
    ) -> Result<(), Box<Diagnostic>> {
        let blank = self.source[start..end]
            .iter()
            .all(|b| b.is_ascii_whitespace());
        if self.stack.is_empty() {
            if !blank {
                return Err(self.malformed(start, "text outside the root element"));
            }
            return Ok(());
        }
        if blank && !cdata {
            return Ok(());
        }
        if let Some(Frame::Node { id, .. }) = self.stack.last() {
            let node = &mut self.builder.doc_mut().nodes[id.index()];
            let code = node.source_code.get_or_insert(Span::new(start, start));
            code.end = end as u32;
        }
        Ok(())
    }

    /// The attributes of an element, at most [`MAX_FIELDS_PER_NODE`] of them (quick-xml's
    /// duplicate check is linear per attribute). An attribute whose entity references go
    /// past a limit is left out and the limit reported.
    fn attributes<'a>(
        &mut self,
        element: &'a BytesStart<'a>,
        element_start: usize,
    ) -> Result<Vec<Attr<'a>>, Box<Diagnostic>> {
        let mut out = Vec::new();
        let (plain, checked) = match plain_attributes(element.attributes_raw()) {
            Some(plain) => (plain, None),
            None => {
                let mut checked = element.attributes();
                checked.with_checks(true);
                (Vec::new(), Some(checked))
            }
        };
        let attributes = plain
            .into_iter()
            .map(Ok)
            .chain(checked.into_iter().flatten());
        for (count, attribute) in attributes.enumerate() {
            if count == MAX_FIELDS_PER_NODE {
                let at = Span::new(element_start + 1, element_start + 1);
                let message = format!(
                    "an element with more than {MAX_FIELDS_PER_NODE} attributes; the rest are not read"
                );
                self.builder.exceeded(Limit::FieldsPerNode, at, message);
                break;
            }
            let attribute: Attribute<'a> =
                attribute.map_err(|e| self.malformed(element_start, &e.to_string()))?;
            let name: &'a str = attribute.key.0;
            let name_span = self
                .span_of(name.as_bytes())
                .unwrap_or(Span::new(element_start, element_start));
            let raw: &'a str = match &attribute.value {
                Cow::Borrowed(raw) => raw,
                Cow::Owned(_) => {
                    return Err(self.malformed(element_start, "attribute value not read in place"))
                }
            };
            let value_span = self.span_of(raw.as_bytes()).unwrap_or(name_span);
            // Entities need quick-xml's unescaping. Without them the raw text serves: the
            // number parsers take any XML whitespace as a separator, and string fields
            // get XML's whitespace normalization in `parse_attr_value`. This spares a copy
            // of every multi-line coordinate list.
            let (value, verbatim) = if memchr::memchr(b'&', raw.as_bytes()).is_some() {
                let normalized = match self.entities.expand(&attribute) {
                    Ok(normalized) => normalized,
                    Err(ExpandError::Malformed { at, message }) => {
                        return Err(self.malformed(value_span.start as usize + at, &message))
                    }
                    Err(ExpandError::Limit(message)) => {
                        self.builder
                            .exceeded(Limit::EntityExpansion, value_span, message);
                        continue;
                    }
                };
                let verbatim = normalized.len() == raw.len();
                (normalized, verbatim)
            } else {
                (Cow::Borrowed(raw), true)
            };
            out.push(Attr {
                name,
                name_span,
                value,
                value_span,
                verbatim,
            });
        }
        Ok(out)
    }

    fn start(
        &mut self,
        element: &BytesStart,
        start: usize,
        end: usize,
        empty: bool,
    ) -> Result<(), Box<Diagnostic>> {
        let name = element.name().0;
        let attrs = self.attributes(element, start)?;
        self.open(name, &attrs, start, end, empty)
    }

    /// An element `name` from `start` to the end of its start tag (`end`), `name` written
    /// right after `start`'s `<`; `empty` when it has no content. Its end is [`Self::end`].
    pub(super) fn open(
        &mut self,
        name: &str,
        attrs: &[Attr],
        start: usize,
        end: usize,
        empty: bool,
    ) -> Result<(), Box<Diagnostic>> {
        self.directives.start(self.stack.len(), start);
        let name_span = Span::new(start + 1, start + 1 + name.len());
        let frame = match self.stack.last() {
            None => {
                if self.root_closed {
                    return Err(self.malformed(start, "a second root element"));
                }
                if name != "X3D" {
                    return Err(Box::new(Diagnostic::new(
                        &ROOT_NOT_X3D,
                        name_span,
                        format!("the root element is `{name}`, not `X3D`"),
                    )));
                }
                self.root(attrs, Span::new(start, end));
                Frame::Root
            }
            Some(parent) => {
                let context = Context::of(parent);
                self.child(context, name, name_span, attrs, start, end, empty)
            }
        };
        self.stack.push(frame);
        Ok(())
    }

    fn root(&mut self, attrs: &[Attr], span: Span) {
        let doc = self.builder.doc_mut();
        doc.root_span = span;
        for attr in attrs {
            let named = Named {
                text: attr.value.to_string(),
                span: attr.value_span,
            };
            match attr.name {
                "version" => {
                    doc.version = crate::schema::Version::parse(attr.value.trim());
                    doc.version_text = Some(named);
                }
                "profile" => doc.profile = Some(named),
                // The DOCTYPE, read before the root, wins.
                name if name.ends_with("noNamespaceSchemaLocation")
                    && doc.version_hint.is_none() =>
                {
                    doc.version_hint = VersionHint::find(&attr.value, "schema location");
                }
                _ => {}
            }
        }
        doc.apply_version_hint();
    }

    #[allow(clippy::too_many_arguments)]
    fn child(
        &mut self,
        context: Context,
        name: &str,
        name_span: Span,
        attrs: &[Attr],
        start: usize,
        end: usize,
        empty: bool,
    ) -> Frame {
        let element = Span::new(start, end);
        let hint = context.parent_hint();
        match (context, name) {
            (Context::Root, "head") => {
                self.statement_attributes("head", attrs);
                Frame::Head
            }
            (Context::Root, "Scene") => {
                self.builder.doc_mut().scene_span = Some(element);
                Frame::Scene
            }
            // An XML Signature (x3d-4.0.xsd allows `ds:Signature` after the Scene).
            (Context::Root, _) if name == "Signature" || name.ends_with(":Signature") => {
                Frame::Other
            }
            (Context::Root, _) => self.ignored(name, name_span, HeaderPart::Root),
            (Context::Head, "component") => {
                self.statement_attributes("component", attrs);
                self.component(attrs, element);
                Frame::Other
            }
            (Context::Head, "unit") => {
                self.statement_attributes("unit", attrs);
                self.unit(attrs, element);
                Frame::Other
            }
            (Context::Head, "meta") => {
                self.statement_attributes("meta", attrs);
                self.builder.doc_mut().head.metas += 1;
                Frame::Other
            }
            (Context::Head, _) => self.ignored(name, name_span, HeaderPart::Head),
            (Context::Nodes(_), "ROUTE") => {
                self.route(attrs, element);
                Frame::Other
            }
            (Context::Nodes(_), "IMPORT") => {
                let missing = || Named {
                    text: String::new(),
                    span: element,
                };
                self.builder.add_import(Import {
                    inline_def: named_attr(attrs, "inlineDEF").unwrap_or_else(missing),
                    imported_def: named_attr(attrs, "importedDEF").unwrap_or_else(missing),
                    as_name: named_attr(attrs, "AS"),
                    span: element,
                    scope: Scope::Scene,
                });
                Frame::Other
            }
            (Context::Nodes(_), "EXPORT") => {
                self.builder.add_export(Export {
                    local_def: named_attr(attrs, "localDEF").unwrap_or(Named {
                        text: String::new(),
                        span: element,
                    }),
                    as_name: named_attr(attrs, "AS"),
                    span: element,
                    scope: Scope::Scene,
                });
                Frame::Other
            }
            (Context::Nodes(_), "ProtoDeclare") => {
                let proto = self.declare_proto(attrs, element, false);
                Frame::ProtoDeclare { proto }
            }
            (Context::Nodes(_), "ExternProtoDeclare") => {
                let proto = self.declare_proto(attrs, element, true);
                Frame::ExternProtoDeclare { proto }
            }
            (Context::ProtoDeclare(proto), "ProtoInterface") => Frame::ProtoInterface { proto },
            (Context::ProtoDeclare(proto), "ProtoBody") => {
                self.builder.begin_proto_body(proto);
                Frame::ProtoBody
            }
            (Context::ProtoInterface(proto) | Context::ExternProto(proto), "field") => {
                self.field_decl(DeclOwner::Proto(proto), attrs, element)
            }
            (Context::Nodes(Some(node)), "field") => {
                self.field_decl(DeclOwner::Node(node), attrs, element)
            }
            (Context::Nodes(Some(node)), "fieldValue") => self.field_value(node, attrs),
            (Context::Nodes(Some(node)), "IS") => Frame::Is { node },
            (Context::FieldValue(node, ..), "IS") => Frame::Is { node },
            (Context::Is(node), "connect") => {
                self.connect(node, attrs, element);
                Frame::Other
            }
            (Context::Nodes(_), _) => self.node(hint, name, name_span, attrs, element, empty),
            (Context::FieldDecl(owner, field), _) => {
                let parent = match owner {
                    DeclOwner::Node(node) => Hint::Field {
                        node,
                        field,
                        origin: Origin::Children,
                    },
                    DeclOwner::Proto(proto) => Hint::ProtoField { proto, field },
                };
                self.node(parent, name, name_span, attrs, element, empty)
            }
            (Context::FieldValue(node, field, name_span_of_field), _) => self.node(
                Hint::FieldValue {
                    node,
                    field,
                    name_span: name_span_of_field,
                },
                name,
                name_span,
                attrs,
                element,
                empty,
            ),
            (Context::Use, _) => {
                self.builder.report(Diagnostic::new(
                    &USE_WITH_FIELDS,
                    name_span,
                    format!("a USE node has a child `{name}`: USE takes no children or fields"),
                ));
                Frame::Other
            }
            _ => Frame::Other,
        }
    }

    /// An element X3D gives no meaning where it stands: recorded, its content skipped.
    fn ignored(&mut self, name: &str, span: Span, part: HeaderPart) -> Frame {
        let name = Named {
            text: name.to_string(),
            span,
        };
        record(
            &mut self.builder.doc_mut().ignored,
            IgnoredContent { name, part },
        );
        Frame::Other
    }

    /// Records the attributes that a head statement (`statement`) does not have.
    fn statement_attributes(&mut self, statement: &'static str, attrs: &[Attr]) {
        let known = statement_attributes(statement).unwrap_or(&[]);
        let unknown = attrs
            .iter()
            .filter(|a| !known.contains(&a.name) && !is_namespace_declaration(a.name));
        for attr in unknown {
            let name = Named {
                text: attr.name.to_string(),
                span: attr.name_span,
            };
            record(
                &mut self.builder.doc_mut().head.unknown_attributes,
                UnknownAttribute { statement, name },
            );
        }
    }

    /// A comment `<!-- … -->` from `start` to `end`: kept when addressed to x3dcheck; one
    /// before the root element applies to the whole file.
    pub(super) fn comment(&mut self, start: usize, end: usize) {
        let inner = Span::new(start + 4, end.saturating_sub(3).max(start + 4));
        if let Some(text) = addressed(self.source, inner) {
            let before_root = self.stack.is_empty() && !self.root_closed;
            self.directives
                .comment(Span::new(start, end), text, before_root);
        }
    }

    pub(super) fn end(&mut self, end: usize) {
        if !self.stack.is_empty() {
            self.directives.end(self.stack.len() - 1, end);
        }
        match self.stack.pop() {
            Some(Frame::Node { id, start }) => self.builder.end_node(id, Span::new(start, end)),
            Some(Frame::ProtoBody) => self.builder.end_proto_body(),
            Some(Frame::Root) => self.root_closed = true,
            _ => {}
        }
    }

    fn component(&mut self, attrs: &[Attr], span: Span) {
        let mut name = None;
        let mut level = None;
        for attr in attrs {
            match attr.name {
                "name" => {
                    name = Some(Named {
                        text: attr.value.to_string(),
                        span: attr.value_span,
                    })
                }
                "level" => {
                    level = attr
                        .value
                        .trim()
                        .parse::<i32>()
                        .ok()
                        .map(|l| (l, attr.value_span))
                }
                _ => {}
            }
        }
        let name = name.unwrap_or(Named {
            text: String::new(),
            span,
        });
        self.builder
            .doc_mut()
            .head
            .components
            .push(ComponentStatement { name, level, span });
    }

    fn unit(&mut self, attrs: &[Attr], span: Span) {
        let conversion_factor = attrs
            .iter()
            .find(|a| a.name == "conversionFactor")
            .map(|attr| {
                let factor = match self.parse_attr_value(FieldType::SFDouble, attr) {
                    Value::Doubles(v) => v.first().copied(),
                    _ => None,
                };
                (factor, attr.value_span)
            });
        let unit = UnitStatement {
            category: named_attr(attrs, "category"),
            name: named_attr(attrs, "name"),
            conversion_factor,
            span,
        };
        self.builder.doc_mut().head.units.push(unit);
    }

    fn route(&mut self, attrs: &[Attr], span: Span) {
        let get = |key: &str| {
            attrs
                .iter()
                .find(|a| a.name == key)
                .map(|a| Named {
                    text: a.value.to_string(),
                    span: a.value_span,
                })
                .unwrap_or(Named {
                    text: String::new(),
                    span,
                })
        };
        self.builder.add_route(Route {
            from_node: get("fromNode"),
            from_field: get("fromField"),
            to_node: get("toNode"),
            to_field: get("toField"),
            span,
            scope: Scope::Scene,
            vrml97_ends: None,
        });
    }

    fn declare_proto(&mut self, attrs: &[Attr], span: Span, external: bool) -> usize {
        let name = named_attr(attrs, "name").unwrap_or(Named {
            text: String::new(),
            span,
        });
        let url = attrs
            .iter()
            .find(|a| a.name == "url")
            .and_then(|a| {
                xml_value::parse_value(FieldType::MFString, &a.value)
                    .or_else(|e| e.into_recovered().ok_or(()))
                    .ok()
            })
            .and_then(|v| match v {
                Value::Strings(s) => Some(s),
                _ => None,
            })
            .unwrap_or_default();
        self.builder.declare_proto(ProtoDecl {
            name,
            span,
            external,
            scope: Scope::Scene,
            interface: Vec::new(),
            body: Vec::new(),
            url,
        })
    }

    /// A `field` declaration (ProtoInterface, ExternProtoDeclare, Script, shaders).
    fn field_decl(&mut self, owner: DeclOwner, attrs: &[Attr], span: Span) -> Frame {
        let name = named_attr(attrs, "name").unwrap_or(Named {
            text: String::new(),
            span,
        });
        let ty_attr = attrs.iter().find(|a| a.name == "type");
        let ty = ty_attr.and_then(|a| FieldType::parse(a.value.trim()));
        if let (Some(attr), None) = (ty_attr, ty) {
            self.builder.report(Diagnostic::new(
                &FIELD_VALUE_SYNTAX,
                attr.value_span,
                format!("`{}` is not an X3D field type", attr.value),
            ));
        }
        let access = attrs
            .iter()
            .find(|a| a.name == "accessType")
            .and_then(|a| AccessType::parse(a.value.trim()));
        let value = match (attrs.iter().find(|a| a.name == "value"), ty) {
            (Some(attr), Some(ty)) => Some((self.parse_attr_value(ty, attr), attr.value_span)),
            (Some(attr), None) => Some((Value::Unparsed(attr.value.to_string()), attr.value_span)),
            (None, _) => None,
        };
        let field = name.text.clone();
        let decl = FieldDecl {
            name,
            ty,
            access,
            span,
            value,
        };
        match owner {
            DeclOwner::Node(node) => self.builder.doc_mut().nodes[node.index()]
                .declared
                .push(decl),
            DeclOwner::Proto(proto) => self.builder.doc_mut().protos[proto].interface.push(decl),
        }
        Frame::FieldDecl { owner, field }
    }

    /// A ProtoInstance's `fieldValue`: typed by the ProtoDeclare when it is known.
    fn field_value(&mut self, node: NodeId, attrs: &[Attr]) -> Frame {
        let Some(name) = named_attr(attrs, "name") else {
            return Frame::Other;
        };
        if let Some(attr) = attrs.iter().find(|a| a.name == "value") {
            let field = self.builder.field_ref(node, &name.text);
            let value = match field.clone() {
                FieldRef::Declared { ty: Some(ty), .. } => self.parse_attr_value(ty, attr),
                _ => Value::Unparsed(attr.value.to_string()),
            };
            self.builder.add_field(
                node,
                FieldEntry {
                    field,
                    name_span: name.span,
                    span: attr.value_span,
                    origin: Origin::FieldValue,
                    value,
                },
            );
        }
        Frame::FieldValue {
            node,
            field: name.text,
            name_span: name.span,
        }
    }

    fn connect(&mut self, node: NodeId, attrs: &[Attr], span: Span) {
        let get = |key| {
            named_attr(attrs, key).unwrap_or(Named {
                text: String::new(),
                span,
            })
        };
        let connect = IsConnect {
            node_field: get("nodeField"),
            proto_field: get("protoField"),
            span,
        };
        self.builder.doc_mut().nodes[node.index()]
            .connects
            .push(connect);
    }

    /// The field a child element without `containerField` goes to. X3D 4 gave the
    /// Metadata nodes the default `value` (the field of a MetadataSet), and x3d-4.0.xsd says
    /// what it means elsewhere: "Default containerField='metadata' when providing
    /// information about the parent element itself, otherwise apply containerField='value'
    /// when this element contains payload metadata inside a parent/ancestor MetadataSet
    /// element". So under a parent without a `value` node field, such a node is the
    /// parent's `metadata`, as it was by default in X3D 3.
    fn default_container_field(&self, def: &NodeDef, hint: &Hint) -> String {
        let default = def.container_field;
        if default == "value" && def.field("metadata").is_some() {
            if let Hint::Node(parent) = hint {
                let parent_def = self.builder.doc().node(*parent).def();
                let holds_value = parent_def
                    .and_then(|p| p.field("value"))
                    .is_some_and(|f| f.ty.scalar() == Scalar::Node);
                if parent_def.is_some_and(|p| p.field("metadata").is_some()) && !holds_value {
                    return "metadata".to_string();
                }
            }
        }
        default.to_string()
    }

    /// A node element: a new node, or a USE of a DEF'd one.
    fn node(
        &mut self,
        hint: Hint,
        name: &str,
        name_span: Span,
        attrs: &[Attr],
        element: Span,
        empty: bool,
    ) -> Frame {
        let kind = if name == "ProtoInstance" {
            let proto_name = named_attr(attrs, "name")
                .map(|n| n.text)
                .unwrap_or_default();
            NodeKind::ProtoInstance {
                proto: self.builder.find_proto(&proto_name),
                name: proto_name,
            }
        } else {
            self.builder.node_kind(name)
        };
        let container = attrs.iter().find(|a| a.name == "containerField");
        let field_name = container
            .map(|a| a.value.trim().to_string())
            .unwrap_or_else(|| match &kind {
                NodeKind::Known { def, .. } => self.default_container_field(def, &hint),
                _ => "children".to_string(),
            });
        let field_span = container.map(|a| a.value_span).unwrap_or(name_span);
        let parent = hint.parent(&field_name, field_span);

        if let Some(use_attr) = attrs.iter().find(|a| a.name == "USE") {
            let use_name = Named {
                text: use_attr.value.to_string(),
                span: use_attr.value_span,
            };
            let extras: Vec<&Attr> = attrs
                .iter()
                .filter(|a| !matches!(a.name, "USE" | "containerField"))
                .filter(|a| !is_html_attribute(kind.def(), a.name))
                .filter(|a| !(name == "ProtoInstance" && a.name == "name"))
                .collect();
            if let Some(first) = extras.first() {
                let names: Vec<String> = extras.iter().map(|a| format!("`{}`", a.name)).collect();
                self.builder.report(
                    Diagnostic::new(
                        &USE_WITH_FIELDS,
                        first.name_span,
                        format!(
                            "USE `{}` also sets {}: a USE takes no fields",
                            use_name.text,
                            names.join(", ")
                        ),
                    )
                    .help("a USE is the DEF'd node itself; set the values on the DEF"),
                );
            }
            let element_type = (name != "ProtoInstance").then_some(name);
            self.builder
                .use_node(&use_name, element_type, element, parent);
            return if empty { Frame::Other } else { Frame::Use };
        }

        let def = kind.def();
        let Some(id) = self.builder.begin_node(kind, name_span, parent) else {
            return Frame::Other;
        };
        for attr in attrs {
            match attr.name {
                "DEF" => self.builder.define(
                    id,
                    Named {
                        text: attr.value.to_string(),
                        span: attr.value_span,
                    },
                ),
                "containerField" => {}
                _ if is_html_attribute(def, attr.name) => {}
                "name" if name == "ProtoInstance" => {}
                _ if attr.name.starts_with("xmlns") => {}
                _ => self.attribute_field(id, attr),
            }
        }
        Frame::Node {
            id,
            start: element.start as usize,
        }
    }

    /// A field given as an attribute.
    fn attribute_field(&mut self, node: NodeId, attr: &Attr) {
        let field = self.builder.field_ref(node, attr.name);
        let value = match field.clone() {
            FieldRef::Schema { def, .. }
                if self.keep == KeepValues::Summaries && Summary::applies_to(def.ty) =>
            {
                self.parse_attr_summary(node, def, attr)
            }
            FieldRef::Schema { def, .. } => self.parse_attr_value(def.ty, attr),
            FieldRef::Declared { ty: Some(ty), .. } => self.parse_attr_value(ty, attr),
            _ => Value::Unparsed(attr.value.to_string()),
        };
        self.builder.add_field(
            node,
            FieldEntry {
                field,
                name_span: attr.name_span,
                span: attr.value_span,
                origin: Origin::Attribute,
                value,
            },
        );
    }

    /// Parses attribute text as a field type, reporting syntax errors at their place.
    fn parse_attr_value(&mut self, ty: FieldType, attr: &Attr) -> Value {
        if ty.scalar() == Scalar::Node {
            self.builder.report(Diagnostic::new(
                &FIELD_VALUE_SYNTAX,
                attr.value_span,
                format!(
                    "`{}` is a {ty} field: its nodes are child elements, not attribute text",
                    attr.name
                ),
            ));
            return Value::Unparsed(attr.value.to_string());
        }
        let text = if ty.scalar() == Scalar::String {
            normalize_whitespace(&attr.value)
        } else {
            Cow::Borrowed(&*attr.value)
        };
        let parsed = xml_value::parse_value(ty, &text);
        self.parsed_or_reported(parsed, attr)
    }

    /// [`Self::parse_attr_value`] for a numeric MF value kept as a [`Summary`].
    fn parse_attr_summary(&mut self, node: NodeId, def: &'static FieldDef, attr: &Attr) -> Value {
        let parsed = xml_value::parse_summary(self.builder.doc().node(node), def, &attr.value);
        self.parsed_or_reported(parsed, attr)
    }

    /// The value parsed, or the syntax error reported at its place (and the text kept).
    fn parsed_or_reported(
        &mut self,
        parsed: Result<Value, xml_value::SyntaxError>,
        attr: &Attr,
    ) -> Value {
        match parsed {
            Ok(value) => value,
            Err(error) => {
                let span = if attr.verbatim {
                    let start = attr.value_span.start as usize + error.offset;
                    Span::new(start, start + error.len)
                } else {
                    attr.value_span
                };
                let mut diagnostic = Diagnostic::new(
                    &FIELD_VALUE_SYNTAX,
                    span,
                    format!("`{}`: {}", attr.name, error.message),
                )
                .value(truncate(&attr.value, 80));
                if let Some(fix) = &error.fix {
                    let written = if fix.contains('\'') {
                        format!("\"{}\"", fix.replace('"', "&quot;"))
                    } else {
                        format!("'{fix}'")
                    };
                    diagnostic = diagnostic.help(format!("write {}={written}", attr.name));
                } else if let Some(help) = &error.help {
                    diagnostic = diagnostic.help(help.clone());
                }
                self.builder.report(diagnostic);
                error
                    .into_recovered()
                    .unwrap_or_else(|| Value::Unparsed(attr.value.to_string()))
            }
        }
    }
}

fn named_attr(attrs: &[Attr], key: &str) -> Option<Named> {
    attrs.iter().find(|a| a.name == key).map(|a| Named {
        text: a.value.to_string(),
        span: a.value_span,
    })
}

/// XML attribute-value normalization (XML 1.0 3.3.3): each line end (`\r\n`, `\r`, `\n`)
/// and tab becomes one space. Applied to string fields, whose text is kept.
fn normalize_whitespace(text: &str) -> Cow<'_, str> {
    if !text.contains(['\t', '\r', '\n']) {
        return Cow::Borrowed(text);
    }
    Cow::Owned(text.replace("\r\n", " ").replace(['\t', '\r', '\n'], " "))
}

pub(crate) fn truncate(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text.to_string(),
    }
}

/// What the innermost open element lets its children be.
#[derive(Clone)]
enum Context {
    Root,
    Head,
    /// Scene, ProtoBody or a node: nodes and statements; `Some` for a node.
    Nodes(Option<NodeId>),
    ProtoDeclare(usize),
    ProtoInterface(usize),
    ExternProto(usize),
    FieldDecl(DeclOwner, String),
    FieldValue(NodeId, String, Span),
    Is(NodeId),
    Use,
    Other,
}

impl Context {
    fn of(frame: &Frame) -> Context {
        match frame {
            Frame::Root => Context::Root,
            Frame::Head => Context::Head,
            Frame::Scene | Frame::ProtoBody => Context::Nodes(None),
            Frame::Node { id, .. } => Context::Nodes(Some(*id)),
            Frame::ProtoDeclare { proto } => Context::ProtoDeclare(*proto),
            Frame::ProtoInterface { proto } => Context::ProtoInterface(*proto),
            Frame::ExternProtoDeclare { proto } => Context::ExternProto(*proto),
            Frame::FieldDecl { owner, field } => Context::FieldDecl(*owner, field.clone()),
            Frame::FieldValue {
                node,
                field,
                name_span,
            } => Context::FieldValue(*node, field.clone(), *name_span),
            Frame::Is { node } => Context::Is(*node),
            Frame::Use => Context::Use,
            Frame::Other => Context::Other,
        }
    }

    /// Where a node element in this context goes, before its containerField is known.
    fn parent_hint(&self) -> Hint {
        match self {
            Context::Nodes(Some(node)) => Hint::Node(*node),
            _ => Hint::TopLevel,
        }
    }
}

/// Where a node element goes; resolved to a [`Parent`] once its field name is known.
enum Hint {
    /// The Scene or the open ProtoBody (the builder knows which by its scope).
    TopLevel,
    Node(NodeId),
    Field {
        node: NodeId,
        field: String,
        origin: Origin,
    },
    FieldValue {
        node: NodeId,
        field: String,
        name_span: Span,
    },
    ProtoField {
        proto: usize,
        field: String,
    },
}

impl Hint {
    fn parent<'a>(&'a self, container_field: &'a str, field_span: Span) -> Parent<'a> {
        match self {
            Hint::TopLevel => Parent::TopLevel,
            Hint::Node(node) => Parent::Field {
                node: *node,
                field: container_field,
                field_span,
                origin: Origin::Children,
            },
            Hint::Field {
                node,
                field,
                origin,
            } => Parent::Field {
                node: *node,
                field,
                field_span,
                origin: *origin,
            },
            Hint::FieldValue {
                node,
                field,
                name_span,
            } => Parent::Field {
                node: *node,
                field,
                field_span: *name_span,
                origin: Origin::FieldValue,
            },
            Hint::ProtoField { proto, field } => Parent::ProtoField {
                proto: *proto,
                field,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use quick_xml::events::attributes::Attributes;

    use super::*;

    /// The chunked scan finds what a look at every byte finds: each kind of character, at
    /// the edges of a chunk and in the tail, in text that has tab, line feed and CR too.
    #[test]
    fn forbidden_chars_are_found_wherever_they_are() {
        let every_byte = |text: &[u8]| {
            let s = std::str::from_utf8(text).unwrap();
            s.char_indices()
                .find(|&(_, c)| {
                    (c < ' ' && !matches!(c, '\t' | '\n' | '\r'))
                        || matches!(c, '\u{FFFE}' | '\u{FFFF}')
                })
                .map(|(at, _)| at)
        };
        let plain = "a\tb\nc\rd 0.5 1 2, \u{FEFF}\u{FFFD} ".repeat(20);
        assert_eq!(first_forbidden_char(plain.as_bytes(), 0..plain.len()), None);
        for bad in ["\u{0}", "\u{1}", "\u{B}", "\u{1F}", "\u{FFFE}", "\u{FFFF}"] {
            for at in [0, 1, 62, 63, 64, 65, 127, 128, 200, plain.len()] {
                let at = (0..=at).rev().find(|&i| plain.is_char_boundary(i)).unwrap();
                let text = format!("{}{bad}{}", &plain[..at], &plain[at..]);
                let found = first_forbidden_char(text.as_bytes(), 0..text.len());
                assert_eq!(found, every_byte(text.as_bytes()), "{bad:?} at {at}");
                assert_eq!(found, Some(at));
            }
        }
    }

    /// Where the plain reading takes a tag, it gives what quick-xml's checked iterator
    /// gives, in the same places of the text; every tag it leaves has an error there or
    /// something it does not read (whitespace around `=`, over 32 attributes).
    #[test]
    fn plain_attributes_are_quick_xml_attributes() {
        let many: String = (0..33).map(|k| format!(" a{k}='{k}'")).collect();
        let tags = [
            "",
            "   ",
            r#" a="1" b='2'"#,
            " a='1'b='2' ",
            " a='x\"y' b=\"x'y\"\n\tc='>'",
            " point='1 2 3\n4 5 6'",
            " a='1' a='2'",
            " a='1' b='2' a='3'",
            " a = '1'",
            " a= '1'",
            " a ='1'",
            " a=1",
            " a",
            " a=",
            " a='1",
            " ='1'",
            " =='1'",
            " é='ü' b='€'",
            " a=''",
            &many,
        ];
        for raw in tags {
            let mut checked = Attributes::new(raw, 0);
            checked.with_checks(true);
            let expected: Vec<_> = checked.collect();
            match plain_attributes(raw) {
                Some(plain) => {
                    let plain: Vec<_> = plain.into_iter().map(Ok).collect();
                    assert_eq!(plain, expected, "{raw:?}");
                    for (ours, theirs) in plain.iter().flatten().zip(expected.iter().flatten()) {
                        assert_eq!(ours.key.0.as_ptr(), theirs.key.0.as_ptr());
                        assert_eq!(ours.value.as_ptr(), theirs.value.as_ptr());
                    }
                }
                None => assert!(
                    expected.iter().any(Result::is_err)
                        || raw.contains(" =")
                        || raw.contains("= ")
                        || raw == many,
                    "{raw:?}: {expected:?}"
                ),
            }
        }
        assert!(plain_attributes(r#" a="1" b='2'"#).is_some());
        assert!(plain_attributes(" a='x\"y' b=\"x'y\"\n\tc='>'").is_some());
    }
}
