//! The ClassicVRML encoding (ISO/IEC 19776-2, `#X3D V3.x utf8`) and VRML97 (ISO/IEC
//! 14772-1, `#VRML V2.0 utf8`) read by one recursive-descent reader into the scene model,
//! through the same [`Builder`] as the XML and JSON readers. Field values are typed by the
//! schema (or the PROTO interface) of the node they belong to, as 19776-2 A.1.2 asks, and
//! parsed by [`xml_value`](crate::model::text::xml_value)'s flat-array parsers: the text between a
//! field's brackets is handed over as it stands.
//!
//! Syntax errors are VRML_MALFORMED at their place; the reader then goes on at the next
//! field, node or statement. Nesting is bounded by [`MAX_DEPTH`] whatever the input.

mod lexer;
mod value;

use lexer::{Kind, Lexer, Token};

use crate::diagnostic::Diagnostic;
use crate::limits::{MAX_DEPTH, MAX_INPUT_BYTES};
use crate::model::builder::Parent;
use crate::model::draft::Limit;
use crate::model::text::number::parse_f64;
use crate::model::*;
use crate::parse::behind::{self, Progress};
use crate::parse::directive::place_following;
use crate::parse::rules::{FIELD_VALUE_SYNTAX, VRML_MALFORMED};
use crate::parse::{KeepValues, Parsed};
use crate::schema::{AccessType, FieldType, Scalar, Version};

/// Reads a ClassicVRML or VRML97 document.
pub fn read(source: &[u8]) -> Parsed {
    read_with(source, KeepValues::All, &())
}

/// Which language the header names.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
enum Dialect {
    X3d,
    Vrml97,
}

/// Reads a ClassicVRML or VRML97 document, keeping numeric MF values whole or as
/// summaries, telling `progress` how far its UTF-8 check and its tokens have got.
pub fn read_with(source: &[u8], keep: KeepValues, progress: &dyn Progress) -> Parsed {
    let stop = |encoding, at: usize, message: String| Parsed {
        encoding: Some(encoding),
        document: None,
        diagnostics: vec![Diagnostic::new(&VRML_MALFORMED, Span::new(at, at), message)],
    };
    let bom = if source.starts_with(b"\xEF\xBB\xBF") {
        3
    } else {
        0
    };
    let start = bom
        + source[bom..]
            .iter()
            .position(|b| !b.is_ascii_whitespace())
            .unwrap_or(0);
    let dialect = if source[start..].starts_with(b"#VRML") {
        Dialect::Vrml97
    } else {
        Dialect::X3d
    };
    let encoding = match dialect {
        Dialect::X3d => Encoding::ClassicVrml,
        Dialect::Vrml97 => Encoding::Vrml97,
    };
    if source.len() > MAX_INPUT_BYTES {
        return stop(encoding, 0, "the input is larger than 4 GiB".into());
    }
    let text = match behind::utf8(source, progress) {
        Ok(text) => text,
        Err(error) => {
            let at = error.valid_up_to;
            return stop(
                encoding,
                at,
                format!("byte {at} is not UTF-8: the header says `utf8`, and ClassicVRML and VRML97 files are UTF-8 text"),
            );
        }
    };
    let mut reader = Reader {
        lexer: Lexer::new(text, start, false, dialect == Dialect::Vrml97).with_progress(progress),
        keep,
        dialect,
        builder: Builder::new(encoding),
        depth: 0,
        seen_body: false,
        end_reported: false,
    };
    reader.header(start);
    // Directive comments before the first token after the header apply to the whole file.
    let first_token = reader.lexer.peek().start;
    reader.statements(None);
    // As in the XML reader: the pieces' vectors are kept for this document only.
    crate::model::text::split::scratch::release();
    if let Some(at) = reader.lexer.unterminated_comment {
        reader.malformed(
            Span::new(at, at + 3),
            "a block comment `#/*` that never ends with `*/#`",
        );
    }
    let (mut document, diagnostics) = reader.builder.finish();
    document.directives = place_following(source, &document, &reader.lexer.directives, first_token);
    Parsed {
        encoding: Some(encoding),
        document: Some(document),
        diagnostics,
    }
}

struct Reader<'s> {
    lexer: Lexer<'s>,
    keep: KeepValues,
    dialect: Dialect,
    builder: Builder,
    /// Nodes, PROTOs and bracketed node lists open now: bounded by [`MAX_DEPTH`].
    depth: usize,
    /// Whether a node, PROTO or ROUTE was read: PROFILE, COMPONENT, UNIT and META come first.
    seen_body: bool,
    /// The end of the input inside an open node is reported once, at the innermost.
    end_reported: bool,
}

/// Where a node goes, before its field name is known.
#[derive(Copy, Clone)]
enum Hint<'s> {
    /// The scene or the open PROTO body.
    TopLevel,
    /// A node field, named in the text.
    Field {
        node: NodeId,
        field: &'s str,
        field_span: Span,
        origin: Origin,
    },
    /// A PROTO interface field's initial value.
    ProtoField { proto: usize, field: &'s str },
}

impl<'s> Hint<'s> {
    fn parent(self) -> Parent<'s> {
        match self {
            Hint::TopLevel => Parent::TopLevel,
            Hint::Field {
                node,
                field,
                field_span,
                origin,
            } => Parent::Field {
                node,
                field,
                field_span,
                origin,
            },
            Hint::ProtoField { proto, field } => Parent::ProtoField { proto, field },
        }
    }
}

/// Whose interface a declaration belongs to.
#[derive(Copy, Clone)]
enum Owner {
    Node(NodeId),
    Proto { proto: usize, external: bool },
}

impl<'s> Reader<'s> {
    fn malformed(&mut self, span: Span, message: impl Into<String>) {
        self.builder
            .report(Diagnostic::new(&VRML_MALFORMED, span, message.into()));
    }

    /// The header line: `#X3D V4.0 utf8` or `#VRML V2.0 utf8` (19776-2 4.3.2.2,
    /// 14772-1 4.2.2). Detection has checked that it starts so.
    fn header(&mut self, start: usize) {
        let text = self.lexer.text;
        let line_end = memchr::memchr2(b'\n', b'\r', &text.as_bytes()[start..])
            .map_or(text.len(), |k| start + k);
        let line = &text[start..line_end];
        self.builder.doc_mut().root_span = Span::new(start, line_end);
        let mut words = line.split([' ', '\t']).filter(|w| !w.is_empty());
        let offset = |word: &str| word.as_ptr() as usize - text.as_ptr() as usize;
        let _magic = words.next();
        let version = words.next();
        let charset = words.next();
        match version {
            Some(word) => {
                let number = word.strip_prefix('V').unwrap_or(word);
                let at = offset(number);
                let named = Named {
                    text: number.to_string(),
                    span: Span::new(at, at + number.len()),
                };
                let doc = self.builder.doc_mut();
                match self.dialect {
                    Dialect::X3d => doc.version = Version::parse(number),
                    Dialect::Vrml97 => {
                        doc.version = Some(Version::Vrml97);
                        if number != "2.0" {
                            let span = named.span;
                            self.malformed(
                                span,
                                format!(
                                    "`#VRML V{number}`: VRML97 files start with `#VRML V2.0 utf8`"
                                ),
                            );
                        }
                    }
                }
                // Block comments came with X3D 3.3 (19776-2 A.1.2).
                self.lexer.block_comments = self.dialect == Dialect::X3d
                    && self
                        .builder
                        .doc()
                        .version
                        .is_none_or(|v| v >= Version::V3_3);
                self.builder.doc_mut().version_text = Some(named);
            }
            None => self.malformed(
                Span::new(start, line_end),
                "the header names no version: write `#X3D V4.0 utf8` (or `#VRML V2.0 utf8`)",
            ),
        }
        if let Some(word) = charset.filter(|w| *w != "utf8") {
            let at = offset(word);
            self.malformed(
                Span::new(at, at + word.len()),
                format!("`{word}`: the header's character set is `utf8`"),
            );
        } else if version.is_some() && charset.is_none() {
            self.malformed(
                Span::new(line_end, line_end),
                "the header ends without its character set `utf8`",
            );
        }
        self.lexer.pos = line_end;
        self.builder.doc_mut().scene_span = Some(Span::new(line_end, text.len()));
    }

    /// Statements of the scene (`proto` None, up to the end of the input) or of a PROTO
    /// body (up to its `}`, left for the caller).
    fn statements(&mut self, proto: Option<usize>) {
        loop {
            let token = self.lexer.peek();
            match token.kind {
                Kind::End => return,
                Kind::CloseBrace if proto.is_some() => return,
                Kind::Id => self.statement(token, proto.is_none()),
                _ => {
                    let what = describe(&token);
                    self.malformed(
                        token.span(),
                        format!("{what} where a node or statement belongs"),
                    );
                    self.lexer.next();
                    self.recover(proto.is_some());
                }
            }
        }
    }

    /// One statement starting with a name.
    fn statement(&mut self, token: Token<'s>, top: bool) {
        let header = matches!(token.text, "PROFILE" | "COMPONENT" | "UNIT" | "META");
        if header && self.dialect == Dialect::X3d {
            if !top || self.seen_body {
                self.malformed(
                    token.span(),
                    format!("`{}` belongs at the start of the file, after the header and before any node, PROTO or ROUTE", token.text),
                );
            }
            self.lexer.next();
            self.header_statement(token);
            return;
        }
        self.seen_body = true;
        match token.text {
            "PROTO" | "EXTERNPROTO" => {
                self.lexer.next();
                self.proto(token);
            }
            "ROUTE" => {
                self.lexer.next();
                self.route(token);
            }
            "IMPORT" | "EXPORT" if self.dialect == Dialect::X3d => {
                self.lexer.next();
                self.import_export(token);
            }
            "PROFILE" | "COMPONENT" | "UNIT" | "META" | "IMPORT" | "EXPORT" => {
                self.malformed(
                    token.span(),
                    format!(
                        "VRML97 has no {} statement (X3D's ClassicVRML encoding has)",
                        token.text
                    ),
                );
                self.lexer.next();
                self.recover_statement();
            }
            _ => self.node_statement(Hint::TopLevel),
        }
    }

    /// PROFILE, COMPONENT, UNIT or META (19776-2 4.3.2.3–4.3.2.6), keyword consumed.
    fn header_statement(&mut self, keyword: Token<'s>) {
        match keyword.text {
            "PROFILE" => {
                if let Some(name) = self.expect_name("a profile name after PROFILE") {
                    self.builder.doc_mut().profile = Some(name);
                }
            }
            "COMPONENT" => {
                let Some(name) = self.expect_name("a component name after COMPONENT") else {
                    return;
                };
                let mut level = None;
                let mut end = name.span.end as usize;
                if self.lexer.peek().is(Kind::Colon) {
                    self.lexer.next();
                    let token = self.lexer.peek();
                    match token.text.parse::<i32>() {
                        Ok(value) if token.is(Kind::Number) => {
                            self.lexer.next();
                            level = Some((value, token.span()));
                            end = token.end();
                        }
                        _ => self.malformed(
                            token.span(),
                            format!(
                                "{} where the component level belongs (`COMPONENT {}:1`)",
                                describe(&token),
                                name.text
                            ),
                        ),
                    }
                } else {
                    let at = self.lexer.pos;
                    self.malformed(
                        Span::new(at, at),
                        format!(
                            "COMPONENT {} has no level: write `COMPONENT {}:1`",
                            name.text, name.text
                        ),
                    );
                }
                let span = Span::new(keyword.start, end);
                let statement = ComponentStatement { name, level, span };
                self.builder.doc_mut().head.components.push(statement);
            }
            "UNIT" => {
                let category = self.lexer.next();
                let name = self.lexer.next();
                let factor = self.lexer.next();
                if !(category.is(Kind::Id) && name.is(Kind::Id) && factor.is(Kind::Number)) {
                    self.malformed(
                        Span::new(keyword.start, factor.end()),
                        "a UNIT statement is `UNIT category name conversionFactor`, as in `UNIT length millimetre 0.001`",
                    );
                    self.recover_statement();
                }
                let unit = UnitStatement {
                    category: category.is(Kind::Id).then(|| named(&category)),
                    name: name.is(Kind::Id).then(|| named(&name)),
                    conversion_factor: factor
                        .is(Kind::Number)
                        .then(|| (parse_f64(factor.text.as_bytes()), factor.span())),
                    span: Span::new(keyword.start, factor.end()),
                };
                self.builder.doc_mut().head.units.push(unit);
            }
            _ => {
                let key = self.lexer.next();
                let value = self.lexer.next();
                if !(key.is(Kind::String) && value.is(Kind::String)) {
                    self.malformed(
                        Span::new(keyword.start, value.end()),
                        "a META statement is two quoted strings, as in `META \"creator\" \"Jane Doe\"`",
                    );
                    self.recover_statement();
                }
                self.builder.doc_mut().head.metas += 1;
            }
        }
    }

    /// The next token as a name, or a VRML_MALFORMED saying what was expected.
    fn expect_name(&mut self, what: &str) -> Option<Named> {
        let token = self.lexer.peek();
        if token.is(Kind::Id) {
            self.lexer.next();
            return Some(named(&token));
        }
        self.malformed(
            token.span(),
            format!("{} where {what} belongs", describe(&token)),
        );
        None
    }

    /// `ROUTE a.b TO c.d` (19776-2 4.3.2.13), keyword consumed.
    fn route(&mut self, keyword: Token<'s>) {
        let parsed = (|| {
            let (from_node, from_field) = self.dotted("ROUTE")?;
            let to = self.lexer.peek();
            if !to.is_id("TO") {
                self.malformed(
                    to.span(),
                    format!("{} where `TO` belongs in `ROUTE a.b TO c.d`", describe(&to)),
                );
                return None;
            }
            self.lexer.next();
            let (to_node, to_field) = self.dotted("ROUTE")?;
            Some((from_node, from_field, to_node, to_field))
        })();
        match parsed {
            Some((from_node, from_field, to_node, to_field)) => {
                let span = Span::new(keyword.start, to_field.span.end as usize);
                self.builder.add_route(Route {
                    from_node,
                    from_field,
                    to_node,
                    to_field,
                    span,
                    scope: Scope::Scene,
                    vrml97_ends: None,
                });
            }
            None => self.recover_statement(),
        }
    }

    /// `node.field` of a ROUTE or IMPORT.
    fn dotted(&mut self, statement: &str) -> Option<(Named, Named)> {
        let node = self.expect_name(&format!("a node name in {statement}"))?;
        let dot = self.lexer.peek();
        // A name may not hold a `.`, so `a.b` is three tokens with nothing between.
        if !dot.is(Kind::Period) {
            self.malformed(
                dot.span(),
                format!("{} where `.` belongs after `{}`", describe(&dot), node.text),
            );
            return None;
        }
        self.lexer.next();
        let field = self.expect_name(&format!("a field name after `{}.`", node.text))?;
        Some((node, field))
    }

    /// IMPORT and EXPORT (19776-2 4.3.2.14–15): `IMPORT inline.exported [AS name]`,
    /// `EXPORT local [AS name]`.
    fn import_export(&mut self, keyword: Token<'s>) {
        let import = keyword.text == "IMPORT";
        let names = if import {
            self.dotted("IMPORT")
                .map(|(inline, exported)| (inline, Some(exported)))
        } else {
            self.expect_name("a node name after EXPORT")
                .map(|local| (local, None))
        };
        let Some((first, exported)) = names else {
            self.recover_statement();
            return;
        };
        let mut end = exported.as_ref().unwrap_or(&first).span.end;
        let mut as_name = None;
        if self.lexer.peek().is_id("AS") {
            self.lexer.next();
            match self.expect_name("a name after AS") {
                Some(name) => {
                    end = name.span.end;
                    as_name = Some(name);
                }
                None => self.recover_statement(),
            }
        }
        let span = Span::new(keyword.start, end as usize);
        match exported {
            Some(imported_def) => self.builder.add_import(Import {
                inline_def: first,
                imported_def,
                as_name,
                span,
                scope: Scope::Scene,
            }),
            None => self.builder.add_export(Export {
                local_def: first,
                as_name,
                span,
                scope: Scope::Scene,
            }),
        }
    }

    /// `PROTO Name [ interface ] { body }` or `EXTERNPROTO Name [ interface ] url`
    /// (19776-2 4.3.2.9, 4.3.2.11), keyword consumed.
    fn proto(&mut self, keyword: Token<'s>) {
        let external = keyword.text == "EXTERNPROTO";
        let Some(name) = self.expect_name(&format!("the prototype's name after {}", keyword.text))
        else {
            self.recover_statement();
            return;
        };
        if !self.enter(keyword.span()) {
            return;
        }
        let proto = self.builder.declare_proto(ProtoDecl {
            name,
            span: keyword.span(),
            external,
            scope: Scope::Scene,
            interface: Vec::new(),
            body: Vec::new(),
            url: Vec::new(),
        });
        let open = self.lexer.peek();
        if open.is(Kind::OpenBracket) {
            self.lexer.next();
            self.declarations(Owner::Proto { proto, external });
        } else {
            self.malformed(
                open.span(),
                format!("{} where the interface `[ … ]` belongs", describe(&open)),
            );
        }
        let end = if external {
            self.extern_url(proto)
        } else {
            self.proto_body(proto)
        };
        self.builder.doc_mut().protos[proto].span = Span::new(keyword.start, end);
        self.depth -= 1;
    }

    /// Whether a `[ … ]` list ends at `token`: its `]` (taken), or the end of the file
    /// (reported as a missing `]` of `what`).
    fn bracket_list_ends(&mut self, token: &Token<'s>, what: &str) -> bool {
        match token.kind {
            Kind::CloseBracket => {
                self.lexer.next();
                true
            }
            Kind::End => {
                if !self.end_reported {
                    self.end_reported = true;
                    self.malformed(
                        token.span(),
                        format!("the file ends inside {what}: `]` is missing"),
                    );
                }
                true
            }
            _ => false,
        }
    }

    /// The `[ … ]` of declarations after its `[`, up to and with its `]`.
    fn declarations(&mut self, owner: Owner) {
        loop {
            let token = self.lexer.peek();
            if self.bracket_list_ends(&token, "a PROTO interface `[`") {
                return;
            }
            match token.kind {
                Kind::Id if access_type(token.text).is_some() => {
                    self.lexer.next();
                    self.declaration(owner, token);
                }
                _ => {
                    self.malformed(
                        token.span(),
                        format!(
                            "{} where a field declaration (`inputOutput SFFloat name 1`) belongs",
                            describe(&token)
                        ),
                    );
                    self.lexer.next();
                    while !matches!(
                        self.lexer.peek().kind,
                        Kind::Id | Kind::CloseBracket | Kind::End
                    ) {
                        self.skip_one();
                    }
                }
            }
        }
    }

    /// `accessType fieldType name [value | IS name]` after its access type: in a PROTO or
    /// EXTERNPROTO interface or in a Script or shader node's body.
    fn declaration(&mut self, owner: Owner, keyword: Token<'s>) {
        let access = access_type(keyword.text);
        let ty_token = self.lexer.peek();
        let ty = if ty_token.is(Kind::Id) {
            self.lexer.next();
            let ty = FieldType::parse(ty_token.text);
            if ty.is_none() {
                self.malformed(
                    ty_token.span(),
                    format!("`{}` is not a field type", ty_token.text),
                );
            }
            ty
        } else {
            self.malformed(
                ty_token.span(),
                format!(
                    "{} where a field type (SFFloat, MFNode, …) belongs",
                    describe(&ty_token)
                ),
            );
            None
        };
        let Some(name) = self.expect_name("the field's name") else {
            return;
        };
        let name_token = Token {
            kind: Kind::Id,
            text: &self.lexer.text[name.span.range()],
            start: name.span.start as usize,
        };
        let decl = FieldDecl {
            name,
            ty,
            access,
            span: Span::new(keyword.start, name_token.end()),
            value: None,
        };
        let index = match owner {
            Owner::Node(node) => {
                let declared = &mut self.builder.doc_mut().nodes[node.index()].declared;
                declared.push(decl);
                declared.len() - 1
            }
            Owner::Proto { proto, .. } => {
                let interface = &mut self.builder.doc_mut().protos[proto].interface;
                interface.push(decl);
                interface.len() - 1
            }
        };
        if let Owner::Node(node) = owner {
            if self.lexer.peek().is_id("IS") {
                self.lexer.next();
                self.is_connect(node, name_token);
                return;
            }
        }
        let takes_value = !matches!(owner, Owner::Proto { external: true, .. })
            && access.is_some_and(AccessType::is_initializable);
        if !takes_value {
            return;
        }
        let hint = match owner {
            Owner::Node(node) => Hint::Field {
                node,
                field: name_token.text,
                field_span: name_token.span(),
                origin: Origin::Member,
            },
            Owner::Proto { proto, .. } => Hint::ProtoField {
                proto,
                field: name_token.text,
            },
        };
        let value = match ty {
            Some(ty) if ty.scalar() == Scalar::Node => {
                self.node_value(ty, hint, name_token);
                None
            }
            Some(ty) => self.typed_value(ty, None, &name_token),
            None => self.untyped_value(hint, name_token),
        };
        if let Some(value) = value {
            let decl = match owner {
                Owner::Node(node) => {
                    &mut self.builder.doc_mut().nodes[node.index()].declared[index]
                }
                Owner::Proto { proto, .. } => {
                    &mut self.builder.doc_mut().protos[proto].interface[index]
                }
            };
            decl.span.end = value.1.end;
            decl.value = Some(value);
        }
    }

    /// `{ statements }` of a PROTO; the end of what was read.
    fn proto_body(&mut self, proto: usize) -> usize {
        let open = self.lexer.peek();
        if !open.is(Kind::OpenBrace) {
            self.malformed(
                open.span(),
                format!("{} where the PROTO body `{{ … }}` belongs", describe(&open)),
            );
            self.recover_statement();
            return self.lexer.pos;
        }
        self.lexer.next();
        self.builder.begin_proto_body(proto);
        self.statements(Some(proto));
        self.builder.end_proto_body();
        let close = self.lexer.next();
        if close.is(Kind::End) {
            self.malformed(open.span(), "this PROTO body's `{` is never closed");
        }
        close.end()
    }

    /// The url list of an EXTERNPROTO; the end of what was read.
    fn extern_url(&mut self, proto: usize) -> usize {
        let token = self.lexer.peek();
        if !matches!(token.kind, Kind::String | Kind::OpenBracket) {
            self.malformed(
                token.span(),
                format!(
                    "{} where the EXTERNPROTO's url (`\"file.x3dv#Name\"`) belongs",
                    describe(&token)
                ),
            );
            return self.lexer.pos;
        }
        let url = Token {
            kind: Kind::Id,
            text: "url",
            start: token.start,
        };
        if let Some((Value::Strings(urls), span)) =
            self.typed_value(FieldType::MFString, None, &url)
        {
            self.builder.doc_mut().protos[proto].url = urls;
            return span.end as usize;
        }
        self.lexer.pos
    }

    /// Counts one more level of nesting; false (reported, and the construct skipped)
    /// past [`MAX_DEPTH`].
    fn enter(&mut self, at: Span) -> bool {
        if self.depth >= MAX_DEPTH {
            let message = format!(
                "the scene graph is nested deeper than {MAX_DEPTH} nodes here; deeper nodes are not read"
            );
            self.builder.exceeded(Limit::Depth, at, message);
            self.skip_construct();
            return false;
        }
        self.depth += 1;
        true
    }

    /// Skips what is left of a construct whose head was read: up to and with the `{ … }`
    /// or `[ … ]` that comes first (and for a PROTO, its body too).
    fn skip_construct(&mut self) {
        let mut groups = 0;
        loop {
            let token = self.lexer.peek();
            match token.kind {
                Kind::End => return,
                Kind::OpenBrace | Kind::OpenBracket => {
                    self.skip_one();
                    groups += 1;
                    if groups == 2 || token.is(Kind::OpenBrace) {
                        return;
                    }
                }
                Kind::CloseBrace | Kind::CloseBracket => return,
                _ => self.skip_one(),
            }
        }
    }

    /// Skips one token, or one balanced `{ … }` or `[ … ]` (without recursion).
    fn skip_one(&mut self) {
        let first = self.lexer.next();
        if !matches!(first.kind, Kind::OpenBrace | Kind::OpenBracket) {
            return;
        }
        let mut depth = 1usize;
        while depth > 0 {
            let token = self.lexer.next();
            match token.kind {
                Kind::OpenBrace | Kind::OpenBracket => depth += 1,
                Kind::CloseBrace | Kind::CloseBracket => depth -= 1,
                Kind::End => return,
                _ => {}
            }
        }
    }

    /// After an error: skips to the next name (a field, node or statement) or to the `}`
    /// that closes the construct being read (`in_braces`), whichever comes first.
    fn recover(&mut self, in_braces: bool) {
        loop {
            let token = self.lexer.peek();
            match token.kind {
                Kind::End | Kind::Id => return,
                Kind::CloseBrace if in_braces => return,
                Kind::CloseBrace | Kind::CloseBracket => {
                    self.lexer.next();
                }
                _ => self.skip_one(),
            }
        }
    }

    /// After an error in a statement (ROUTE, IMPORT, a header statement): skips the
    /// names, dots and numbers left on the line, since such statements are written on
    /// one line, then on as [`Self::recover`] does.
    fn recover_statement(&mut self) {
        let bytes = self.lexer.text.as_bytes();
        let at = self.lexer.pos;
        let line_end = memchr::memchr2(b'\n', b'\r', &bytes[at..]).map_or(bytes.len(), |k| at + k);
        loop {
            let token = self.lexer.peek();
            let on_line = token.start < line_end;
            match token.kind {
                Kind::Id | Kind::Period | Kind::Number | Kind::Colon | Kind::String if on_line => {
                    if token.is(Kind::Id) && self.followed_by_brace(token) {
                        break;
                    }
                    self.lexer.next();
                }
                _ => break,
            }
        }
        self.recover(true);
    }

    /// A node statement: `Type { … }`, `DEF name Type { … }` or `USE name`
    /// (19776-2 4.3.2.7, 4.3.2.12).
    fn node_statement(&mut self, hint: Hint<'s>) {
        let first = self.lexer.next();
        match first.text {
            "USE" => {
                let Some(name) = self.expect_name("the DEF name after USE") else {
                    return;
                };
                let site = Span::new(first.start, name.span.end as usize);
                self.builder.use_node(&name, None, site, hint.parent());
            }
            "DEF" => {
                let Some(name) = self.expect_name("the name after DEF") else {
                    self.recover_statement();
                    return;
                };
                let ty = self.lexer.peek();
                if !ty.is(Kind::Id) {
                    self.malformed(
                        ty.span(),
                        format!(
                            "{} where the node type after `DEF {}` belongs",
                            describe(&ty),
                            name.text
                        ),
                    );
                    self.recover_statement();
                    return;
                }
                self.lexer.next();
                self.node(hint, ty, Some((name, first.start)));
            }
            _ => self.node(hint, first, None),
        }
    }

    /// `Type { body }` with its type name read.
    fn node(&mut self, hint: Hint<'s>, ty: Token<'s>, def: Option<(Named, usize)>) {
        let start = def.as_ref().map_or(ty.start, |(_, at)| *at);
        let open = self.lexer.peek();
        if !open.is(Kind::OpenBrace) {
            self.malformed(
                open.span(),
                format!(
                    "{} where `{{` belongs after the node type `{}`",
                    describe(&open),
                    ty.text
                ),
            );
            self.recover_statement();
            return;
        }
        if !self.enter(ty.span()) {
            return;
        }
        self.lexer.next();
        let kind = match self.builder.find_proto(ty.text) {
            Some(proto) => NodeKind::ProtoInstance {
                name: ty.text.to_string(),
                proto: Some(proto),
            },
            None => self.builder.node_kind(ty.text),
        };
        let instance = matches!(kind, NodeKind::ProtoInstance { .. });
        let Some(id) = self.builder.begin_node(kind, ty.span(), hint.parent()) else {
            // Too deep or too many nodes (reported): skip the body.
            self.lexer.pos = open.start;
            self.skip_one();
            self.depth -= 1;
            return;
        };
        if let Some((name, _)) = def {
            self.builder.define(id, name);
        }
        let origin = if instance {
            Origin::FieldValue
        } else {
            Origin::Member
        };
        let end = self.node_body(id, origin, ty);
        self.builder.end_node(id, Span::new(start, end));
        self.depth -= 1;
    }

    /// The fields and statements of a node up to and with its `}`; the end of the node.
    fn node_body(&mut self, id: NodeId, origin: Origin, ty: Token<'s>) -> usize {
        loop {
            let token = self.lexer.peek();
            match token.kind {
                Kind::CloseBrace => {
                    self.lexer.next();
                    return token.end();
                }
                Kind::End => {
                    if !self.end_reported {
                        self.end_reported = true;
                        self.malformed(
                            ty.span(),
                            format!(
                                "the file ends inside this `{}`: its `}}` is missing",
                                ty.text
                            ),
                        );
                    }
                    return token.start;
                }
                Kind::Id => {
                    self.lexer.next();
                    match token.text {
                        "ROUTE" => self.route(token),
                        "PROTO" | "EXTERNPROTO" => self.proto(token),
                        text if access_type(text).is_some() => {
                            self.declaration(Owner::Node(id), token)
                        }
                        _ => self.field(id, origin, token),
                    }
                }
                _ => {
                    self.malformed(
                        token.span(),
                        format!(
                            "{} where a field name of `{}` belongs",
                            describe(&token),
                            ty.text
                        ),
                    );
                    self.lexer.next();
                    self.recover(true);
                }
            }
        }
    }

    /// `name value` or `name IS protoField`, with the name read.
    fn field(&mut self, node: NodeId, origin: Origin, name: Token<'s>) {
        if self.lexer.peek().is_id("IS") {
            self.lexer.next();
            self.is_connect(node, name);
            return;
        }
        let field = self.builder.field_ref(node, name.text);
        let hint = Hint::Field {
            node,
            field: name.text,
            field_span: name.span(),
            origin,
        };
        let value = match field.clone() {
            FieldRef::Schema { def, .. } if def.ty.scalar() == Scalar::Node => {
                self.node_value(def.ty, hint, name);
                return;
            }
            FieldRef::Declared { ty: Some(ty), .. } if ty.scalar() == Scalar::Node => {
                self.node_value(ty, hint, name);
                return;
            }
            FieldRef::Schema { def, .. } => {
                let summary = (self.keep == KeepValues::Summaries && Summary::applies_to(def.ty))
                    .then_some((node, def));
                self.typed_value(def.ty, summary, &name)
            }
            FieldRef::Declared { ty: Some(ty), .. } => self.typed_value(ty, None, &name),
            _ => self.untyped_value(hint, name),
        };
        let Some((value, span)) = value else {
            return;
        };
        self.builder.add_field(
            node,
            FieldEntry {
                field,
                name_span: name.span(),
                span,
                origin,
                value,
            },
        );
    }

    /// `IS protoField` after a field name or declaration (19776-2 4.3.2.10).
    fn is_connect(&mut self, node: NodeId, field: Token<'s>) {
        let Some(proto_field) = self.expect_name("the PROTO's field name after IS") else {
            return;
        };
        let span = Span::new(field.start, proto_field.span.end as usize);
        let connect = IsConnect {
            node_field: named(&field),
            proto_field,
            span,
        };
        self.builder.doc_mut().nodes[node.index()]
            .connects
            .push(connect);
    }

    /// An SFNode or MFNode value: `NULL`, one node statement, or `[ node statements ]`.
    fn node_value(&mut self, ty: FieldType, hint: Hint<'s>, field: Token<'s>) {
        let token = self.lexer.peek();
        match token.kind {
            Kind::Id if token.text == "NULL" => {
                self.lexer.next();
            }
            Kind::Id => self.node_statement(hint),
            Kind::OpenBracket if self.values_inside(token) => {
                // Values where nodes belong (a field typed otherwise in another version,
                // e.g. VRML97's NurbsCurve.controlPoint): one finding for the whole list.
                self.builder.report(Diagnostic::new(
                    &FIELD_VALUE_SYNTAX,
                    token.span(),
                    format!(
                        "`{}` is an {ty} field: it takes nodes, not values",
                        field.text
                    ),
                ));
                self.skip_one();
            }
            Kind::OpenBracket => {
                if !ty.is_mf() {
                    self.malformed(
                        token.span(),
                        format!(
                            "`{}` is an SFNode field: its value is one node or NULL, not a list",
                            field.text
                        ),
                    );
                }
                self.lexer.next();
                self.node_list(hint);
            }
            _ => {
                self.malformed(
                    token.span(),
                    format!(
                        "{} where the value of `{}` (a node{}) belongs",
                        describe(&token),
                        field.text,
                        if ty.is_mf() {
                            " or `[ … ]`"
                        } else {
                            " or NULL"
                        }
                    ),
                );
                self.recover(true);
            }
        }
    }

    /// Node statements up to and with a `]`.
    fn node_list(&mut self, hint: Hint<'s>) {
        loop {
            let token = self.lexer.peek();
            if self.bracket_list_ends(&token, "a node list") {
                return;
            }
            match token.kind {
                Kind::CloseBrace => {
                    // Left for the node it closes.
                    self.malformed(
                        token.span(),
                        "the node list's `]` is missing before this `}`",
                    );
                    return;
                }
                Kind::Id if matches!(token.text, "PROTO" | "EXTERNPROTO" | "ROUTE") => {
                    // One finding, and the statement read as if written outside the
                    // list: skipping token by token would misread its interface and
                    // body as nodes and fields, and its prototype's instances as unknown.
                    self.malformed(
                        token.span(),
                        format!(
                            "a {} statement where a node belongs: a node list holds node statements only",
                            token.text
                        ),
                    );
                    self.lexer.next();
                    if token.text == "ROUTE" {
                        self.route(token);
                    } else {
                        self.proto(token);
                    }
                }
                Kind::Id if token.text != "NULL" => {
                    // A name followed by a name is a field of the enclosing node: the
                    // list's `]` is missing.
                    if !matches!(token.text, "DEF" | "USE") && !self.followed_by_brace(token) {
                        if self.names_field_of_parent(hint, token.text) {
                            self.malformed(
                                token.span(),
                                format!(
                                    "`{}` where a node belongs: is the node list's `]` missing?",
                                    token.text
                                ),
                            );
                            return;
                        }
                        // Neither a node nor a field of the enclosing node: skipped with
                        // the value that follows it, and the list read on.
                        self.malformed(
                            token.span(),
                            format!("`{}` where a node belongs in a node list", token.text),
                        );
                        self.lexer.next();
                        if matches!(self.lexer.peek().kind, Kind::OpenBracket | Kind::OpenBrace) {
                            self.skip_one();
                        }
                        continue;
                    }
                    self.node_statement(hint);
                }
                _ => {
                    self.malformed(
                        token.span(),
                        format!("{} where a node belongs in a node list", describe(&token)),
                    );
                    self.lexer.next();
                    while !matches!(
                        self.lexer.peek().kind,
                        Kind::Id | Kind::CloseBracket | Kind::CloseBrace | Kind::End
                    ) {
                        self.skip_one();
                    }
                    if self.lexer.peek().is(Kind::CloseBrace) {
                        return;
                    }
                }
            }
        }
    }

    /// Whether `name` is a field of the node whose field value is being read (a name
    /// there in a node list means the list's `]` is missing).
    fn names_field_of_parent(&self, hint: Hint<'s>, name: &str) -> bool {
        match hint {
            Hint::Field { node, .. } => {
                !matches!(self.builder.field_ref(node, name), FieldRef::Unknown { .. })
            }
            Hint::TopLevel | Hint::ProtoField { .. } => true,
        }
    }

    /// Whether the bracket `open` (the next token) holds numbers or strings first.
    fn values_inside(&mut self, open: Token<'s>) -> bool {
        let saved = self.lexer.pos;
        self.lexer.pos = open.end();
        let inner = self.lexer.peek();
        self.lexer.pos = saved;
        matches!(inner.kind, Kind::Number | Kind::String)
    }

    /// Whether `{` follows the name `token` (the next token).
    fn followed_by_brace(&mut self, token: Token<'s>) -> bool {
        let saved = self.lexer.pos;
        self.lexer.pos = token.end();
        let next = self.lexer.peek();
        self.lexer.pos = saved;
        next.is(Kind::OpenBrace)
    }
}

/// The access type a declaration keyword names: X3D's, or VRML97's (14772-1 4.7) that
/// ClassicVRML files still use.
fn access_type(keyword: &str) -> Option<AccessType> {
    Some(match keyword {
        "inputOnly" | "eventIn" => AccessType::InputOnly,
        "outputOnly" | "eventOut" => AccessType::OutputOnly,
        "initializeOnly" | "field" => AccessType::InitializeOnly,
        "inputOutput" | "exposedField" => AccessType::InputOutput,
        _ => return None,
    })
}

fn named(token: &Token) -> Named {
    Named {
        text: token.text.to_string(),
        span: token.span(),
    }
}

/// A token for a message: `` `text` ``, or what it is.
fn describe(token: &Token) -> String {
    match token.kind {
        Kind::End => "the end of the file".to_string(),
        Kind::Unterminated => "a string that never ends (no closing `\"`)".to_string(),
        _ => {
            let text: String = token.text.chars().take(40).collect();
            format!("`{text}`")
        }
    }
}
