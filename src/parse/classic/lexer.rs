//! Tokens of the ClassicVRML and VRML97 encodings (19776-2 A.2, 14772-1 A.2): names,
//! numbers, strings and the punctuation `{ } [ ] . :`, separated by whitespace, commas
//! and comments. Positions are byte offsets into the whole input.

use crate::model::Span;
use crate::parse::behind::{Pass, Progress};
use crate::parse::directive::addressed;

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A name or keyword (`Transform`, `DEF`, `TRUE`).
    Id,
    /// Starts with a digit, a sign or `.digit`: one number (or a malformed one).
    Number,
    /// A double-quoted string, quotes included.
    String,
    /// A string whose closing quote is missing: it runs to the end of the input.
    Unterminated,
    OpenBrace,
    CloseBrace,
    OpenBracket,
    CloseBracket,
    Period,
    Colon,
    /// A byte no token starts with (`'`, `\`, a control character).
    Stray,
    End,
}

#[derive(Copy, Clone, Debug)]
pub struct Token<'s> {
    pub kind: Kind,
    pub text: &'s str,
    pub start: usize,
}

impl Token<'_> {
    pub fn span(&self) -> Span {
        Span::new(self.start, self.start + self.text.len())
    }

    pub fn end(&self) -> usize {
        self.start + self.text.len()
    }

    pub fn is(&self, kind: Kind) -> bool {
        self.kind == kind
    }

    pub fn is_id(&self, text: &str) -> bool {
        self.kind == Kind::Id && self.text == text
    }
}

pub struct Lexer<'s> {
    pub text: &'s str,
    bytes: &'s [u8],
    pub pos: usize,
    /// X3D 3.3 and later: `#/* … */#` block comments (19776-2 A.1.2).
    pub block_comments: bool,
    /// VRML97 names may contain `:` (14772-1 A.2); X3D uses it in COMPONENT statements.
    colon_in_names: bool,
    /// Where a block comment that never ends starts, once seen.
    pub unterminated_comment: Option<usize>,
    /// The comments addressed to x3dcheck, in document order: each comment's place and
    /// that of its text after `x3dcheck:`.
    pub directives: Vec<(Span, Span)>,
    /// Told how far the tokens have got.
    pass: Pass<'s>,
}

/// The separators outside strings: whitespace and the comma (19776-2 A.1.2).
#[inline(always)]
pub fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b',')
}

/// Bytes that end a name or a number (besides separators).
#[inline(always)]
fn ends_word(b: u8, colon: bool) -> bool {
    is_space(b)
        || matches!(
            b,
            b'"' | b'#' | b'\'' | b'[' | b']' | b'{' | b'}' | b'\\' | b'.'
        )
        || (b == b':' && !colon)
        || b < 0x20
        || b == 0x7f
}

impl<'s> Lexer<'s> {
    pub fn new(text: &'s str, start: usize, block_comments: bool, colon_in_names: bool) -> Self {
        Lexer {
            text,
            bytes: text.as_bytes(),
            pos: start,
            block_comments,
            colon_in_names,
            unterminated_comment: None,
            directives: Vec::new(),
            pass: Pass::new(text.as_bytes(), &()),
        }
    }

    /// The lexer, telling `progress` how far its tokens have got.
    pub fn with_progress(mut self, progress: &'s dyn Progress) -> Self {
        self.pass = Pass::new(self.bytes, progress);
        self
    }

    /// Skips whitespace, commas and comments from `pos`.
    #[inline]
    pub fn skip_space(&mut self) {
        let b = self.bytes;
        loop {
            while self.pos < b.len() && is_space(b[self.pos]) {
                self.pos += 1;
            }
            if self.pos < b.len() && b[self.pos] == b'#' {
                self.pos = self.comment_end(self.pos);
            } else {
                return;
            }
        }
    }

    /// The end of the comment starting at `at` (a `#`), noting it when it is addressed to
    /// x3dcheck.
    pub fn comment_end(&mut self, at: usize) -> usize {
        let b = self.bytes;
        let (inner, end) = if self.block_comments && b[at + 1..].starts_with(b"/*") {
            match memchr::memmem::find(&b[at + 3..], b"*/#") {
                Some(k) => (Span::new(at + 3, at + 3 + k), at + 3 + k + 3),
                None => {
                    self.unterminated_comment.get_or_insert(at);
                    return b.len();
                }
            }
        } else {
            let end = memchr::memchr2(b'\n', b'\r', &b[at..]).map_or(b.len(), |k| at + k);
            (Span::new(at + 1, end), end)
        };
        // The reader may look at a comment twice (peeking); it is noted once.
        let new = self
            .directives
            .last()
            .is_none_or(|(seen, _)| (seen.start as usize) < at);
        if new {
            if let Some(text) = addressed(b, inner) {
                self.directives.push((Span::new(at, end), text));
            }
        }
        end
    }

    /// The next token, without consuming it.
    pub fn peek(&mut self) -> Token<'s> {
        self.skip_space();
        let start = self.pos;
        let b = self.bytes;
        let Some(&first) = b.get(start) else {
            return Token {
                kind: Kind::End,
                text: "",
                start,
            };
        };
        let (kind, end) = match first {
            b'{' => (Kind::OpenBrace, start + 1),
            b'}' => (Kind::CloseBrace, start + 1),
            b'[' => (Kind::OpenBracket, start + 1),
            b']' => (Kind::CloseBracket, start + 1),
            b':' if !self.colon_in_names => (Kind::Colon, start + 1),
            b'"' => match string_end(b, start) {
                Some(end) => (Kind::String, end),
                None => (Kind::Unterminated, b.len()),
            },
            b'.' if !b.get(start + 1).is_some_and(u8::is_ascii_digit) => (Kind::Period, start + 1),
            b'0'..=b'9' | b'+' | b'-' | b'.' => (Kind::Number, self.word_end(start + 1, true)),
            _ if ends_word(first, self.colon_in_names) => {
                let width = self.text[start..].chars().next().map_or(1, char::len_utf8);
                (Kind::Stray, start + width)
            }
            _ => (Kind::Id, self.word_end(start + 1, false)),
        };
        Token {
            kind,
            text: &self.text[start..end],
            start,
        }
    }

    /// The end of a name or number whose first byte is before `from`. A number may hold
    /// a `.` (and `+`/`-` after an exponent): it ends at a separator or bracket only.
    fn word_end(&self, from: usize, number: bool) -> usize {
        let b = self.bytes;
        let mut i = from;
        while i < b.len() {
            let c = b[i];
            if ends_word(c, self.colon_in_names) && !(number && c == b'.') {
                break;
            }
            i += 1;
        }
        i
    }

    /// Consumes and returns the next token.
    pub fn next(&mut self) -> Token<'s> {
        let token = self.peek();
        self.pos = token.end();
        self.pass.reached(self.pos);
        token
    }

    /// The closing `]` of a bracket whose content starts at `from`, with the comments in
    /// between (so that the caller can blank them), skipping strings. None when the
    /// input ends first.
    pub fn bracket_end(
        &mut self,
        from: usize,
        comments: &mut Vec<(usize, usize)>,
    ) -> Option<usize> {
        let b = self.bytes;
        let mut i = from;
        loop {
            let k = memchr::memchr3(b']', b'#', b'"', &b[i..])?;
            let at = i + k;
            match b[at] {
                b']' => return Some(at),
                b'#' => {
                    let end = self.comment_end(at);
                    comments.push((at, end));
                    i = end;
                }
                _ => i = string_end(b, at)?,
            }
            if i >= b.len() {
                return None;
            }
        }
    }
}

/// The end (after the closing quote) of the string opening at `start`.
fn string_end(b: &[u8], start: usize) -> Option<usize> {
    let mut i = start + 1;
    loop {
        let k = memchr::memchr2(b'"', b'\\', &b[i..])?;
        let at = i + k;
        if b[at] == b'"' {
            return Some(at + 1);
        }
        i = at + 2;
        if i > b.len() {
            return None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<(Kind, &str)> {
        let mut lexer = Lexer::new(text, 0, true, false);
        let mut out = Vec::new();
        loop {
            let t = lexer.next();
            if t.kind == Kind::End {
                return out;
            }
            out.push((t.kind, t.text));
        }
    }

    #[test]
    fn tokens() {
        use Kind::*;
        assert_eq!(
            kinds("DEF T Transform{translation 1,-2.5e3 .5}"),
            vec![
                (Id, "DEF"),
                (Id, "T"),
                (Id, "Transform"),
                (OpenBrace, "{"),
                (Id, "translation"),
                (Number, "1"),
                (Number, "-2.5e3"),
                (Number, ".5"),
                (CloseBrace, "}")
            ]
        );
        assert_eq!(
            kinds("ROUTE a.b TO c.d # comment\n[\"x\\\"y\" ] COMPONENT Geo:1"),
            vec![
                (Id, "ROUTE"),
                (Id, "a"),
                (Period, "."),
                (Id, "b"),
                (Id, "TO"),
                (Id, "c"),
                (Period, "."),
                (Id, "d"),
                (OpenBracket, "["),
                (String, "\"x\\\"y\""),
                (CloseBracket, "]"),
                (Id, "COMPONENT"),
                (Id, "Geo"),
                (Colon, ":"),
                (Number, "1"),
            ]
        );
        assert_eq!(kinds("#/* a\n } */# b"), vec![(Id, "b")]);
        assert_eq!(kinds("\"abc"), vec![(Unterminated, "\"abc")]);
        assert_eq!(kinds("'x"), vec![(Stray, "'"), (Id, "x")]);
        assert_eq!(kinds("é1"), vec![(Id, "é1")]);
    }

    #[test]
    fn brackets() {
        let text = "1 2 # ] \n \"]\" 3 ] x";
        let mut lexer = Lexer::new(text, 0, true, false);
        let mut comments = Vec::new();
        assert_eq!(lexer.bracket_end(0, &mut comments), Some(16));
        assert_eq!(comments, vec![(4, 8)]);
        assert_eq!(lexer.bracket_end(0, &mut Vec::new()).map(|_| ()), Some(()));
        assert_eq!(
            Lexer::new("1 2", 0, true, false).bracket_end(0, &mut comments),
            None
        );
        assert_eq!(
            Lexer::new("\"a]", 0, true, false).bracket_end(0, &mut comments),
            None
        );
    }
}
