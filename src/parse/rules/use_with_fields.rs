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
    /// > "USE means reuse an already DEF-ed node ID, excluding all child nodes and all other attributes (except for containerField, which can have a different value)." (x3d-4.0.xsd, attribute group DEF_USE, the USE attribute)
    ///
    /// That annotation of the X3D XML Schema (the XML encoding's schema, 19776-1 V3.0
    /// 6.1) is the only wording found; a USE element with a field, a DEF or children
    /// breaks it. ClassicVRML has no syntax for it (`USE name` takes nothing after it), and
    /// the X3D JSON schema's USE form of each node admits `@USE`, `@class` and comments only
    /// (`additionalProperties: false`).
    pub static USE_WITH_FIELDS = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
