//! XML_MALFORMED: reported by the XML reader at the first well-formedness error.

crate::declare_rule! {
    /// ## What it does
    /// Reports input that is not well-formed XML, at the first error: mismatched or
    /// unclosed tags, a duplicated attribute, an undeclared entity, text after the root.
    ///
    /// ## Why it matters
    /// An XML processor must stop at a well-formedness error (XML 1.0 §1.2), so nothing
    /// after it is seen by any browser. x3dcheck checks nothing else in such a file.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0'><Scene><Shape></Scene></X3D>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 (XML encoding) 4.1; XML 1.0 2.1 Well-formed documents.
    /// > "Taken as a whole, it matches the production labeled document" (XML 1.0 2.1, the definition of a well-formed document)
    pub static XML_MALFORMED = {
        severity: Error,
        level: Fast,
        clause: "19776-1 4.1",
        versions: "all",
    }
}
