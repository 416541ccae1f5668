//! `file:` URIs ↔ paths. Hand-written (a few lines) rather than pulling in the `url` crate
//! and its IDNA tables for the one scheme a language server sees.

use std::path::PathBuf;

use lsp_types::Uri;

/// The local path a `file:` URI names; None for other schemes (`untitled:`).
pub fn to_path(uri: &Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    // Skip the authority (empty or `localhost` on local files).
    let path = &rest[rest.find('/')?..];
    let path = path.split(['?', '#']).next().unwrap_or(path);
    let decoded = String::from_utf8(percent_decoded(path)).ok()?;
    // `/C:/scenes/a.x3d` is a Windows drive path.
    let bytes = decoded.as_bytes();
    if cfg!(windows) && bytes.len() > 2 && bytes[2] == b':' {
        return Some(PathBuf::from(&decoded[1..]));
    }
    Some(PathBuf::from(decoded))
}

/// The `file:` URI of an absolute path.
pub fn from_path(path: &std::path::Path) -> Option<Uri> {
    crate::report::sarif::uri(&path.display().to_string())
        .parse()
        .ok()
}

fn percent_decoded(text: &str) -> Vec<u8> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = bytes
            .get(i + 1..i + 3)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (bytes[i], hex) {
            (b'%', Some(byte)) => {
                out.push(byte);
                i += 3;
            }
            (byte, _) => {
                out.push(byte);
                i += 1;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_uris_decode_to_paths_and_back() {
        let uri: Uri = "file:///work/a%20b/%C3%BC.x3d".parse().unwrap();
        assert_eq!(to_path(&uri), Some(PathBuf::from("/work/a b/ü.x3d")));
        let back = from_path(&PathBuf::from("/work/a b/ü.x3d")).unwrap();
        assert_eq!(back.as_str(), "file:///work/a%20b/%C3%BC.x3d");
        let untitled: Uri = "untitled:Untitled-1".parse().unwrap();
        assert_eq!(to_path(&untitled), None);
    }
}
