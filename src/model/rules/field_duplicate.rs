//! FIELD_DUPLICATE: reported by the model builder (`Builder::add_field`) and, for
//! duplicate JSON keys of node fields, by the JSON reader. The first value is kept.

crate::declare_rule! {
    /// ## What it does
    /// Reports a field given twice on one node: a duplicate JSON key, a field given both
    /// as a value and as nodes (`@x` and `-x`), two `fieldValue` statements or two
    /// `field` declarations with one name. (A duplicate XML attribute is not well-formed
    /// XML and gets XML_MALFORMED.)
    ///
    /// ## Why it matters
    /// Which value wins differs between browsers and JSON parsers; x3dcheck keeps the
    /// first. Either way one of the author's values is silently lost.
    ///
    /// ## Example
    /// ```json
    /// { "Material": { "@diffuseColor": [1, 0, 0], "@diffuseColor": [0, 1, 0] } }
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.2 Field semantics; 19776-5 (JSON encoding).
    ///
    /// A warning (issue 32): JSON itself only recommends unique member names ("The names
    /// within an object SHOULD be unique", RFC 8259 4), the X3D JSON schema cannot say
    /// it, and no sentence was found that forbids two `fieldValue` statements or two
    /// `field` declarations of one name. (The XML attribute case is XML 1.0's
    /// well-formedness constraint Unique Att Spec, reported as XML_MALFORMED.)
    pub static FIELD_DUPLICATE = {
        severity: Warning,
        level: Fast,
        clause: "4.4.2",
        versions: "all",
    }
}
