//! MOVIE_FORMAT_UNSUPPORTED: a MovieTexture file that is not MPEG-1.

use std::io::Read;
use std::path::Path;

use super::files::{url_fields, Resolution, Resolver};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

/// How much of a file is read to tell its format: enough for an MPEG-2 sequence
/// extension to follow the sequence header.
const SNIFF_BYTES: u64 = 4096;

crate::declare_rule! {
    /// ## What it does
    /// Reports a MovieTexture url whose local file is not an MPEG-1 stream. The format is
    /// read from the file's first bytes, not its name:
    /// - MPEG-1 Systems: a pack start code `00 00 01 BA` whose next byte begins with the
    ///   bits `0010` (an MPEG-2 program stream begins them with `01`);
    /// - MPEG-1 Video: a sequence header `00 00 01 B3` with no sequence extension
    ///   `00 00 01 B5` in the first 4 KiB (MPEG-2 video puts one right after the header).
    ///
    /// Anything else is reported with what it looks like (MP4/QuickTime, AVI, WebM or
    /// Matroska, Ogg, MPEG-2, an image) or as unknown. Which files are read: see
    /// URL_UNRESOLVED; a file that cannot be read is not judged.
    ///
    /// ## Why it matters
    /// 18.4.2: "The url field that defines the movie data shall support MPEG1-Systems
    /// (audio and video) or MPEG1-Video (video-only) movie file formats". Every other
    /// format plays in some browsers only.
    ///
    /// ## Example
    /// ```xml
    /// <MovieTexture url='"clip.mp4"'/>
    /// ```
    ///
    /// ## Use instead
    /// An MPEG-1 file first in the url list; other formats may follow as alternatives.
    ///
    /// ## Clause
    /// 19775-1 18.4.2 MovieTexture (ISO/IEC 11172-1 and -2).
    pub static MOVIE_FORMAT_UNSUPPORTED = {
        severity: Warning,
        level: Deep,
        clause: "18.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
    let mut found = Vec::new();
    for field in url_fields(ctx.doc) {
        if ctx.doc.node(field.node).type_name() != "MovieTexture" {
            continue;
        }
        for url in field.entry.value.as_strings().unwrap_or_default() {
            let Resolution::Local(path) = resolver.resolve_node(ctx.doc, field.node, url) else {
                continue;
            };
            let Some(head) = head_of(&path) else {
                continue;
            };
            let Some(what) = not_mpeg1(&head) else {
                continue;
            };
            found.push(
                Diagnostic::new(
                    &MOVIE_FORMAT_UNSUPPORTED,
                    field.entry.span,
                    format!(
                        "MovieTexture.url: \"{url}\" is {what}; browsers must play only MPEG-1 Systems and MPEG-1 Video"
                    ),
                )
                .node(field.node)
                .value(url.clone())
                .help("give an MPEG-1 file first in the url list"),
            );
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// The first [`SNIFF_BYTES`] of a file; None when it cannot be read.
fn head_of(path: &Path) -> Option<Vec<u8>> {
    let mut head = Vec::new();
    std::fs::File::open(path)
        .ok()?
        .take(SNIFF_BYTES)
        .read_to_end(&mut head)
        .ok()?;
    Some(head)
}

/// None for an MPEG-1 Systems or Video stream; else what the bytes look like.
fn not_mpeg1(head: &[u8]) -> Option<&'static str> {
    const PACK: &[u8] = &[0, 0, 1, 0xBA];
    const SEQUENCE: &[u8] = &[0, 0, 1, 0xB3];
    const EXTENSION: &[u8] = &[0, 0, 1, 0xB5];
    if head.starts_with(PACK) {
        return match head.get(4) {
            Some(b) if b >> 4 == 0b0010 => None,
            Some(b) if b >> 6 == 0b01 => Some("an MPEG-2 program stream"),
            _ => Some("an MPEG stream of unknown version"),
        };
    }
    if head.starts_with(SEQUENCE) {
        let extended = head.windows(4).any(|w| w == EXTENSION);
        return extended.then_some("MPEG-2 video");
    }
    let at = |offset: usize, magic: &[u8]| head.get(offset..offset + magic.len()) == Some(magic);
    Some(if at(4, b"ftyp") || at(4, b"moov") || at(4, b"mdat") {
        "an MP4 or QuickTime file"
    } else if at(0, b"RIFF") && at(8, b"AVI ") {
        "an AVI file"
    } else if at(0, &[0x1A, 0x45, 0xDF, 0xA3]) {
        "a WebM or Matroska file"
    } else if at(0, b"OggS") {
        "an Ogg file"
    } else if at(0, b"GIF8") || at(0, b"\x89PNG") || at(0, &[0xFF, 0xD8, 0xFF]) {
        "an image, not a movie"
    } else if head.is_empty() {
        "empty"
    } else {
        "not an MPEG-1 stream (format unknown)"
    })
}

#[cfg(test)]
mod tests {
    use super::not_mpeg1;

    #[test]
    fn tells_mpeg1_from_its_successors() {
        assert_eq!(not_mpeg1(&[0, 0, 1, 0xBA, 0x21, 0, 1]), None);
        assert_eq!(
            not_mpeg1(&[0, 0, 1, 0xBA, 0x44, 0, 1]),
            Some("an MPEG-2 program stream")
        );
        assert_eq!(not_mpeg1(&[0, 0, 1, 0xB3, 0x14, 0, 0xF0, 0x13]), None);
        let mpeg2 = [
            0, 0, 1, 0xB3, 0x14, 0, 0xF0, 0x13, 0, 0, 0, 0, 0, 0, 1, 0xB5, 0x14,
        ];
        assert_eq!(not_mpeg1(&mpeg2), Some("MPEG-2 video"));
        assert_eq!(
            not_mpeg1(b"\0\0\0\x18ftypmp42"),
            Some("an MP4 or QuickTime file")
        );
        assert_eq!(not_mpeg1(b""), Some("empty"));
    }
}
