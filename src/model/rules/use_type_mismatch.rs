//! USE_TYPE_MISMATCH: reported by the model builder when the element naming a USE is of
//! another type than the DEF'd node.

crate::declare_rule! {
    /// ## What it does
    /// Reports a `USE` written as an element (XML) or object key (JSON) of another node type
    /// than the node its `DEF` defined.
    ///
    /// ## Why it matters
    /// The encodings require the USE element to name the DEF node's type. A mismatch
    /// usually means the wrong name was used, and the node lands in a field that does not
    /// expect it.
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture DEF='Wood' url='"wood.png"'/>
    /// <Material USE='Wood'/>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 (XML encoding) 4.3 DEF/USE; 19775-1 4.4.3.
    pub static USE_TYPE_MISMATCH = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
