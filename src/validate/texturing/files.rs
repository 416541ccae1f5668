//! The files a scene refers to, for the deep level: which fields hold URLs, how an entry
//! resolves to a local file, and what an image file decodes to.
//!
//! Decisions, documented in the rules that use them:
//! - Network URLs (`http:`, `https:`, `ftp:`, `urn:` and any other scheme) are never
//!   fetched. Inline content (`data:`, and `ecmascript:`/`javascript:`/`vrmlscript:` code
//!   in Script and shader urls, Castle Game Engine's `castlescript:`/`kambiscript:` and
//!   `compiled:`) has nothing to resolve.
//! - `file:` URLs are local paths (`file:///abs`, `file://localhost/abs`, `file:rel`);
//!   `%XX` escapes are decoded (the written form is tried too); a fragment (`#Viewpoint`)
//!   or query is dropped; a backslash is tried as `/` as well (Windows exporters).
//! - Nothing is read outside the allowed tree: `CheckConfig::root` when set, else the
//!   document's directory. `..` is resolved lexically before the file system is touched,
//!   and symlinks by canonicalizing after; a path leaving the tree is not read.
//! - A node copied from an external prototype's body (another file) resolves its urls
//!   against that file's directory, as browsers do, and falls back to the document's,
//!   which VRML97 14772-1 4.5.3 names ("The file in which the prototype is instantiated,
//!   if the statement is part of a prototype definition"): see [`Resolver::for_node`].

use std::collections::HashMap;
use std::ffi::OsString;
use std::path::{Component, Path, PathBuf};

use crate::limits::{image_limits, MAX_IMAGE_BYTES, MAX_IMAGE_SIDE};
use crate::model::{Document, FieldEntry, NodeId};

/// What a url field's entries hold.
#[derive(Copy, Clone, PartialEq, Eq)]
pub enum Content {
    /// A 2D image: ImageTexture, Background's six urls.
    Image,
    /// Anything else: movies, sounds, scenes, scripts, shaders, 3D and cube-map textures,
    /// fonts. Only resolved.
    Other,
}

/// A field holding URLs that a browser loads.
pub struct UrlField<'a> {
    pub node: NodeId,
    pub entry: &'a FieldEntry,
    pub content: Content,
}

/// Background and TextureBackground image urls (not X3DUrlObject, but loaded the same way).
const BACKGROUND_URLS: &[&str] = &[
    "backUrl",
    "bottomUrl",
    "frontUrl",
    "leftUrl",
    "rightUrl",
    "topUrl",
];

/// Every url field the document sets, in document order. Anchor (a hyperlink followed on
/// demand, often to web pages) and GeoMetadata (a reference to documentation) are not
/// loaded with the scene and are left out.
pub fn url_fields(doc: &Document) -> Vec<UrlField<'_>> {
    let mut fields = Vec::new();
    for (id, node) in doc.iter() {
        let name = node.type_name();
        for entry in &node.fields {
            let field = entry.name();
            if node.connects.iter().any(|c| c.node_field.text == field) {
                continue;
            }
            let content = if field == "url"
                && node.is_a("X3DUrlObject")
                && !matches!(name, "Anchor" | "GeoMetadata")
            {
                if name == "ImageTexture" {
                    Content::Image
                } else {
                    Content::Other
                }
            } else if BACKGROUND_URLS.contains(&field) && node.is_a("X3DBackgroundNode") {
                Content::Image
            } else {
                continue;
            };
            if entry.value.as_strings().is_some() {
                fields.push(UrlField {
                    node: id,
                    entry,
                    content,
                });
            }
        }
    }
    fields
}

/// What one url entry turned out to be.
#[derive(Debug, PartialEq)]
pub enum Resolution {
    /// A readable regular file inside the allowed tree (canonical path).
    Local(PathBuf),
    /// No such file. `case_differs` names a file that matches when case is ignored.
    Missing {
        path: PathBuf,
        case_differs: Option<String>,
    },
    /// A network URL (or another scheme): not fetched.
    Network(String),
    /// Content written into the url itself (data:, script code) or a fragment of this
    /// document (`#Viewpoint`): nothing to resolve.
    Inline,
    /// Resolves outside the tree x3dcheck may read: not read.
    Outside(PathBuf),
    /// A relative URL of a document read from standard input.
    NoBase,
}

/// "network URL "…" is not fetched" for an address of a network scheme; for any other
/// scheme (`urn:`, `mailto:`, …) it names the scheme instead of calling it a network URL.
pub fn not_fetched(url: &str) -> String {
    let scheme = url
        .split_once(':')
        .map(|(scheme, _)| scheme.to_ascii_lowercase())
        .unwrap_or_default();
    if matches!(
        scheme.as_str(),
        "http" | "https" | "ftp" | "ftps" | "ws" | "wss" | "file"
    ) || url.starts_with("//")
    {
        format!("network URL \"{url}\" is not fetched")
    } else {
        format!("\"{url}\" is a `{scheme}:` address, which x3dcheck does not resolve")
    }
}

/// Resolves url entries against one document's directory within the allowed tree.
pub struct Resolver {
    base: Option<PathBuf>,
    /// The allowed tree, lexically absolute and canonical (symlinks resolved).
    root: Option<(PathBuf, PathBuf)>,
}

impl Resolver {
    pub fn new(base: Option<&Path>, root: Option<&Path>) -> Resolver {
        let base = base
            .and_then(|b| std::path::absolute(b).ok())
            .map(|b| normalize(&b));
        let root = root
            .and_then(|r| std::path::absolute(r).ok())
            .map(|r| normalize(&r))
            .or_else(|| base.clone())
            .and_then(|lexical| {
                let canonical = lexical.canonicalize().ok()?;
                Some((lexical, canonical))
            });
        Resolver { base, root }
    }

    /// The resolver of the external prototype file `node` is copied from (its body's
    /// relative urls are relative to that file, as browsers read them), within the same
    /// tree; None for a node this document writes or passes to an instance.
    pub fn for_node(&self, doc: &Document, node: NodeId) -> Option<Resolver> {
        let dir = doc.library_file_of(node)?.parent()?;
        let base = std::path::absolute(dir).ok().map(|b| normalize(&b));
        Some(Resolver {
            base,
            root: self.root.clone(),
        })
    }

    /// How `url`, an entry of a url field of `node`, resolves: against the external
    /// prototype file `node` is copied from first, then against the document's directory.
    pub fn resolve_node(&self, doc: &Document, node: NodeId, url: &str) -> Resolution {
        let Some(library) = self.for_node(doc, node) else {
            return self.resolve(url);
        };
        match library.resolve(url) {
            Resolution::Local(path) => Resolution::Local(path),
            first => match self.resolve(url) {
                Resolution::Local(path) => Resolution::Local(path),
                _ => first,
            },
        }
    }

    pub fn resolve(&self, url: &str) -> Resolution {
        let url = url.trim();
        let Some(path) = local_path(url) else {
            let lower = url.to_ascii_lowercase();
            return if [
                "data:",
                "ecmascript:",
                "javascript:",
                "vrmlscript:",
                "castlescript:",
                "kambiscript:",
                "compiled:",
            ]
            .iter()
            .any(|s| lower.starts_with(s))
            {
                Resolution::Inline
            } else {
                Resolution::Network(url.to_string())
            };
        };
        if path.is_empty() {
            return Resolution::Inline;
        }
        let mut candidates = vec![percent_decode(&path)];
        if path.contains('%') {
            candidates.push(OsString::from(&path));
        }
        if path.contains('\\') {
            candidates.push(percent_decode(&path.replace('\\', "/")));
        }
        let mut first = None;
        for candidate in candidates {
            let found = self.resolve_path(Path::new(&candidate));
            if matches!(found, Resolution::Local(_)) {
                return found;
            }
            first.get_or_insert(found);
        }
        first.unwrap_or(Resolution::NoBase)
    }

    fn resolve_path(&self, path: &Path) -> Resolution {
        let joined = if path.is_absolute() {
            normalize(path)
        } else {
            match &self.base {
                Some(base) => normalize(&base.join(path)),
                None => return Resolution::NoBase,
            }
        };
        let Some((lexical_root, canonical_root)) = &self.root else {
            return Resolution::Outside(joined);
        };
        // A library file's directory (the base of its body's urls) is canonical.
        if !joined.starts_with(lexical_root) && !joined.starts_with(canonical_root) {
            return Resolution::Outside(joined);
        }
        let Ok(canonical) = joined.canonicalize() else {
            let case_differs = case_insensitive_match(&joined, canonical_root);
            return Resolution::Missing {
                path: joined,
                case_differs,
            };
        };
        if !canonical.starts_with(canonical_root) {
            return Resolution::Outside(joined);
        }
        let readable = canonical.is_file() && std::fs::File::open(&canonical).is_ok();
        if readable {
            Resolution::Local(canonical)
        } else {
            Resolution::Missing {
                path: joined,
                case_differs: None,
            }
        }
    }
}

/// The path part of a url, or None for a URL with a non-file scheme. Fragment and query
/// are dropped.
fn local_path(url: &str) -> Option<String> {
    let end = url.find(['#', '?']).unwrap_or(url.len());
    let url = &url[..end];
    match scheme(url) {
        None => Some(url.to_string()),
        Some(scheme) if scheme.eq_ignore_ascii_case("file") => {
            let rest = &url[scheme.len() + 1..];
            let Some(authority_and_path) = rest.strip_prefix("//") else {
                return Some(rest.to_string());
            };
            let slash = authority_and_path
                .find('/')
                .unwrap_or(authority_and_path.len());
            let host = &authority_and_path[..slash];
            (host.is_empty() || host.eq_ignore_ascii_case("localhost"))
                .then(|| authority_and_path[slash..].to_string())
        }
        Some(_) => None,
    }
}

/// A URI scheme (RFC 3986 3.1); one letter is a Windows drive (`C:`), not a scheme.
fn scheme(url: &str) -> Option<&str> {
    let colon = url.find(':')?;
    let scheme = &url[..colon];
    let mut chars = scheme.chars();
    let valid = chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '-' | '.'));
    (valid && scheme.len() > 1).then_some(scheme)
}

/// `%XX` escapes decoded (a path's); malformed escapes are kept as written.
fn percent_decode(text: &str) -> OsString {
    bytes_to_os(percent_decoded(text))
}

/// `%XX` escapes decoded to bytes; a `%` not followed by two hex digits stays as written.
pub(crate) fn percent_decoded(text: &str) -> Vec<u8> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = |b: u8| (b as char).to_digit(16);
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            if let (Some(h), Some(l)) = (hex(bytes[i + 1]), hex(bytes[i + 2])) {
                out.push((h * 16 + l) as u8);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    out
}

#[cfg(unix)]
fn bytes_to_os(bytes: Vec<u8>) -> OsString {
    use std::os::unix::ffi::OsStringExt;
    OsString::from_vec(bytes)
}

#[cfg(not(unix))]
fn bytes_to_os(bytes: Vec<u8>) -> OsString {
    OsString::from(String::from_utf8_lossy(&bytes).into_owned())
}

/// `.` and `..` resolved without touching the file system.
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// A file in the same (existing, allowed) directory whose name matches ignoring case.
fn case_insensitive_match(path: &Path, canonical_root: &Path) -> Option<String> {
    let dir = path.parent()?.canonicalize().ok()?;
    if !dir.starts_with(canonical_root) {
        return None;
    }
    let wanted = path.file_name()?.to_str()?;
    std::fs::read_dir(&dir)
        .ok()?
        .filter_map(Result::ok)
        .filter_map(|e| e.file_name().into_string().ok())
        .find(|name| name.eq_ignore_ascii_case(wanted) && name != wanted)
}

/// What an image file is.
#[derive(Clone, Debug, PartialEq)]
pub enum Probe {
    /// Decodes; the format's name.
    Decodes(image::ImageFormat),
    /// Does not decode, and why.
    Broken(String),
    /// Larger than the limits of [`crate::limits`] (its header says so, or decoding would
    /// allocate more): not decoded, and why.
    TooLarge(String),
    /// A format x3dcheck does not decode, known by its extension (DDS, KTX, …).
    Undecoded(&'static str),
}

/// Image formats recognised by extension only: browsers may support them, x3dcheck does
/// not decode them.
const UNDECODED_FORMATS: &[(&str, &str)] = &[
    ("dds", "DDS"),
    ("ktx", "KTX"),
    ("ktx2", "KTX2"),
    ("tga", "TGA"),
    ("exr", "OpenEXR"),
    ("hdr", "Radiance HDR"),
    ("svg", "SVG"),
    ("jp2", "JPEG 2000"),
    ("j2k", "JPEG 2000"),
    ("avif", "AVIF"),
];

/// Probes each image file once per document, however many nodes name it.
#[derive(Default)]
pub struct Prober {
    /// Full decodes, by canonical path.
    decoded: HashMap<PathBuf, Probe>,
}

impl Prober {
    /// The format the file's first bytes announce, without decoding it.
    pub fn format(&self, path: &Path) -> Option<image::ImageFormat> {
        if let Some(Probe::Decodes(format)) = self.decoded.get(path) {
            return Some(*format);
        }
        image::ImageReader::open(path)
            .ok()?
            .with_guessed_format()
            .ok()?
            .format()
    }

    /// Decodes the whole image (needed to tell that it is readable), within the limits.
    pub fn decode(&mut self, path: &Path) -> Probe {
        if let Some(probe) = self.decoded.get(path) {
            return probe.clone();
        }
        let probe = decode(path);
        self.decoded.insert(path.to_path_buf(), probe.clone());
        probe
    }
}

/// The channels (1–4) an image file's header announces, without decoding its pixels;
/// None when it cannot be read as an image.
pub fn file_channels(path: &Path) -> Option<u8> {
    let reader = image::ImageReader::open(path)
        .ok()?
        .with_guessed_format()
        .ok()?;
    Some(image::ImageDecoder::color_type(&reader.into_decoder().ok()?).channel_count())
}

/// [`file_channels`] of the image a `data:` URL carries.
pub fn bytes_channels(bytes: &[u8]) -> Option<u8> {
    let reader = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .ok()?;
    Some(image::ImageDecoder::color_type(&reader.into_decoder().ok()?).channel_count())
}

/// The width and height an image file's header announces, without decoding its pixels;
/// None when it cannot be read as an image.
pub fn file_dimensions(path: &Path) -> Option<(u32, u32)> {
    image::ImageReader::open(path)
        .ok()?
        .with_guessed_format()
        .ok()?
        .into_dimensions()
        .ok()
}

/// [`file_dimensions`] of the image a `data:` URL carries.
pub fn bytes_dimensions(bytes: &[u8]) -> Option<(u32, u32)> {
    image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .ok()?
        .into_dimensions()
        .ok()
}

/// What the image a `data:` URL carries is (decoded within the same limits as files).
pub fn probe_bytes(bytes: &[u8]) -> Probe {
    let reader = image::ImageReader::new(std::io::Cursor::new(bytes));
    let reader = match reader.with_guessed_format() {
        Ok(reader) => reader,
        Err(e) => return Probe::Broken(format!("cannot be read: {e}")),
    };
    let Some(format) = reader.format() else {
        return Probe::Broken("is not in an image format x3dcheck recognises".into());
    };
    probe_format(reader, format, || {
        format!(
            "is too large to decode: more than {MAX_IMAGE_SIDE} pixels on a side or {} GiB decoded",
            MAX_IMAGE_BYTES >> 30
        )
    })
}

fn decode(path: &Path) -> Probe {
    let reader = match image::ImageReader::open(path).and_then(|r| r.with_guessed_format()) {
        Ok(reader) => reader,
        Err(e) => return Probe::Broken(format!("cannot be read: {e}")),
    };
    let Some(format) = reader.format() else {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        if let Some((_, name)) = UNDECODED_FORMATS
            .iter()
            .find(|(ext, _)| Some(*ext) == extension.as_deref())
        {
            return Probe::Undecoded(name);
        }
        return Probe::Broken("is not in an image format x3dcheck recognises".into());
    };
    probe_format(reader, format, || too_large(path))
}

/// Decodes an image of a known format within [`image_limits`].
fn probe_format<R: std::io::BufRead + std::io::Seek>(
    mut reader: image::ImageReader<R>,
    format: image::ImageFormat,
    too_large: impl Fn() -> String,
) -> Probe {
    if !format.reading_enabled() {
        return Probe::Undecoded(format_name(format));
    }
    reader.limits(image_limits());
    match reader.decode() {
        Ok(_) => Probe::Decodes(format),
        Err(image::ImageError::Limits(_)) => Probe::TooLarge(too_large()),
        Err(e) => Probe::Broken(format!("does not decode as {}: {e}", format_name(format))),
    }
}

/// Why an image went past [`image_limits`], with the size its header claims when known.
pub fn too_large(path: &Path) -> String {
    let claimed = image::ImageReader::open(path)
        .and_then(|r| r.with_guessed_format())
        .ok()
        .and_then(|r| r.into_dimensions().ok());
    let size = claimed.map_or(String::new(), |(w, h)| format!(" ({w}×{h})"));
    format!(
        "is too large to decode{size}: more than {MAX_IMAGE_SIDE} pixels on a side or {} GiB decoded",
        MAX_IMAGE_BYTES >> 30
    )
}

pub fn format_name(format: image::ImageFormat) -> &'static str {
    format
        .extensions_str()
        .first()
        .map_or("an image", |e| match *e {
            "png" => "PNG",
            "jpg" | "jpeg" => "JPEG",
            "gif" => "GIF",
            "bmp" => "BMP",
            "tif" | "tiff" => "TIFF",
            "webp" => "WebP",
            "hdr" => "Radiance HDR",
            other => other,
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schemes_and_local_paths() {
        assert_eq!(local_path("a b.png#frag"), Some("a b.png".into()));
        assert_eq!(local_path("FILE:///tmp/x.png"), Some("/tmp/x.png".into()));
        assert_eq!(
            local_path("file://localhost/tmp/x.png"),
            Some("/tmp/x.png".into())
        );
        assert_eq!(local_path("file:rel/x.png"), Some("rel/x.png".into()));
        assert_eq!(local_path("file://server/x.png"), None);
        assert_eq!(local_path("HTTPS://example.org/x.png"), None);
        assert_eq!(
            local_path("C:/textures/x.png"),
            Some("C:/textures/x.png".into())
        );
        assert_eq!(local_path("#Viewpoint"), Some(String::new()));
    }

    #[test]
    fn percent_escapes_decode_and_malformed_ones_stay() {
        assert_eq!(percent_decode("a%20b.png"), OsString::from("a b.png"));
        assert_eq!(percent_decode("100%.png"), OsString::from("100%.png"));
        assert_eq!(percent_decode("x%2"), OsString::from("x%2"));
        assert_eq!(percent_decode("%41%42"), OsString::from("AB"));
    }

    #[test]
    fn parent_steps_cannot_leave_the_tree() {
        let dir = std::env::temp_dir().join(format!("x3dcheck-files-{}", std::process::id()));
        let scenes = dir.join("scenes");
        std::fs::create_dir_all(&scenes).unwrap();
        std::fs::write(dir.join("secret.png"), b"x").unwrap();
        std::fs::write(scenes.join("Tex.png"), b"x").unwrap();
        let confined = Resolver::new(Some(&scenes), None);
        assert!(matches!(
            confined.resolve("../secret.png"),
            Resolution::Outside(_)
        ));
        assert!(matches!(
            confined.resolve("/etc/passwd"),
            Resolution::Outside(_)
        ));
        assert!(matches!(confined.resolve("Tex.png"), Resolution::Local(_)));
        match confined.resolve("tex.png") {
            Resolution::Missing { case_differs, .. } => {
                assert_eq!(case_differs.as_deref(), Some("Tex.png"))
            }
            other => panic!("{other:?}"),
        }
        let wider = Resolver::new(Some(&scenes), Some(&dir));
        assert!(matches!(
            wider.resolve("../secret.png"),
            Resolution::Local(_)
        ));
        assert!(matches!(
            wider.resolve("../../secret.png"),
            Resolution::Outside(_)
        ));
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(dir.join("secret.png"), scenes.join("link.png")).unwrap();
            assert!(matches!(
                confined.resolve("link.png"),
                Resolution::Outside(_)
            ));
        }
        assert_eq!(
            Resolver::new(None, None).resolve("a.png"),
            Resolution::NoBase
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
