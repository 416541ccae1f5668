//! JSON_MALFORMED: reported by the JSON reader at the first syntax error.

crate::declare_rule! {
    /// ## What it does
    /// Reports input that is not valid JSON (RFC 8259), at the first error.
    ///
    /// ## Why it matters
    /// A JSON parser stops at a syntax error, so no browser sees anything of the scene.
    ///
    /// ## Example
    /// ```json
    /// { "X3D": { "@version": "4.0", } }
    /// ```
    ///
    /// ## Clause
    /// 19776-5 (JSON encoding); RFC 8259.
    /// > "JSON-text = ws value ws" (RFC 8259 2, the grammar the text does not match)
    pub static JSON_MALFORMED = {
        severity: Error,
        level: Fast,
        clause: "19776-5",
        versions: "all",
    }
}
