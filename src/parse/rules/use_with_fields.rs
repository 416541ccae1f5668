//! USE_WITH_FIELDS: reported by the readers when a USE node carries fields or children.

crate::declare_rule! {
    /// ## What it does
    /// Reports a `USE` node that also sets fields, a `DEF`, or has children.
    /// `containerField` is allowed (it says where the shared node goes), and so are the
    /// `class`, `id` and `style` attributes of the XML encoding.
    ///
    /// ## Why it matters
    /// A USE is the same node as its DEF, not a copy: values given with it are ignored
    /// by browsers, so the author's intent is silently lost.
    ///
    /// ## Example
    /// ```xml
    /// <Material USE='Red' transparency='0.5'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.3 DEF/USE semantics; 19776-1 4.3.
    pub static USE_WITH_FIELDS = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
