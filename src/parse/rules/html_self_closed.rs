//! HTML_SELF_CLOSED: reported by the HTML reader when an X3D element written `<Box/>`
//! took the elements after it as its children.

crate::declare_rule! {
    /// ## What it does
    /// Reports an X3D element written self-closed (`<Box/>`, `<Material .../>`) in an HTML
    /// page (not XHTML) that the HTML parser left open, so that the elements after it
    /// became its children: it names them.
    ///
    /// ## Why it matters
    /// HTML has no self-closing elements beyond its void elements (`br`, `img`, `param`…):
    /// on any other element the `/` is a parse error and is ignored, and the element stays
    /// open until its parent's end tag. `<Shape><Box/><Appearance>…</Appearance></Shape>`
    /// puts the Appearance inside the Box, where X3DOM and X_ITE do not look for it: the
    /// scene drawn is not the one written (X3DOM issue 685). An XHTML page (`.xhtml`,
    /// served as XML) reads `<Box/>` as closed.
    ///
    /// ## Example
    /// ```html
    /// <x3d><scene><shape><box/><appearance><material diffuseColor='1 0 0'/></appearance></shape></scene></x3d>
    /// ```
    ///
    /// ## Use instead
    /// ```html
    /// <x3d><scene><shape><box></box><appearance><material diffuseColor='1 0 0'></material></appearance></shape></scene></x3d>
    /// ```
    ///
    /// ## Clause
    /// HTML Living Standard 13.1.2.1 (Start tags); 19776-1 4 (the element tree is the scene graph).
    /// > "Then, if the element is one of the void elements, or if the element is a foreign element, then there may be a single U+002F SOLIDUS character (/), which on foreign elements marks the start tag as self-closing. On void elements, it does not mark the start tag as self-closing but instead is unnecessary and has no effect of any kind." (HTML 13.1.2.1)
    ///
    /// X3D elements in an HTML page are neither void nor foreign, so the `/` breaks this
    /// sentence; what makes it an error here is that the tree the page builds differs from
    /// the one written, and the tree is the scene graph.
    pub static HTML_SELF_CLOSED = {
        severity: Error,
        level: Fast,
        clause: "HTML 13.1.2.1",
        versions: "all",
    }
}
