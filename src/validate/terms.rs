//! The words messages use for prototypes, IS and ROUTE: each encoding's own. An XML or
//! JSON file says `ProtoDeclare`, `fieldValue`, `<connect nodeField protoField>` and
//! `fromField`; a ClassicVRML or VRML97 file says `PROTO`, a field set in the instance's
//! braces, `field IS name` and `ROUTE A.f TO B.g`. VRML97 also names access types its
//! own way (field, eventIn, eventOut, exposedField, 14772-1 4.7).

use crate::model::Encoding;
use crate::schema::AccessType;

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Terms {
    encoding: Encoding,
}

impl Terms {
    pub fn of(encoding: Encoding) -> Terms {
        Terms { encoding }
    }

    /// Whether the file is written in statements (ClassicVRML, VRML97), not elements.
    pub fn statements(self) -> bool {
        matches!(self.encoding, Encoding::ClassicVrml | Encoding::Vrml97)
    }

    /// `ProtoDeclare` or `PROTO`.
    pub fn proto(self) -> &'static str {
        if self.statements() {
            "PROTO"
        } else {
            "ProtoDeclare"
        }
    }

    /// `ExternProtoDeclare` or `EXTERNPROTO`.
    pub fn extern_proto(self) -> &'static str {
        if self.statements() {
            "EXTERNPROTO"
        } else {
            "ExternProtoDeclare"
        }
    }

    /// `ProtoBody` or `PROTO body`.
    pub fn proto_body(self) -> &'static str {
        if self.statements() {
            "PROTO body"
        } else {
            "ProtoBody"
        }
    }

    /// What a prototype instance sets a field with: `fieldValue` or `field`.
    pub fn field_value(self) -> &'static str {
        if self.statements() {
            "field"
        } else {
            "fieldValue"
        }
    }

    /// An IS statement as ClassicVRML and VRML97 write it: `` `a IS b` ``.
    pub fn is_statement(node_field: &str, proto_field: &str) -> String {
        format!("`{node_field} IS {proto_field}`")
    }

    /// The end of a ROUTE: `fromField`/`toField`, in VRML97 `eventOut`/`eventIn`, in
    /// ClassicVRML the field after (or before) `TO`.
    pub fn route_end(self, from: bool) -> &'static str {
        match (self.encoding, from) {
            (Encoding::Vrml97, true) => "from eventOut",
            (Encoding::Vrml97, false) => "to eventIn",
            (Encoding::ClassicVrml, true) => "from field",
            (Encoding::ClassicVrml, false) => "to field",
            (_, true) => "fromField",
            (_, false) => "toField",
        }
    }

    /// The access type's name: X3D's, or VRML97's.
    pub fn access(self, access: AccessType) -> &'static str {
        if self.encoding != Encoding::Vrml97 {
            return access.as_str();
        }
        match access {
            AccessType::InitializeOnly => "field",
            AccessType::InputOnly => "eventIn",
            AccessType::OutputOnly => "eventOut",
            AccessType::InputOutput => "exposedField",
        }
    }

    /// The access type with its article: `an inputOnly`, `a field`.
    pub fn an_access(self, access: AccessType) -> String {
        let name = self.access(access);
        let article = if name.starts_with(['a', 'e', 'i', 'o', 'u']) {
            "an"
        } else {
            "a"
        };
        format!("{article} {name}")
    }

    /// The standard that holds Table 4.4 (IS mapping rules) for this file.
    pub fn standard(self) -> &'static str {
        if self.encoding == Encoding::Vrml97 {
            "14772-1"
        } else {
            "19775-1"
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_encoding_its_words() {
        let xml = Terms::of(Encoding::Xml);
        let classic = Terms::of(Encoding::ClassicVrml);
        let vrml97 = Terms::of(Encoding::Vrml97);
        assert_eq!(
            (xml.proto(), classic.proto(), vrml97.extern_proto()),
            ("ProtoDeclare", "PROTO", "EXTERNPROTO")
        );
        assert_eq!(Terms::is_statement("a", "b"), "`a IS b`");
        assert_eq!(
            (xml.route_end(true), vrml97.route_end(false)),
            ("fromField", "to eventIn")
        );
        assert_eq!(
            (
                classic.an_access(AccessType::InputOnly),
                vrml97.an_access(AccessType::InitializeOnly),
                vrml97.an_access(AccessType::InputOutput)
            ),
            (
                "an inputOnly".to_string(),
                "a field".to_string(),
                "an exposedField".to_string()
            )
        );
    }
}
