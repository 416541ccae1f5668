//! Typed field values, stored flat: an MFVec3f of a million points is one `Vec<f32>` of
//! three million numbers, not a million allocations. The field's [`FieldType`] (from the
//! schema) says how to read the flat data: its arity and whether it is SF or MF.
//!
//! At `--level fast`, when the document is not rendered, a numeric MF value of a schema
//! field (MFFloat, MFInt32, MFDouble and every vector, colour, rotation and matrix MF type)
//! is not kept: the reader checks each number as it parses it and keeps a [`Summary`]
//! instead, with what the fast level needs (the length, the first non-finite and
//! out-of-range element and their counts, the run sums of the report's stats). SF values,
//! declared (Script, prototype) fields and every other type are kept whole.
//!
//! [`FieldType`]: crate::schema::FieldType

use super::{Node, NodeId};
use crate::model::Span;
use crate::schema::{in_range_f32, in_range_f64};
use crate::schema::{FieldDef, FieldType, Scalar};

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
    /// A numeric MF value checked while it was read and not kept (the fast level).
    Summary(Box<Summary>),
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
            Value::Summary(s) => s.len,
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

/// What the fast level knows of a numeric MF value it did not keep. The failures are
/// `(first index, count)` over the flat scalars, as FIELD_VALUE_NONFINITE and
/// FIELD_OUT_OF_RANGE report them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Summary {
    /// [`Scalar::Int32`], [`Scalar::Float`] or [`Scalar::Double`].
    pub scalar: Scalar,
    /// Number of scalars.
    pub len: usize,
    /// NaN or an infinity (floats and doubles).
    pub nonfinite: Option<(usize, usize)>,
    /// Outside the field's range, when [`range_applies`] (else None).
    pub out_of_range: Option<(usize, usize)>,
    /// Int32 only: Σ max(n − k, 0) over the runs of n values ended by −1 or the end
    /// (`[0]` for k = 1, `[1]` for k = 2), as the stats count polygons and polylines.
    pub index_runs: [u64; 2],
    /// Int32 only: Σ max(max(v, 0) − k, 0) over the values (`[0]` for k = 1, `[1]` for
    /// k = 2), as the stats count strips, fans and line vertex counts.
    pub counts: [u64; 2],
}

impl Summary {
    /// Whether the values of a field of this type are summarized when asked.
    pub fn applies_to(ty: FieldType) -> bool {
        ty.is_mf() && matches!(ty.scalar(), Scalar::Int32 | Scalar::Float | Scalar::Double)
    }
}

/// Where a reader puts the numbers of a value as it parses them: a vector (the value
/// kept) or a [`Summarizer`]. The parsers are generic over it, so keeping costs nothing.
pub trait Sink<T> {
    fn push(&mut self, value: T);
    /// How many numbers it took.
    fn count(&self) -> usize;
    /// Takes `values` in order, as one `push` each (the numbers of a value parsed in
    /// pieces on several threads).
    fn extend_from(&mut self, values: &[T])
    where
        T: Copy,
    {
        for &value in values {
            self.push(value);
        }
    }
}

impl<T> Sink<T> for Vec<T> {
    #[inline(always)]
    fn push(&mut self, value: T) {
        Vec::push(self, value);
    }

    #[inline(always)]
    fn count(&self) -> usize {
        Vec::len(self)
    }

    fn extend_from(&mut self, values: &[T])
    where
        T: Copy,
    {
        self.extend_from_slice(values);
    }
}

/// A number a [`Summarizer`] takes: the same tests the fast-level rules make.
pub trait Summarized: Copy {
    const SCALAR: Scalar;
    fn is_finite(self) -> bool;
    fn in_range(self, def: &FieldDef) -> bool;
    /// The index run and count sums (Int32 only).
    #[inline(always)]
    fn count(self, _state: &mut RunState) {}
}

impl Summarized for f32 {
    const SCALAR: Scalar = Scalar::Float;
    #[inline(always)]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }
    #[inline(always)]
    fn in_range(self, def: &FieldDef) -> bool {
        in_range_f32(self, def)
    }
}

impl Summarized for f64 {
    const SCALAR: Scalar = Scalar::Double;
    #[inline(always)]
    fn is_finite(self) -> bool {
        f64::is_finite(self)
    }
    #[inline(always)]
    fn in_range(self, def: &FieldDef) -> bool {
        in_range_f64(self, def)
    }
}

impl Summarized for i32 {
    const SCALAR: Scalar = Scalar::Int32;
    #[inline(always)]
    fn is_finite(self) -> bool {
        true
    }
    #[inline(always)]
    fn in_range(self, def: &FieldDef) -> bool {
        in_range_f64(f64::from(self), def)
    }
    #[inline(always)]
    fn count(self, state: &mut RunState) {
        if self == -1 {
            state.end_run();
        } else {
            state.run += 1;
        }
        let n = u64::from(self.max(0) as u32);
        state.counts[0] += n.saturating_sub(1);
        state.counts[1] += n.saturating_sub(2);
    }
}

/// The run sums of an Int32 value being summarized.
#[derive(Default)]
pub struct RunState {
    run: u64,
    index_runs: [u64; 2],
    counts: [u64; 2],
}

impl RunState {
    #[inline(always)]
    fn end_run(&mut self) {
        self.index_runs[0] += self.run.saturating_sub(1);
        self.index_runs[1] += self.run.saturating_sub(2);
        self.run = 0;
    }
}

/// Checks the numbers of one value as they are parsed, keeping none of them.
pub struct Summarizer<T> {
    len: usize,
    /// The field whose range is checked, when [`range_applies`].
    range: Option<&'static FieldDef>,
    nonfinite: Option<(usize, usize)>,
    out_of_range: Option<(usize, usize)>,
    runs: RunState,
    _scalar: std::marker::PhantomData<T>,
}

#[inline(always)]
fn fail(found: &mut Option<(usize, usize)>, index: usize) {
    match found {
        None => *found = Some((index, 1)),
        Some((_, count)) => *count += 1,
    }
}

impl<T: Summarized> Summarizer<T> {
    /// For a value of the schema field `def` on `node`.
    pub fn new(node: &Node, def: &'static FieldDef) -> Summarizer<T> {
        Summarizer {
            len: 0,
            range: range_applies(node, def).then_some(def),
            nonfinite: None,
            out_of_range: None,
            runs: RunState::default(),
            _scalar: std::marker::PhantomData,
        }
    }

    pub fn finish(mut self) -> Value {
        self.runs.end_run();
        Value::Summary(Box::new(Summary {
            scalar: T::SCALAR,
            len: self.len,
            nonfinite: self.nonfinite,
            out_of_range: self.out_of_range,
            index_runs: self.runs.index_runs,
            counts: self.runs.counts,
        }))
    }
}

impl<T: Summarized> Sink<T> for Summarizer<T> {
    #[inline(always)]
    fn push(&mut self, value: T) {
        if !value.is_finite() {
            fail(&mut self.nonfinite, self.len);
        }
        if let Some(def) = self.range {
            if !value.in_range(def) {
                fail(&mut self.out_of_range, self.len);
            }
        }
        value.count(&mut self.runs);
        self.len += 1;
    }

    #[inline(always)]
    fn count(&self) -> usize {
        self.len
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

/// Whether FIELD_OUT_OF_RANGE checks the values of field `def` on `node`: the field has a range,
/// and is not a geometry index field. The fast level's summaries
/// ([`Summarizer`]) decide with this too.
pub fn range_applies(node: &Node, def: &FieldDef) -> bool {
    !(def.min.is_none() && def.max.is_none() || is_geometry_index(node, def.name))
}

/// Index fields of geometry (coordIndex, index, …) have the more specific INDEX_NEGATIVE,
/// which knows the -1 separator; reporting them here too would say the same twice.
fn is_geometry_index(node: &Node, field: &str) -> bool {
    (field == "index" || field.ends_with("Index")) && node.is_a("X3DGeometryNode")
}
