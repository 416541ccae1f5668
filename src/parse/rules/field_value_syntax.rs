//! FIELD_VALUE_SYNTAX: reported by the readers when a value does not parse as its type.

crate::declare_rule! {
    /// ## What it does
    /// Reports a field value that does not parse as the field's type: a wrong token
    /// (`True` for an XML SFBool, `1.5` for an SFInt32), a wrong count of numbers (an
    /// SFColor with 2, an MFVec3f whose count is not a multiple of 3), bad MFString
    /// quoting, a JSON string where a number belongs, or an attribute given to a node
    /// field. The diagnostic points at the offending token.
    ///
    /// ## Why it matters
    /// Browsers reject or truncate such values, each differently; the field silently
    /// keeps its default or loses its last elements.
    ///
    /// ## Example
    /// ```xml
    /// <Material diffuseColor='1 0'/>
    /// <Shape visible='True'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 5 Field type reference; 19776-1 5 (XML encoding of field values).
    pub static FIELD_VALUE_SYNTAX = {
        severity: Error,
        level: Fast,
        clause: "5",
        versions: "all",
    }
}
