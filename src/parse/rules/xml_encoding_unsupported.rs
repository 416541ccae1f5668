//! XML_ENCODING_UNSUPPORTED: reported by the decoding stage (`parse::decode`) when the XML
//! declaration names a character encoding that cannot be decoded.

crate::declare_rule! {
    /// ## What it does
    /// Reports an XML declaration whose `encoding` names a character encoding x3dcheck
    /// cannot decode. x3dcheck reads UTF-8 (with or without a byte-order mark), UTF-16 LE
    /// and BE (told by a byte-order mark or by the first characters, XML 1.0 Appendix F),
    /// and every encoding the WHATWG Encoding Standard defines, by any of its labels
    /// (`ISO-8859-1`, `windows-1252`, `Shift_JIS`, `EUC-KR`, `GB18030`, `KOI8-R`, …); as
    /// that standard says, `ISO-8859-1` and `US-ASCII` are read as windows-1252. Names
    /// outside it (`UTF-32`, `EBCDIC`, `UCS-2`, made-up names) are reported here, at the
    /// name, and the document is not read.
    ///
    /// ## Why it matters
    /// An XML processor must read UTF-8 and UTF-16 and may refuse other encodings
    /// (XML 1.0 §4.3.3); the X3D browsers people use read the WHATWG set. A document in
    /// another encoding is unreadable to most tools.
    ///
    /// ## Example
    /// ```xml
    /// <?xml version="1.0" encoding="EBCDIC-US"?>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <?xml version="1.0" encoding="UTF-8"?>
    /// ```
    /// and the file saved as UTF-8 (`iconv -f OLD -t UTF-8`).
    ///
    /// ## Clause
    /// 19776-1 4.2 (X3D XML documents are XML 1.0); XML 1.0 §4.3.3 Character Encoding in
    /// Entities; WHATWG Encoding Standard §4.2 Names and labels.
    /// X3D names one character encoding for its files; a document declared in an encoding
    /// x3dcheck cannot decode is in none that X3D allows. The sentence is 7.2.5.2's list of
    /// what the header identifies, read in a copy of the 19775-1 V4.0 text
    /// (tools.realism.com, "Core Component", X3D Declarative Tag).
    /// > "identification of the character encoding being supported (for this standard, this shall be \"UTF-8\")" (19775-1 V4.0 7.2.5.2)
    pub static XML_ENCODING_UNSUPPORTED = {
        severity: Error,
        level: Fast,
        clause: "19776-1 4.2",
        versions: "all",
    }
}
