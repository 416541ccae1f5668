//! What the Rendering rules read of a geometry node: its coordinates and the colour,
//! normal and texture-coordinate lists bound to it, each with its length, and the f64
//! vector arithmetic the deep rules share.
//!
//! A value the checker cannot know is *unknown*, never empty: a field connected to a
//! prototype field by `IS` (each instance sets it), a value that did not parse (already
//! reported), a property node that is a ProtoInstance, an empty list on a DEF'd node
//! (filled by a Script or ROUTE at run time). Rules skip what is unknown, so prototypes
//! and scripted geometry never give false positives.

use rayon::prelude::*;

use crate::diagnostic::{Diagnostic, Rule};
use crate::model::faces::{Attribute, Face, Polygonal};
use crate::model::{ChildRef, Document, FieldEntry, Node, NodeId, Span, Value};
use crate::validate::Ctx;

/// Fields that decide a geometry's topology and binding: when one of them is unknown
/// the geometry is not checked.
const SHAPE_FIELDS: &[&str] = &[
    "coordIndex",
    "index",
    "colorIndex",
    "normalIndex",
    "texCoordIndex",
    "stripCount",
    "fanCount",
    "vertexCount",
    "ccw",
    "colorPerVertex",
    "normalPerVertex",
    "xDimension",
    "zDimension",
    "height",
    "coord",
    "color",
    "normal",
    "texCoord",
];

/// Whether a field's value is known: not `IS`-connected and, when set, parsed.
pub fn is_known(node: &Node, field: &str) -> bool {
    !node.is_connected(field)
        && !node
            .entry(field)
            .is_some_and(|e| matches!(e.value, Value::Unparsed(_)))
}

/// Whether every field that decides the geometry's topology and binding is known.
pub fn shape_is_known(node: &Node) -> bool {
    SHAPE_FIELDS.iter().all(|f| is_known(node, f))
}

/// A property node's value list: Coordinate.point, Color.color, Normal.vector,
/// TextureCoordinate.point and their kin.
#[derive(Copy, Clone, Debug)]
pub struct PropertyList<'a> {
    pub node: NodeId,
    pub type_name: &'a str,
    /// Where the node stands in its parent field (the element, or the USE).
    pub child_span: Span,
    /// The list's field, when the document set it.
    pub entry: Option<&'a FieldEntry>,
    pub len: usize,
    pub values: Scalars<'a>,
}

/// The flat numbers of a list.
#[derive(Copy, Clone, Debug)]
pub enum Scalars<'a> {
    Single(&'a [f32]),
    Double(&'a [f64]),
}

impl Scalars<'_> {
    /// Element `i` of a list of 3-vectors, in f64.
    #[inline]
    pub fn vec3(&self, i: usize) -> Option<[f64; 3]> {
        let at = i.checked_mul(3)?;
        match self {
            Scalars::Single(v) => v
                .get(at..at + 3)
                .map(|c| [c[0].into(), c[1].into(), c[2].into()]),
            Scalars::Double(v) => v.get(at..at + 3).map(|c| [c[0], c[1], c[2]]),
        }
    }
}

/// What a geometry's property field holds.
#[derive(Clone, Debug)]
pub enum Property<'a> {
    /// NULL: the field is not set.
    Missing,
    /// Cannot be told (IS, ProtoInstance, unparsed).
    Unknown,
    /// One list, or several for MultiTextureCoordinate.
    Lists(Vec<PropertyList<'a>>),
}

/// The list field and arity of each property node type with a countable list.
fn list_field(type_name: &str) -> Option<(&'static str, usize)> {
    Some(match type_name {
        "Coordinate" | "CoordinateDouble" | "GeoCoordinate" => ("point", 3),
        "Color" => ("color", 3),
        "ColorRGBA" => ("color", 4),
        "Normal" => ("vector", 3),
        "TextureCoordinate" => ("point", 2),
        "TextureCoordinate3D" => ("point", 3),
        "TextureCoordinate4D" => ("point", 4),
        _ => return None,
    })
}

/// The list of one property node; None when it cannot be counted.
fn property_list(doc: &Document, child: ChildRef) -> Option<PropertyList<'_>> {
    let node = doc.node(child.node);
    let type_name = node.def()?.name;
    let (field, arity) = list_field(type_name)?;
    if !is_known(node, field) {
        return None;
    }
    let entry = node.entry(field);
    let values = match entry.map(|e| &e.value) {
        None => Scalars::Single(&[]),
        Some(Value::Floats(v)) => Scalars::Single(v),
        Some(Value::Doubles(v)) => Scalars::Double(v),
        Some(_) => return None,
    };
    let scalars = match values {
        Scalars::Single(v) => v.len(),
        Scalars::Double(v) => v.len(),
    };
    // An empty list on a DEF'd node is the idiom for values a Script or ROUTE fills in
    // at run time: its length cannot be told from the document.
    if scalars == 0 && node.def_name.is_some() {
        return None;
    }
    Some(PropertyList {
        node: child.node,
        type_name,
        child_span: child.span,
        entry,
        len: scalars / arity,
        values,
    })
}

/// The lists a geometry's `field` (coord, color, normal, texCoord) holds.
pub fn property<'a>(doc: &'a Document, geometry: NodeId, field: &str) -> Property<'a> {
    let node = doc.node(geometry);
    if !is_known(node, field) {
        return Property::Unknown;
    }
    let Some(&child) = node.children(field).first() else {
        return Property::Missing;
    };
    let child_node = doc.node(child.node);
    let lists: Option<Vec<PropertyList>> = match child_node.def().map(|d| d.name) {
        // A generator computes its coordinates: there is nothing to count.
        Some("TextureCoordinateGenerator") => Some(Vec::new()),
        Some("MultiTextureCoordinate") if is_known(child_node, "texCoord") => child_node
            .children("texCoord")
            .iter()
            .filter(|c| {
                doc.node(c.node).def().map(|d| d.name) != Some("TextureCoordinateGenerator")
            })
            .map(|&c| property_list(doc, c))
            .collect(),
        _ => property_list(doc, child).map(|l| vec![l]),
    };
    lists.map_or(Property::Unknown, Property::Lists)
}

/// The coordinate list of a geometry with a `coord` field, when it is known and single.
pub fn coord_list<'a>(doc: &'a Document, geometry: NodeId) -> Option<PropertyList<'a>> {
    match property(doc, geometry, "coord") {
        Property::Lists(lists) if lists.len() == 1 => lists.into_iter().next(),
        _ => None,
    }
}

/// A polygonal geometry whose shape fields are all known, with its coordinate list (None
/// for ElevationGrid and for a NULL coord).
pub struct Checked<'a> {
    pub id: NodeId,
    pub node: &'a Node,
    pub faces: Polygonal<'a>,
    pub coord: Option<PropertyList<'a>>,
}

/// Every polygonal geometry of the document that can be checked: known shape fields and,
/// except for ElevationGrid, a known coordinate list.
pub fn polygonal(doc: &Document) -> impl Iterator<Item = Checked<'_>> {
    doc.iter().filter_map(move |(id, node)| {
        if !shape_is_known(node) {
            return None;
        }
        let faces = Polygonal::read(doc, id, 0)?;
        if !faces.kind.has_coord() {
            return Some(Checked {
                id,
                node,
                faces,
                coord: None,
            });
        }
        let coord = coord_list(doc, id)?;
        let faces = Polygonal::read(doc, id, coord.len)?;
        Some(Checked {
            id,
            node,
            faces,
            coord: Some(coord),
        })
    })
}

/// Every geometry of [`polygonal`] with what `judge` makes of it (None: nothing), in
/// document order. Geometries are judged in parallel: a judgement is a few counts, so
/// memory stays bounded, and a large file's deep check uses every core.
pub fn judge_polygonal<'a, T: Send>(
    doc: &'a Document,
    judge: impl Fn(&Checked<'a>) -> Option<T> + Sync,
) -> Vec<(Checked<'a>, T)> {
    let geometries: Vec<Checked<'a>> = polygonal(doc).collect();
    let judged: Vec<Option<T>> = geometries.par_iter().map(&judge).collect();
    geometries
        .into_iter()
        .zip(judged)
        .filter_map(|(geometry, judged)| Some((geometry, judged?)))
        .collect()
}

/// The vertex positions of a checked geometry, in f64: its coordinates, or an
/// ElevationGrid's grid points. None for geospatial coordinates, whose numbers are not
/// Cartesian.
pub enum Points<'a> {
    List(Scalars<'a>),
    Grid {
        heights: &'a [f32],
        x: usize,
        x_spacing: f64,
        z_spacing: f64,
    },
}

impl Points<'_> {
    pub fn of<'a>(doc: &'a Document, geometry: &Checked<'a>) -> Option<Points<'a>> {
        match &geometry.coord {
            Some(list) if list.type_name == "GeoCoordinate" => None,
            Some(list) => Some(Points::List(list.values)),
            None => Some(Points::Grid {
                heights: geometry
                    .node
                    .value("height")
                    .and_then(Value::as_floats)
                    .unwrap_or(&[]),
                x: doc
                    .i32_of(geometry.id, "xDimension")
                    .map_or(0, |x| x.max(0) as usize),
                x_spacing: doc.f32_of(geometry.id, "xSpacing").map_or(1.0, f64::from),
                z_spacing: doc.f32_of(geometry.id, "zSpacing").map_or(1.0, f64::from),
            }),
        }
    }

    /// The position of a vertex; None past the end or when not finite.
    #[inline]
    pub fn get(&self, vertex: usize) -> Option<[f64; 3]> {
        let point = match self {
            Points::List(values) => values.vec3(vertex)?,
            Points::Grid {
                heights,
                x,
                x_spacing,
                z_spacing,
            } => {
                let height = f64::from(*heights.get(vertex)?);
                let (i, j) = (vertex % x, vertex / x);
                [i as f64 * x_spacing, height, j as f64 * z_spacing]
            }
        };
        finite(point)
    }
}

/// The point, when all its coordinates are finite.
#[inline]
pub fn finite(point: [f64; 3]) -> Option<[f64; 3]> {
    point.iter().all(|c| c.is_finite()).then_some(point)
}

/// The attribute's lists as bound to a geometry; None when unknown.
pub fn attribute_lists<'a>(
    doc: &'a Document,
    geometry: NodeId,
    attribute: Attribute,
) -> Option<Vec<PropertyList<'a>>> {
    match property(doc, geometry, attribute.field()) {
        Property::Missing => Some(Vec::new()),
        Property::Unknown => None,
        Property::Lists(lists) => Some(lists),
    }
}

/// The places of a field's numbers, found in one forward pass: asking for the k-th number
/// after the j-th (k ≥ j) costs only the text between them, so that reporting every bad
/// element of a million-element field stays linear. Separators are those of the XML and
/// JSON encodings (white space, commas, brackets), and comments in ClassicVRML.
pub struct ScalarSpans<'s> {
    text: &'s [u8],
    base: usize,
    whole: Span,
    /// Offset in `text` after the last number found, and how many were found.
    at: usize,
    seen: usize,
}

impl<'s> ScalarSpans<'s> {
    pub fn new(source: &'s [u8], entry: &FieldEntry) -> ScalarSpans<'s> {
        let range = entry.span.range();
        ScalarSpans {
            text: source.get(range.clone()).unwrap_or_default(),
            base: range.start,
            whole: entry.span,
            at: 0,
            seen: 0,
        }
    }

    /// The span of number `k`; the whole value when `k` is behind the cursor or not found.
    pub fn span(&mut self, k: usize) -> Span {
        let is_separator = |b: u8| b.is_ascii_whitespace() || matches!(b, b',' | b'[' | b']');
        if k < self.seen {
            return self.whole;
        }
        while self.at < self.text.len() {
            if is_separator(self.text[self.at]) {
                self.at += 1;
                continue;
            }
            if self.text[self.at] == b'#' {
                self.at = crate::validate::comment_end(self.text, self.at);
                continue;
            }
            let start = self.at;
            while self.at < self.text.len()
                && !is_separator(self.text[self.at])
                && self.text[self.at] != b'#'
            {
                self.at += 1;
            }
            self.seen += 1;
            if self.seen == k + 1 {
                return Span::new(self.base + start, self.base + self.at);
            }
        }
        self.whole
    }

    /// The span from number `first` to number `last` (`first ≤ last`).
    pub fn span_of(&mut self, first: usize, last: usize) -> Span {
        let start = self.span(first);
        let end = if last > first { self.span(last) } else { start };
        if start == self.whole || end == self.whole {
            return self.whole;
        }
        Span {
            start: start.start,
            end: end.end,
        }
    }
}

/// The numbers written in `text` (a span of a field's value), one space apart: without
/// the comments and line breaks a ClassicVRML value may hold between them.
fn numbers_text(text: &[u8]) -> String {
    let mut words = Vec::new();
    let mut at = 0;
    while at < text.len() {
        match text[at] {
            b'#' => at = crate::validate::comment_end(text, at),
            b if b.is_ascii_whitespace() || b == b',' => at += 1,
            _ => {
                let start = at;
                while at < text.len()
                    && !(text[at].is_ascii_whitespace() || matches!(text[at], b',' | b'#'))
                {
                    at += 1;
                }
                words.push(String::from_utf8_lossy(&text[start..at]));
            }
        }
    }
    words.join(" ")
}

/// A LineSet, TriangleStripSet or TriangleFanSet with its count field and coordinates.
pub struct Counted<'a> {
    pub type_name: &'static str,
    pub field: &'static str,
    /// The count field's entry, when set.
    pub entry: Option<&'a FieldEntry>,
    /// The sum of the counts; negative counts (FIELD_OUT_OF_RANGE) add nothing.
    pub total: u64,
    pub coord: PropertyList<'a>,
}

/// The counted geometries whose counts and coordinates are known.
pub fn counted(doc: &Document) -> impl Iterator<Item = (NodeId, Counted<'_>)> {
    doc.iter().filter_map(move |(id, node)| {
        let type_name = node.def()?.name;
        let field = match type_name {
            "LineSet" => "vertexCount",
            "TriangleStripSet" => "stripCount",
            "TriangleFanSet" => "fanCount",
            _ => return None,
        };
        if !shape_is_known(node) {
            return None;
        }
        let entry = node.entry(field);
        let counts = entry.and_then(|e| e.value.as_int32s()).unwrap_or(&[]);
        let total = counts.iter().map(|&c| c.max(0) as u64).sum();
        let coord = coord_list(doc, id)?;
        Some((
            id,
            Counted {
                type_name,
                field,
                entry,
                total,
                coord,
            },
        ))
    })
}

/// The fields whose vectors are normals, which "shall have unit length": Normal's (11.2.1)
/// and NormalInterpolator's key values ("Values in the keyValue field shall be of unit
/// length", 19.4).
const NORMAL_FIELDS: [(&str, &str); 2] = [("Normal", "vector"), ("NormalInterpolator", "keyValue")];

/// Reports every normal vector (of `NORMAL_FIELDS`) that `judge` (given its f64 length)
/// finds fault with, as `Normal.vector[k] = x y z <what judge says>` (or
/// `NormalInterpolator.keyValue[k] = …`) with the vector as the document writes it, folded
/// per node. Non-finite vectors are skipped:
/// FIELD_VALUE_NONFINITE reports them.
pub fn each_normal(ctx: &mut Ctx, rule: &'static Rule, judge: impl Fn(f64) -> Option<String>) {
    for (type_name, field) in NORMAL_FIELDS {
        each_normal_of(ctx, rule, &judge, type_name, field);
    }
}

fn each_normal_of(
    ctx: &mut Ctx,
    rule: &'static Rule,
    judge: &impl Fn(f64) -> Option<String>,
    type_name: &'static str,
    field: &'static str,
) {
    let doc = ctx.doc;
    for id in doc.nodes_of_type(type_name) {
        let node = doc.node(id);
        if !is_known(node, field) {
            continue;
        }
        let Some(entry) = node.entry(field) else {
            continue;
        };
        let Some(values) = entry.value.as_floats() else {
            continue;
        };
        let source = ctx.source;
        let mut spans = ScalarSpans::new(source, entry);
        for (k, v) in values.chunks_exact(3).enumerate() {
            if !v.iter().all(|c| c.is_finite()) {
                continue;
            }
            // `length` of a finite f32 vector: no square of one over- or underflows.
            let v = [v[0], v[1], v[2]].map(f64::from);
            let Some(what) = judge(dot(v, v).sqrt()) else {
                continue;
            };
            ctx.report_repeated(rule, id, field, k, || {
                let span = spans.span_of(3 * k, 3 * k + 2);
                let text = numbers_text(source.get(span.range()).unwrap_or_default());
                Diagnostic::new(
                    rule,
                    span,
                    format!("{type_name}.{field}[{k}] = {text} {what}"),
                )
                .node(id)
                .value(text)
            });
        }
    }
}

#[inline]
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline]
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The largest absolute component.
#[inline]
fn max_abs(v: [f64; 3]) -> f64 {
    v[0].abs().max(v[1].abs()).max(v[2].abs())
}

/// Largest components within which vectors need no scaling: a square, or a product of
/// four components (the cross product's squared length in [`is_degenerate`]), neither
/// overflows nor leaves the normal range of f64 (2^±800 against 2^±1022). Every
/// coordinate and every difference of coordinates read as f32 lies inside.
pub const UNSCALED: std::ops::RangeInclusive<f64> = 1.0e-60..=1.0e60;

/// `v` scaled so that squaring neither overflows nor underflows: unchanged when its
/// largest component is in [`UNSCALED`], else divided by that component; None for the
/// zero vector and non-finite ones. Callers use it only where the scale cancels out.
#[inline]
pub fn scaled(v: [f64; 3]) -> Option<[f64; 3]> {
    let m = max_abs(v);
    if !(m > 0.0 && v.iter().all(|c| c.is_finite())) {
        return None;
    }
    Some(if UNSCALED.contains(&m) {
        v
    } else {
        [v[0] / m, v[1] / m, v[2] / m]
    })
}

/// The Euclidean length, exact for every finite input from 1e-320 to 1e308: computed
/// directly when no square can overflow or underflow, else on the vector scaled by its
/// largest component.
pub fn length(v: [f64; 3]) -> f64 {
    if v.iter().any(|c| c.is_nan()) {
        return f64::NAN;
    }
    let m = max_abs(v);
    if UNSCALED.contains(&m) {
        return dot(v, v).sqrt();
    }
    match scaled(v) {
        Some(s) => m * dot(s, s).sqrt(),
        None => m,
    }
}

/// The unit vector along `v`; None for zero and non-finite vectors.
#[inline]
pub fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let s = scaled(v)?;
    let l = dot(s, s).sqrt();
    Some([s[0] / l, s[1] / l, s[2] / l])
}

/// Below this sine of the angle between its edges, a triangle counts as zero-area. f32
/// coordinates carry about 7 digits, so collinear points written in decimal come out a
/// few 1e-8 off their line: 1e-6 (about 0.2 arc seconds) keeps those degenerate and every
/// triangle a modeller means to draw not.
pub const DEGENERATE_SINE: f64 = 1e-6;

/// Whether the triangle a, b, c has zero area relative to its edges: the sine of the
/// angle at `a` between its edges is below [`DEGENERATE_SINE`], or two corners
/// coincide. An edge outside [`UNSCALED`] is scaled by its own largest component first,
/// which the sine does not depend on, so huge and tiny coordinates give the same answer.
/// None when a corner is not finite.
pub fn is_degenerate(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Option<bool> {
    let (e1, e2) = (sub(b, a), sub(c, a));
    if !(e1.iter().chain(&e2).all(|x| x.is_finite())) {
        return None;
    }
    let (Some(u), Some(v)) = (scaled(e1), scaled(e2)) else {
        return Some(true);
    };
    let n = cross(u, v);
    Some(dot(n, n) <= DEGENERATE_SINE * DEGENERATE_SINE * dot(u, u) * dot(v, v))
}

/// The position of a face's corner: None when its index or coordinates do not resolve.
#[inline]
pub fn corner_point(g: &Checked, points: &Points, position: usize) -> Option<[f64; 3]> {
    points.get(g.faces.coord_index(position)?)
}

/// A face's corners resolved once: whether it has zero area and what its geometric normal
/// is made of.
pub struct FaceShape {
    /// Whether the face has zero area: fewer than three corners, or every triangle of its
    /// fan degenerate (which happens exactly when all its corners are collinear). None
    /// when a corner does not resolve to finite coordinates.
    pub degenerate: Option<bool>,
    /// The sum of the fan's cross products.
    sum: [f64; 3],
    /// The sum of the fan's edge-length products, against which `sum` is negligible.
    scale: f64,
}

impl FaceShape {
    pub fn of(g: &Checked, points: &Points, face: &Face) -> FaceShape {
        FaceShape::with(face, |p| corner_point(g, points, p))
    }

    /// [`FaceShape::of`] with each corner's point given by `corner` (from its stream
    /// position), for callers that resolve corners faster than [`corner_point`] can.
    #[inline]
    pub fn with(face: &Face, corner: impl Fn(usize) -> Option<[f64; 3]>) -> FaceShape {
        let unresolved = FaceShape {
            degenerate: None,
            sum: [0.0; 3],
            scale: 0.0,
        };
        if face.len() < 3 {
            let resolved = face.corners().all(|p| corner(p).is_some());
            return FaceShape {
                degenerate: resolved.then_some(true),
                ..unresolved
            };
        }
        let Some(first) = corner(face.corner(0)) else {
            return unresolved;
        };
        let (mut sum, mut scale, mut degenerate) = ([0.0; 3], 0.0, true);
        for [_, b, c] in face.triangles() {
            let (Some(b), Some(c)) = (corner(b), corner(c)) else {
                return unresolved;
            };
            let Some(fan) = FanTriangle::of(first, b, c) else {
                return unresolved;
            };
            degenerate &= fan.degenerate;
            for (s, x) in sum.iter_mut().zip(fan.cross) {
                *s += x;
            }
            scale += fan.edge_lengths;
        }
        FaceShape {
            degenerate: Some(degenerate),
            sum,
            scale,
        }
    }

    /// [`FaceShape::with`] for a triangle whose corners are resolved to finite points
    /// (its fan is the one triangle), for callers that walk triangles directly.
    #[inline(always)]
    pub fn triangle(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> FaceShape {
        let Some(fan) = FanTriangle::of(a, b, c) else {
            return FaceShape {
                degenerate: None,
                sum: [0.0; 3],
                scale: 0.0,
            };
        };
        // The sums `with` starts from zero, kept so that the result is the same to the bit.
        FaceShape {
            degenerate: Some(fan.degenerate),
            sum: fan.cross.map(|x| 0.0 + x),
            scale: 0.0 + fan.edge_lengths,
        }
    }

    /// The geometric unit normal by the right-hand rule over the corners in order (ccw not
    /// applied): the sum of the fan's cross products, in f64, which is exact for concave
    /// polygons too. None when a corner does not resolve, the face is degenerate, or the
    /// sum is negligible next to its edges (a self-intersecting face that cancels out).
    pub fn normal(&self) -> Option<[f64; 3]> {
        if self.degenerate != Some(false) {
            return None;
        }
        if UNSCALED.contains(&max_abs(self.sum)) {
            // length's and unit's arithmetic on an unscaled vector, sharing the root.
            let l = dot(self.sum, self.sum).sqrt();
            return (l > DEGENERATE_SINE * self.scale).then(|| self.sum.map(|c| c / l));
        }
        (length(self.sum) > DEGENERATE_SINE * self.scale)
            .then(|| unit(self.sum))
            .flatten()
    }
}

/// A face's geometric unit normal: [`FaceShape::normal`].
pub fn face_normal(g: &Checked, points: &Points, face: &Face) -> Option<[f64; 3]> {
    FaceShape::of(g, points, face).normal()
}

/// One triangle a, b, c of a face's fan, judged once for both [`FaceShape`]'s sum and
/// its degeneracy.
struct FanTriangle {
    /// (b − a) × (c − a).
    cross: [f64; 3],
    /// As [`is_degenerate`] decides.
    degenerate: bool,
    /// |b − a| · |c − a|.
    edge_lengths: f64,
}

impl FanTriangle {
    /// None when a corner is not finite.
    #[inline(always)]
    fn of(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Option<FanTriangle> {
        let (e1, e2) = (sub(b, a), sub(c, a));
        let cross = cross(e1, e2);
        if UNSCALED.contains(&max_abs(e1)) && UNSCALED.contains(&max_abs(e2)) {
            // is_degenerate's own arithmetic on unscaled edges, sharing the cross product.
            let (q1, q2) = (dot(e1, e1), dot(e2, e2));
            return Some(FanTriangle {
                cross,
                degenerate: dot(cross, cross) <= DEGENERATE_SINE * DEGENERATE_SINE * q1 * q2,
                edge_lengths: (q1 * q2).sqrt(),
            });
        }
        Some(FanTriangle {
            cross,
            degenerate: is_degenerate(a, b, c)?,
            edge_lengths: length(e1) * length(e2),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_neither_underflow_nor_overflow() {
        assert_eq!(length([1e-30, 0.0, 0.0]), 1e-30);
        assert_eq!(length([3e38, 0.0, 0.0]), 3e38);
        assert_eq!(length([f64::MAX, 0.0, 0.0]), f64::MAX);
        assert_eq!(length([5e-324, 0.0, 0.0]), 5e-324);
        assert!((length([3e200, 4e200, 0.0]) - 5e200).abs() <= 5e200 * 1e-15);
        assert!((length([3e-200, 4e-200, 0.0]) - 5e-200).abs() <= 5e-200 * 1e-15);
        assert_eq!(length([0.0, -0.0, 0.0]), 0.0);
        assert!(length([f64::NAN, 0.0, 0.0]).is_nan());
        assert_eq!(unit([0.0, 0.0, -1e-40]), Some([0.0, 0.0, -1.0]));
        assert_eq!(unit([-0.0, 0.0, 0.0]), None);
        assert_eq!(unit([f64::NAN, 1.0, 0.0]), None);
        assert_eq!(length([f64::INFINITY, 1.0, 0.0]), f64::INFINITY);
    }

    #[test]
    fn degenerate_triangles_are_judged_relative_to_their_edges() {
        let o = [0.0, 0.0, 0.0];
        assert_eq!(
            is_degenerate(o, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            Some(false)
        );
        assert_eq!(is_degenerate(o, o, [0.0, 1.0, 0.0]), Some(true));
        assert_eq!(
            is_degenerate(o, [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]),
            Some(true)
        );
        // f32-rounded collinear points: 0.1 and 0.3 are not exact.
        let f = |x: f32| f64::from(x);
        let (a, b) = ([f(0.1); 3], [f(0.3); 3]);
        assert_eq!(is_degenerate(o, a, b), Some(true));
        // Huge finite coordinates: a real triangle stays real, a flat one flat.
        let big = f64::from(f32::MAX);
        assert_eq!(
            is_degenerate([-big, -big, 0.0], [big, -big, 0.0], [0.0, big, 0.0]),
            Some(false)
        );
        assert_eq!(
            is_degenerate([-big, 0.0, 0.0], [big, 0.0, 0.0], [0.0, 0.0, 0.0]),
            Some(true)
        );
        // Tiny ones too.
        let tiny = f64::from(f32::from_bits(1));
        assert_eq!(
            is_degenerate(o, [tiny, 0.0, 0.0], [0.0, tiny, 0.0]),
            Some(false)
        );
        // A thin but real sliver (1e-4 rad) is not degenerate.
        assert_eq!(
            is_degenerate(o, [1.0, 0.0, 0.0], [1.0, 1e-4, 0.0]),
            Some(false)
        );
        assert_eq!(
            is_degenerate(o, [f64::INFINITY, 0.0, 0.0], [0.0, 1.0, 0.0]),
            None
        );
    }
}
