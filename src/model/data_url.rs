//! `data:` URLs (RFC 2397): content a url entry carries in itself, base64 or
//! percent-encoded, as in `url='"data:image/png;base64,iVBORw0KGgo…"'`. They are decoded
//! as browsers decode them, by the `data-url` crate (servo's implementation of the WHATWG
//! Fetch Standard's data: URL processing: forgiving base64, percent-decoding, the MIME
//! type), never looked up as files. The decoded bytes are never more than the url's own
//! text, which the input size limit already bounds; images in them are decoded within
//! the same limits as image files ([`crate::limits::image_limits`]).

/// A data: URL's content. Its MIME type is not consulted: as browsers do, an image's
/// format is told from its bytes.
pub struct Data {
    pub bytes: Vec<u8>,
}

/// Whether a url entry is a data: URL (the scheme in any case; whitespace around the
/// entry is ignored, as URL parsing ignores it).
pub fn is_data_url(url: &str) -> bool {
    url.trim()
        .get(..5)
        .is_some_and(|scheme| scheme.eq_ignore_ascii_case("data:"))
}

/// The content of a data: URL, or why it has none; None for any other url.
pub fn decode(url: &str) -> Option<Result<Data, String>> {
    if !is_data_url(url) {
        return None;
    }
    let parsed = match ::data_url::DataUrl::process(url.trim()) {
        Ok(parsed) => parsed,
        Err(e) => return Some(Err(format!("is not a valid data: URL ({e})"))),
    };
    Some(match parsed.decode_to_vec() {
        Ok((bytes, _fragment)) => Ok(Data { bytes }),
        Err(_) => Err("is a data: URL whose base64 content does not decode".to_string()),
    })
}

/// A url as messages name it: a data: URL cut after its first characters (the content
/// can be megabytes long).
pub fn shown(url: &str) -> String {
    const SHOWN: usize = 40;
    if !is_data_url(url) || url.chars().count() <= SHOWN {
        return url.to_string();
    }
    let head: String = url.trim().chars().take(SHOWN).collect();
    format!("{head}…")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_and_percent_encoded_content_decodes() {
        let data = decode("data:image/png;base64,iVBORw0KGgo=")
            .unwrap()
            .unwrap();
        assert_eq!(data.bytes, b"\x89PNG\r\n\x1a\n");
        // Whitespace inside base64 is skipped, as browsers skip it.
        let spaced = decode(" DATA:image/png;base64,iVBO Rw0K\nGgo= ").unwrap();
        assert_eq!(spaced.unwrap().bytes, b"\x89PNG\r\n\x1a\n");
        let text = decode("data:,%89PNG%0D%0A").unwrap().unwrap();
        assert_eq!(text.bytes, b"\x89PNG\r\n");
    }

    #[test]
    fn other_urls_are_not_data_and_bad_data_says_why() {
        assert!(decode("textures/data:x.png").is_none());
        assert!(decode("image.png").is_none());
        assert!(decode("data:image/png;base64,!!!!").unwrap().is_err());
        assert!(decode("data:image/png").unwrap().is_err());
    }

    #[test]
    fn long_data_urls_are_shown_cut() {
        let long = format!("data:image/png;base64,{}", "A".repeat(1000));
        let shown = shown(&long);
        assert!(
            shown.ends_with('…') && shown.chars().count() == 41,
            "{shown}"
        );
        assert_eq!(super::shown("a.png"), "a.png");
    }
}
