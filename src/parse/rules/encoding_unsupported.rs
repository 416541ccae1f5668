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
