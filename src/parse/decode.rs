//! The stage before the readers: turns the bytes of an input into the UTF-8 text they read.
//! A gzip stream (magic `1f 8b`) is inflated, within the input size limit while it is
//! inflated; then a UTF-8 byte-order mark is dropped, UTF-16 (byte-order mark, or `<` as
//! the first UTF-16 character, XML 1.0 Appendix F) is decoded, and so is any encoding of
//! the WHATWG Encoding Standard that an XML declaration names (encoding_rs, the decoder
//! Firefox uses). Every position a report gives is an offset into the decoded text, which
//! is why callers get it back (see [`crate::check::Checked`]): its lines and columns are
//! those an editor shows.
//!
//! XML text that declares no other encoding must be UTF-8, and is checked to be here, so
//! that the XML reader can rely on it; JSON is UTF-8 by RFC 8259 §8.1 (a byte-order mark
//! is ignored, as that section allows) and its reader checks it.

use std::borrow::Cow;
use std::io::Read;

use encoding_rs::{DecoderResult, Encoding as Charset, UTF_16BE, UTF_16LE, UTF_8};
use flate2::read::MultiGzDecoder;

use super::behind::{self, Progress};
use super::rules::{GZIP_CORRUPT, XML_ENCODING_UNSUPPORTED, XML_MALFORMED};
use crate::diagnostic::Diagnostic;
use crate::limits::MAX_INPUT_BYTES;
use crate::model::rules::LIMIT_EXCEEDED;
use crate::model::Span;

/// The first bytes of every gzip stream (RFC 1952 §2.3.1).
pub const GZIP_MAGIC: [u8; 2] = [0x1f, 0x8b];

const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// An input made ready for the readers.
pub struct Decoded<'a> {
    /// UTF-8 text (when `failure` is None and the input is XML; JSON's reader checks its
    /// own): what the readers read and every reported position is an offset into. When
    /// decoding failed, what was decoded before the failure.
    pub text: Cow<'a, [u8]>,
    /// Whether the input was gzip-compressed.
    pub compressed: bool,
    /// Why the input cannot be read: GZIP_CORRUPT, LIMIT_EXCEEDED, XML_ENCODING_UNSUPPORTED,
    /// or XML_MALFORMED for bytes that are not of the encoding they should be in.
    pub failure: Option<Diagnostic>,
}

/// Decodes an input of at most [`MAX_INPUT_BYTES`], compressed or not.
pub fn decode(source: &[u8]) -> Decoded<'_> {
    decode_within(source, MAX_INPUT_BYTES, &())
}

/// [`decode`], telling `progress` how far the check that the text is UTF-8 has got (see
/// [`behind`]).
pub fn decode_with_progress<'a>(source: &'a [u8], progress: &dyn Progress) -> Decoded<'a> {
    decode_within(source, MAX_INPUT_BYTES, progress)
}

/// [`decode_with_progress`] with another size limit, on the input and on its decompressed
/// and decoded text (tests use a small one).
pub fn decode_within<'a>(source: &'a [u8], limit: usize, progress: &dyn Progress) -> Decoded<'a> {
    let failed = |text, compressed, failure| Decoded {
        text,
        compressed,
        failure: Some(failure),
    };
    if source.len() > limit {
        return failed(Cow::Borrowed(&[]), false, too_large("the input", limit));
    }
    let compressed = source.starts_with(&GZIP_MAGIC);
    let text = if compressed {
        match inflate(source, limit) {
            Ok(text) => Cow::Owned(text),
            Err(failure) => return failed(Cow::Borrowed(&[]), true, *failure),
        }
    } else {
        Cow::Borrowed(source)
    };
    match to_utf8(text, limit, progress) {
        Ok(text) => Decoded {
            text,
            compressed,
            failure: None,
        },
        Err((text, failure)) => failed(text, compressed, *failure),
    }
}

/// An input not read because it is larger than [`MAX_INPUT_BYTES`] (for callers that learn
/// that before reading it all).
pub fn too_large_input() -> Decoded<'static> {
    Decoded {
        text: Cow::Borrowed(&[]),
        compressed: false,
        failure: Some(too_large("the input", MAX_INPUT_BYTES)),
    }
}

fn too_large(what: &str, limit: usize) -> Diagnostic {
    Diagnostic::new(
        &LIMIT_EXCEEDED,
        Span::new(0, 0),
        format!("{what} is larger than {limit} bytes, the most x3dcheck reads"),
    )
}

/// Inflates a gzip stream (all its members, as gunzip does), reading at most one byte past
/// `limit`: a bomb stops there, never holding more.
fn inflate(source: &[u8], limit: usize) -> Result<Vec<u8>, Box<Diagnostic>> {
    let mut text = Vec::with_capacity(source.len().saturating_mul(4).min(limit) + 1);
    let read = MultiGzDecoder::new(source)
        .take(limit as u64 + 1)
        .read_to_end(&mut text);
    match read {
        Err(error) => Err(Box::new(
            Diagnostic::new(
                &GZIP_CORRUPT,
                Span::new(0, 0),
                format!("the gzip-compressed input does not decompress: {error}"),
            )
            .help("the file is damaged or cut short; `gzip -t FILE` tests it"),
        )),
        Ok(_) if text.len() > limit => Err(Box::new(too_large("the decompressed input", limit))),
        Ok(_) => Ok(text),
    }
}

/// How the text of an input is made UTF-8.
enum Plan {
    /// It is UTF-8 after `bom` bytes; `check` whether it is (XML, which the reader trusts).
    Utf8 {
        bom: usize,
        check: bool,
    },
    /// Decode what follows `bom` bytes from this encoding.
    Decode {
        charset: &'static Charset,
        bom: usize,
    },
    Refuse(Diagnostic),
}

type Failed<'a> = (Cow<'a, [u8]>, Box<Diagnostic>);

fn to_utf8<'a>(
    text: Cow<'a, [u8]>,
    limit: usize,
    progress: &dyn Progress,
) -> Result<Cow<'a, [u8]>, Failed<'a>> {
    match plan(&text) {
        Plan::Refuse(failure) => Err((text, Box::new(failure))),
        Plan::Utf8 { bom, check } => {
            let text = drop_prefix(text, bom);
            match check.then(|| behind::utf8(&text, progress)) {
                Some(Err(error)) => {
                    let at = error.valid_up_to;
                    let failure = not_utf8(&text[at..at + error.error_len.unwrap_or(1)], at);
                    Err((text, Box::new(failure)))
                }
                _ => Ok(text),
            }
        }
        Plan::Decode { charset, bom } => match decode_strict(charset, &text[bom..]) {
            Ok(decoded) if decoded.len() > limit => Err((
                Cow::Borrowed(&[]),
                Box::new(too_large("the input decoded to UTF-8", limit)),
            )),
            Ok(decoded) => Ok(Cow::Owned(decoded.into_bytes())),
            Err((decoded, bad)) => {
                let at = decoded.len();
                let failure = Diagnostic::new(
                    &XML_MALFORMED,
                    Span::new(at, at),
                    format!(
                        "not well-formed XML: {} is not a character in {}, the encoding \
                         the document is read in",
                        hex(&bad),
                        charset.name()
                    ),
                )
                .help("save the file in the encoding its XML declaration names, or as UTF-8");
                Err((Cow::Owned(decoded.into_bytes()), Box::new(failure)))
            }
        },
    }
}

fn plan(text: &[u8]) -> Plan {
    // UTF-32 (what `FF FE 00 00` is more likely than UTF-16 with a NUL) is left for
    // encoding detection to name.
    if text.starts_with(b"\xFF\xFE\0\0") || text.starts_with(b"\0\0\xFE\xFF") {
        return Plan::Utf8 {
            bom: 0,
            check: false,
        };
    }
    if text.starts_with(UTF8_BOM) {
        return Plan::Utf8 {
            bom: UTF8_BOM.len(),
            check: looks_like_xml(&text[UTF8_BOM.len()..]),
        };
    }
    let charset = |charset| Plan::Decode { charset, bom: 2 };
    match text {
        [0xFF, 0xFE, ..] => return charset(UTF_16LE),
        [0xFE, 0xFF, ..] => return charset(UTF_16BE),
        // `<` as a UTF-16 character: no UTF-8 document starts with a NUL.
        [b'<', 0, ..] => {
            return Plan::Decode {
                charset: UTF_16LE,
                bom: 0,
            }
        }
        [0, b'<', ..] => {
            return Plan::Decode {
                charset: UTF_16BE,
                bom: 0,
            }
        }
        _ => {}
    }
    let check = looks_like_xml(text);
    match declared_encoding(text) {
        // Labels of the "replacement" encoding (ISO-2022-KR, …) name no decodable text.
        Some((label, span)) => match Charset::for_label_no_replacement(label.as_bytes()) {
            None => Plan::Refuse(
                Diagnostic::new(
                    &XML_ENCODING_UNSUPPORTED,
                    span,
                    format!(
                        "the XML declaration names the encoding `{label}`, which x3dcheck \
                         cannot decode"
                    ),
                )
                .help(
                    "x3dcheck reads UTF-8, UTF-16 and the encodings of the WHATWG Encoding \
                     Standard; save the file as UTF-8 and declare encoding=\"UTF-8\"",
                ),
            ),
            // A UTF-16 name over bytes read as ASCII: the bytes are not UTF-16, so they are
            // read as UTF-8 (the WHATWG rule for such a label found in ASCII-compatible text).
            Some(charset) if charset == UTF_8 || charset == UTF_16LE || charset == UTF_16BE => {
                Plan::Utf8 { bom: 0, check }
            }
            Some(charset) => Plan::Decode { charset, bom: 0 },
        },
        None => Plan::Utf8 { bom: 0, check },
    }
}

/// Whether the first byte past white space is `<`: what encoding detection reads as XML.
fn looks_like_xml(text: &[u8]) -> bool {
    text.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'<')
}

/// The label of the `encoding` of an XML declaration at the very start of `text`, and its
/// place.
fn declared_encoding(text: &[u8]) -> Option<(&str, Span)> {
    let head = &text[..text.len().min(1024)];
    if !(head.starts_with(b"<?xml") && head.get(5).is_some_and(u8::is_ascii_whitespace)) {
        return None;
    }
    let declaration = &head[..memchr::memmem::find(head, b"?>")?];
    let name_end = memchr::memmem::find(declaration, b"encoding")? + b"encoding".len();
    let skip_space = |mut at: usize| {
        while declaration.get(at).is_some_and(u8::is_ascii_whitespace) {
            at += 1;
        }
        at
    };
    let equals = skip_space(name_end);
    if declaration.get(equals) != Some(&b'=') {
        return None;
    }
    let open = skip_space(equals + 1);
    let quote = *declaration
        .get(open)
        .filter(|q| matches!(q, b'"' | b'\''))?;
    let start = open + 1;
    let end = start + memchr::memchr(quote, &declaration[start..])?;
    let label = std::str::from_utf8(&declaration[start..end]).ok()?;
    Some((label, Span::new(start, end)))
}

/// Decodes `bytes` from `charset` without replacing anything: Err holds what was decoded
/// before the first malformed sequence, and that sequence.
fn decode_strict(charset: &'static Charset, bytes: &[u8]) -> Result<String, (String, Vec<u8>)> {
    let mut decoder = charset.new_decoder_without_bom_handling();
    let mut text = String::with_capacity(bytes.len());
    let mut read = 0;
    loop {
        let (result, n) =
            decoder.decode_to_string_without_replacement(&bytes[read..], &mut text, true);
        read += n;
        match result {
            DecoderResult::InputEmpty => return Ok(text),
            DecoderResult::OutputFull => {
                let rest = bytes.len() - read;
                let more = decoder.max_utf8_buffer_length_without_replacement(rest);
                text.reserve(more.unwrap_or(rest.saturating_mul(3)).max(4));
            }
            DecoderResult::Malformed(bad, after) => {
                let end = read - usize::from(after);
                let bad = bytes[end - usize::from(bad)..end].to_vec();
                return Err((text, bad));
            }
        }
    }
}

fn drop_prefix(text: Cow<'_, [u8]>, n: usize) -> Cow<'_, [u8]> {
    match text {
        Cow::Borrowed(text) => Cow::Borrowed(&text[n..]),
        Cow::Owned(mut text) => {
            text.drain(..n);
            Cow::Owned(text)
        }
    }
}

fn not_utf8(bad: &[u8], at: usize) -> Diagnostic {
    Diagnostic::new(
        &XML_MALFORMED,
        Span::new(at, at),
        format!(
            "not well-formed XML: {} is not UTF-8, and the XML declaration names no other \
             encoding",
            hex(bad)
        ),
    )
    .help(
        "declare the encoding the file is saved in, e.g. <?xml version=\"1.0\" \
         encoding=\"ISO-8859-1\"?>, or convert it to UTF-8 (iconv -f ISO-8859-1 -t UTF-8)",
    )
}

fn hex(bytes: &[u8]) -> String {
    let bytes: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
    format!("the byte sequence {}", bytes.join(" "))
}
