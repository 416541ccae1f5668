//! Byte offset → line and column, for the few positions that are reported. Built once per
//! file (one memchr pass); a lookup is a binary search plus a walk over one line's chars.

use memchr::memchr_iter;

/// A 1-based line and a 1-based column counted in Unicode scalar values.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct LineCol {
    pub line: usize,
    pub column: usize,
}

pub struct LineIndex<'a> {
    source: &'a [u8],
    /// Byte offset where each line starts; the first is 0.
    starts: Vec<usize>,
}

impl<'a> LineIndex<'a> {
    pub fn new(source: &'a [u8]) -> LineIndex<'a> {
        let mut starts = vec![0];
        starts.extend(memchr_iter(b'\n', source).map(|i| i + 1));
        LineIndex { source, starts }
    }

    /// The position of `offset`, clamped to the end of the input. A `\r` before `\n` belongs
    /// to its line; an offset inside a multi-byte character counts as that character.
    pub fn line_col(&self, offset: usize) -> LineCol {
        let mut offset = offset.min(self.source.len());
        while offset > 0 && offset < self.source.len() && is_continuation(self.source[offset]) {
            offset -= 1;
        }
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let text = &self.source[self.starts[line]..offset];
        let chars = text.iter().filter(|&&b| !is_continuation(b)).count();
        LineCol {
            line: line + 1,
            column: chars + 1,
        }
    }

    /// The byte range of a 1-based line, without its line break.
    pub fn line_range(&self, line: usize) -> std::ops::Range<usize> {
        let index = line.saturating_sub(1).min(self.starts.len() - 1);
        let start = self.starts[index];
        let mut end = self
            .starts
            .get(index + 1)
            .map_or(self.source.len(), |next| next - 1);
        if end > start && self.source[end - 1] == b'\r' {
            end -= 1;
        }
        start..end
    }

    pub fn line_count(&self) -> usize {
        self.starts.len()
    }
}

fn is_continuation(byte: u8) -> bool {
    byte & 0xC0 == 0x80
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(source: &str, offset: usize) -> (usize, usize) {
        let p = LineIndex::new(source.as_bytes()).line_col(offset);
        (p.line, p.column)
    }

    #[test]
    fn empty_input() {
        assert_eq!(at("", 0), (1, 1));
        assert_eq!(at("", 10), (1, 1));
        assert_eq!(LineIndex::new(b"").line_range(1), 0..0);
    }

    #[test]
    fn lines_and_columns() {
        let s = "ab\ncd\n\nef";
        assert_eq!(at(s, 0), (1, 1));
        assert_eq!(at(s, 2), (1, 3));
        assert_eq!(at(s, 3), (2, 1));
        assert_eq!(at(s, 6), (3, 1));
        assert_eq!(at(s, 8), (4, 2));
    }

    #[test]
    fn crlf() {
        let s = "ab\r\ncd";
        assert_eq!(at(s, 2), (1, 3));
        assert_eq!(at(s, 4), (2, 1));
        assert_eq!(at(s, 5), (2, 2));
        let index = LineIndex::new(s.as_bytes());
        assert_eq!(index.line_range(1), 0..2);
        assert_eq!(index.line_range(2), 4..6);
    }

    #[test]
    fn columns_count_chars() {
        let s = "<a b='é€😀' c/>";
        let c = s.find(" c").unwrap() + 1;
        assert_eq!(at(s, c), (1, 12));
        // Inside a multi-byte character: that character's column.
        let e = s.find('€').unwrap();
        assert_eq!(at(s, e + 1), (1, 8));
    }

    #[test]
    fn past_the_end() {
        assert_eq!(at("ab\ncd", 99), (2, 3));
        assert_eq!(at("ab\n", 99), (2, 1));
    }
}
