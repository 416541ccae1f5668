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
    /// > "each Name must match the value of an ID attribute on some element in the XML document" (XML 1.0, validity constraint IDREF)
    /// > "Nodes given a name by a DEF construct outside the prototype scope may not be referenced in a USE construct inside the prototype scope" (14772-1 4.8.4)
    ///
    /// The X3D XML Schema types `USE` as `xs:IDREF` (x3d-4.0.xsd, attribute group
    /// DEF_USE): a USE whose name no DEF carries breaks the first; a USE in a prototype
    /// body of a name defined only outside it breaks the second (its wording read in a
    /// copy of the 1997 text). That the DEF comes before the USE is the reading of 14772-1
    /// 4.6.2, "A node given a name using the DEF keyword may be referenced by name later
    /// in the same file with USE or ROUTE statements".
    pub static USE_UNDEFINED = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
