//! Where a ShaderPart's or ShaderProgram's GLSL comes from, and where each of its lines
//! stands in the X3D file.
//!
//! The entries are tried in order, as a browser tries them (19775-1 9.2.1): the XML
//! encoding's CDATA section (or JSON `#sourceCode`) first, then each url entry:
//! - a `data:` URL: its text after the first comma, base64 (`;base64`) or percent-encoded.
//!   Decoded here, not by the Fetch Standard's data: URL rules the textures use: those
//!   drop line breaks and cut the text at `#`, which would turn `#version 300 es` or any
//!   `//` comment into another program; X_ITE and Castle Game Engine pass the text on as
//!   written, and so does this.
//! - source text written straight in the entry (31.2.2.1: shader programs are "defined
//!   in a file that can be externally loaded or defined internally within the X3D
//!   world"): an entry with no URL scheme holding a line break, `;` or `{`, which no
//!   file name does;
//! - at the deep level, a local file of the checked tree (resolved as texture urls are).
//!
//! Network URLs are never fetched.

use std::path::Path;

use crate::model::{Document, NodeId, Span};
use crate::read::{read_path, Contents};
use crate::validate::texturing::files::{not_fetched, Resolution, Resolver};

/// The largest shader file read (the largest real one is a few hundred KB).
pub const MAX_SHADER_FILE: usize = 4 << 20;

/// A part's GLSL and where it was found.
pub struct Source {
    pub text: String,
    pub origin: Origin,
}

pub enum Origin {
    /// In the X3D file. `first_line` is the file offset where the text's first line
    /// starts when its lines are the file's lines (CDATA, ClassicVRML strings, url
    /// entries with literal line breaks); otherwise findings go to `entry`.
    Inline {
        entry: Span,
        first_line: Option<usize>,
    },
    /// A local file, named by the url entry at `entry`.
    File { entry: Span, url: String },
}

/// What a part's entries gave.
pub enum Found {
    Source(Source),
    /// No source to compile; the note says why when nothing else reports it (at the deep
    /// level URL_UNRESOLVED reports missing files and unfetched network URLs).
    Unavailable(Option<String>),
}

/// Whether a url entry is GLSL written in place rather than a URL.
pub fn is_source_text(entry: &str) -> bool {
    !has_scheme(entry) && entry.contains(['\n', ';', '{'])
}

/// `scheme:` at the start (RFC 3986 3.1), two letters or more so that `C:\…` is a path.
fn has_scheme(entry: &str) -> bool {
    let entry = entry.trim_start();
    let Some(colon) = entry.find(':') else {
        return false;
    };
    let scheme = &entry[..colon];
    scheme.len() >= 2
        && scheme.starts_with(|c: char| c.is_ascii_alphabetic())
        && scheme
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '-' | '.'))
}

/// The text a `data:` URL carries, and the byte offset in `url` where it starts; None
/// for other urls, Err when base64 content does not decode.
pub fn data_text(url: &str) -> Option<Result<(String, usize), String>> {
    let lead = url.len() - url.trim_start().len();
    let trimmed = &url[lead..];
    if !trimmed.get(..5)?.eq_ignore_ascii_case("data:") {
        return None;
    }
    let Some(comma) = trimmed.find(',') else {
        return Some(Err(
            "is a data: URL without a comma before its content".into()
        ));
    };
    let header = trimmed[5..comma].trim();
    let body = &trimmed[comma + 1..];
    let base64 = header
        .rsplit(';')
        .next()
        .is_some_and(|last| last.trim().eq_ignore_ascii_case("base64"));
    let bytes = if base64 {
        match data_url::forgiving_base64::decode_to_vec(body.as_bytes()) {
            Ok(bytes) => bytes,
            Err(_) => {
                return Some(Err(
                    "is a data: URL whose base64 content does not decode".into()
                ))
            }
        }
    } else {
        crate::validate::texturing::files::percent_decoded(body)
    };
    Some(Ok((
        String::from_utf8_lossy(&bytes).into_owned(),
        lead + comma + 1,
    )))
}

/// Finds the source of a ShaderPart or ShaderProgram. `resolver` is given at the deep
/// level only.
pub fn find(doc: &Document, file: &[u8], id: NodeId, resolver: Option<&Resolver>) -> Found {
    let node = doc.node(id);
    let name = node.type_name();
    if node.is_connected("url") {
        return Found::Unavailable(Some(format!(
            "{name}: the url passed in through IS is not checked"
        )));
    }
    if let Some(span) = node.source_code {
        if let Some(found) = embedded(file, span, name) {
            return found;
        }
    }
    let Some(entry) = node.entry("url") else {
        return Found::Unavailable(Some(format!("{name}: no source (no url)")));
    };
    let urls = entry.value.as_strings().unwrap_or_default();
    let raw = file.get(entry.span.range()).unwrap_or_default();
    let elements = string_elements(raw);
    let element_span = |k: usize| match elements.get(k) {
        Some(&(start, end)) if elements.len() == urls.len() => Span::new(
            entry.span.range().start + start,
            entry.span.range().start + end,
        ),
        _ => entry.span,
    };
    let mut deferred = None;
    let mut network = None;
    for (k, url) in urls.iter().enumerate() {
        let span = element_span(k);
        let region = file.get(span.range()).unwrap_or_default();
        if let Some(data) = data_text(url) {
            return match data {
                Ok((text, offset)) => inline(text, url, offset, span, region),
                Err(why) => unreadable(name, url, why),
            };
        }
        if is_source_text(url) {
            return inline(url.clone(), url, 0, span, region);
        }
        let Some(resolver) = resolver else {
            if has_scheme(url) && !url.trim_start().to_ascii_lowercase().starts_with("file:") {
                network.get_or_insert(url.clone());
            } else {
                deferred.get_or_insert(url.clone());
            }
            continue;
        };
        match resolver.resolve(url) {
            Resolution::Local(path) => return read_file(&path, url, span, name),
            Resolution::Network(_) => {
                network.get_or_insert(url.clone());
            }
            _ => {}
        }
    }
    let note = if resolver.is_some() {
        None
    } else if let Some(url) = deferred {
        Some(format!(
            "{name}: the source file \"{url}\" is read at the deep level only"
        ))
    } else if let Some(url) = network {
        Some(format!("{name}: {}", not_fetched(&url)))
    } else if urls.is_empty() {
        Some(format!("{name}: no source (the url is empty)"))
    } else {
        None
    };
    Found::Unavailable(note)
}

/// A data: URL that does not decode: nothing to compile.
fn unreadable(name: &str, url: &str, why: String) -> Found {
    let shown = crate::model::data_url::shown(url);
    Found::Unavailable(Some(format!("{name}: url \"{shown}\" {why}")))
}

/// CDATA (XML) or `#sourceCode` (JSON) content, taken as the first url entry. None when
/// it is blank.
fn embedded(file: &[u8], span: Span, name: &str) -> Option<Found> {
    let raw = std::str::from_utf8(file.get(span.range())?).ok()?;
    let (text, start) = if raw.starts_with('[') || raw.starts_with('"') {
        // JSON: a string, or an array of strings joined by line breaks.
        let text = match serde_json::from_str::<serde_json::Value>(raw).ok()? {
            serde_json::Value::String(s) => s,
            serde_json::Value::Array(items) => items
                .iter()
                .filter_map(|i| i.as_str())
                .collect::<Vec<_>>()
                .join("\n"),
            _ => return None,
        };
        (text, span.range().start)
    } else if let Some(inner) = raw.strip_prefix("<![CDATA[") {
        // Each CDATA section is one url entry (as Titania writes an MFString of sources);
        // the first is the one a browser loads.
        let end = inner.find("]]>").unwrap_or(inner.len());
        let start = span.range().start + "<![CDATA[".len();
        let text = inner[..end].to_string();
        if text.trim().is_empty() {
            return None;
        }
        let entry = Span::new(start, start + end);
        let region = &file[entry.range()];
        return Some(match data_text(&text) {
            Some(Ok((glsl, offset))) => inline(glsl, &text, offset, entry, region),
            Some(Err(why)) => unreadable(name, &text, why),
            None => inline(text.clone(), &text, 0, entry, region),
        });
    } else {
        (unescape_xml(raw), span.range().start)
    };
    if text.trim().is_empty() {
        return None;
    }
    let region = &file[start..span.range().end];
    let entry = Span::new(start, span.range().end);
    Some(match data_text(&text) {
        Some(Ok((glsl, offset))) => inline(glsl, &text, offset, entry, region),
        Some(Err(why)) => unreadable(name, &text, why),
        None => inline(text.clone(), &text, 0, entry, region),
    })
}

fn unescape_xml(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// A source written in the X3D file: `entry_text` is the entry as read, `glsl` the source
/// starting at byte `offset` of it, `region` the entry as written in the file at `span`.
/// Its lines are the file's when the entry as read and as written break lines alike.
fn inline(glsl: String, entry_text: &str, offset: usize, span: Span, region: &[u8]) -> Found {
    let breaks_read = entry_text.matches('\n').count();
    let breaks_written = region.iter().filter(|&&b| b == b'\n').count();
    let glsl_breaks = glsl.matches('\n').count();
    let before = entry_text
        .get(..offset)
        .map_or(0, |head| head.matches('\n').count());
    let first_line = (breaks_read == breaks_written && before + glsl_breaks <= breaks_written)
        .then(|| {
            let mut at = span.range().start;
            let mut skipped = 0;
            while skipped < before {
                if region[at - span.range().start] == b'\n' {
                    skipped += 1;
                }
                at += 1;
            }
            at
        });
    Found::Source(Source {
        text: glsl,
        origin: Origin::Inline {
            entry: span,
            first_line,
        },
    })
}

fn read_file(path: &Path, url: &str, span: Span, name: &str) -> Found {
    match read_path(path, MAX_SHADER_FILE) {
        Ok(Contents::Bytes(bytes)) => Found::Source(Source {
            text: String::from_utf8_lossy(&bytes).into_owned(),
            origin: Origin::File {
                entry: span,
                url: url.to_string(),
            },
        }),
        Ok(Contents::TooLarge) => Found::Unavailable(Some(format!(
            "{name}: \"{url}\" is larger than {} MiB and is not compiled",
            MAX_SHADER_FILE >> 20
        ))),
        Err(why) => Found::Unavailable(Some(format!("{name}: {why}"))),
    }
}

/// The byte ranges (inside the quotes) of the quoted strings of an MFString as written:
/// `"a" "b"` (XML), `["a", "b"]` (JSON), `[ "a" "b" ]` (ClassicVRML); `\` escapes the
/// next character in all three.
fn string_elements(raw: &[u8]) -> Vec<(usize, usize)> {
    let mut found = Vec::new();
    let mut i = 0;
    while i < raw.len() {
        if raw[i] != b'"' {
            i += 1;
            continue;
        }
        let start = i + 1;
        i = start;
        while i < raw.len() && raw[i] != b'"' {
            i += if raw[i] == b'\\' { 2 } else { 1 };
        }
        found.push((start, i.min(raw.len())));
        i += 1;
    }
    found
}

/// The span of line `line` (1-based) of a source, trimmed, for a finding; the entry when
/// its lines are not the file's.
pub fn line_span(file: &[u8], origin: &Origin, line: Option<u32>) -> Span {
    let (entry, first_line) = match origin {
        Origin::Inline { entry, first_line } => (*entry, *first_line),
        Origin::File { entry, .. } => (*entry, None),
    };
    let (Some(mut at), Some(line)) = (first_line, line) else {
        return entry;
    };
    for _ in 1..line.max(1) {
        match memchr::memchr(b'\n', &file[at..entry.range().end]) {
            Some(newline) => at += newline + 1,
            None => return entry,
        }
    }
    let end =
        memchr::memchr(b'\n', &file[at..entry.range().end]).map_or(entry.range().end, |n| at + n);
    let text = &file[at..end];
    let lead = text.iter().take_while(|b| b.is_ascii_whitespace()).count();
    let trail = text
        .iter()
        .rev()
        .take_while(|b| b.is_ascii_whitespace())
        .count();
    if lead == text.len() {
        return Span::new(at, at);
    }
    Span::new(at + lead, end - trail)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_urls_keep_line_breaks_and_hashes() {
        let (text, offset) = data_text("data:text/plain,#version 300 es\nvoid main() {}")
            .unwrap()
            .unwrap();
        assert_eq!(text, "#version 300 es\nvoid main() {}");
        assert_eq!(offset, 16);
        let (text, _) = data_text("data:text/plain;charset=utf-8,a%20b%zz%")
            .unwrap()
            .unwrap();
        assert_eq!(text, "a b%zz%");
        let (text, _) = data_text("data:text/plain;base64,dm9pZCBtYWluKCkge30=")
            .unwrap()
            .unwrap();
        assert_eq!(text, "void main() {}");
        assert!(data_text("shader.vs").is_none());
        assert!(data_text("data:;base64,!!").unwrap().is_err());
    }

    #[test]
    fn source_text_is_told_from_urls() {
        assert!(is_source_text("void main() { gl_FragColor = vec4(1.0); }"));
        assert!(is_source_text("uniform float a;\nvoid main(){}"));
        assert!(!is_source_text("shaders/phong.fs"));
        assert!(!is_source_text("https://example.org/a.fs"));
        assert!(!is_source_text("C:\\shaders\\a.fs"));
    }

    #[test]
    fn quoted_elements_are_found() {
        assert_eq!(string_elements(br#""a" "b\"c""#), vec![(1, 2), (5, 9)]);
        assert_eq!(string_elements(br#"["x", "y"]"#), vec![(2, 3), (7, 8)]);
    }
}
