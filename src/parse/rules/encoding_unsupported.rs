//! ENCODING_UNSUPPORTED: reported by encoding detection (`parse::detect`).

crate::declare_rule! {
    /// ## What it does
    /// Reports an input that is neither X3D XML nor X3D JSON, and says what it looks like:
    /// ClassicVRML (`#X3D`), VRML97 (`#VRML`), gzip-compressed, UTF-16, binary, or other text.
    ///
    /// ## Why it matters
    /// x3dcheck reads the XML and JSON encodings. Saying what the file is instead tells
    /// the user how to convert it, rather than reporting a confusing parse error.
    ///
    /// ## Example
    /// ```text
    /// #X3D V3.3 utf8
    /// PROFILE Interchange
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
