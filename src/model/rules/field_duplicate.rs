//! FIELD_DUPLICATE: reported by the model builder (`Builder::add_field`, and
//! `Builder::end_node` for `field` declarations) and, for duplicate JSON keys of node
//! fields, by the JSON reader. The first value is kept.

crate::declare_rule! {
    /// ## What it does
    /// Reports a field given twice on one node: a duplicate JSON key, a field given both
    /// as a value and as nodes (`@x` and `-x`), two `fieldValue` statements or two
    /// `field` declarations with one name. (A duplicate XML attribute is not well-formed
    /// XML and gets XML_MALFORMED.)
    ///
    /// ## Why it matters
    /// Which value wins differs between browsers and JSON parsers; x3dcheck keeps the
    /// first. Either way one of the author's values is silently lost. Two declarations of
    /// one name on a Script or shader node leave the script's or the shader's variable
    /// with two types or values.
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
    /// it, and no sentence was found that forbids two `fieldValue` statements of one
    /// name. (The XML attribute case is XML 1.0's well-formedness constraint Unique Att
    /// Spec, reported as XML_MALFORMED.)
    ///
    /// Two `field` declarations of one name on a Script or shader node are reported as
    /// an error, the severity ../shared/RULES.md gives the code (issue 33):
    ///
    /// > "Name shall be an identifier that is unique for this Script node." (19775-1 29.4.1 Script; read in the 3.x text copied in H3D and Coin)
    ///
    /// > "Name shall be an identifier that is unique for this shader node" (19775-1 31, X3DProgrammableShaderObject; read in H3D's copy)
    pub static FIELD_DUPLICATE = {
        severity: Warning,
        level: Fast,
        clause: "4.4.2",
        versions: "all",
    }
}
