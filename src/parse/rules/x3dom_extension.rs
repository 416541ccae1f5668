//! X3DOM_EXTENSION: reported by the HTML reader for X3DOM's own nodes and attributes.

crate::declare_rule! {
    /// ## What it does
    /// Reports, in an X3D island of an HTML page, an element or attribute that X3DOM
    /// reads but X3D does not have: X3DOM's node types (`<param>`, `<multipart>`,
    /// `<binaryGeometry>`, `<imageGeometry>`, `<plane>`, `<commonSurfaceShader>`…, and in
    /// an X3DOM island `<RenderedTexture>`, X3DOM's own node of the name X3D 4.1 gives
    /// another node, with other fields: `viewpoint`, `scene`, `excludeNodes`,
    /// `dimensions`, `update`), the
    /// attributes of its `<x3d>` element (`showStat`, `showLog`, `mapDEFToID`, `width`…),
    /// its node fields (`render`, `isPickable`…) and HTML event handlers on nodes
    /// (`onclick`). The list is X3DOM's own (src/parse/html/x3dom.rs).
    ///
    /// ## Why it matters
    /// They work in X3DOM and nowhere else: another X3D browser (X_ITE, Castle, FreeWRL)
    /// or a conversion to an X3D file drops them. They are not errors of the page, so they
    /// are reported apart from unknown nodes and fields, and the nodes' content is not
    /// checked as X3D.
    ///
    /// ## Example
    /// ```html
    /// <x3d showStat='true'><scene><shape><plane></plane></shape></scene></x3d>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 4.2 (X3D element); X3DOM's source for what it adds.
    /// > "X3D is the root node for an Extensible 3D (X3D) Graphics model." (x3d-4.0.xsd, the X3D element: its attributes are `version`, `profile` and those of X3DStatement)
    pub static X3DOM_EXTENSION = {
        severity: Info,
        level: Fast,
        clause: "19776-1 4.2",
        versions: "all",
    }
}
