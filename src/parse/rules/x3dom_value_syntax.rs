//! X3DOM_VALUE_SYNTAX: reported by the HTML reader for a field value that the island's
//! library (X3DOM, X_ITE) reads and the X3D XML encoding does not.

crate::declare_rule! {
    /// ## What it does
    /// Reports, in an X3D island of an HTML page, a field value written in a form that the
    /// page's library reads but the X3D XML encoding does not, and reads the value as the
    /// library does (so later rules judge what is drawn):
    /// - an MFString without double quotes (`url='Deer.x3d'`): X3DOM's
    ///   `x3dom.fields.MFString.parse` takes a value that does not start with `"` as one
    ///   string (`arr.push( str )`), and X_ITE's XMLParser does the same after a console
    ///   warning ("make sure to separate each individual string with double quotation
    ///   marks!");
    /// - in an X3DOM island, an SFBool in another case (`on='TRUE'`): X3DOM reads
    ///   `getAttribute( name ).toLowerCase() === "true"`;
    /// - in an X3DOM island, an SFColor or SFColorRGBA written as a CSS colour
    ///   (`diffuseColor='#FF6633'`, `#f63`, `rgb(255, 102, 51)`, `tomato`): X3DOM's
    ///   `SFColor.parse` falls back to its `_colorParse`, which reads the colour names
    ///   of its table (lower case), `#rgb`, `#rgba`, `#rrggbb`, `#rrggbbaa`, `rgb()` and
    ///   `rgba()`.
    ///
    /// A value neither the encoding nor the library reads is FIELD_VALUE_SYNTAX, as in an
    /// `.x3d` file (X3DOM reads `on='yes'` as false, a colour it cannot parse as black).
    /// `.x3d`, `.x3dv`, `.wrl` and JSON files are not concerned.
    ///
    /// ## Why it matters
    /// The page works in its library, but the scene is not portable: copied into an `.x3d`
    /// file, or loaded by another X3D browser (Castle, FreeWRL, X_ITE for X3DOM's forms),
    /// the value is an error and the field keeps its default.
    ///
    /// ## Example
    /// ```html
    /// <x3d><scene>
    ///   <directionalLight on='TRUE'></directionalLight>
    ///   <shape><appearance><material diffuseColor='#FF6633'></material></appearance><box></box></shape>
    ///   <inline url='Deer.x3d'></inline>
    /// </scene></x3d>
    /// ```
    ///
    /// ## Use instead
    /// ```html
    /// <x3d><scene>
    ///   <directionalLight on='true'></directionalLight>
    ///   <shape><appearance><material diffuseColor='1 0.4 0.2'></material></appearance><box></box></shape>
    ///   <inline url='"Deer.x3d"'></inline>
    /// </scene></x3d>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 5 (XML encoding of field values: 5.3 SFBool, 5.15 SFString and MFString);
    /// X3DOM's and X_ITE's source for what they read.
    /// > "SFxxxx fields may only contain a single value of the type indicated by the name of the field type" (19775-1 5.2.3)
    ///
    /// A warning, not an error: the page is right for the library it is written for.
    pub static X3DOM_VALUE_SYNTAX = {
        severity: Warning,
        level: Fast,
        clause: "19776-1 5",
        versions: "all",
    }
}
