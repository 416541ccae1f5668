//! The tags of an HTML page where they stand in its text: the HTML tokenizer gives the
//! tree builder names, attributes and a line number, but no byte offsets, so the page is
//! scanned here for its tags in order, with the offsets of each name and attribute, and
//! each token is matched with its tag ([`Tags::matching`]).

/// What a scanned piece of markup is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Start,
    End,
    Comment,
}

/// An attribute of a start tag: its name as written and where its name and value stand.
#[derive(Clone, Debug)]
pub struct TagAttr {
    /// ASCII-lowercased, as the tokenizer gives it.
    pub name: String,
    pub name_start: usize,
    pub name_end: usize,
    /// The value's text without its quotes (empty where the attribute has no value).
    pub value_start: usize,
    pub value_end: usize,
}

/// A tag or comment from `start` (its `<`) to `end` (after its `>`).
#[derive(Clone, Debug)]
pub struct Tag {
    pub kind: Kind,
    /// ASCII-lowercased; empty for a comment.
    pub name: String,
    pub start: usize,
    pub end: usize,
    /// Written `<name/>`.
    pub self_closing: bool,
    pub attrs: Vec<TagAttr>,
    /// The line (1-based) of the tag's last character, which is the line the tokenizer
    /// reports with the token it emits there.
    pub last_line: u64,
}

/// Elements whose content is text up to their end tag (HTML 13.1.2; the tokenizer's
/// RAWTEXT, RCDATA and script data states, `noscript` with scripting on).
const TEXT_ELEMENTS: &[&str] = &[
    "script", "style", "textarea", "title", "xmp", "iframe", "noembed", "noframes", "noscript",
];

/// The tags of a page in order, and how far the matching has got.
pub struct Tags {
    pub list: Vec<Tag>,
    next: usize,
}

impl Tags {
    pub fn scan(source: &[u8]) -> Tags {
        let mut list = Vec::new();
        let mut lines = LineCounter::default();
        let mut at = 0;
        while let Some(found) = memchr::memchr(b'<', &source[at..]) {
            let lt = at + found;
            let rest = &source[lt + 1..];
            let tag = if rest.starts_with(b"!--") {
                let body = lt + 4;
                let end = find(source, body, b"-->").map_or(source.len(), |e| e + 3);
                Some((Kind::Comment, String::new(), end, false, Vec::new()))
            } else if rest.first().is_some_and(|b| matches!(b, b'!' | b'?')) {
                // A DOCTYPE or a bogus comment: up to the next `>`.
                at = find(source, lt, b">").map_or(source.len(), |e| e + 1);
                continue;
            } else if rest.first().is_some_and(u8::is_ascii_alphabetic) {
                Some(start_tag(source, lt))
            } else if rest.starts_with(b"/") && rest.get(1).is_some_and(u8::is_ascii_alphabetic) {
                let (_, name, end, _, _) = start_tag(source, lt + 1);
                Some((Kind::End, name, end, false, Vec::new()))
            } else {
                None
            };
            let Some((kind, name, end, self_closing, attrs)) = tag else {
                at = lt + 1;
                continue;
            };
            let last_line = lines.line_at(source, end.saturating_sub(1));
            let text_element = kind == Kind::Start && TEXT_ELEMENTS.contains(&name.as_str());
            let close = format!("</{name}");
            list.push(Tag {
                kind,
                name,
                start: lt,
                end,
                self_closing,
                attrs,
                last_line,
            });
            at = end;
            if text_element {
                at = find_ignoring_case(source, at, close.as_bytes()).unwrap_or(source.len());
            }
        }
        Tags { list, next: 0 }
    }

    /// The tag of the tokenizer's next token of `kind` named `name` (lowercase) that it
    /// emitted on `line`: the first such tag after the last one matched on that line, else
    /// the first of that kind and name at all (a page the scan reads otherwise than the
    /// tokenizer, which the tests look for), else none.
    pub fn matching(&mut self, kind: Kind, name: &str, line: u64) -> Option<usize> {
        let same = |t: &Tag| t.kind == kind && (kind == Kind::Comment || t.name == name);
        let rest = self.next..self.list.len();
        let found = rest
            .clone()
            .find(|&i| same(&self.list[i]) && self.list[i].last_line == line)
            .or_else(|| rest.clone().find(|&i| same(&self.list[i])))?;
        self.next = found + 1;
        Some(found)
    }
}

/// Reads the tag whose name starts after `lt` (`<` or `</`): its name, end and attributes,
/// as the HTML tokenizer's tag states read them (13.2.5.6–13.2.5.40).
fn start_tag(source: &[u8], lt: usize) -> (Kind, String, usize, bool, Vec<TagAttr>) {
    let is_space = |b: u8| matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b'\x0C');
    let len = source.len();
    let mut i = lt + 1;
    let name_start = i;
    while i < len && !is_space(source[i]) && source[i] != b'/' && source[i] != b'>' {
        i += 1;
    }
    let name = lower(&source[name_start..i]);
    let mut attrs = Vec::new();
    let mut self_closing = false;
    loop {
        while i < len && (is_space(source[i]) || source[i] == b'/') {
            self_closing = source[i] == b'/';
            i += 1;
        }
        if i >= len {
            return (Kind::Start, name, len, false, attrs);
        }
        if source[i] == b'>' {
            return (Kind::Start, name, i + 1, self_closing, attrs);
        }
        self_closing = false;
        // The first character of a name may be `=`; after it, `=` ends the name.
        let name_start = i;
        i += 1;
        while i < len && !is_space(source[i]) && !matches!(source[i], b'/' | b'>' | b'=') {
            i += 1;
        }
        let name_end = i;
        let mut j = i;
        while j < len && is_space(source[j]) {
            j += 1;
        }
        let (mut value_start, mut value_end) = (name_end, name_end);
        if j < len && source[j] == b'=' {
            j += 1;
            while j < len && is_space(source[j]) {
                j += 1;
            }
            match source.get(j) {
                Some(&quote @ (b'"' | b'\'')) => {
                    value_start = j + 1;
                    value_end = memchr::memchr(quote, &source[value_start..])
                        .map_or(len, |e| value_start + e);
                    i = (value_end + 1).min(len);
                }
                _ => {
                    value_start = j;
                    while j < len && !is_space(source[j]) && source[j] != b'>' {
                        j += 1;
                    }
                    value_end = j;
                    i = j;
                }
            }
        }
        attrs.push(TagAttr {
            name: lower(&source[name_start..name_end]),
            name_start,
            name_end,
            value_start,
            value_end,
        });
    }
}

fn lower(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).to_ascii_lowercase()
}

fn find(source: &[u8], from: usize, needle: &[u8]) -> Option<usize> {
    memchr::memmem::find(&source[from.min(source.len())..], needle).map(|e| from + e)
}

fn find_ignoring_case(source: &[u8], from: usize, needle: &[u8]) -> Option<usize> {
    (from..source.len().saturating_sub(needle.len() - 1))
        .find(|&i| source[i..i + needle.len()].eq_ignore_ascii_case(needle))
}

/// Line numbers of offsets asked in increasing order, counted once over the text.
#[derive(Default)]
struct LineCounter {
    at: usize,
    line: u64,
}

impl LineCounter {
    fn line_at(&mut self, source: &[u8], offset: usize) -> u64 {
        let offset = offset.min(source.len());
        if offset >= self.at {
            self.line += memchr::memchr_iter(b'\n', &source[self.at..offset]).count() as u64;
            self.at = offset;
        }
        self.line + 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_have_their_offsets_names_and_attributes() {
        let page = b"<!DOCTYPE html>\n<x3d width='5'><scene>\n<Box size=\"1 2 3\" solid/></scene>";
        let tags = Tags::scan(page);
        let names: Vec<_> = tags
            .list
            .iter()
            .map(|t| (t.kind, t.name.as_str()))
            .collect();
        assert_eq!(
            names,
            [
                (Kind::Start, "x3d"),
                (Kind::Start, "scene"),
                (Kind::Start, "box"),
                (Kind::End, "scene")
            ]
        );
        let b = &tags.list[2];
        assert!(b.self_closing);
        assert_eq!(b.last_line, 3);
        assert_eq!(&page[b.attrs[0].name_start..b.attrs[0].name_end], b"size");
        assert_eq!(
            &page[b.attrs[0].value_start..b.attrs[0].value_end],
            b"1 2 3"
        );
        assert_eq!(b.attrs[1].name, "solid");
    }

    #[test]
    fn script_content_is_not_read_as_tags() {
        let page = b"<script>if (a<b) x = '<Box>';</SCRIPT><p>";
        let names: Vec<_> = Tags::scan(page).list.into_iter().map(|t| t.name).collect();
        assert_eq!(names, ["script", "script", "p"]);
    }

    #[test]
    fn a_token_is_matched_with_its_tag_on_its_line() {
        let mut tags = Tags::scan(b"<a>\n<b>\n<a>");
        assert_eq!(tags.matching(Kind::Start, "a", 3), Some(2));
        assert_eq!(tags.matching(Kind::Start, "b", 2), None);
    }
}
