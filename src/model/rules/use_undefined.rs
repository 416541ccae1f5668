//! USE_UNDEFINED: reported by the model builder when a USE names no earlier DEF.

crate::declare_rule! {
    /// ## What it does
    /// Reports a `USE` whose name is not defined by a `DEF` earlier in document order, in
    /// the same name scope.
    ///
    /// ## Why it matters
    /// A USE must refer back to a node already defined; browsers drop an unresolved USE
    /// and with it whatever the node was meant to show.
    ///
    /// ## Example
    /// ```xml
    /// <Shape><Appearance USE='Shiny'/><Box/></Shape>
    /// <Appearance DEF='Shiny'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.3 DEF/USE semantics.
    pub static USE_UNDEFINED = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
