//! VRML_MALFORMED: reported by the ClassicVRML and VRML97 reader (`parse::classic`).

crate::declare_rule! {
    /// ## What it does
    /// Reports ClassicVRML (`#X3D V3.x utf8`, `#X3D V4.x utf8`) or VRML97
    /// (`#VRML V2.0 utf8`) text that does not follow the encoding's grammar: a brace or
    /// bracket that is never closed or closes nothing, a node without `{`, a statement
    /// the encoding does not have (PROFILE in VRML97), an unterminated string or block
    /// comment, a ROUTE without `TO`, bytes that are not UTF-8. The reader reports each
    /// error at its place and goes on at the next field, node or statement, so one typo
    /// does not hide the rest of the file. A field value of the wrong shape for its
    /// type (`translation 1 2`) is FIELD_VALUE_SYNTAX, as in the other encodings.
    ///
    /// ## Why it matters
    /// A browser that meets a syntax error stops reading the file or skips part of it,
    /// differently from browser to browser: what follows the error may never be seen.
    ///
    /// ## Example
    /// ```text
    /// #X3D V4.0 utf8
    /// PROFILE Interchange
    /// Transform { children [ Shape { geometry Box { } } }
    /// ```
    ///
    /// ## Use instead
    /// ```text
    /// Transform { children [ Shape { geometry Box { } } ] }
    /// ```
    ///
    /// ## Clause
    /// 19776-2 (ClassicVRML encoding) Annex A Grammar; ISO/IEC 14772-1 (VRML97) Annex A,
    /// which a finding in a VRML97 file cites (`14772-1 A`).
    /// > "vrmlScene ::= statements ;" (14772-1 A.2, the grammar the text does not match; 19776-2 Annex A likewise)
    pub static VRML_MALFORMED = {
        severity: Error,
        level: Fast,
        clause: "19776-2 A",
        versions: "all",
    }
}
