//! The text edits the rules' fixes are made of, per encoding. Each works on the checked
//! (decoded) text and gives up (None) where the text is not as the model says, so that a
//! fix never edits bytes it did not find.

use crate::diagnostic::{Applicability, Edit, Fix, Span};
use crate::model::{Document, Encoding, Node, NodeId};

/// A fix of one or more edits.
pub fn fix(title: impl Into<String>, applicability: Applicability, edits: Vec<Edit>) -> Fix {
    Fix {
        title: title.into(),
        applicability,
        edits,
    }
}

pub fn edit(span: Span, replacement: impl Into<String>) -> Edit {
    Edit {
        span,
        replacement: replacement.into(),
    }
}

/// The place of `name` at the end of `span` (an XML name, a JSON key without its quotes,
/// `@name` in JSON, a ClassicVRML token), if the text there is `name`.
pub fn name_at_end(source: &[u8], span: Span, name: &str) -> Option<Span> {
    let text = source.get(span.range())?;
    text.ends_with(name.as_bytes())
        .then(|| Span::new(span.end as usize - name.len(), span.end as usize))
}

/// Whether a node's spans are its own text: not a prototype instance's copy (whose spans
/// are the instance's) and not a node of another file.
pub fn written(doc: &Document, id: NodeId) -> bool {
    doc.node(id).copy_of.is_none()
}

/// The name in the end tag of an XML element (`</name>`), when it has one.
pub fn xml_end_tag_name(source: &[u8], node: &Node, name: &str) -> Option<Span> {
    let element = source.get(node.span.range())?;
    if element.ends_with(b"/>") {
        return None;
    }
    let open = memchr::memmem::rfind(element, b"</")?;
    let start = node.span.start as usize + open + 2;
    let rest = source.get(start..node.span.end as usize)?;
    let after = rest.strip_prefix(name.as_bytes())?;
    after
        .iter()
        .all(|b| b.is_ascii_whitespace() || *b == b'>')
        .then(|| Span::new(start, start + name.len()))
}

/// Renames a node type written at `node.name_span` (and in its XML end tag).
pub fn rename_node(
    source: &[u8],
    encoding: Encoding,
    node: &Node,
    from: &str,
    to: &str,
) -> Option<Vec<Edit>> {
    let mut edits = vec![edit(name_at_end(source, node.name_span, from)?, to)];
    if encoding == Encoding::Xml {
        if let Some(end) = xml_end_tag_name(source, node, from) {
            edits.push(edit(end, to));
        }
    }
    Some(edits)
}

/// The start of the line `at` is on, and the spaces and tabs that indent it.
pub fn indentation(source: &[u8], at: usize) -> &str {
    let line_start = source[..at.min(source.len())]
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    let indent = source[line_start..]
        .iter()
        .take_while(|b| **b == b' ' || **b == b'\t')
        .count();
    std::str::from_utf8(&source[line_start..line_start + indent]).unwrap_or("")
}

/// Removes a field as written: an XML attribute or ClassicVRML `name value` with the
/// white space before it, or a JSON member with its comma. `name` and `value` are the
/// spans the model gives (the value is the attribute's text without quotes in XML).
pub fn remove_field(source: &[u8], encoding: Encoding, name: Span, value: Span) -> Option<Edit> {
    if value.end < name.end {
        return None;
    }
    let mut end = value.end as usize;
    let mut start = name.start as usize;
    match encoding {
        Encoding::Xml => {
            // The closing quote.
            match source.get(end) {
                Some(b'\'' | b'"') => end += 1,
                _ => return None,
            }
            start = skip_back_space(source, start);
        }
        Encoding::Json => {
            // A member `"@name": value`: with the comma before it, or (the first) with the
            // comma after it, or (the only one) alone.
            if source.get(start.checked_sub(1)?) != Some(&b'"') {
                return None;
            }
            start -= 1;
            let before = skip_back_space(source, start);
            match source.get(before.checked_sub(1)?) {
                Some(b',') => start = before - 1,
                Some(b'{') => {
                    let after = skip_space(source, end);
                    if source.get(after) == Some(&b',') {
                        end = skip_space(source, after + 1);
                    } else {
                        start = before;
                    }
                }
                _ => return None,
            }
        }
        Encoding::ClassicVrml | Encoding::Vrml97 => start = skip_back_space(source, start),
    }
    Some(edit(Span::new(start, end), ""))
}

pub fn skip_space(source: &[u8], mut at: usize) -> usize {
    while source.get(at).is_some_and(|b| b.is_ascii_whitespace()) {
        at += 1;
    }
    at
}

fn skip_back_space(source: &[u8], mut at: usize) -> usize {
    while at > 0 && source[at - 1].is_ascii_whitespace() {
        at -= 1;
    }
    at
}

/// Finds `<name` (followed by white space, `>` or `/`) in `source[from..to]`, outside
/// comments: the offset of its `<`.
pub fn xml_start_tag(source: &[u8], from: usize, to: usize, name: &str) -> Option<usize> {
    let mut at = from;
    let to = to.min(source.len());
    while at < to {
        let rest = &source[at..to];
        let open = memchr::memchr(b'<', rest)? + at;
        let tail = &source[open + 1..to];
        if tail.starts_with(b"!--") {
            let close = memchr::memmem::find(tail, b"-->")?;
            at = open + 1 + close + 3;
            continue;
        }
        if tail.starts_with(name.as_bytes())
            && tail
                .get(name.len())
                .is_some_and(|b| b.is_ascii_whitespace() || *b == b'>' || *b == b'/')
        {
            return Some(open);
        }
        at = open + 1;
    }
    None
}

/// Where a JSON key `"name"` followed by `:` and `{` is in `source[from..to]`: the offset
/// just after that `{`.
pub fn json_object_member(source: &[u8], from: usize, to: usize, name: &str) -> Option<usize> {
    let key = format!("\"{name}\"");
    let to = to.min(source.len());
    let mut at = from;
    while at < to {
        let found = memchr::memmem::find(&source[at..to], key.as_bytes())? + at;
        let colon = skip_space(source, found + key.len());
        if source.get(colon) == Some(&b':') {
            let brace = skip_space(source, colon + 1);
            if source.get(brace) == Some(&b'{') {
                return Some(brace + 1);
            }
        }
        at = found + 1;
    }
    None
}

/// Where an XML document's header ends: at its `<head>` or `<Scene>` start tag after
/// `from`, whichever comes first.
pub fn xml_header_end(source: &[u8], from: usize) -> Option<usize> {
    ["head", "Scene"]
        .into_iter()
        .filter_map(|name| xml_start_tag(source, from, source.len(), name))
        .min()
}

/// Where the members of a JSON document's `X3D` object that describe it end: at its
/// `"head"` or `"Scene"` key after `from`, whichever comes first.
pub fn json_header_end(source: &[u8], from: usize) -> Option<usize> {
    let rest = source.get(from..)?;
    [&b"\"head\""[..], b"\"Scene\""]
        .into_iter()
        .filter_map(|key| memchr::memmem::find(rest, key))
        .min()
        .map(|at| from + at)
}

/// The version numbers `version` in the names of the DTD and schema files written in
/// `source[..end]`: the DOCTYPE's public identifier (`DTD X3D 3.3//EN`) and system file
/// (`x3d-3.3.dtd`), the XML Schema (`x3d-3.3.xsd`) and the JSON schema
/// (`x3d-3.3-JSONSchema.json`).
pub fn schema_file_versions(source: &[u8], end: usize, version: &str) -> Vec<Span> {
    const NAMES: [(&str, &str); 4] = [
        ("DTD X3D ", "//EN"),
        ("x3d-", ".dtd"),
        ("x3d-", ".xsd"),
        ("x3d-", "-JSONSchema.json"),
    ];
    let header = &source[..end.min(source.len())];
    let mut spans: Vec<Span> = NAMES
        .iter()
        .flat_map(|(before, after)| {
            let name = format!("{before}{version}{after}");
            memchr::memmem::find_iter(header, name.as_bytes())
                .map(|at| {
                    let start = at + before.len();
                    Span::new(start, start + version.len())
                })
                .collect::<Vec<_>>()
        })
        .collect();
    spans.sort_by_key(|span| span.start);
    spans
}
