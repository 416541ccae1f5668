//! Axis-aligned bounds of geometry and of scene subtrees, computed in f64.
//!
//! Guarantees, which the rules and the renderer rely on:
//! - `None` means "unknown" (Text, Inline, prototypes, HAnim, geospatial nodes, a USE
//!   cycle, a non-finite transform, too much work): callers must not guess.
//! - A result never holds NaN. Non-finite input points are skipped (they are reported by
//!   FIELD_VALUE_NONFINITE and no browser draws them); a finite point that a transform
//!   carries out of f64 range makes the result unknown.
//! - [`Bounds::exact`] says the box is the geometry's own bounding box; when false it is a
//!   box that encloses the geometry (Extrusion, Arc2D, ArcClose2D), good for "does the
//!   light reach it" but not for "is the declared box too small".
//! - Geometry is carried through transforms as what it is (points, circles, spheres), not
//!   as its local box, so a rotated sphere keeps its exact bounds.
//! - Indexed geometry counts only the points its indices use (a shared Coordinate may hold
//!   points another geometry uses); count-based geometry only the points its counts use.
//!
//! Grouping follows 10.2.2 and 10.4: Transform (and CADPart) compose
//! `T × C × R × SR × S × -SR × -C`; Switch shows its `whichChoice` child (or every child,
//! on request); LOD counts every level; Billboard counts as a Group (its rotation towards
//! the viewer is not modelled); Collision counts its children, not its proxy.

use super::{Document, NodeId, Value};

/// Deeper nesting than this is treated as a USE cycle: the bounds are unknown.
const MAX_DEPTH: usize = 256;
/// Points and node visits one computation may spend before giving up (unknown).
const MAX_WORK: u64 = 20_000_000;
/// Node instances (USEs expanded, `Node::instances`) a walk may have to visit; more is
/// refused at once rather than after spending MAX_WORK, since DEF/USE makes a few
/// kilobytes stand for 2^199 instances.
const MAX_INSTANCES: u64 = 1_000_000;

fn too_many_instances(doc: &Document, node: NodeId) -> bool {
    doc.node(node).instances > MAX_INSTANCES
}

/// An axis-aligned box. Empty (nothing is drawn) when `min > max`.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Bounds {
    pub min: [f64; 3],
    pub max: [f64; 3],
    /// Whether this is the geometry's own bounding box rather than an enclosing one.
    pub exact: bool,
}

impl Bounds {
    pub const EMPTY: Bounds = Bounds {
        min: [f64::INFINITY; 3],
        max: [f64::NEG_INFINITY; 3],
        exact: true,
    };

    pub fn is_empty(&self) -> bool {
        (0..3).any(|i| self.min[i] > self.max[i])
    }

    pub fn size(&self) -> [f64; 3] {
        std::array::from_fn(|i| (self.max[i] - self.min[i]).max(0.0))
    }

    pub fn center(&self) -> [f64; 3] {
        std::array::from_fn(|i| self.min[i] / 2.0 + self.max[i] / 2.0)
    }

    pub fn union(mut self, other: &Bounds) -> Bounds {
        for i in 0..3 {
            self.min[i] = self.min[i].min(other.min[i]);
            self.max[i] = self.max[i].max(other.max[i]);
        }
        self.exact &= other.exact;
        self
    }

    /// Adds a box given by its centre and half extents; false when it is not finite.
    fn add_box(&mut self, center: [f64; 3], half: [f64; 3]) -> bool {
        for i in 0..3 {
            let (low, high) = (center[i] - half[i], center[i] + half[i]);
            if !low.is_finite() || !high.is_finite() {
                return false;
            }
            self.min[i] = self.min[i].min(low);
            self.max[i] = self.max[i].max(high);
        }
        true
    }
}

/// An affine map `p ↦ linear · p + translation`, in f64.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Affine {
    /// Row-major 3×3 matrix.
    pub linear: [[f64; 3]; 3],
    pub translation: [f64; 3],
}

impl Affine {
    pub const IDENTITY: Affine = Affine {
        linear: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        translation: [0.0; 3],
    };

    pub fn translate(v: [f64; 3]) -> Affine {
        Affine {
            translation: v,
            ..Affine::IDENTITY
        }
    }

    pub fn scale(s: [f64; 3]) -> Affine {
        let mut a = Affine::IDENTITY;
        for (i, row) in a.linear.iter_mut().enumerate() {
            row[i] = s[i];
        }
        a
    }

    /// An SFRotation: a zero axis means no rotation (there is no axis to turn about).
    pub fn rotate(axis: [f64; 3], angle: f64) -> Affine {
        let length = axis.iter().map(|c| c * c).sum::<f64>().sqrt();
        if length == 0.0 || !length.is_finite() || angle == 0.0 {
            return Affine::IDENTITY;
        }
        let [x, y, z] = axis.map(|c| c / length);
        let (s, c) = angle.sin_cos();
        let t = 1.0 - c;
        Affine {
            linear: [
                [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
            ],
            translation: [0.0; 3],
        }
    }

    /// `self ∘ inner`: first `inner`, then `self`.
    pub fn then_after(&self, inner: &Affine) -> Affine {
        let a = &self.linear;
        let b = &inner.linear;
        let linear = std::array::from_fn(|r| {
            std::array::from_fn(|c| (0..3).map(|k| a[r][k] * b[k][c]).sum())
        });
        Affine {
            linear,
            translation: self.apply(inner.translation),
        }
    }

    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|r| self.apply_linear_row(r, p) + self.translation[r])
    }

    pub fn apply_linear(&self, v: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|r| self.apply_linear_row(r, v))
    }

    fn apply_linear_row(&self, r: usize, v: [f64; 3]) -> f64 {
        (0..3).map(|k| self.linear[r][k] * v[k]).sum()
    }

    pub fn is_finite(&self) -> bool {
        self.translation.iter().all(|v| v.is_finite())
            && self.linear.iter().flatten().all(|v| v.is_finite())
    }

    /// The largest factor by which the map stretches a length (its largest singular
    /// value), from the eigenvalues of LᵀL in closed form; never below the true value by
    /// more than rounding. L is divided by its largest entry first, so that LᵀL neither
    /// overflows (entries beyond 1e154, from nested scales) nor underflows; ∞ when the
    /// stretch itself is beyond f64, NaN for a non-finite map.
    pub fn max_stretch(&self) -> f64 {
        if !self.is_finite() {
            return f64::NAN;
        }
        let largest = self
            .linear
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        if largest == 0.0 {
            return 0.0;
        }
        let l = self.linear.map(|row| row.map(|v| v / largest));
        let m: [[f64; 3]; 3] = std::array::from_fn(|r| {
            std::array::from_fn(|c| (0..3).map(|k| l[k][r] * l[k][c]).sum())
        });
        largest * largest_symmetric_eigenvalue(&m).max(0.0).sqrt()
    }
}

/// The largest eigenvalue of a symmetric 3×3 matrix (trigonometric method).
fn largest_symmetric_eigenvalue(m: &[[f64; 3]; 3]) -> f64 {
    let off = m[0][1].powi(2) + m[0][2].powi(2) + m[1][2].powi(2);
    if off == 0.0 {
        return m[0][0].max(m[1][1]).max(m[2][2]);
    }
    let q = (m[0][0] + m[1][1] + m[2][2]) / 3.0;
    let p2 = (m[0][0] - q).powi(2) + (m[1][1] - q).powi(2) + (m[2][2] - q).powi(2) + 2.0 * off;
    let p = (p2 / 6.0).sqrt();
    let b: [[f64; 3]; 3] = std::array::from_fn(|r| {
        std::array::from_fn(|c| (m[r][c] - if r == c { q } else { 0.0 }) / p)
    });
    let det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1])
        - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
        + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
    let phi = (det / 2.0).clamp(-1.0, 1.0).acos() / 3.0;
    // Rounding can put the computed value a hair below the true one; callers use it as an
    // upper bound, so widen it by a few ulps of the matrix's scale.
    (q + 2.0 * p * phi.cos()) * (1.0 + 1e-12)
}

/// The bounds of a geometry node's drawn shape, carried through `to_world`.
pub fn geometry_bounds(doc: &Document, geometry: NodeId, to_world: &Affine) -> Option<Bounds> {
    Walker::new(doc, false).geometry(geometry, to_world)
}

/// The bounds of what a node draws in its own coordinate system carried through
/// `to_world`: a Shape's geometry, a grouping node's children (a Transform's children in
/// the Transform's local system: where its bboxCenter lives).
pub fn content_bounds(doc: &Document, node: NodeId, to_world: &Affine) -> Option<Bounds> {
    if too_many_instances(doc, node) {
        return None;
    }
    Walker::new(doc, false).content(node, to_world, 0)
}

/// The bounds of a node and everything under it, in its parent's coordinate system
/// carried through `to_world` (a Transform's own transformation included).
pub fn subtree_bounds(doc: &Document, node: NodeId, to_world: &Affine) -> Option<Bounds> {
    if too_many_instances(doc, node) {
        return None;
    }
    Walker::new(doc, false).subtree(node, to_world, 0)
}

/// The world bounds of the whole scene (what a camera must frame).
pub fn scene_bounds(doc: &Document) -> Option<Bounds> {
    if doc.instances() > MAX_INSTANCES {
        return None;
    }
    let mut walker = Walker::new(doc, false);
    let mut total = Bounds::EMPTY;
    for child in &doc.scene {
        total = total.union(&walker.subtree(child.node, &Affine::IDENTITY, 0)?);
    }
    Some(total)
}

/// Calls `visit` for every node instance of the scene graph (a USE'd node once per
/// place), with the transformation from the coordinate system it lives in to the world.
/// `all_choices` visits every child of a Switch rather than the chosen one. Returns false
/// when the walk was incomplete: it met content it cannot see into (Inline, prototypes,
/// HAnim, …), a USE cycle, too many instances or a non-finite transform.
pub fn visit_scene(
    doc: &Document,
    all_choices: bool,
    mut visit: impl FnMut(NodeId, &Affine),
) -> bool {
    if doc.instances() > MAX_INSTANCES {
        return false;
    }
    let mut walker = Walker::new(doc, all_choices);
    doc.scene
        .iter()
        .all(|c| walker.visit(c.node, &Affine::IDENTITY, 0, &mut visit))
}

/// The transformation a node applies to its children: the Transform fields of Transform,
/// CADPart and the H-Anim nodes that have them (HAnimHumanoid, HAnimJoint, HAnimSite,
/// 26.3), the identity for every other node. None when a value is not finite.
pub fn local_transform(doc: &Document, node: NodeId) -> Option<Affine> {
    let name = doc.node(node).type_name();
    if !matches!(
        name,
        "Transform" | "CADPart" | "HAnimHumanoid" | "HAnimJoint" | "HAnimSite"
    ) {
        return Some(Affine::IDENTITY);
    }
    let vec3 = |field: &str, default: [f64; 3]| -> [f64; 3] {
        match doc
            .value_of(node, field)
            .as_deref()
            .and_then(Value::as_floats)
        {
            Some(v) if v.len() >= 3 => [v[0], v[1], v[2]].map(f64::from),
            _ => default,
        }
    };
    // A non-finite axis would make `Affine::rotate` the identity (it has no direction):
    // NaN instead, so that the transform is unknown like any other with a non-finite value.
    let rotation = |field: &str| -> Affine {
        match doc
            .value_of(node, field)
            .as_deref()
            .and_then(Value::as_floats)
        {
            Some(v) if v.len() >= 4 && v[..4].iter().all(|c| c.is_finite()) => {
                Affine::rotate([v[0], v[1], v[2]].map(f64::from), f64::from(v[3]))
            }
            Some(v) if v.len() >= 4 => Affine::scale([f64::NAN; 3]),
            _ => Affine::IDENTITY,
        }
    };
    let center = vec3("center", [0.0; 3]);
    let scale_orientation = rotation("scaleOrientation");
    let scale_orientation_inverse = {
        let mut inverse = scale_orientation;
        // A rotation matrix's inverse is its transpose.
        inverse.linear =
            std::array::from_fn(|r| std::array::from_fn(|c| scale_orientation.linear[c][r]));
        inverse
    };
    let m = Affine::translate(vec3("translation", [0.0; 3]))
        .then_after(&Affine::translate(center))
        .then_after(&rotation("rotation"))
        .then_after(&scale_orientation)
        .then_after(&Affine::scale(vec3("scale", [1.0; 3])))
        .then_after(&scale_orientation_inverse)
        .then_after(&Affine::translate(center.map(|c| -c)));
    m.is_finite().then_some(m)
}

/// Grouping nodes whose children count as they are.
const PLAIN_GROUPS: &[&str] = &[
    "Group",
    "StaticGroup",
    "Anchor",
    "Billboard",
    "Collision",
    "CADAssembly",
    "CADLayer",
    "PickableGroup",
    "ViewpointGroup",
    "LOD",
    "Layer",
    "Transform",
    "CADPart",
];

struct Walker<'a> {
    doc: &'a Document,
    all_choices: bool,
    work: u64,
    /// The nodes being walked through, to stop at a USE cycle.
    path: Vec<NodeId>,
}

impl<'a> Walker<'a> {
    fn new(doc: &'a Document, all_choices: bool) -> Walker<'a> {
        Walker {
            doc,
            all_choices,
            work: 0,
            path: Vec::new(),
        }
    }

    fn spend(&mut self, amount: u64) -> Option<()> {
        self.work = self.work.saturating_add(amount);
        (self.work <= MAX_WORK).then_some(())
    }

    /// The nodes a grouping node draws, in its local system; None when the node's content
    /// is unknown; an empty list for a node that draws nothing itself.
    fn drawn_children(&self, node: NodeId) -> Option<Vec<NodeId>> {
        let n = self.doc.node(node);
        let name = n.type_name();
        let ids = |field: &str| n.children(field).iter().map(|c| c.node).collect::<Vec<_>>();
        if PLAIN_GROUPS.contains(&name) {
            return Some(ids("children"));
        }
        match name {
            "Switch" => {
                let children = ids("children");
                if self.all_choices {
                    return Some(children);
                }
                let choice = self.doc.i32_of(node, "whichChoice").unwrap_or(-1);
                Some(
                    usize::try_from(choice)
                        .ok()
                        .and_then(|i| children.get(i).copied())
                        .into_iter()
                        .collect(),
                )
            }
            "LayerSet" => Some(ids("layers")),
            "CADFace" => Some(ids("shape")),
            _ if n.def().is_none() => None,
            // A shape's geometry is not a scene-graph child; `content` measures it.
            _ if n.is_a("X3DShapeNode") => Some(Vec::new()),
            // Other nodes with bounds (Inline, HAnim, geospatial, particle systems, …)
            // draw what this module does not model.
            _ if n.is_a("X3DBoundedObject") => None,
            // Lights, sensors, interpolators, viewpoints, scripts: nothing drawn.
            _ => Some(Vec::new()),
        }
    }

    fn subtree(&mut self, node: NodeId, to_world: &Affine, depth: usize) -> Option<Bounds> {
        let local = local_transform(self.doc, node)?;
        self.content(node, &to_world.then_after(&local), depth)
    }

    fn content(&mut self, node: NodeId, to_world: &Affine, depth: usize) -> Option<Bounds> {
        if depth > MAX_DEPTH || !to_world.is_finite() || self.path.contains(&node) {
            return None;
        }
        self.spend(1)?;
        let n = self.doc.node(node);
        if n.type_name() == "Shape" {
            return match n.child("geometry") {
                Some(geometry) => self.geometry(geometry, to_world),
                None => Some(Bounds::EMPTY),
            };
        }
        if n.is_a("X3DShapeNode") {
            // ParticleSystem and other shapes draw what this module does not model.
            return None;
        }
        self.path.push(node);
        let total = self.children_bounds(node, to_world, depth);
        self.path.pop();
        total
    }

    fn children_bounds(&mut self, node: NodeId, to_world: &Affine, depth: usize) -> Option<Bounds> {
        let mut total = Bounds::EMPTY;
        for child in self.drawn_children(node)? {
            total = total.union(&self.subtree(child, to_world, depth + 1)?);
        }
        Some(total)
    }

    fn visit(
        &mut self,
        node: NodeId,
        to_world: &Affine,
        depth: usize,
        visit: &mut impl FnMut(NodeId, &Affine),
    ) -> bool {
        if depth > MAX_DEPTH || self.path.contains(&node) || self.spend(1).is_none() {
            return false;
        }
        visit(node, to_world);
        let Some(local) = local_transform(self.doc, node) else {
            return false;
        };
        let inner = to_world.then_after(&local);
        let Some(children) = self.drawn_children(node) else {
            return false;
        };
        self.path.push(node);
        let complete = children
            .into_iter()
            .all(|child| self.visit(child, &inner, depth + 1, visit));
        self.path.pop();
        complete
    }

    fn geometry(&mut self, geometry: NodeId, m: &Affine) -> Option<Bounds> {
        let doc = self.doc;
        let node = doc.node(geometry);
        let floats = |field: &str| {
            doc.value_of(geometry, field)
                .and_then(|v| v.as_floats().map(<[f32]>::to_vec))
        };
        let float = |field: &str| doc.f32_of(geometry, field).map(f64::from);
        let mut out = Bounds::EMPTY;
        let mut hull = Hull { m, out: &mut out };
        let ok = match node.type_name() {
            "Box" => {
                let size = floats("size")?;
                let half: [f64; 3] =
                    std::array::from_fn(|i| f64::from(*size.get(i).unwrap_or(&2.0)) / 2.0);
                nonnegative(&half)?;
                let mut ok = true;
                for corner in 0..8 {
                    let sign = |bit: usize| if corner >> bit & 1 == 1 { 1.0 } else { -1.0 };
                    ok &= hull.point([sign(0) * half[0], sign(1) * half[1], sign(2) * half[2]]);
                }
                ok
            }
            "Sphere" => {
                let r = float("radius")?;
                nonnegative(&[r])?;
                hull.sphere([0.0; 3], r)
            }
            "Cylinder" => {
                let (r, h) = (float("radius")?, float("height")?);
                nonnegative(&[r, h])?;
                hull.circle_y(h / 2.0, r) && hull.circle_y(-h / 2.0, r)
            }
            "Cone" => {
                let (r, h) = (float("bottomRadius")?, float("height")?);
                nonnegative(&[r, h])?;
                hull.circle_y(-h / 2.0, r) && hull.point([0.0, h / 2.0, 0.0])
            }
            "ElevationGrid" => self.elevation_grid(geometry, &mut hull)?,
            "Extrusion" => {
                hull.out.exact = false;
                extrusion(
                    &floats("spine")?,
                    &floats("crossSection")?,
                    &floats("scale")?,
                    &mut hull,
                )
            }
            "Circle2D" => hull.circle_z(float("radius")?),
            "Disk2D" => hull.circle_z(float("outerRadius")?),
            // An arc is part of its circle: the circle encloses it.
            "Arc2D" | "ArcClose2D" => {
                hull.out.exact = false;
                hull.circle_z(float("radius")?)
            }
            "Rectangle2D" => {
                let size = floats("size")?;
                let half = [0, 1].map(|i| f64::from(*size.get(i).unwrap_or(&2.0)) / 2.0);
                nonnegative(&half)?;
                [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
                    .into_iter()
                    .all(|(sx, sy)| hull.point([sx * half[0], sy * half[1], 0.0]))
            }
            "Polyline2D" => self.points_2d(&floats("lineSegments")?, &mut hull)?,
            "Polypoint2D" => self.points_2d(&floats("point")?, &mut hull)?,
            "TriangleSet2D" => self.points_2d(&floats("vertices")?, &mut hull)?,
            _ => self.coordinate_geometry(geometry, &mut hull)?,
        };
        ok.then_some(out)
    }

    fn points_2d(&mut self, xy: &[f32], hull: &mut Hull) -> Option<bool> {
        self.spend(xy.len() as u64)?;
        Some(
            xy.chunks_exact(2)
                .all(|p| hull.point_if_finite([f64::from(p[0]), f64::from(p[1]), 0.0])),
        )
    }

    fn elevation_grid(&mut self, grid: NodeId, hull: &mut Hull) -> Option<bool> {
        let doc = self.doc;
        let x_dim = doc.i32_of(grid, "xDimension")?;
        let z_dim = doc.i32_of(grid, "zDimension")?;
        let x_spacing = f64::from(doc.f32_of(grid, "xSpacing")?);
        let z_spacing = f64::from(doc.f32_of(grid, "zSpacing")?);
        if x_dim < 2 || z_dim < 2 {
            return Some(true);
        }
        let heights = doc.value_of(grid, "height")?;
        let heights = heights.as_floats()?;
        let cells = (x_dim as usize)
            .saturating_mul(z_dim as usize)
            .min(heights.len());
        self.spend(cells as u64)?;
        Some((0..cells).all(|k| {
            let (i, j) = (k % x_dim as usize, k / x_dim as usize);
            hull.point_if_finite([
                i as f64 * x_spacing,
                f64::from(heights[k]),
                j as f64 * z_spacing,
            ])
        }))
    }

    fn coordinate_geometry(&mut self, geometry: NodeId, hull: &mut Hull) -> Option<bool> {
        let doc = self.doc;
        let name = doc.node(geometry).type_name();
        let index_field = match name {
            "IndexedFaceSet" | "IndexedLineSet" => Some("coordIndex"),
            "IndexedTriangleSet"
            | "IndexedTriangleStripSet"
            | "IndexedTriangleFanSet"
            | "IndexedQuadSet" => Some("index"),
            "PointSet" | "LineSet" | "TriangleSet" | "TriangleStripSet" | "TriangleFanSet"
            | "QuadSet" => None,
            _ => return None,
        };
        let Some(coord) = doc.child_of(geometry, "coord") else {
            return Some(true);
        };
        let points = Points::of(doc, coord)?;
        let count = points.len();
        self.spend(count as u64)?;
        if let Some(field) = index_field {
            let indices = doc.value_of(geometry, field)?;
            let indices = indices.as_int32s()?;
            self.spend(indices.len() as u64)?;
            // Each point once, however many faces share it: the bounds are the same.
            let mut used = vec![false; count];
            for &i in indices {
                if let Some(slot) = usize::try_from(i).ok().and_then(|i| used.get_mut(i)) {
                    *slot = true;
                }
            }
            return Some(
                (0..count)
                    .filter(|&i| used[i])
                    .all(|i| hull.point_if_finite(points.get(i))),
            );
        }
        let used = match name {
            "TriangleSet" => count - count % 3,
            "QuadSet" => count - count % 4,
            "LineSet" => counted(doc, geometry, "vertexCount", count)?,
            "TriangleStripSet" => counted(doc, geometry, "stripCount", count)?,
            "TriangleFanSet" => counted(doc, geometry, "fanCount", count)?,
            _ => count,
        };
        Some((0..used).all(|i| hull.point_if_finite(points.get(i))))
    }
}

/// How many points a count field (vertexCount, stripCount, fanCount) uses.
fn counted(doc: &Document, geometry: NodeId, field: &str, available: usize) -> Option<usize> {
    let counts = doc.value_of(geometry, field)?;
    let total = counts
        .as_int32s()?
        .iter()
        .fold(0usize, |sum, &c| sum.saturating_add(c.max(0) as usize));
    Some(total.min(available))
}

fn nonnegative(values: &[f64]) -> Option<()> {
    values
        .iter()
        .all(|v| *v >= 0.0 && v.is_finite())
        .then_some(())
}

/// The points of a Coordinate or CoordinateDouble node.
enum Points<'a> {
    Single(std::borrow::Cow<'a, Value>),
    Double(std::borrow::Cow<'a, Value>),
}

impl<'a> Points<'a> {
    fn of(doc: &'a Document, coord: NodeId) -> Option<Points<'a>> {
        let value = doc.value_of(coord, "point")?;
        match doc.node(coord).type_name() {
            "Coordinate" if value.as_floats().is_some() => Some(Points::Single(value)),
            "CoordinateDouble" if value.as_doubles().is_some() => Some(Points::Double(value)),
            _ => None,
        }
    }

    fn len(&self) -> usize {
        match self {
            Points::Single(v) | Points::Double(v) => v.len() / 3,
        }
    }

    fn get(&self, i: usize) -> [f64; 3] {
        match self {
            Points::Single(v) => {
                let f = v.as_floats().unwrap_or_default();
                [f[3 * i], f[3 * i + 1], f[3 * i + 2]].map(f64::from)
            }
            Points::Double(v) => {
                let d = v.as_doubles().unwrap_or_default();
                [d[3 * i], d[3 * i + 1], d[3 * i + 2]]
            }
        }
    }
}

/// Extrusion, approximated: every cross-section point lies within the scaled
/// cross-section's radius of its spine point, whatever the orientation, so a sphere of
/// that radius around each spine point encloses the surface.
fn extrusion(spine: &[f32], cross_section: &[f32], scale: &[f32], hull: &mut Hull) -> bool {
    let radius_sq = |sx: f64, sz: f64| {
        cross_section
            .chunks_exact(2)
            .map(|p| (f64::from(p[0]) * sx).powi(2) + (f64::from(p[1]) * sz).powi(2))
            .filter(|r| r.is_finite())
            .fold(0.0f64, f64::max)
    };
    let scales: Vec<[f64; 2]> = scale
        .chunks_exact(2)
        .map(|s| [f64::from(s[0]), f64::from(s[1])])
        .collect();
    spine.chunks_exact(3).enumerate().all(|(k, p)| {
        let [sx, sz] = scales
            .get(k)
            .or(scales.last())
            .copied()
            .unwrap_or([1.0, 1.0]);
        let center = [p[0], p[1], p[2]].map(f64::from);
        if !center.iter().all(|c| c.is_finite()) {
            return true;
        }
        hull.sphere(center, radius_sq(sx.abs(), sz.abs()).sqrt())
    })
}

/// Accumulates shapes carried through a transform into bounds, exactly.
struct Hull<'a> {
    m: &'a Affine,
    out: &'a mut Bounds,
}

impl Hull<'_> {
    fn point(&mut self, p: [f64; 3]) -> bool {
        self.out.add_box(self.m.apply(p), [0.0; 3])
    }

    /// Non-finite input points are not drawn: skipped, not an error.
    fn point_if_finite(&mut self, p: [f64; 3]) -> bool {
        !p.iter().all(|c| c.is_finite()) || self.point(p)
    }

    /// A sphere maps to an ellipsoid whose half extent along axis i is r·|row i|.
    fn sphere(&mut self, center: [f64; 3], r: f64) -> bool {
        let half = self
            .m
            .linear
            .map(|row| r * row.iter().map(|v| v * v).sum::<f64>().sqrt());
        self.out.add_box(self.m.apply(center), half)
    }

    /// An ellipse `c + u cos t + v sin t` has half extent sqrt(u_i² + v_i²) along axis i.
    fn ellipse(&mut self, center: [f64; 3], u: [f64; 3], v: [f64; 3]) -> bool {
        let (u, v) = (self.m.apply_linear(u), self.m.apply_linear(v));
        let half = std::array::from_fn(|i| u[i].hypot(v[i]));
        self.out.add_box(self.m.apply(center), half)
    }

    /// A circle of radius r in the plane y = height (Cylinder and Cone caps).
    fn circle_y(&mut self, height: f64, r: f64) -> bool {
        self.ellipse([0.0, height, 0.0], [r, 0.0, 0.0], [0.0, 0.0, r])
    }

    /// A circle of radius r about the origin in the plane z = 0 (Geometry2D).
    fn circle_z(&mut self, r: f64) -> bool {
        r >= 0.0 && self.ellipse([0.0; 3], [r, 0.0, 0.0], [0.0, r, 0.0])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn doc(scene: &str) -> Document {
        let source = format!("<X3D version='4.0' profile='Full'><Scene>{scene}</Scene></X3D>");
        parse::read(source.as_bytes()).document.unwrap()
    }

    /// Angles are SFFloat: π/2 rounds to f32, so a quarter turn is off by ~4e-8.
    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() <= 1e-6 * (1.0 + b[i].abs()))
    }

    #[test]
    fn box_rotated_45_degrees_about_y() {
        let d = doc("<Transform rotation='0 1 0 0.785398163397'><Shape><Box size='2 2 2'/></Shape></Transform>");
        let b = scene_bounds(&d).unwrap();
        let r = 2f64.sqrt();
        assert!(
            close(b.min, [-r, -1.0, -r]) && close(b.max, [r, 1.0, r]),
            "{b:?}"
        );
        assert!(b.exact);
    }

    #[test]
    fn rotated_sphere_keeps_its_exact_bounds() {
        let d =
            doc("<Transform rotation='1 1 0 0.7'><Shape><Sphere radius='3'/></Shape></Transform>");
        let b = scene_bounds(&d).unwrap();
        assert!(close(b.min, [-3.0; 3]) && close(b.max, [3.0; 3]), "{b:?}");
    }

    #[test]
    fn scaled_transform_with_center_and_translation() {
        let d = doc(
            "<Transform translation='10 0 0' scale='2 3 4' center='1 1 1'>
               <Shape><IndexedFaceSet coordIndex='0 1 2 -1'>
                 <Coordinate point='0 0 0 1 0 0 0 1 0 99 99 99'/></IndexedFaceSet></Shape></Transform>",
        );
        let b = scene_bounds(&d).unwrap();
        // p' = T + C + S(p - C): x in [10+1-2, 10+1+0], y in [1-3, 1+0], z = 1-4.
        assert!(
            close(b.min, [9.0, -2.0, -3.0]) && close(b.max, [11.0, 1.0, -3.0]),
            "{b:?}"
        );
    }

    #[test]
    fn scale_orientation_rotates_the_scale_axes() {
        let d = doc("<Transform scale='2 1 1' scaleOrientation='0 0 1 1.5707963267949'><Shape><Box size='2 2 2'/></Shape></Transform>");
        let b = scene_bounds(&d).unwrap();
        assert!(
            close(b.min, [-1.0, -2.0, -1.0]) && close(b.max, [1.0, 2.0, 1.0]),
            "{b:?}"
        );
    }

    #[test]
    fn extreme_coordinates_do_not_overflow() {
        let d = doc("<Transform scale='3e38 3e38 3e38'><Shape><PointSet>
               <Coordinate point='3e38 -3e38 0 -3e38 3e38 1'/></PointSet></Shape></Transform>");
        let b = scene_bounds(&d).unwrap();
        assert!(b.min.iter().chain(&b.max).all(|v| v.is_finite()));
        assert!(b.max[0] > 8.9e76 && b.min[0] < -8.9e76, "{b:?}");
    }

    #[test]
    fn non_finite_points_are_skipped_and_bounds_never_nan() {
        let mut d = doc("<Shape><PointSet><Coordinate point='1 2 3 4 5 6'/></PointSet></Shape>");
        let coord = d.nodes_of_type("Coordinate").next().unwrap();
        for entry in &mut d.nodes[coord.index()].fields {
            entry.value = Value::Floats(vec![
                f32::NAN,
                0.0,
                0.0,
                1.0,
                2.0,
                3.0,
                f32::INFINITY,
                0.0,
                0.0,
            ]);
        }
        let b = scene_bounds(&d).unwrap();
        assert_eq!((b.min, b.max), ([1.0, 2.0, 3.0], [1.0, 2.0, 3.0]));
    }

    #[test]
    fn unknown_content_is_none_and_empty_content_is_empty() {
        assert!(scene_bounds(&doc("<Shape><Text string='\"a\"'/></Shape>")).is_none());
        assert!(scene_bounds(&doc("<Inline url='\"x.x3d\"'/>")).is_none());
        let empty = scene_bounds(&doc("<Group><PointLight/><Shape/></Group>")).unwrap();
        assert!(empty.is_empty());
    }

    #[test]
    fn switch_shows_its_choice_and_lod_all_levels() {
        let d = doc(
            "<Switch whichChoice='1'><Shape><Sphere radius='5'/></Shape><Shape><Sphere radius='1'/></Shape></Switch>
             <LOD><Shape><Box size='1 1 1'/></Shape><Shape><Box size='4 4 4'/></Shape></LOD>",
        );
        let b = scene_bounds(&d).unwrap();
        assert!(close(b.min, [-2.0; 3]) && close(b.max, [2.0; 3]), "{b:?}");
        let none = doc("<Switch><Shape><Sphere/></Shape></Switch>");
        assert!(scene_bounds(&none).unwrap().is_empty());
    }

    #[test]
    fn indexed_geometry_counts_only_used_points() {
        let d = doc("<Shape><IndexedLineSet coordIndex='0 1 -1 7'><Coordinate point='0 0 0 1 1 1 50 50 50'/></IndexedLineSet></Shape>");
        let b = scene_bounds(&d).unwrap();
        assert_eq!((b.min, b.max), ([0.0; 3], [1.0; 3]));
    }

    #[test]
    fn extrusion_is_enclosed_but_not_exact() {
        let d = doc("<Shape><Extrusion/></Shape>");
        let b = scene_bounds(&d).unwrap();
        assert!(!b.exact);
        // The default square cross-section spans ±1 along a spine from y 0 to 1.
        assert!(b.min[0] <= -1.0 && b.max[0] >= 1.0 && b.min[1] <= 0.0 && b.max[1] >= 1.0);
    }

    #[test]
    fn cylinder_and_cone_under_rotation() {
        let d = doc("<Transform rotation='0 0 1 1.5707963267949'><Shape><Cylinder radius='1' height='4'/></Shape></Transform>");
        let b = scene_bounds(&d).unwrap();
        assert!(
            close(b.min, [-2.0, -1.0, -1.0]) && close(b.max, [2.0, 1.0, 1.0]),
            "{b:?}"
        );
    }

    #[test]
    fn max_stretch_is_the_largest_singular_value() {
        let uniform = Affine::rotate([1.0, 2.0, 3.0], 0.9).then_after(&Affine::scale([2.0; 3]));
        assert!((uniform.max_stretch() - 2.0).abs() < 1e-9);
        let skew = Affine::scale([1.0, 5.0, 0.5]);
        assert!((skew.max_stretch() - 5.0).abs() < 1e-9);
        let zero = Affine::scale([0.0; 3]);
        assert_eq!(zero.max_stretch(), 0.0);
    }

    #[test]
    fn visit_reaches_every_use_instance() {
        let d = doc("<Transform translation='1 0 0'><Shape DEF='S'><Box/></Shape></Transform><Transform translation='-1 0 0'><Shape USE='S'/></Transform>");
        let mut seen = Vec::new();
        assert!(visit_scene(&d, false, |n, m| {
            if d.node(n).type_name() == "Shape" {
                seen.push(m.translation[0]);
            }
        }));
        assert_eq!(seen, vec![1.0, -1.0]);
    }
}
