//! Field values (19776-2 5, 14772-1 5): the extent of a value is found here, bracketed
//! (`[ … ]`, scanned with memchr) or single (one string, one boolean, or the numbers
//! that follow), and its text is parsed by [`xml_value`]'s flat-array parsers, which
//! share the whitespace-and-comma separators of ClassicVRML. Comments inside a value are
//! blanked in a copy of that value's text, so offsets stay those of the input.

use super::lexer::{Kind, Token};
use super::{describe, Hint, Reader};
use crate::diagnostic::Diagnostic;
use crate::model::text::xml_value::{self, Syntax};
use crate::model::{NodeId, Span, Value};
use crate::parse::rules::FIELD_VALUE_SYNTAX;
use crate::schema::{FieldDef, FieldType, Scalar};

/// A field value's text: where it is, and the comments inside it.
struct Extent {
    /// The whole value, brackets included.
    span: Span,
    /// What the parser reads (inside the brackets).
    content: (usize, usize),
    comments: Vec<(usize, usize)>,
    /// Values written without brackets: the tokens read.
    single: Option<usize>,
}

impl<'s> Reader<'s> {
    /// A value of a non-node type, read and parsed; None (reported) when there is none.
    /// `summary` names the schema field whose numbers are summarized, at the fast level.
    pub(super) fn typed_value(
        &mut self,
        ty: FieldType,
        summary: Option<(NodeId, &'static FieldDef)>,
        name: &Token<'s>,
    ) -> Option<(Value, Span)> {
        let extent = self.extent(ty, name)?;
        let (start, end) = extent.content;
        let raw = &self.lexer.text[start..end];
        let blanked;
        let text = if extent.comments.is_empty() {
            raw
        } else {
            blanked = blank(raw, start, &extent.comments);
            blanked.as_str()
        };
        if let (Some(count), true) = (extent.single, ty.is_mf() && is_numeric(ty)) {
            if count != ty.arity() {
                let single = ty.single();
                let message = format!(
                    "`{}`: without brackets an {ty} holds one {single} ({}), found {count} numbers; enclose a list in `[ ]`",
                    name.text,
                    plural(ty.arity()),
                );
                self.value_error(Span::new(start, end), message, raw);
                return Some((Value::Unparsed(raw.to_string()), extent.span));
            }
        }
        let parsed = match summary {
            Some((node, def)) => xml_value::parse_summary(self.builder.doc().node(node), def, text),
            None => xml_value::parse_value_in(Syntax::Classic, ty, text),
        };
        match parsed {
            Ok(value) => Some((value, extent.span)),
            Err(error) => {
                let at = start + error.offset;
                let message = format!("`{}`: {}", name.text, error.message);
                self.value_error(Span::new(at, at + error.len), message, raw);
                Some((Value::Unparsed(raw.to_string()), extent.span))
            }
        }
    }

    fn value_error(&mut self, span: Span, message: String, raw: &str) {
        self.builder.report(
            Diagnostic::new(&FIELD_VALUE_SYNTAX, span, message)
                .value(crate::parse::xml::truncate(raw, 80)),
        );
    }

    /// Where the value of a field of type `ty` is, consumed; None (reported) when the
    /// next token cannot start one.
    fn extent(&mut self, ty: FieldType, name: &Token<'s>) -> Option<Extent> {
        let token = self.lexer.peek();
        if token.is(Kind::OpenBracket) {
            return self.bracketed(token, name);
        }
        let found = match (ty.scalar(), token.kind) {
            (Scalar::String, Kind::String) => true,
            (Scalar::Bool, Kind::Id) => {
                token.text.eq_ignore_ascii_case("true") || token.text.eq_ignore_ascii_case("false")
            }
            (Scalar::Float | Scalar::Double | Scalar::Int32 | Scalar::Image, Kind::Number) => {
                return Some(self.numbers());
            }
            _ => false,
        };
        if found {
            self.lexer.next();
            return Some(Extent {
                span: token.span(),
                content: (token.start, token.end()),
                comments: Vec::new(),
                single: Some(1),
            });
        }
        if token.is(Kind::Unterminated) {
            self.lexer.next();
            // The string runs to the end of the file: the braces it swallowed are not
            // reported missing as well.
            self.end_reported = true;
            self.malformed(
                token.span(),
                format!(
                    "the string of `{}` never ends: its closing `\"` is missing",
                    name.text
                ),
            );
            return None;
        }
        let what = match ty.scalar() {
            Scalar::String => "a quoted string",
            Scalar::Bool => "TRUE or FALSE",
            _ => "numbers",
        };
        let at = self.lexer.pos;
        let span = if token.is(Kind::End) {
            Span::new(at, at)
        } else {
            token.span()
        };
        let brackets = if ty.is_mf() { " or `[ … ]`" } else { "" };
        self.builder.report(Diagnostic::new(
            &FIELD_VALUE_SYNTAX,
            span,
            format!(
                "`{}` ({ty}) needs {what}{brackets}; found {}",
                name.text,
                describe(&token)
            ),
        ));
        None
    }

    /// `[ … ]` starting at `open`, consumed with its `]`.
    fn bracketed(&mut self, open: Token<'s>, name: &Token<'s>) -> Option<Extent> {
        let from = open.end();
        let mut comments = Vec::new();
        let Some(close) = self.lexer.bracket_end(from, &mut comments) else {
            self.lexer.pos = self.lexer.text.len();
            self.end_reported = true;
            self.malformed(
                open.span(),
                format!("the `[` of `{}` is never closed", name.text),
            );
            return None;
        };
        self.lexer.pos = close + 1;
        Some(Extent {
            span: Span::new(open.start, close + 1),
            content: (from, close),
            comments,
            single: None,
        })
    }

    /// The numbers that follow, consumed (at least one: the next token is a number).
    fn numbers(&mut self) -> Extent {
        let first = self.lexer.next();
        let mut end = first.end();
        let mut count = 1;
        while self.lexer.peek().is(Kind::Number) {
            end = self.lexer.next().end();
            count += 1;
        }
        let mut comments = Vec::new();
        let bytes = self.lexer.text.as_bytes();
        let mut at = first.start;
        while let Some(k) = memchr::memchr(b'#', &bytes[at..end]) {
            let comment_end = self.lexer.comment_end(at + k).min(end);
            comments.push((at + k, comment_end));
            at = comment_end;
        }
        Extent {
            span: Span::new(first.start, end),
            content: (first.start, end),
            comments,
            single: Some(count),
        }
    }

    /// The value of a field whose type is unknown (an unknown field or node type, a
    /// prototype not declared): nodes are read into the model, anything else is kept as
    /// text. None when there is no value or it was nodes.
    pub(super) fn untyped_value(
        &mut self,
        hint: Hint<'s>,
        name: Token<'s>,
    ) -> Option<(Value, Span)> {
        let token = self.lexer.peek();
        match token.kind {
            Kind::OpenBracket => {
                let saved = self.lexer.pos;
                self.lexer.pos = token.end();
                let inner = self.lexer.peek();
                self.lexer.pos = saved;
                if inner.is(Kind::Id)
                    && (matches!(inner.text, "DEF" | "USE") || self.followed_by_brace(inner))
                {
                    self.lexer.next();
                    self.node_list(hint);
                    return None;
                }
                let extent = self.bracketed(token, &name)?;
                let text = &self.lexer.text[extent.content.0..extent.content.1];
                Some((Value::Unparsed(text.to_string()), extent.span))
            }
            Kind::Id if token.text == "NULL" => {
                self.lexer.next();
                None
            }
            Kind::Id if matches!(token.text, "DEF" | "USE") || self.followed_by_brace(token) => {
                self.node_statement(hint);
                None
            }
            Kind::Id if token.text == "TRUE" || token.text == "FALSE" => {
                self.lexer.next();
                Some((Value::Unparsed(token.text.to_string()), token.span()))
            }
            Kind::String => {
                self.lexer.next();
                Some((Value::Unparsed(token.text.to_string()), token.span()))
            }
            Kind::Number => {
                let extent = self.numbers();
                let text = &self.lexer.text[extent.content.0..extent.content.1];
                Some((Value::Unparsed(text.to_string()), extent.span))
            }
            _ => None,
        }
    }
}

/// The numeric types whose unbracketed MF form is one element of `arity` numbers.
fn is_numeric(ty: FieldType) -> bool {
    matches!(ty.scalar(), Scalar::Float | Scalar::Double | Scalar::Int32)
}

fn plural(n: usize) -> String {
    if n == 1 {
        "1 number".to_string()
    } else {
        format!("{n} numbers")
    }
}

/// `raw` (which starts at `base` in the input) with the comments at `comments` (input
/// offsets) replaced by spaces, byte for byte.
fn blank(raw: &str, base: usize, comments: &[(usize, usize)]) -> String {
    let mut bytes = raw.as_bytes().to_vec();
    for &(start, end) in comments {
        for b in &mut bytes[start - base..end - base] {
            *b = b' ';
        }
    }
    // Only whole comments were replaced, each with ASCII spaces.
    String::from_utf8(bytes).unwrap_or_default()
}
