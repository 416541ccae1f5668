//! Byte offset → line and column, for the few positions that are reported. Built once per
//! file (one memchr pass); offsets are looked up together, in ascending order, so that even
//! a one-line 86 MB file is scanned once for its columns. Both passes go a
//! [`STEP`] at a time, telling their progress (see [`crate::parse::behind`]).

use memchr::memchr_iter;

use crate::parse::behind::{Pass, Progress, STEP};

/// A 1-based line and a 1-based column counted in Unicode scalar values.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct LineCol {
    pub line: usize,
    pub column: usize,
}

pub struct LineIndex<'a> {
    source: &'a [u8],
    progress: &'a dyn Progress,
    /// Byte offset where each line starts; the first is 0.
    starts: Vec<usize>,
}

impl<'a> LineIndex<'a> {
    /// The index of `source`, telling `progress` how far its passes over it have got.
    pub fn new(source: &'a [u8], progress: &'a dyn Progress) -> LineIndex<'a> {
        let mut starts = vec![0];
        let mut pass = Pass::new(source, progress);
        for (k, step) in source.chunks(STEP).enumerate() {
            let base = k * STEP;
            starts.extend(memchr_iter(b'\n', step).map(|i| base + i + 1));
            pass.reached(base + step.len());
        }
        LineIndex {
            source,
            progress,
            starts,
        }
    }

    /// The positions of `offsets`, each clamped to the end of the input. A `\r` before `\n`
    /// belongs to its line; an offset inside a multi-byte character counts as that character.
    /// Give them in ascending order: then each line is scanned once, however many offsets
    /// fall on it (an 86 MB single-line file with many findings stays linear).
    pub fn line_cols(&self, offsets: &[usize]) -> Vec<LineCol> {
        let mut previous: Option<(usize, LineCol)> = None;
        // The stretches counted go forward only: from an offset, or the start of a later line.
        let mut pass = Pass::new(self.source, self.progress);
        offsets
            .iter()
            .map(|&offset| {
                let mut offset = offset.min(self.source.len());
                while offset > 0
                    && offset < self.source.len()
                    && is_continuation(self.source[offset])
                {
                    offset -= 1;
                }
                let line = self.line_of(offset);
                let (from, column) = match previous {
                    Some((from, at)) if at.line == line && from <= offset => (from, at.column),
                    _ => (self.starts[line - 1], 1),
                };
                let (mut chars, mut at) = (0, from);
                while at < offset {
                    let end = offset.min(at + STEP);
                    chars += self.source[at..end]
                        .iter()
                        .filter(|&&b| !is_continuation(b))
                        .count();
                    at = end;
                    pass.reached(at);
                }
                let at = LineCol {
                    line,
                    column: column + chars,
                };
                previous = Some((offset, at));
                at
            })
            .collect()
    }

    /// The 1-based line of `offset`.
    pub fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset)
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
        let p = LineIndex::new(source.as_bytes(), &()).line_cols(&[offset])[0];
        (p.line, p.column)
    }

    #[test]
    fn empty_input() {
        assert_eq!(at("", 0), (1, 1));
        assert_eq!(at("", 10), (1, 1));
        assert_eq!(LineIndex::new(b"", &()).line_range(1), 0..0);
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
        let index = LineIndex::new(s.as_bytes(), &());
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
    fn ascending_offsets_share_the_scan() {
        let s = "aé\nbcd€e\nf";
        let offsets = [0, 1, 4, 5, 9, 10, 12, 99, 99];
        let one_by_one: Vec<_> = offsets.iter().map(|&o| at(s, o)).collect();
        let together: Vec<_> = LineIndex::new(s.as_bytes(), &())
            .line_cols(&offsets)
            .iter()
            .map(|p| (p.line, p.column))
            .collect();
        assert_eq!(together, one_by_one);
        assert_eq!(
            together,
            [
                (1, 1),
                (1, 2),
                (2, 1),
                (2, 2),
                (2, 4),
                (2, 5),
                (3, 1),
                (3, 2),
                (3, 2)
            ]
        );
    }

    #[test]
    fn past_the_end() {
        assert_eq!(at("ab\ncd", 99), (2, 3));
        assert_eq!(at("ab\n", 99), (2, 1));
    }
}
