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
    /// A warning, not an error (issue 32): the finding says x3dcheck cannot read the file,
    /// not that the file breaks a sentence of an X3D encoding. What it flags is mostly
    /// another language (VRML 1.0, whose files are right by their own specification) or
    /// content no X3D encoding describes; no "shall" of 19776-1, 19776-2, 19776-5 or
    /// 14772-1 applies to a file that is none of them.
    pub static ENCODING_UNSUPPORTED = {
        severity: Warning,
        level: Fast,
        clause: "19776",
        versions: "all",
    }
}
