//! HTML_SCENE_MISSING: reported by the HTML reader for an X3D island with no scene.

crate::declare_rule! {
    /// ## What it does
    /// Reports an X3D island of an HTML page (`<x3d>` of X3DOM, `<X3D>` in an X_ITE
    /// `<x3d-canvas>`) with no `<Scene>` element.
    ///
    /// ## Why it matters
    /// The Scene holds everything that is drawn: an island without one shows an empty
    /// canvas. X3DOM logs an error and draws nothing. Often the scene is there but
    /// misspelt (`<scenes>`), or sits outside the `<x3d>` element.
    ///
    /// ## Example
    /// ```html
    /// <x3d width='400px' height='300px'><shape><box></box></shape></x3d>
    /// ```
    ///
    /// ## Use instead
    /// ```html
    /// <x3d width='400px' height='300px'><scene><shape><box></box></shape></scene></x3d>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 4.2 (X3D element); x3d-4.0.xsd, the X3D element's content.
    /// > "<xs:element ref="Scene"/>" (x3d-4.0.xsd, the X3D element's sequence, after `<xs:element ref="head" minOccurs="0"/>`: Scene has no minOccurs="0", so it is required)
    pub static HTML_SCENE_MISSING = {
        severity: Error,
        level: Fast,
        clause: "19776-1 4.2",
        versions: "all",
    }
}
