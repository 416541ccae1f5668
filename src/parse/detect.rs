//! Tells the encoding from the first bytes of the decoded text: XML, JSON,
//! ClassicVRML/VRML97, or something x3dcheck does not read (VRML 1.0, UTF-32, binary;
//! gzip and UTF-16 when not decoded first), with a diagnostic that says which.

use super::rules::ENCODING_UNSUPPORTED;
use crate::diagnostic::Diagnostic;
use crate::model::Span;

pub enum Detected {
    Xml,
    Json,
    /// ClassicVRML (`#X3D`) or VRML97 (`#VRML V2.0`).
    Classic,
    /// An HTML page (`xhtml`: one that starts with an XML declaration, read as XML).
    Html {
        xhtml: bool,
    },
    Unsupported(Diagnostic),
}

pub fn detect(source: &[u8]) -> Detected {
    let unsupported = |what: &str, help: &str| {
        Detected::Unsupported(
            Diagnostic::new(
                &ENCODING_UNSUPPORTED,
                Span::new(0, 0),
                format!("this is {what}, not an X3D or VRML97 encoding"),
            )
            .help(help.to_string()),
        )
    };
    // A gzip stream inside a gzip stream (`decode` inflates one), or undecoded input.
    if source.starts_with(&[0x1f, 0x8b]) {
        return unsupported(
            "gzip-compressed data",
            "decompress it first (gunzip -c file.x3dz > file.x3d)",
        );
    }
    if source.starts_with(b"\xFF\xFE\0\0") || source.starts_with(b"\0\0\xFE\xFF") {
        return unsupported(
            "UTF-32 text",
            "x3dcheck reads UTF-8 and UTF-16; convert it (iconv -f UTF-32 -t UTF-8)",
        );
    }
    // What `decode` did not decode (callers of the readers that skip it).
    if source.starts_with(&[0xff, 0xfe]) || source.starts_with(&[0xfe, 0xff]) {
        return unsupported(
            "UTF-16 text",
            "x3dcheck reads UTF-8; convert it (iconv -f UTF-16 -t UTF-8)",
        );
    }
    let text = source.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(source);
    let start = text
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(text.len());
    let text = &text[start..];
    if text.starts_with(b"#VRML V1.0") {
        return Detected::Unsupported(
            Diagnostic::new(
                &ENCODING_UNSUPPORTED,
                Span::new(0, 0),
                "this is VRML 1.0, a different language from VRML97 and X3D (nodes such as Separator, no ROUTEs)".to_string(),
            )
            .help("convert it to VRML97 or X3D first, e.g. with Castle Game Engine's tovrmlx3d"),
        );
    }
    if text.starts_with(b"#X3D") || text.starts_with(b"#VRML") {
        return Detected::Classic;
    }
    if let Some(xhtml) = html_page(text) {
        return Detected::Html { xhtml };
    }
    // A server's page template (Jinja, Django: `{% extends "base.html" %}`) is HTML to
    // be: `{%`, `{{` and `{#` start no JSON text.
    if [&b"{%"[..], b"{{", b"{#"]
        .iter()
        .any(|p| text.starts_with(p))
        && text.contains(&b'<')
    {
        return Detected::Html { xhtml: false };
    }
    match text.first() {
        Some(b'<') => Detected::Xml,
        Some(b'{') | Some(b'[') => Detected::Json,
        None => unsupported(
            "an empty file",
            "an X3D document starts with `<X3D` (XML), `{ \"X3D\"` (JSON) or `#X3D V4.0 utf8` (ClassicVRML), a VRML97 one with `#VRML V2.0 utf8`",
        ),
        Some(_) if looks_binary(text) => unsupported(
            "binary data",
            "x3dcheck reads the XML (.x3d), JSON (.x3dj, .json), ClassicVRML (.x3dv) and VRML97 (.wrl) encodings",
        ),
        Some(_) => unsupported(
            "text in no X3D encoding",
            "an X3D document starts with `<X3D` (XML), `{ \"X3D\"` (JSON) or `#X3D V4.0 utf8` (ClassicVRML), a VRML97 one with `#VRML V2.0 utf8`",
        ),
    }
}

/// Whether `text` is an HTML page: after an XML declaration and comments, a DOCTYPE
/// that does not name X3D, an `html`, `head` or `body` element, or an X3DOM fragment's lower-case `<x3d>`
/// (an X3D document's root is `X3D`). Some(true) when it has an XML declaration: an XHTML
/// page, which a browser reads as XML when it is served as such (`.xhtml`).
fn html_page(text: &[u8]) -> Option<bool> {
    let mut rest = text;
    let mut declared = false;
    loop {
        let start = rest.iter().position(|b| !b.is_ascii_whitespace())?;
        rest = &rest[start..];
        let close: &[u8] = if rest.starts_with(b"<?xml") {
            declared = true;
            b"?>"
        } else if rest.starts_with(b"<!--") {
            b"-->"
        } else {
            break;
        };
        let end = memchr::memmem::find(rest, close)?;
        rest = &rest[end + close.len()..];
    }
    let opens = |prefix: &[u8]| {
        rest.len() > prefix.len()
            && rest[..prefix.len()].eq_ignore_ascii_case(prefix)
            && (rest[prefix.len()].is_ascii_whitespace() || rest[prefix.len()] == b'>')
    };
    // A DOCTYPE naming anything but X3D (`<!DOCTYPE>` alone among them, which browsers take).
    let doctype = rest.len() >= 9 && rest[..9].eq_ignore_ascii_case(b"<!doctype") && {
        let name = rest[9..].trim_ascii_start();
        !(name.len() >= 3 && name[..3].eq_ignore_ascii_case(b"x3d"))
    };
    let html = doctype || [&b"<html"[..], b"<head", b"<body"].into_iter().any(opens);
    let fragment = rest.starts_with(b"<x3d") && opens(b"<x3d");
    (html || fragment).then_some(declared)
}

/// NUL bytes or invalid UTF-8 near the start (a multi-byte character cut by the window is fine).
fn looks_binary(text: &[u8]) -> bool {
    let window = &text[..text.len().min(512)];
    window.contains(&0) || std::str::from_utf8(window).is_err_and(|e| e.error_len().is_some())
}
