//! The shapes of the schema tables: X3D versions (and VRML97), field types, access types,
//! and the node and field definitions that `generated.rs` fills in for every version.

use std::fmt;

/// A specification version this tool knows: VRML97 (ISO/IEC 14772-1:1997), which X3D 3.0
/// succeeded and so orders before it, and the X3D versions (ISO/IEC 19775-1).
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Version {
    Vrml97,
    V3_0,
    V3_1,
    V3_2,
    V3_3,
    V4_0,
    V4_1,
}

impl Version {
    /// Every version with a schema table, oldest first.
    pub const ALL: [Version; 7] = [
        Version::Vrml97,
        Version::V3_0,
        Version::V3_1,
        Version::V3_2,
        Version::V3_3,
        Version::V4_0,
        Version::V4_1,
    ];

    /// The X3D versions: those an X3D document's `version` names, with a UOM and profiles.
    pub const X3D: [Version; 6] = [
        Version::V3_0,
        Version::V3_1,
        Version::V3_2,
        Version::V3_3,
        Version::V4_0,
        Version::V4_1,
    ];

    /// The latest version: the schema used when a document's version is missing or unknown.
    pub const LATEST: Version = Version::V4_1;

    /// The X3D version an X3D document's `version` text names (never VRML97, which is
    /// known by its file header instead).
    pub fn parse(text: &str) -> Option<Version> {
        Version::X3D.into_iter().find(|v| v.as_str() == text)
    }

    /// "3.0" … "4.1", or "VRML97".
    pub fn as_str(self) -> &'static str {
        match self {
            Version::Vrml97 => "VRML97",
            Version::V3_0 => "3.0",
            Version::V3_1 => "3.1",
            Version::V3_2 => "3.2",
            Version::V3_3 => "3.3",
            Version::V4_0 => "4.0",
            Version::V4_1 => "4.1",
        }
    }

    /// The name messages use: "X3D 3.3", or "VRML97".
    pub fn name(self) -> &'static str {
        match self {
            Version::Vrml97 => "VRML97",
            Version::V3_0 => "X3D 3.0",
            Version::V3_1 => "X3D 3.1",
            Version::V3_2 => "X3D 3.2",
            Version::V3_3 => "X3D 3.3",
            Version::V4_0 => "X3D 4.0",
            Version::V4_1 => "X3D 4.1",
        }
    }

    pub fn is_4x(self) -> bool {
        self >= Version::V4_0
    }
}

impl fmt::Display for Version {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The scalar kind one element of a field's value is made of.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Scalar {
    Bool,
    Int32,
    /// Single precision: SFFloat and every `…f` vector, colour, rotation and matrix type.
    Float,
    /// Double precision: SFDouble, SFTime and every `…d` type.
    Double,
    String,
    Image,
    Node,
}

macro_rules! field_types {
    ($($sf:ident / $mf:ident : $scalar:ident * $arity:literal),* $(,)?) => {
        /// Every X3D field type.
        #[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
        pub enum FieldType { $($sf, $mf,)* }

        impl FieldType {
            pub const ALL: &'static [FieldType] = &[$(FieldType::$sf, FieldType::$mf,)*];

            pub fn as_str(self) -> &'static str {
                match self { $(FieldType::$sf => stringify!($sf), FieldType::$mf => stringify!($mf),)* }
            }

            pub fn parse(text: &str) -> Option<FieldType> {
                match text { $(stringify!($sf) => Some(FieldType::$sf), stringify!($mf) => Some(FieldType::$mf),)* _ => None }
            }

            /// True for the multiple-valued (`MF…`) types.
            pub fn is_mf(self) -> bool {
                match self { $(FieldType::$sf => false, FieldType::$mf => true,)* }
            }

            pub fn scalar(self) -> Scalar {
                match self { $(FieldType::$sf | FieldType::$mf => Scalar::$scalar,)* }
            }

            /// Scalars per element: 3 for SFVec3f and MFVec3f, 16 for SFMatrix4f, 1 for SFImage
            /// (an image is one element) and for nodes.
            pub fn arity(self) -> usize {
                match self { $(FieldType::$sf | FieldType::$mf => $arity,)* }
            }

            /// The single-valued type an MF type is a list of (itself for SF types).
            pub fn single(self) -> FieldType {
                match self { $(FieldType::$sf | FieldType::$mf => FieldType::$sf,)* }
            }
        }
    };
}

field_types! {
    SFBool / MFBool: Bool * 1,
    SFInt32 / MFInt32: Int32 * 1,
    SFFloat / MFFloat: Float * 1,
    SFDouble / MFDouble: Double * 1,
    SFTime / MFTime: Double * 1,
    SFString / MFString: String * 1,
    SFVec2f / MFVec2f: Float * 2,
    SFVec3f / MFVec3f: Float * 3,
    SFVec4f / MFVec4f: Float * 4,
    SFVec2d / MFVec2d: Double * 2,
    SFVec3d / MFVec3d: Double * 3,
    SFVec4d / MFVec4d: Double * 4,
    SFColor / MFColor: Float * 3,
    SFColorRGBA / MFColorRGBA: Float * 4,
    SFRotation / MFRotation: Float * 4,
    SFMatrix3f / MFMatrix3f: Float * 9,
    SFMatrix4f / MFMatrix4f: Float * 16,
    SFMatrix3d / MFMatrix3d: Double * 9,
    SFMatrix4d / MFMatrix4d: Double * 16,
    SFImage / MFImage: Image * 1,
    SFNode / MFNode: Node * 1,
}

impl fmt::Display for FieldType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum AccessType {
    InitializeOnly,
    InputOnly,
    OutputOnly,
    InputOutput,
}

impl AccessType {
    pub fn parse(text: &str) -> Option<AccessType> {
        Some(match text {
            "initializeOnly" => AccessType::InitializeOnly,
            "inputOnly" => AccessType::InputOnly,
            "outputOnly" => AccessType::OutputOnly,
            "inputOutput" => AccessType::InputOutput,
            _ => return None,
        })
    }

    pub fn as_str(self) -> &'static str {
        match self {
            AccessType::InitializeOnly => "initializeOnly",
            AccessType::InputOnly => "inputOnly",
            AccessType::OutputOnly => "outputOnly",
            AccessType::InputOutput => "inputOutput",
        }
    }

    /// Whether a document may give the field a value (19775-1 4.4.2.2).
    pub fn is_initializable(self) -> bool {
        matches!(self, AccessType::InitializeOnly | AccessType::InputOutput)
    }

    /// Whether a ROUTE may read from the field.
    pub fn is_output(self) -> bool {
        matches!(self, AccessType::OutputOnly | AccessType::InputOutput)
    }

    /// Whether a ROUTE may write to the field.
    pub fn is_input(self) -> bool {
        matches!(self, AccessType::InputOnly | AccessType::InputOutput)
    }
}

/// One end of a numeric range.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Bound {
    pub value: f64,
    pub inclusive: bool,
}

/// A component's name and level, as in `componentInfo` and the support-level tables.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ComponentLevel {
    pub component: &'static str,
    pub level: u8,
}

/// One field of a node type, for one version.
#[derive(Debug)]
pub struct FieldDef {
    pub name: &'static str,
    pub ty: FieldType,
    pub access: AccessType,
    /// The default in XML encoding syntax, as the UOM gives it; "" where it gives none.
    pub default: &'static str,
    pub min: Option<Bound>,
    pub max: Option<Bound>,
    /// Enumerated string values (empty when the field has none).
    pub enumeration: &'static [&'static str],
    /// True when no values beyond `enumeration` are allowed.
    pub enumeration_strict: bool,
    /// Node types (concrete or abstract) an SFNode/MFNode field accepts.
    pub acceptable: &'static [&'static str],
    /// A component level the field needs above its node's, where the UOM states one.
    pub component: Option<ComponentLevel>,
}

/// One concrete node type, for one version.
#[derive(Debug)]
pub struct NodeDef {
    pub name: &'static str,
    pub component: ComponentLevel,
    /// The field a node of this type fills in its parent when `containerField` is not given.
    pub container_field: &'static str,
    /// Every abstract type and interface this type inherits, transitively.
    pub ancestors: &'static [&'static str],
    /// All fields, inherited ones included, sorted by name.
    pub fields: &'static [&'static FieldDef],
}

impl NodeDef {
    pub fn field(&self, name: &str) -> Option<&'static FieldDef> {
        self.fields
            .binary_search_by(|f| f.name.cmp(name))
            .ok()
            .map(|i| self.fields[i])
    }

    /// Whether this type is `type_name` or inherits it.
    pub fn is_a(&self, type_name: &str) -> bool {
        self.name == type_name || self.ancestors.contains(&type_name)
    }
}

/// A component and the highest level any of its nodes or fields needs.
#[derive(Debug)]
pub struct ComponentDef {
    pub name: &'static str,
    pub max_level: u8,
}

/// Everything the schema knows of one version.
#[derive(Debug)]
pub struct VersionSchema {
    pub version: Version,
    /// Concrete node types sorted by name.
    pub nodes: &'static [NodeDef],
    /// Components sorted by name.
    pub components: &'static [ComponentDef],
}

impl VersionSchema {
    pub fn node(&self, name: &str) -> Option<&'static NodeDef> {
        self.nodes
            .binary_search_by(|n| n.name.cmp(name))
            .ok()
            .map(|i| &self.nodes[i])
    }

    pub fn component(&self, name: &str) -> Option<&'static ComponentDef> {
        self.components
            .binary_search_by(|c| c.name.cmp(name))
            .ok()
            .map(|i| &self.components[i])
    }
}
