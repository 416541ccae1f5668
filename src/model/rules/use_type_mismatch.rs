//! USE_TYPE_MISMATCH: reported by the model builder when the element naming a USE is of
//! another type than the DEF'd node.

crate::declare_rule! {
    /// ## What it does
    /// Reports a `USE` written as an element (XML) or object key (JSON) of another node type
    /// than the node its `DEF` defined.
    ///
    /// ## Why it matters
    /// A USE element names a node type, and readers expect it to be the DEF node's. A
    /// mismatch usually means the wrong name was used, and the node lands in a field that
    /// does not expect it.
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture DEF='Wood' url='"wood.png"'/>
    /// <Material USE='Wood'/>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 (XML encoding) 4.3 DEF/USE; 19775-1 4.4.3.
    ///
    /// A warning (issue 32): no sentence was found that requires the USE element's name
    /// to be the DEF node's type; the X3D XML Schema types USE as `xs:IDREF`, which only
    /// has to match some DEF, and the node used is the DEF node whatever the element says.
    pub static USE_TYPE_MISMATCH = {
        severity: Warning,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
