//! The faces of every polygonal geometry node, as corner lists over one *vertex stream*,
//! with the rules that bind colours, normals and texture coordinates to those corners.
//! The validator and the renderer both read geometry through this module, so that the
//! two agree on what a node means.
//!
//! The vertex stream of a node is the list its faces are cut from:
//! - IndexedFaceSet (19775-1 13.3.6): `coordIndex`, one polygon per run of indices ended
//!   by `-1` (the last run need not be). Polygons are triangulated as a fan from their
//!   first corner, which is exact for the convex polygons `convex TRUE` promises; a
//!   concave-aware triangulation is the renderer's business.
//! - IndexedTriangleSet (11.4.7) and IndexedQuadSet (32.4.5): `index`, three (four)
//!   consecutive entries per face; a shorter rest is ignored.
//! - TriangleSet (11.4.13) and QuadSet (32.4.6): the coordinates themselves in order,
//!   three (four) per face; a shorter rest is ignored.
//! - IndexedTriangleStripSet (11.4.8) and IndexedTriangleFanSet (11.4.6): `index`, one
//!   strip (fan) per run ended by `-1`. TriangleStripSet (11.4.14) and TriangleFanSet
//!   (11.4.12): the coordinates in order, `stripCount[n]` (`fanCount[n]`) per strip
//!   (fan). Strip triangle k is (k, k+1, k+2), with the first two swapped for odd k so
//!   that every triangle keeps the strip's winding; fan triangle k is (0, k+1, k+2).
//! - ElevationGrid (13.3.4): the `xDimension × zDimension` grid vertices, numbered
//!   `i + j × xDimension` for column i and row j; one quadrilateral per grid cell, its
//!   corners ordered so that `ccw TRUE` gives normals towards +y.
//!
//! A *position* is an offset into the vertex stream; [`Polygonal::coord_index`] maps it
//! to a coordinate index. Every negative index ends a run (the checker reports those
//! other than `-1`); indices are never trusted: a corner whose index is negative or past
//! the end of a list simply resolves to `None` or is looked up by the caller with
//! `get`. Nothing here allocates per face.

use std::ops::Range;

use super::{Document, NodeId, Value};

/// The polygonal geometry node types.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum PolygonKind {
    IndexedFaceSet,
    IndexedTriangleSet,
    IndexedTriangleFanSet,
    IndexedTriangleStripSet,
    TriangleSet,
    TriangleFanSet,
    TriangleStripSet,
    QuadSet,
    IndexedQuadSet,
    ElevationGrid,
}

impl PolygonKind {
    pub const ALL: [PolygonKind; 10] = [
        PolygonKind::IndexedFaceSet,
        PolygonKind::IndexedTriangleSet,
        PolygonKind::IndexedTriangleFanSet,
        PolygonKind::IndexedTriangleStripSet,
        PolygonKind::TriangleSet,
        PolygonKind::TriangleFanSet,
        PolygonKind::TriangleStripSet,
        PolygonKind::QuadSet,
        PolygonKind::IndexedQuadSet,
        PolygonKind::ElevationGrid,
    ];

    pub fn of(type_name: &str) -> Option<PolygonKind> {
        PolygonKind::ALL.into_iter().find(|k| k.name() == type_name)
    }

    pub fn name(self) -> &'static str {
        match self {
            PolygonKind::IndexedFaceSet => "IndexedFaceSet",
            PolygonKind::IndexedTriangleSet => "IndexedTriangleSet",
            PolygonKind::IndexedTriangleFanSet => "IndexedTriangleFanSet",
            PolygonKind::IndexedTriangleStripSet => "IndexedTriangleStripSet",
            PolygonKind::TriangleSet => "TriangleSet",
            PolygonKind::TriangleFanSet => "TriangleFanSet",
            PolygonKind::TriangleStripSet => "TriangleStripSet",
            PolygonKind::QuadSet => "QuadSet",
            PolygonKind::IndexedQuadSet => "IndexedQuadSet",
            PolygonKind::ElevationGrid => "ElevationGrid",
        }
    }

    /// The field holding the vertex indices, for the indexed nodes.
    pub fn index_field(self) -> Option<&'static str> {
        match self {
            PolygonKind::IndexedFaceSet => Some("coordIndex"),
            PolygonKind::IndexedTriangleSet
            | PolygonKind::IndexedTriangleFanSet
            | PolygonKind::IndexedTriangleStripSet
            | PolygonKind::IndexedQuadSet => Some("index"),
            _ => None,
        }
    }

    /// The field of per-strip or per-fan vertex counts, for the counted nodes.
    pub fn count_field(self) -> Option<&'static str> {
        match self {
            PolygonKind::TriangleFanSet => Some("fanCount"),
            PolygonKind::TriangleStripSet => Some("stripCount"),
            _ => None,
        }
    }

    /// Whether the node's `colorPerVertex` is ignored and treated as TRUE: every
    /// triangle and quad set says so (11.4.6–11.4.8, 11.4.12–11.4.14, 32.4.5, 32.4.6).
    pub fn colors_always_per_vertex(self) -> bool {
        !matches!(
            self,
            PolygonKind::IndexedFaceSet | PolygonKind::ElevationGrid
        )
    }

    /// Whether the node takes its vertices from a `coord` field (all but ElevationGrid).
    pub fn has_coord(self) -> bool {
        self != PolygonKind::ElevationGrid
    }

    /// Corners per face for the nodes whose faces all have the same size.
    fn fixed_face_size(self) -> Option<usize> {
        match self {
            PolygonKind::IndexedTriangleSet | PolygonKind::TriangleSet => Some(3),
            PolygonKind::IndexedQuadSet | PolygonKind::QuadSet => Some(4),
            _ => None,
        }
    }
}

/// The per-vertex property lists a geometry can bind to its corners.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Attribute {
    Color,
    Normal,
    TexCoord,
}

impl Attribute {
    /// The node field holding the attribute's values.
    pub fn field(self) -> &'static str {
        match self {
            Attribute::Color => "color",
            Attribute::Normal => "normal",
            Attribute::TexCoord => "texCoord",
        }
    }

    /// The IndexedFaceSet field indexing the attribute's values.
    pub fn index_field(self) -> &'static str {
        match self {
            Attribute::Color => "colorIndex",
            Attribute::Normal => "normalIndex",
            Attribute::TexCoord => "texCoordIndex",
        }
    }
}

/// How an attribute's values are bound to a geometry's corners.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Binding<'a> {
    /// One value per corner: `index[position]` where an index list is given (IndexedFaceSet
    /// colorIndex, normalIndex, texCoordIndex), else the corner's coordinate index (or
    /// grid vertex number): the values are applied "in the same manner" as coordinates.
    PerVertex { index: Option<&'a [i32]> },
    /// One value per face: `index[face number]` where an index list is given, else the
    /// face number itself.
    PerFace { index: Option<&'a [i32]> },
}

#[derive(Copy, Clone, Debug)]
enum Stream<'a> {
    /// Positions are offsets into an index list.
    Indexed(&'a [i32]),
    /// Positions are coordinate indices: `0..len`.
    Sequential(usize),
    /// ElevationGrid: positions are grid vertex numbers of an `x × z` grid.
    Grid { x: usize, z: usize },
}

/// A polygonal geometry node read for its faces: the fields that decide topology and
/// attribute binding, borrowed from the document.
#[derive(Copy, Clone, Debug)]
pub struct Polygonal<'a> {
    pub kind: PolygonKind,
    pub ccw: bool,
    pub color_per_vertex: bool,
    pub normal_per_vertex: bool,
    stream: Stream<'a>,
    /// stripCount or fanCount.
    counts: &'a [i32],
    color_index: &'a [i32],
    normal_index: &'a [i32],
    tex_coord_index: &'a [i32],
}

fn int32s<'a>(doc: &'a Document, node: NodeId, name: &str) -> &'a [i32] {
    doc.node(node)
        .value(name)
        .and_then(Value::as_int32s)
        .unwrap_or(&[])
}

fn non_negative(value: Option<i32>) -> usize {
    value.map_or(0, |v| v.max(0) as usize)
}

impl<'a> Polygonal<'a> {
    /// Reads a polygonal node. `coord_count` is the number of coordinates of its `coord`
    /// node (0 when it has none): the vertex stream of the non-indexed nodes. An
    /// ElevationGrid's grid is cut to the rows its `height` values fill, so that a huge
    /// declared size over a short list costs nothing.
    pub fn read(doc: &'a Document, node: NodeId, coord_count: usize) -> Option<Polygonal<'a>> {
        let kind = PolygonKind::of(doc.node(node).def()?.name)?;
        let stream = match kind {
            PolygonKind::ElevationGrid => {
                let x = non_negative(doc.i32_of(node, "xDimension"));
                let z = non_negative(doc.i32_of(node, "zDimension"));
                let heights = doc.node(node).value("height").map_or(0, Value::len);
                let filled_rows = heights.checked_div(x).unwrap_or(0);
                Stream::Grid {
                    x,
                    z: z.min(filled_rows),
                }
            }
            _ => match kind.index_field() {
                Some(field) => Stream::Indexed(int32s(doc, node, field)),
                None => Stream::Sequential(coord_count),
            },
        };
        let ifs = kind == PolygonKind::IndexedFaceSet;
        let ifs_list = |name| if ifs { int32s(doc, node, name) } else { &[] };
        Some(Polygonal {
            kind,
            ccw: doc.bool_of(node, "ccw").unwrap_or(true),
            color_per_vertex: doc.bool_of(node, "colorPerVertex").unwrap_or(true),
            normal_per_vertex: doc.bool_of(node, "normalPerVertex").unwrap_or(true),
            stream,
            counts: kind.count_field().map_or(&[], |f| int32s(doc, node, f)),
            color_index: ifs_list("colorIndex"),
            normal_index: ifs_list("normalIndex"),
            tex_coord_index: ifs_list("texCoordIndex"),
        })
    }

    /// The index list positions are offsets into, for the indexed nodes.
    pub fn indices(&self) -> Option<&'a [i32]> {
        match self.stream {
            Stream::Indexed(list) => Some(list),
            _ => None,
        }
    }

    /// Length of the vertex stream.
    pub fn stream_len(&self) -> usize {
        match self.stream {
            Stream::Indexed(list) => list.len(),
            Stream::Sequential(len) => len,
            Stream::Grid { x, z } => x.saturating_mul(z),
        }
    }

    /// The coordinate index (grid vertex number) at a stream position; None for a
    /// negative index or a position past the stream.
    #[inline]
    pub fn coord_index(&self, position: usize) -> Option<usize> {
        match self.stream {
            Stream::Indexed(list) => list.get(position).and_then(|&i| usize::try_from(i).ok()),
            _ => (position < self.stream_len()).then_some(position),
        }
    }

    pub fn faces(&self) -> Faces<'_, 'a> {
        Faces {
            geometry: self,
            at: 0,
            number: 0,
            run: 0..0,
            triangle: 0,
            next_count: 0,
        }
    }

    pub fn face_count(&self) -> usize {
        match (self.kind.fixed_face_size(), self.stream) {
            (Some(size), _) => self.stream_len() / size,
            (None, Stream::Grid { x, z }) => x.saturating_sub(1) * z.saturating_sub(1),
            _ => self.faces().count(),
        }
    }

    /// How `attribute` is bound to the corners (13.3.4, 13.3.6, 11.4, 32.4).
    pub fn binding(&self, attribute: Attribute) -> Binding<'a> {
        let listed = |list: &'a [i32]| (!list.is_empty()).then_some(list);
        match (self.kind, attribute) {
            (PolygonKind::IndexedFaceSet, Attribute::Color) => {
                per(self.color_per_vertex, listed(self.color_index))
            }
            (PolygonKind::IndexedFaceSet, Attribute::Normal) => {
                per(self.normal_per_vertex, listed(self.normal_index))
            }
            (PolygonKind::IndexedFaceSet, Attribute::TexCoord) => Binding::PerVertex {
                index: listed(self.tex_coord_index),
            },
            (PolygonKind::ElevationGrid, Attribute::Color) => per(self.color_per_vertex, None),
            (_, Attribute::Normal) => per(self.normal_per_vertex, None),
            _ => Binding::PerVertex { index: None },
        }
    }

    /// The index into `attribute`'s values used at stream position `position` of `face`;
    /// None where the binding gives a negative or no index. A per-vertex index list
    /// shorter than the vertex stream falls back to the coordinate index past its end
    /// (13.3.6 states no count for colorIndex and normalIndex; browsers do this).
    pub fn attribute_index(
        &self,
        attribute: Attribute,
        face: &Face,
        position: usize,
    ) -> Option<usize> {
        self.bound_index(self.binding(attribute), face, position)
    }

    /// [`Polygonal::attribute_index`] with the attribute's binding already looked up, for
    /// callers that visit every corner.
    #[inline]
    pub fn bound_index(&self, binding: Binding, face: &Face, position: usize) -> Option<usize> {
        let index = |list: &[i32], at: usize| list.get(at).and_then(|&i| usize::try_from(i).ok());
        match binding {
            Binding::PerVertex { index: Some(list) } if position < list.len() => {
                index(list, position)
            }
            Binding::PerVertex { .. } => self.coord_index(position),
            Binding::PerFace { index: Some(list) } => index(list, face.number),
            Binding::PerFace { index: None } => Some(face.number),
        }
    }
}

fn per(per_vertex: bool, index: Option<&[i32]>) -> Binding<'_> {
    if per_vertex {
        Binding::PerVertex { index }
    } else {
        Binding::PerFace { index }
    }
}

/// One face: its number (what per-face attributes are indexed by) and its corners as
/// stream positions, in winding order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Face {
    pub number: usize,
    corners: Corners,
}

#[derive(Clone, Debug, PartialEq, Eq)]
enum Corners {
    /// Consecutive positions.
    Run(Range<usize>),
    /// Up to four positions.
    Listed([usize; 4], usize),
}

impl Face {
    pub fn len(&self) -> usize {
        match &self.corners {
            Corners::Run(range) => range.len(),
            Corners::Listed(_, len) => *len,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The stream position of corner `k` (`k < len()`).
    #[inline]
    pub fn corner(&self, k: usize) -> usize {
        match &self.corners {
            Corners::Run(range) => range.start + k,
            Corners::Listed(at, _) => at[k],
        }
    }

    pub fn corners(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.len()).map(|k| self.corner(k))
    }

    /// The face as a fan of triangles from its first corner, as stream positions.
    pub fn triangles(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        (1..self.len().saturating_sub(1))
            .map(|k| [self.corner(0), self.corner(k), self.corner(k + 1)])
    }
}

/// The faces of a [`Polygonal`], in order. See the module doc for each node's faces.
pub struct Faces<'g, 'a> {
    geometry: &'g Polygonal<'a>,
    /// Next unread stream position.
    at: usize,
    /// Number of the next face.
    number: usize,
    /// The current strip or fan.
    run: Range<usize>,
    /// The next triangle of the current strip or fan.
    triangle: usize,
    /// The next entry of stripCount / fanCount.
    next_count: usize,
}

impl Faces<'_, '_> {
    fn face(&mut self, corners: Corners) -> Face {
        self.number += 1;
        Face {
            number: self.number - 1,
            corners,
        }
    }

    /// The next run of non-negative indices, skipping separators.
    fn next_indexed_run(&mut self, list: &[i32]) -> Option<Range<usize>> {
        let run = next_run(list, self.at)?;
        self.at = run.end;
        Some(run)
    }

    /// The next strip or fan taken by stripCount / fanCount, cut at the stream's end.
    fn next_counted_run(&mut self) -> Option<Range<usize>> {
        let count = *self.geometry.counts.get(self.next_count)?;
        self.next_count += 1;
        let start = self.at;
        let len = (count.max(0) as usize).min(self.geometry.stream_len() - start);
        self.at = start + len;
        Some(start..start + len)
    }

    fn next_strip_or_fan_triangle(&mut self, fan: bool) -> Option<Face> {
        while self.triangle + 2 >= self.run.len().max(2) {
            self.run = match self.geometry.stream {
                Stream::Indexed(list) => self.next_indexed_run(list)?,
                _ => self.next_counted_run()?,
            };
            self.triangle = 0;
        }
        let (s, k) = (self.run.start, self.triangle);
        self.triangle += 1;
        let corners = if fan {
            [s, s + k + 1, s + k + 2, 0]
        } else if k % 2 == 0 {
            [s + k, s + k + 1, s + k + 2, 0]
        } else {
            [s + k + 1, s + k, s + k + 2, 0]
        };
        Some(self.face(Corners::Listed(corners, 3)))
    }
}

impl Iterator for Faces<'_, '_> {
    type Item = Face;

    fn next(&mut self) -> Option<Face> {
        let kind = self.geometry.kind;
        if let Some(size) = kind.fixed_face_size() {
            let start = self.at;
            if start + size > self.geometry.stream_len() {
                return None;
            }
            self.at += size;
            return Some(self.face(Corners::Run(start..start + size)));
        }
        match (kind, self.geometry.stream) {
            (PolygonKind::IndexedFaceSet, Stream::Indexed(list)) => {
                let run = self.next_indexed_run(list)?;
                Some(self.face(Corners::Run(run)))
            }
            (PolygonKind::IndexedTriangleFanSet | PolygonKind::TriangleFanSet, _) => {
                self.next_strip_or_fan_triangle(true)
            }
            (PolygonKind::IndexedTriangleStripSet | PolygonKind::TriangleStripSet, _) => {
                self.next_strip_or_fan_triangle(false)
            }
            (_, Stream::Grid { x, z }) => {
                let columns = x.checked_sub(1).filter(|&c| c > 0)?;
                let (i, j) = (self.number % columns, self.number / columns);
                if j + 1 >= z {
                    return None;
                }
                let at = |i: usize, j: usize| i + j * x;
                let corners = [at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)];
                Some(self.face(Corners::Listed(corners, 4)))
            }
            _ => None,
        }
    }
}

/// The first run of non-negative entries at or after `from`: a face, strip, fan or
/// polyline. Every negative entry ends a run; empty runs are skipped.
pub fn next_run(list: &[i32], from: usize) -> Option<Range<usize>> {
    let start = from + list.get(from..)?.iter().position(|&i| i >= 0)?;
    let len = list[start..]
        .iter()
        .position(|&i| i < 0)
        .unwrap_or(list.len() - start);
    Some(start..start + len)
}

/// Every run of non-negative entries of an index list separated by negative ones.
pub fn runs(list: &[i32]) -> impl Iterator<Item = Range<usize>> + '_ {
    let mut at = 0;
    std::iter::from_fn(move || {
        let run = next_run(list, at)?;
        at = run.end;
        Some(run)
    })
}

/// Whether a run of [`runs`] is bounded by a negative entry other than the `-1`
/// separator: such an entry is INDEX_NEGATIVE, and the runs it cuts are not what the
/// author wrote, so the rules that judge a run's length leave them alone.
pub fn next_to_invalid_index(list: &[i32], run: &Range<usize>) -> bool {
    let before = run.start.checked_sub(1).and_then(|at| list.get(at));
    let after = list.get(run.end);
    [before, after]
        .into_iter()
        .flatten()
        .any(|&index| index < -1)
}

/// The ranges of consecutive vertices `counts` takes from `total` (LineSet.vertexCount,
/// stripCount, fanCount), cut at `total`; negative counts take nothing.
pub fn counted_runs(counts: &[i32], total: usize) -> impl Iterator<Item = Range<usize>> + '_ {
    let mut at = 0usize;
    counts.iter().map(move |&count| {
        let len = (count.max(0) as usize).min(total - at);
        at += len;
        at - len..at
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn geometry_of(source: &str, coord_count: usize, test: impl FnOnce(&Polygonal)) {
        let doc = parse::read(source.as_bytes()).document.unwrap();
        let id = doc
            .node_ids()
            .find(|&id| {
                doc.node(id)
                    .def()
                    .and_then(|d| PolygonKind::of(d.name))
                    .is_some()
            })
            .unwrap();
        let geometry = Polygonal::read(&doc, id, coord_count).unwrap();
        test(&geometry);
    }

    fn scene(geometry: &str) -> String {
        format!("<X3D version='4.0' profile='Full'><Scene><Shape>{geometry}</Shape></Scene></X3D>")
    }

    fn corner_lists(g: &Polygonal) -> Vec<Vec<usize>> {
        g.faces().map(|f| f.corners().collect()).collect()
    }

    #[test]
    fn face_set_polygons_tolerate_missing_final_and_repeated_separators() {
        geometry_of(
            &scene("<IndexedFaceSet coordIndex='-1 0 1 2 3 -1 -1 4 5 6'/>"),
            0,
            |g| {
                assert_eq!(corner_lists(g), vec![vec![1, 2, 3, 4], vec![7, 8, 9]]);
                assert_eq!(g.face_count(), 2);
                let first = g.faces().next().unwrap();
                assert_eq!(
                    first.triangles().collect::<Vec<_>>(),
                    vec![[1, 2, 3], [1, 3, 4]]
                );
                assert_eq!(g.coord_index(0), None);
                assert_eq!(g.coord_index(1), Some(0));
                assert_eq!(g.coord_index(99), None);
            },
        );
        geometry_of(&scene("<IndexedFaceSet/>"), 5, |g| {
            assert_eq!(g.faces().count(), 0)
        });
    }

    #[test]
    fn triangle_sets_ignore_the_incomplete_rest() {
        geometry_of(
            &scene("<IndexedTriangleSet index='0 1 2 2 1 3 0 1'/>"),
            0,
            |g| {
                assert_eq!(corner_lists(g), vec![vec![0, 1, 2], vec![3, 4, 5]]);
                assert_eq!(g.face_count(), 2);
            },
        );
        geometry_of(&scene("<TriangleSet/>"), 7, |g| {
            assert_eq!(corner_lists(g), vec![vec![0, 1, 2], vec![3, 4, 5]]);
        });
        geometry_of(&scene("<QuadSet/>"), 9, |g| assert_eq!(g.face_count(), 2));
    }

    #[test]
    fn strips_alternate_winding_and_fans_share_the_first_corner() {
        geometry_of(
            &scene("<IndexedTriangleStripSet index='0 1 2 3 -1 4 5 -1 6 7 8'/>"),
            0,
            |g| {
                assert_eq!(
                    corner_lists(g),
                    vec![vec![0, 1, 2], vec![2, 1, 3], vec![8, 9, 10]]
                );
                let numbers: Vec<usize> = g.faces().map(|f| f.number).collect();
                assert_eq!(numbers, vec![0, 1, 2]);
            },
        );
        // The second fan has 2 vertices, the third is cut to the 2 coordinates left.
        geometry_of(&scene("<TriangleFanSet fanCount='4 2 3'/>"), 8, |g| {
            assert_eq!(corner_lists(g), vec![vec![0, 1, 2], vec![0, 2, 3]]);
        });
    }

    #[test]
    fn counted_strips_are_cut_at_the_coordinates_end() {
        geometry_of(
            &scene("<TriangleStripSet stripCount='3 2147483647 -5'/>"),
            9,
            |g| {
                assert_eq!(
                    corner_lists(g),
                    vec![
                        vec![0, 1, 2],
                        vec![3, 4, 5],
                        vec![5, 4, 6],
                        vec![5, 6, 7],
                        vec![7, 6, 8]
                    ]
                );
            },
        );
        let runs: Vec<_> = counted_runs(&[2, -3, i32::MAX, 4], 5).collect();
        assert_eq!(runs, vec![0..2, 2..2, 2..5, 5..5]);
    }

    #[test]
    fn elevation_grid_quads_face_up_and_are_cut_to_the_heights_given() {
        geometry_of(
            &scene("<ElevationGrid xDimension='3' zDimension='2' height='0 0 0 0 0 0'/>"),
            0,
            |g| {
                assert_eq!(corner_lists(g), vec![vec![0, 3, 4, 1], vec![1, 4, 5, 2]]);
                assert_eq!(g.face_count(), 2);
                assert_eq!(
                    g.binding(Attribute::Color),
                    Binding::PerVertex { index: None }
                );
            },
        );
        geometry_of(
            &scene("<ElevationGrid xDimension='100000' zDimension='100000' height='0 0 0 0'/>"),
            0,
            |g| assert_eq!(g.faces().count(), 0),
        );
        geometry_of(
            &scene("<ElevationGrid xDimension='-3' zDimension='2'/>"),
            0,
            |g| {
                assert_eq!(g.faces().count(), 0);
            },
        );
    }

    #[test]
    fn face_set_attribute_bindings_follow_13_3_6() {
        let source = scene(
            "<IndexedFaceSet coordIndex='0 1 2 -1 2 1 3 -1' colorPerVertex='false' colorIndex='5 6' \
             normalIndex='7 8' texCoordIndex='9 9 9'/>",
        );
        geometry_of(&source, 0, |g| {
            let faces: Vec<Face> = g.faces().collect();
            // Per face, through colorIndex.
            assert_eq!(g.attribute_index(Attribute::Color, &faces[1], 4), Some(6));
            // Per vertex through normalIndex while it lasts, then through coordIndex.
            assert_eq!(g.attribute_index(Attribute::Normal, &faces[0], 1), Some(8));
            assert_eq!(g.attribute_index(Attribute::Normal, &faces[1], 6), Some(3));
            assert_eq!(
                g.attribute_index(Attribute::TexCoord, &faces[0], 2),
                Some(9)
            );
        });
        geometry_of(
            &scene("<IndexedFaceSet coordIndex='4 5 6' colorPerVertex='false'/>"),
            0,
            |g| {
                let face = g.faces().next().unwrap();
                assert_eq!(g.attribute_index(Attribute::Color, &face, 0), Some(0));
                assert_eq!(g.attribute_index(Attribute::TexCoord, &face, 1), Some(5));
            },
        );
    }

    #[test]
    fn triangle_sets_bind_colours_per_vertex_whatever_color_per_vertex_says() {
        geometry_of(&scene("<IndexedTriangleSet colorPerVertex='false' normalPerVertex='false' index='3 4 5'/>"), 0, |g| {
            assert_eq!(g.binding(Attribute::Color), Binding::PerVertex { index: None });
            assert_eq!(g.binding(Attribute::Normal), Binding::PerFace { index: None });
            let face = g.faces().next().unwrap();
            assert_eq!(g.attribute_index(Attribute::Color, &face, 2), Some(5));
        });
    }

    #[test]
    fn runs_skip_empty_and_end_at_any_negative() {
        let list = [-1, 0, 1, -2, -1, 2, 3, 4];
        let found: Vec<_> = runs(&list).collect();
        assert_eq!(found, vec![1..3, 5..8]);
        assert_eq!(runs(&[]).count(), 0);
        assert_eq!(runs(&[-1, -1]).count(), 0);
    }
}
