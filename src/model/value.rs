//! Typed field values, stored flat: an MFVec3f of a million points is one `Vec<f32>` of
//! three million numbers, not a million allocations. The field's [`FieldType`] (from the
//! schema) says how to read the flat data: its arity and whether it is SF or MF.
//!
//! [`FieldType`]: crate::schema::FieldType

use super::NodeId;
use crate::model::Span;

/// The parsed value of one field as the document gave it.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Bools(Vec<bool>),
    Int32s(Vec<i32>),
    /// SFFloat and every single-precision vector, colour, rotation and matrix type.
    Floats(Vec<f32>),
    /// SFDouble, SFTime and every double-precision type.
    Doubles(Vec<f64>),
    Strings(Vec<String>),
    Images(Vec<Image>),
    /// SFNode and MFNode: the nodes given, in document order. An SFNode field holding
    /// more than one is kept as it is so that the checker can report it.
    Nodes(Vec<ChildRef>),
    /// The text of a field the schema does not know, or whose value did not parse
    /// (the parser has reported why).
    Unparsed(String),
}

impl Value {
    /// Number of scalars (or strings, images, nodes) held.
    pub fn len(&self) -> usize {
        match self {
            Value::Bools(v) => v.len(),
            Value::Int32s(v) => v.len(),
            Value::Floats(v) => v.len(),
            Value::Doubles(v) => v.len(),
            Value::Strings(v) => v.len(),
            Value::Images(v) => v.len(),
            Value::Nodes(v) => v.len(),
            Value::Unparsed(_) => 0,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn as_floats(&self) -> Option<&[f32]> {
        match self {
            Value::Floats(v) => Some(v),
            _ => None,
        }
    }

    pub fn as_doubles(&self) -> Option<&[f64]> {
        match self {
            Value::Doubles(v) => Some(v),
            _ => None,
        }
    }

    pub fn as_int32s(&self) -> Option<&[i32]> {
        match self {
            Value::Int32s(v) => Some(v),
            _ => None,
        }
    }

    pub fn as_bools(&self) -> Option<&[bool]> {
        match self {
            Value::Bools(v) => Some(v),
            _ => None,
        }
    }

    pub fn as_strings(&self) -> Option<&[String]> {
        match self {
            Value::Strings(v) => Some(v),
            _ => None,
        }
    }

    pub fn as_nodes(&self) -> Option<&[ChildRef]> {
        match self {
            Value::Nodes(v) => Some(v),
            _ => None,
        }
    }

    pub fn as_images(&self) -> Option<&[Image]> {
        match self {
            Value::Images(v) => Some(v),
            _ => None,
        }
    }
}

/// An SFImage: width, height, components (0–4) and one packed integer per pixel, rows
/// from the bottom up (19775-1 5.3.6). Stored as given; the checker compares the pixel
/// count with width × height.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: i32,
    pub height: i32,
    pub components: i32,
    pub pixels: Vec<u32>,
}

/// A node given to a node field: the node itself, or a `USE` of a DEF'd one. A USE is a
/// second reference to the same arena node, so sharing is explicit and the graph is a DAG.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ChildRef {
    pub node: NodeId,
    /// Where this reference stands in the document: the child element (or JSON object)
    /// itself, which for a USE is the USE element.
    pub span: Span,
    pub is_use: bool,
}
