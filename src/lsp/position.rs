//! Byte offsets ↔ LSP positions. A position's `character` counts UTF-16 code units unless
//! the client and server agreed on UTF-8 (LSP 3.17 `positionEncoding`); lines end at `\n`
//! (a `\r` before it belongs to the line's text, which no position points into).

use lsp_types::{Position, Range};

use crate::diagnostic::Span;

/// How a position's `character` counts.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Units {
    Utf8,
    Utf16,
}

/// Where each line of a text starts, for converting positions.
pub struct Lines<'a> {
    text: &'a [u8],
    starts: Vec<usize>,
    units: Units,
}

impl<'a> Lines<'a> {
    pub fn new(text: &'a [u8], units: Units) -> Lines<'a> {
        let mut starts = vec![0];
        starts.extend(memchr::memchr_iter(b'\n', text).map(|i| i + 1));
        Lines {
            text,
            starts,
            units,
        }
    }

    /// The position of byte `offset` (clamped to the text; an offset inside a character
    /// counts as that character's start).
    pub fn position(&self, offset: usize) -> Position {
        let offset = offset.min(self.text.len());
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let start = self.starts[line];
        let character = match self.units {
            Units::Utf8 => offset - start,
            Units::Utf16 => utf16_len(&self.text[start..offset]),
        };
        Position::new(line as u32, character as u32)
    }

    pub fn range(&self, span: Span) -> Range {
        Range::new(
            self.position(span.start as usize),
            self.position(span.end.max(span.start) as usize),
        )
    }

    /// The byte offset of `position`; a position past a line's end is its end, past the
    /// last line the text's end (as the protocol asks).
    pub fn offset(&self, position: Position) -> usize {
        let Some(&start) = self.starts.get(position.line as usize) else {
            return self.text.len();
        };
        let mut end = self
            .starts
            .get(position.line as usize + 1)
            .map_or(self.text.len(), |next| next - 1);
        if end > start && self.text[end - 1] == b'\r' {
            end -= 1;
        }
        let line = &self.text[start..end];
        let wanted = position.character as usize;
        match self.units {
            Units::Utf8 => {
                let mut at = wanted.min(line.len());
                while at > 0 && at < line.len() && line[at] & 0xC0 == 0x80 {
                    at -= 1;
                }
                start + at
            }
            Units::Utf16 => {
                let mut units = 0;
                for (i, c) in String::from_utf8_lossy(line).char_indices() {
                    if units >= wanted {
                        return start + i;
                    }
                    units += c.len_utf16();
                }
                end
            }
        }
    }
}

/// UTF-16 code units of `bytes` (UTF-8; an invalid byte counts as one unit).
fn utf16_len(bytes: &[u8]) -> usize {
    match std::str::from_utf8(bytes) {
        Ok(text) => text.chars().map(char::len_utf16).sum(),
        Err(_) => String::from_utf8_lossy(bytes)
            .chars()
            .map(char::len_utf16)
            .sum(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf16_counts_surrogate_pairs_and_utf8_counts_bytes() {
        // "é" is 2 bytes and 1 UTF-16 unit; "𝄞" 4 bytes and 2 units.
        let text = "a\n<Té𝄞 x='1'/>\r\nz".as_bytes();
        let x = text.iter().position(|&b| b == b'x').unwrap();
        let utf16 = Lines::new(text, Units::Utf16);
        assert_eq!(utf16.position(x), Position::new(1, 6));
        assert_eq!(utf16.offset(Position::new(1, 6)), x);
        let utf8 = Lines::new(text, Units::Utf8);
        assert_eq!(utf8.position(x), Position::new(1, 9));
        assert_eq!(utf8.offset(Position::new(1, 9)), x);
        // Past the end of a line: its end, before "\r\n"'s "\n"; past the last line: the end.
        assert_eq!(utf16.offset(Position::new(1, 99)), x + 7);
        assert_eq!(utf16.offset(Position::new(9, 0)), text.len());
        assert_eq!(utf16.position(text.len()), Position::new(2, 1));
    }
}
