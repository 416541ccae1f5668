//! What the geometry builders ([`super::geometry`], and [`super::polygons`] under it)
//! make of a geometry node: a mesh in the node's local coordinates.

use super::draw_list::Primitive;

/// A mesh in local coordinates.
#[derive(Clone, Debug, Default)]
pub struct LocalMesh {
    pub primitive: Primitive,
    /// Relative to `origin`.
    pub positions: Vec<[f32; 3]>,
    /// Added to every position, in f64: CoordinateDouble points far from the local
    /// origin keep their precision until the mesh is placed relative to the eye.
    pub origin: [f64; 3],
    pub normals: Option<Vec<[f32; 3]>>,
    pub colors: Option<Vec<[f32; 4]>>,
    /// The colours came from a ColorRGBA node (they replace alpha too).
    pub colors_have_alpha: bool,
    /// One set per [`Needs::tex_coords`](super::geometry::Needs::tex_coords) entry, in order; a [`TexCoordSource::Generated`](super::geometry::TexCoordSource::Generated)
    /// set is empty (it is computed when the mesh is placed).
    pub tex_coords: Vec<Vec<[f32; 2]>>,
    pub indices: Vec<u32>,
    /// Faces left out for having more than [`crate::limits::MAX_FACE_CORNERS`] corners.
    pub faces_over_limit: usize,
}
