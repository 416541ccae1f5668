//! Text decoded out of a document (CDATA, an XML attribute, a JSON or ClassicVRML string)
//! that remembers, for each of its bytes, where in the document it was written: the place
//! of an ECMAScript parser's finding in the decoded code is then the place in the X3D file,
//! through `&quot;`, `\"`, `\u0041` and the like.

use crate::model::Span;

/// Decoded text and, per byte of it, where in the document the character it belongs to is
/// written (from, to).
#[derive(Clone, Debug, Default)]
pub struct Mapped {
    pub text: String,
    from: Vec<u32>,
    to: Vec<u32>,
}

impl Mapped {
    /// Text written as it is, starting at document offset `start`.
    pub fn push_verbatim(&mut self, text: &str, start: usize) {
        self.text.push_str(text);
        for (i, c) in text.char_indices() {
            let (from, to) = ((start + i) as u32, (start + i + c.len_utf8()) as u32);
            for _ in 0..c.len_utf8() {
                self.from.push(from);
                self.to.push(to);
            }
        }
    }

    /// A character written as an escape or reference from `start` to `end` in the document.
    pub fn push_decoded(&mut self, c: char, start: usize, end: usize) {
        self.text.push(c);
        for _ in 0..c.len_utf8() {
            self.from.push(start as u32);
            self.to.push(end as u32);
        }
    }

    /// The character at `index` of another decoded text, keeping its place.
    pub fn push_from(&mut self, other: &Mapped, index: usize, c: char) {
        let (start, end) = (other.from[index], other.to[index]);
        self.push_decoded(c, start as usize, end as usize);
    }

    pub fn len(&self) -> usize {
        self.text.len()
    }

    /// The document span of the text range `start..end` (an empty range at the end of the
    /// text is placed just past its last character).
    pub fn span(&self, start: usize, end: usize) -> Span {
        let at = |i: usize| match self.from.get(i) {
            Some(&from) => from,
            None => self.to.last().copied().unwrap_or(0),
        };
        let doc_start = at(start);
        let doc_end = if end > start {
            self.to.get(end - 1).copied().unwrap_or(doc_start)
        } else {
            doc_start
        };
        Span::new(doc_start as usize, doc_end.max(doc_start) as usize)
    }

    /// The text of `start..end` with its places (a url entry after its `ecmascript:`
    /// scheme).
    pub fn slice(&self, start: usize, end: usize) -> Mapped {
        Mapped {
            text: self.text[start..end].to_string(),
            from: self.from[start..end].to_vec(),
            to: self.to[start..end].to_vec(),
        }
    }
}
