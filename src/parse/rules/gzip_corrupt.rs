//! GZIP_CORRUPT: reported by the decoding stage (`parse::decode`) when compressed input
//! does not decompress.

crate::declare_rule! {
    /// ## What it does
    /// Reports an input that starts with the gzip magic bytes (`1f 8b`: `.x3dz`, `.x3dvz`,
    /// `.x3djz`, `.wrz`, `*.gz`, or compressed standard input) but does not decompress: a
    /// truncated stream, a damaged block, a wrong checksum or length. Nothing of it is
    /// checked. A stream that would expand past the input size limit is LIMIT_EXCEEDED
    /// instead, found while it is inflated.
    ///
    /// ## Why it matters
    /// X3D browsers read gzip-compressed scenes as what they contain; a damaged file is
    /// refused by all of them (or shown cut short), usually after an interrupted download
    /// or copy.
    ///
    /// ## Example
    /// A `scene.x3dz` cut off after its first kilobytes:
    /// ```text
    /// 1f 8b 08 00 00 00 00 00 00 03 b3 89 30 76 51 28 …  (no end of stream)
    /// ```
    ///
    /// ## Use instead
    /// The whole file: `gzip -t scene.x3dz` says whether it is intact.
    ///
    /// ## Clause
    /// 19776-1 (and -2, -5), the compressed forms of the encodings; RFC 1952 (gzip).
    /// > "A compliant decompressor must check ID1, ID2, and CM, and provide an error indication if any of these have incorrect values" (RFC 1952 2.3.1.2)
    pub static GZIP_CORRUPT = {
        severity: Error,
        level: Fast,
        clause: "19776",
        versions: "all",
    }
}
