//! DEF_DUPLICATE: reported by the model builder when a DEF name is taken twice.

crate::declare_rule! {
    /// ## What it does
    /// Reports a `DEF` name defined a second time in the same name scope (the scene, or
    /// one ProtoBody).
    ///
    /// ## Why it matters
    /// DEF names identify nodes for `USE` and `ROUTE`. In X3D a second definition is an
    /// error; browsers disagree on which node a later USE gets. x3dcheck keeps the first.
    ///
    /// VRML97 allows it: "If multiple nodes are given the same name, each USE statement
    /// refers to the closest node with the given name preceding it in either the VRML
    /// file or prototype definition" (14772-1 4.6.2). In a VRML97 file (`#VRML V2.0`)
    /// the finding is a warning, since the file stops being valid once converted to X3D,
    /// and the later DEF takes the name over for the USEs and ROUTEs that follow.
    ///
    /// ## Example
    /// ```xml
    /// <Material DEF='Red' diffuseColor='1 0 0'/>
    /// <Material DEF='Red' diffuseColor='0.9 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.3 DEF/USE semantics; 4.4.7 Run-time name scope; 14772-1 4.6.2.
    /// > "A name must not appear more than once in an XML document as a value of this type" (XML 1.0, validity constraint ID)
    ///
    /// The X3D XML Schema types `DEF` as `xs:ID` (x3d-4.0.xsd, attribute group DEF_USE),
    /// so an XML file that repeats a DEF name breaks the constraint, whatever the scope.
    /// For ClassicVRML and JSON files no sentence of their own was found (issue 32):
    /// x3dcheck holds them to the XML encoding's rule, since such a file cannot be written
    /// as XML without renaming, and it is an error there too.
    pub static DEF_DUPLICATE = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
