//! Tells the encoding from the first bytes: XML, JSON, or something x3dcheck does not read
//! (ClassicVRML, VRML97, gzip, UTF-16, binary), with a diagnostic that says which.

use super::rules::ENCODING_UNSUPPORTED;
use crate::diagnostic::Diagnostic;
use crate::model::Span;

pub enum Detected {
    Xml,
    Json,
    Unsupported(Diagnostic),
}

pub fn detect(source: &[u8]) -> Detected {
    let unsupported = |what: &str, help: &str| {
        Detected::Unsupported(
            Diagnostic::new(
                &ENCODING_UNSUPPORTED,
                Span::new(0, 0),
                format!("this is {what}, not X3D XML or X3D JSON"),
            )
            .help(help.to_string()),
        )
    };
    if source.starts_with(&[0x1f, 0x8b]) {
        return unsupported(
            "gzip-compressed data",
            "decompress it first (gunzip -c file.x3dz > file.x3d)",
        );
    }
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
    if text.starts_with(b"#X3D") {
        return unsupported(
            "X3D ClassicVRML encoding",
            "convert it to XML, e.g. with Castle's tovrmlx3d or X_ITE's x3d-tidy",
        );
    }
    if text.starts_with(b"#VRML") {
        return unsupported(
            "VRML",
            "convert it to X3D XML, e.g. with Castle's tovrmlx3d or X_ITE's x3d-tidy",
        );
    }
    match text.first() {
        Some(b'<') => Detected::Xml,
        Some(b'{') | Some(b'[') => Detected::Json,
        None => unsupported(
            "an empty file",
            "an X3D document starts with `<X3D` (XML) or `{ \"X3D\"` (JSON)",
        ),
        Some(_) if looks_binary(text) => unsupported(
            "binary data",
            "x3dcheck reads the XML (.x3d) and JSON (.x3dj, .json) encodings",
        ),
        Some(_) => unsupported(
            "text in no X3D encoding",
            "an X3D document starts with `<X3D` (XML) or `{ \"X3D\"` (JSON)",
        ),
    }
}

/// NUL bytes or invalid UTF-8 near the start (a multi-byte character cut by the window is fine).
fn looks_binary(text: &[u8]) -> bool {
    let window = &text[..text.len().min(512)];
    window.contains(&0) || std::str::from_utf8(window).is_err_and(|e| e.error_len().is_some())
}
