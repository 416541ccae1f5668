//! ROOT_NOT_X3D: reported by the readers when the document's root is not X3D.

crate::declare_rule! {
    /// ## What it does
    /// Reports an XML document whose root element is not `X3D`, or a JSON document whose
    /// top-level object has no `X3D` member.
    ///
    /// ## Why it matters
    /// Every X3D document has the X3D root, which carries the version and profile. A
    /// file without it is something else: an HTML page, another 3D format, a fragment.
    ///
    /// ## Example
    /// ```xml
    /// <Scene><Shape><Box/></Shape></Scene>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 4.2 (X3D element); 19776-5 (JSON encoding) X3D object.
    /// > "X3D is the root node for an Extensible 3D (X3D) Graphics model." (x3d-4.0.xsd, the X3D element)
    ///
    /// The XML encoding is the X3D XML Schema's (19776-1 V3.0 6.1), whose documents start
    /// at the X3D element; the JSON schema makes `X3D` the one required member of the
    /// top-level object (`"required": ["X3D"]`, `additionalProperties: false`). A
    /// document whose root is another element, or whose object lacks `X3D`, breaks it.
    pub static ROOT_NOT_X3D = {
        severity: Error,
        level: Fast,
        clause: "19776-1 4.2",
        versions: "all",
    }
}
