//! Where a Script's code is written, decoded with its places ([`Mapped`]): the XML
//! element's CDATA and text, url strings in each encoding (an XML attribute holding an
//! MFString, JSON strings, ClassicVRML strings) and JSON's `#sourceCode`.
//!
//! Hand-written because the readers keep only the decoded values, not the place of each
//! decoded character; each decoder follows its reader (`xml_value.rs` for MFString quoting,
//! `classic/lexer.rs` for ClassicVRML strings, RFC 8259 §7 for JSON strings).

use super::mapped::Mapped;
use crate::model::Span;

/// One string of a url field as written: its decoded text and the place of the whole
/// string (quotes included).
pub struct Entry {
    pub text: Mapped,
    pub span: Span,
}

/// The character data of an XML element between `span`: CDATA sections as they are,
/// text with its character and entity references decoded; child elements, comments and
/// processing instructions (and text inside child elements) left out.
pub fn xml_content(source: &[u8], span: Span) -> Mapped {
    let (start, end) = (span.start as usize, (span.end as usize).min(source.len()));
    let s = &source[start.min(end)..end];
    let mut out = Mapped::default();
    let mut depth = 0usize;
    let mut i = 0;
    while i < s.len() {
        let rest = &s[i..];
        if let Some(content) = rest.strip_prefix(b"<![CDATA[") {
            let close = find(content, b"]]>").unwrap_or(content.len());
            if depth == 0 {
                out.push_verbatim(&String::from_utf8_lossy(&content[..close]), start + i + 9);
            }
            i += 9 + close + 3;
        } else if rest.starts_with(b"<!--") {
            i += find(rest, b"-->").map_or(rest.len(), |k| k + 3);
        } else if rest.starts_with(b"<?") {
            i += find(rest, b"?>").map_or(rest.len(), |k| k + 2);
        } else if rest[0] == b'<' {
            let close = tag_end(rest);
            if rest.get(1) == Some(&b'/') {
                depth = depth.saturating_sub(1);
            } else if close == 0 || rest[close - 1] != b'/' {
                depth += 1;
            }
            i += close + 1;
        } else {
            let next = memchr::memchr(b'<', rest).unwrap_or(rest.len());
            if depth == 0 {
                xml_text(&rest[..next], start + i, false, &mut out);
            }
            i += next;
        }
    }
    out
}

/// The strings of an MFString XML attribute whose raw value is at `span` (`"a" "b"`, with
/// `&quot;` and the like for quotes): XML's decoding and attribute-value normalization
/// first (a literal line break is a space, `&#10;` is a line break), then MFString quoting
/// (19776-1 5.15: `\"` and `\\`). A value with no quote at all is read as one string, as
/// browsers (and the reader, which reports it) do.
pub fn xml_attribute_strings(source: &[u8], span: Span) -> Vec<Entry> {
    let raw = &source[span.start as usize..(span.end as usize).min(source.len())];
    let mut decoded = Mapped::default();
    xml_text(raw, span.start as usize, true, &mut decoded);
    quoted_strings(&decoded, false)
}

/// The strings of a ClassicVRML url value at `span`: one string, or a bracketed list with
/// `#` comments and commas between the strings.
pub fn classic_strings(source: &[u8], span: Span) -> Vec<Entry> {
    let raw = &source[span.start as usize..(span.end as usize).min(source.len())];
    let mut text = Mapped::default();
    text.push_verbatim(&String::from_utf8_lossy(raw), span.start as usize);
    quoted_strings(&text, true)
}

/// The JSON strings of the value at `span` (a string, or an array of them).
pub fn json_strings(source: &[u8], span: Span) -> Vec<Entry> {
    let (start, end) = (span.start as usize, (span.end as usize).min(source.len()));
    let mut entries = Vec::new();
    let mut i = start;
    while i < end {
        if source[i] != b'"' {
            i += 1;
            continue;
        }
        let open = i;
        let mut text = Mapped::default();
        i += 1;
        while i < end && source[i] != b'"' {
            if source[i] == b'\\' && i + 1 < end {
                let (c, len) = json_escape(&source[i..end]);
                text.push_decoded(c, i, i + len);
                i += len;
            } else {
                let len = utf8_len(source[i]).min(end - i);
                text.push_verbatim(&String::from_utf8_lossy(&source[i..i + len]), i);
                i += len;
            }
        }
        i += 1;
        entries.push(Entry {
            text,
            span: Span::new(open, i.min(end)),
        });
    }
    entries
}

/// JSON `#sourceCode`: a string, or an array of lines joined by line breaks.
pub fn json_source_code(source: &[u8], span: Span) -> Mapped {
    let mut out = Mapped::default();
    for (k, line) in json_strings(source, span).into_iter().enumerate() {
        if k > 0 {
            out.push_decoded('\n', line.span.start as usize, line.span.start as usize);
        }
        for (index, c) in line.text.text.char_indices() {
            out.push_from(&line.text, index, c);
        }
    }
    out
}

/// XML character data with `&…;` references decoded (the five predefined entities and
/// character references; another entity, declared in a DOCTYPE, is kept as written).
/// `normalize`: attribute-value normalization, a literal tab or line break being a space.
fn xml_text(raw: &[u8], start: usize, normalize: bool, out: &mut Mapped) {
    let text = String::from_utf8_lossy(raw);
    let mut chunk = 0;
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        let replaced = if b == b'&' {
            bytes[i..]
                .iter()
                .position(|&c| c == b';')
                .filter(|&k| k <= 12)
                .and_then(|k| reference(&text[i + 1..i + k]).map(|c| (c, k + 1)))
        } else if normalize && matches!(b, b'\t' | b'\n' | b'\r') {
            // `\r\n` is one line break, so one space.
            let len = if b == b'\r' && bytes.get(i + 1) == Some(&b'\n') {
                2
            } else {
                1
            };
            Some((' ', len))
        } else {
            None
        };
        if let Some((c, len)) = replaced {
            out.push_verbatim(&text[chunk..i], start + chunk);
            out.push_decoded(c, start + i, start + i + len);
            i += len;
            chunk = i;
        } else {
            i += 1;
        }
    }
    out.push_verbatim(&text[chunk..], start + chunk);
}

/// The character an XML reference (`lt`, `#10`, `#x41`) stands for.
fn reference(name: &str) -> Option<char> {
    match name {
        "lt" => Some('<'),
        "gt" => Some('>'),
        "amp" => Some('&'),
        "quot" => Some('"'),
        "apos" => Some('\''),
        _ => {
            let number = name.strip_prefix('#')?;
            let code = match number.strip_prefix(['x', 'X']) {
                Some(hex) => u32::from_str_radix(hex, 16).ok()?,
                None => number.parse().ok()?,
            };
            char::from_u32(code)
        }
    }
}

/// Double-quoted strings separated by whitespace or commas, with `\"` and `\\` escapes (a
/// backslash before another character stands for that character). `classic`: `[`, `]`
/// separate too, and `#` starts a comment to the end of the line.
fn quoted_strings(text: &Mapped, classic: bool) -> Vec<Entry> {
    let s = text.text.as_str();
    if !classic && !s.contains('"') {
        let trimmed = s.trim();
        if trimmed.is_empty() {
            return Vec::new();
        }
        let start = s.len() - s.trim_start().len();
        return vec![Entry {
            text: text.slice(start, start + trimmed.len()),
            span: text.span(start, start + trimmed.len()),
        }];
    }
    let mut entries = Vec::new();
    let mut chars = s.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        match c {
            '"' => {
                let mut value = Mapped::default();
                let mut end = s.len();
                while let Some((k, c)) = chars.next() {
                    match c {
                        '"' => {
                            end = k + 1;
                            break;
                        }
                        '\\' => {
                            if let Some((k, escaped)) = chars.next() {
                                value.push_from(text, k, escaped);
                            }
                        }
                        _ => value.push_from(text, k, c),
                    }
                }
                entries.push(Entry {
                    text: value,
                    span: text.span(i, end),
                });
            }
            '#' if classic => {
                for (_, c) in chars.by_ref() {
                    if c == '\n' || c == '\r' {
                        break;
                    }
                }
            }
            _ => {}
        }
    }
    entries
}

/// A JSON escape at the start of `s` (`\n`, `\"`, `\u0041`, a surrogate pair) and how many
/// bytes it takes.
fn json_escape(s: &[u8]) -> (char, usize) {
    let simple = match s.get(1) {
        Some(b'n') => Some('\n'),
        Some(b't') => Some('\t'),
        Some(b'r') => Some('\r'),
        Some(b'b') => Some('\u{8}'),
        Some(b'f') => Some('\u{c}'),
        Some(b'u') => None,
        Some(&other) => Some(other as char),
        None => return ('\\', 1),
    };
    if let Some(c) = simple {
        return (c, 2);
    }
    let hex = |at: usize| {
        s.get(at..at + 4)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u32::from_str_radix(h, 16).ok())
    };
    let Some(high) = hex(2) else {
        return ('\u{fffd}', 2);
    };
    if (0xD800..0xDC00).contains(&high) && s.get(6..8) == Some(b"\\u") {
        if let Some(low) = hex(8).filter(|l| (0xDC00..0xE000).contains(l)) {
            let code = 0x10000 + ((high - 0xD800) << 10) + (low - 0xDC00);
            return (char::from_u32(code).unwrap_or('\u{fffd}'), 12);
        }
    }
    (char::from_u32(high).unwrap_or('\u{fffd}'), 6)
}

fn utf8_len(first: u8) -> usize {
    match first {
        0xF0.. => 4,
        0xE0.. => 3,
        0xC0.. => 2,
        _ => 1,
    }
}

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    memchr::memmem::find(haystack, needle)
}

/// The index of the `>` closing a tag that starts at `s[0]`, quotes respected.
fn tag_end(s: &[u8]) -> usize {
    let mut quote = None;
    for (i, &b) in s.iter().enumerate().skip(1) {
        match quote {
            Some(q) if b == q => quote = None,
            None if b == b'"' || b == b'\'' => quote = Some(b),
            None if b == b'>' => return i,
            _ => {}
        }
    }
    s.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn whole(text: &str) -> Span {
        Span::new(0, text.len())
    }

    /// The document text each decoded character comes from.
    fn origin<'a>(doc: &'a str, text: &Mapped, index: usize, len: usize) -> &'a str {
        &doc[text.span(index, index + len).range()]
    }

    #[test]
    fn xml_content_keeps_cdata_and_decodes_text() {
        let doc = "<field name='a'/>\n<![CDATA[ecmascript: a < b]]> &amp;&#x41;<!-- c --><f>x</f>";
        let content = xml_content(doc.as_bytes(), whole(doc));
        assert_eq!(content.text, "\necmascript: a < b &A");
        let lt = content.text.find('<').unwrap();
        assert_eq!(origin(doc, &content, lt, 1), "<");
        let a = content.text.find('A').unwrap();
        assert_eq!(origin(doc, &content, a, 1), "&#x41;");
        assert_eq!(origin(doc, &content, a - 1, 1), "&amp;");
    }

    #[test]
    fn xml_attribute_strings_decode_both_levels() {
        // `&quot;` alone would end the MFString string: a quote of the code is `\&quot;`.
        let doc = r#""javascript: f(\&quot;x\&quot;, \"y\")&#10;g()" 'z.js'"#;
        let entries = xml_attribute_strings(doc.as_bytes(), whole(doc));
        assert_eq!(entries.len(), 1);
        assert_eq!(entries[0].text.text, "javascript: f(\"x\", \"y\")\ng()");
        let text = &entries[0].text;
        assert_eq!(origin(doc, text, text.text.find('\n').unwrap(), 1), "&#10;");
        assert_eq!(origin(doc, text, 14, 1), "&quot;");
        assert_eq!(
            &doc[entries[0].span.range()],
            &doc[..doc.find(" 'z").unwrap()]
        );
        // A literal line break in an attribute is a space.
        let doc = "\"a\nb\" \"c.js\"";
        let entries = xml_attribute_strings(doc.as_bytes(), whole(doc));
        assert_eq!(entries[0].text.text, "a b");
        assert_eq!(entries[1].text.text, "c.js");
        let entries = xml_attribute_strings(b" plain.js ", Span::new(0, 10));
        assert_eq!(entries[0].text.text, "plain.js");
        assert_eq!(entries[0].span, Span::new(1, 9));
    }

    #[test]
    fn json_strings_decode_escapes() {
        let doc = r#"["ecmascript: a(\"\u00e9\")\n", "b\ud83d\ude00"]"#;
        let entries = json_strings(doc.as_bytes(), whole(doc));
        assert_eq!(entries[0].text.text, "ecmascript: a(\"é\")\n");
        assert_eq!(entries[1].text.text, "b😀");
        let text = &entries[0].text;
        assert_eq!(
            origin(doc, text, text.text.find('é').unwrap(), 2),
            r"\u00e9"
        );
        assert_eq!(origin(doc, text, text.text.find('\n').unwrap(), 1), r"\n");
        let code = json_source_code(doc.as_bytes(), whole(doc));
        assert_eq!(code.text, "ecmascript: a(\"é\")\n\nb😀");
    }

    #[test]
    fn classic_strings_skip_comments() {
        let doc = "[ \"ecmascript: a = \\\"#\\\";\" # \"not\" \n, \"b.js\" ]";
        let entries = classic_strings(doc.as_bytes(), whole(doc));
        let texts: Vec<&str> = entries.iter().map(|e| e.text.text.as_str()).collect();
        assert_eq!(texts, ["ecmascript: a = \"#\";", "b.js"]);
        assert_eq!(&doc[entries[1].span.range()], "\"b.js\"");
    }
}
