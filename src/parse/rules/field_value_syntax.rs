//! FIELD_VALUE_SYNTAX: reported by the readers when a value does not parse as its type.

crate::declare_rule! {
    /// ## What it does
    /// Reports a field value that does not parse as the field's type: a wrong token
    /// (`True` for an XML SFBool, `1.5` for an SFInt32), a wrong count of numbers (an
    /// SFColor with 2, an MFVec3f whose count is not a multiple of 3), bad MFString
    /// quoting, a JSON string where a number belongs, or an attribute given to a node
    /// field. The diagnostic points at the offending token.
    ///
    /// XML encoding, read strictly by 19776-1:
    /// - MFString: each string is enclosed in double quotes (5.15). `family='SANS'` is an
    ///   error; the help says how to write it (`family='"SANS"'`), and the value is kept as
    ///   the one string browsers read, so later rules judge what is drawn.
    /// - Commas (5.1.2: "within MF arrays, commas may only be used as whitespace between
    ///   values of individual base datatypes"; EXAMPLE 2 calls `color="1, 1, 1, 0, 0, 0"`
    ///   erroneous): a comma may stand only between the values of an MF field, that is after
    ///   a whole element. So `1 2 3, 4 5 6` and `1 2 3,` are fine in an MFVec3f and `0, 1, 2`
    ///   in an MFInt32 or MFFloat; `1, 2, 3` inside one SFVec3f of an MFVec3f, any comma in
    ///   an SF field (`diffuseColor='1,0,0'`, `translation='1,2,3'`), a comma before the
    ///   first value and a comma inside one image of an MFImage are errors. The comma is
    ///   still read as whitespace, as browsers read it, and the value kept.
    ///
    /// JSON gives MF values as arrays, so the question does not arise there; the ClassicVRML
    /// encoding (19776-2 5.1) treats every comma as white space, so none of these would be
    /// an error there (x3dcheck does not read ClassicVRML).
    ///
    /// ## Why it matters
    /// Browsers reject or truncate such values, each differently; the field silently
    /// keeps its default or loses its last elements.
    ///
    /// ## Example
    /// ```xml
    /// <Material diffuseColor='1 0'/>
    /// <Shape visible='True'/>
    /// <FontStyle family='SANS'/>
    /// <Material diffuseColor='1,0,0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 5 Field type reference; 19776-1 5 (XML encoding of field values: 5.1.2
    /// commas, 5.15 SFString and MFString).
    /// The field types fix the form of a value: one value of the type in an SF field, whole
    /// values of the single type in an MF field, and in XML commas only between those values.
    /// A value in another form breaks these sentences. Where the commas set the numbers of an
    /// MF vector field apart in groups of another size (x y w triples in an MFVec2d), the help
    /// says so and asks whether another type was meant, rather than regroup the numbers.
    /// > "SFxxxx fields may only contain a single value of the type indicated by the name of the field type" (19775-1 5.2.3)
    /// > "within MF arrays, commas may only be used as whitespace between values of individual base datatypes" (19776-1 5.1.2)
    pub static FIELD_VALUE_SYNTAX = {
        severity: Error,
        level: Fast,
        clause: "5",
        versions: "all",
    }
}
