//! ENCODING_UNSUPPORTED: reported by encoding detection (`parse::detect`).

crate::declare_rule! {
    /// ## What it does
    /// Reports an input in none of the encodings x3dcheck reads (X3D XML, X3D JSON,
    /// ClassicVRML `#X3D`, VRML97 `#VRML V2.0`), and says what it looks like: VRML 1.0,
    /// gzip-compressed data (inside another gzip stream), UTF-32, binary data, an empty
    /// file, or other text.
    ///
    /// ## Why it matters
    /// x3dcheck reads the XML, JSON, ClassicVRML and VRML97 encodings (gzip-compressed or
    /// not, UTF-8 or UTF-16). Saying what the file is instead tells the user how to convert
    /// it, rather than reporting a confusing parse error.
    ///
    /// ## Example
    /// ```text
    /// #VRML V1.0 ascii
    /// Separator { Cube { } }
    /// ```
    ///
    /// ## Clause
    /// 19776-1 (XML encoding) and 19776-5 (JSON encoding).
    pub static ENCODING_UNSUPPORTED = {
        severity: Error,
        level: Fast,
        clause: "19776",
        versions: "all",
    }
}
