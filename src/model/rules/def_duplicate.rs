//! DEF_DUPLICATE: reported by the model builder when a DEF name is taken twice.

crate::declare_rule! {
    /// ## What it does
    /// Reports a `DEF` name defined a second time in the same name scope (the scene, or
    /// one ProtoBody).
    ///
    /// ## Why it matters
    /// DEF names identify nodes for `USE` and `ROUTE`. A second definition is an error;
    /// browsers disagree on which node a later USE gets. x3dcheck keeps the first.
    ///
    /// ## Example
    /// ```xml
    /// <Material DEF='Red' diffuseColor='1 0 0'/>
    /// <Material DEF='Red' diffuseColor='0.9 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.3 DEF/USE semantics; 4.4.7 Run-time name scope.
    pub static DEF_DUPLICATE = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
