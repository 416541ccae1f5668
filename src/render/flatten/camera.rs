//! The camera: the chosen Viewpoint or OrthoViewpoint (found before the walk, so that
//! Billboards can turn towards it), or a framing of the scene's bounds; the near and far
//! planes; and the rotation of Billboards (10.4.1).

use glam::{DMat3, DMat4, DQuat, DVec3};

use super::{Context, Walker};
use crate::model::bounds::local_transform;
use crate::model::{Document, NodeId};
use crate::render::draw_list::{Camera, Projection};
use crate::render::fields::{floats, rotation, vec3};

/// Scene-graph nodes visited at most while looking for the viewpoint.
const MAX_SEARCH: usize = 1_000_000;

/// The viewpoint chosen, in world coordinates.
#[derive(Clone, Debug)]
pub struct ViewpointFound {
    pub eye: DVec3,
    pub orientation: DQuat,
    pub projection: Projection,
    /// X3D 4 nearDistance and farDistance, where set (positive).
    pub near_distance: Option<f32>,
    pub far_distance: Option<f32>,
}

/// The first Viewpoint or OrthoViewpoint of the tree under `roots` (a layer's) in
/// traversal order (the one a browser binds first), or the one DEF'd `name`.
pub fn find_viewpoint(
    doc: &Document,
    roots: &[NodeId],
    name: Option<&str>,
) -> Option<ViewpointFound> {
    let wanted = |id: NodeId| {
        let node = doc.node(id);
        is_viewpoint(node)
            && name.is_none_or(|n| node.def_name.as_ref().is_some_and(|d| d.text == n))
    };
    let mut stack: Vec<(NodeId, DMat4)> = roots
        .iter()
        .rev()
        .map(|&id| (id, super::scene_root(doc)))
        .collect();
    let mut visited = 0;
    while let Some((id, world)) = stack.pop() {
        visited += 1;
        if visited > MAX_SEARCH {
            break;
        }
        if wanted(id) {
            return Some(viewpoint(doc, id, world));
        }
        let node = doc.node(id);
        if !node.is_a("X3DGroupingNode") && !matches!(node.type_name(), "Switch" | "LOD") {
            continue;
        }
        let local = local_transform(doc, id).map_or(DMat4::IDENTITY, |a| {
            let l = a.linear;
            DMat4::from_cols_array_2d(&[
                [l[0][0], l[1][0], l[2][0], 0.0],
                [l[0][1], l[1][1], l[2][1], 0.0],
                [l[0][2], l[1][2], l[2][2], 0.0],
                [a.translation[0], a.translation[1], a.translation[2], 1.0],
            ])
        });
        for field in ["children", "choice", "level"] {
            for child in node.children(field).iter().rev() {
                stack.push((child.node, world * local));
            }
        }
    }
    None
}

/// The viewpoint DEF'd `name` anywhere in the document, in its own coordinates (for one
/// off the scene graph, e.g. in a prototype). Err when there is none.
pub fn named_anywhere(doc: &Document, name: &str) -> Result<ViewpointFound, String> {
    doc.iter()
        .find(|(_, node)| {
            is_viewpoint(node) && node.def_name.as_ref().is_some_and(|d| d.text == name)
        })
        .map(|(id, _)| viewpoint(doc, id, super::scene_root(doc)))
        .ok_or_else(|| format!("--camera {name}: the scene has no Viewpoint DEF'd `{name}`"))
}

/// The view of a Viewpoint with every field at its default (position 0 0 10, no rotation,
/// fieldOfView π/4, planes left to the NavigationInfo): the view of a scene without any
/// Viewpoint in a browser (bindable nodes, 7.2.2; the NIST conformance scene
/// noviewpoint.x3d expects this view, and X_ITE takes it).
pub fn default_viewpoint() -> ViewpointFound {
    ViewpointFound {
        eye: DVec3::new(0.0, 0.0, 10.0),
        orientation: DQuat::IDENTITY,
        projection: Projection::Perspective {
            field_of_view: std::f32::consts::FRAC_PI_4,
        },
        near_distance: None,
        far_distance: None,
    }
}

/// A Viewpoint, OrthoViewpoint or GeoViewpoint (X3D 3.0 and 3.1 have no
/// X3DViewpointNode type above Viewpoint).
pub fn is_viewpoint(node: &crate::model::Node) -> bool {
    node.is_a("X3DViewpointNode")
        || matches!(
            node.type_name(),
            "Viewpoint" | "OrthoViewpoint" | "GeoViewpoint"
        )
}

fn viewpoint(doc: &Document, id: NodeId, world: DMat4) -> ViewpointFound {
    let position = DVec3::from_array(vec3(doc, id, "position", [0.0, 0.0, 10.0]).map(f64::from));
    let (_, world_rotation, _) = world.to_scale_rotation_translation();
    let orientation = (world_rotation * rotation(doc, id, "orientation")).normalize();
    let default_fov = std::f32::consts::FRAC_PI_4;
    let projection = if doc.node(id).type_name() == "OrthoViewpoint" {
        let rectangle = match floats(doc, id, "fieldOfView").as_ref() {
            [a, b, c, d, ..] if a < c && b < d && [a, b, c, d].iter().all(|v| v.is_finite()) => {
                [*a, *b, *c, *d]
            }
            _ => [-1.0, -1.0, 1.0, 1.0],
        };
        Projection::Orthographic { rectangle }
    } else {
        let fov = crate::render::fields::float(doc, id, "fieldOfView", default_fov);
        Projection::Perspective {
            field_of_view: if fov > 0.0 && fov < std::f32::consts::PI {
                fov
            } else {
                default_fov
            },
        }
    };
    // −1 (the default) leaves the planes to the NavigationInfo; 0 cannot be a plane.
    let distance =
        |field| Some(crate::render::fields::float(doc, id, field, -1.0)).filter(|d| *d > 0.0);
    ViewpointFound {
        near_distance: distance("nearDistance"),
        far_distance: distance("farDistance"),
        eye: world.transform_point3(position),
        orientation: if orientation.is_finite() {
            orientation
        } else {
            DQuat::IDENTITY
        },
        projection,
    }
}

/// Where the image is taken from.
pub struct View {
    pub eye: DVec3,
    pub orientation: DQuat,
    projection: Projection,
    /// Whether the view frames the bounds (there is no viewpoint).
    framed: bool,
    near_distance: Option<f32>,
    far_distance: Option<f32>,
}

impl View {
    /// The viewpoint, or a framing of the bounds from +Z (the default Viewpoint's
    /// direction) with the default field of view.
    pub fn choose(viewpoint: Option<&ViewpointFound>, bounds: Option<(DVec3, DVec3)>) -> View {
        let fov = std::f32::consts::FRAC_PI_4;
        let framing = |eye| View {
            eye,
            orientation: DQuat::IDENTITY,
            projection: Projection::Perspective { field_of_view: fov },
            framed: true,
            near_distance: None,
            far_distance: None,
        };
        match (viewpoint, bounds) {
            (Some(v), _) => View {
                eye: v.eye,
                orientation: v.orientation,
                projection: v.projection,
                framed: false,
                near_distance: v.near_distance,
                far_distance: v.far_distance,
            },
            (None, Some((lo, hi))) => {
                let centre = (lo + hi) / 2.0;
                let radius = ((hi - lo).length() / 2.0).max(f64::MIN_POSITIVE);
                let distance = radius / (f64::from(fov) / 2.0).sin();
                framing(centre + DVec3::new(0.0, 0.0, distance))
            }
            (None, None) => framing(DVec3::new(0.0, 0.0, 10.0)),
        }
    }

    /// A LayoutLayer's view (36.2.1, see [`super::layout`]): the default OrthoViewpoint's
    /// −1 … 1, looking down −Z from in front of the bounds (and at least from z = 10, its
    /// default position).
    pub fn layout(bounds: Option<(DVec3, DVec3)>) -> View {
        let z = bounds.map_or(10.0, |(_, hi)| (hi.z + 1.0).max(10.0));
        View {
            eye: DVec3::new(0.0, 0.0, if z.is_finite() { z } else { 10.0 }),
            orientation: DQuat::IDENTITY,
            projection: Projection::Orthographic {
                rectangle: [-1.0, -1.0, 1.0, 1.0],
            },
            framed: true,
            near_distance: None,
            far_distance: None,
        }
    }

    pub fn camera(&self, near: f32, far: f32) -> Camera {
        Camera {
            orientation: self.orientation.as_quat(),
            projection: self.projection,
            near,
            far,
        }
    }

    /// The near and far planes (23.4.4 NavigationInfo): near is avatarSize[0] / 2 of the
    /// bound NavigationInfo, or of the default one (avatarSize 0.25: 0.125) when the
    /// scene has none, as browsers bind; far is visibilityLimit, or (0, the default:
    /// unlimited) just past the farthest corner of the bounds. An X3D 4 Viewpoint's
    /// nearDistance and farDistance, where set, come first. A framed view (no viewpoint:
    /// x3dcheck's own camera) brings the near plane in front of the bounds when they are
    /// closer than that, so that a small scene is not cut away.
    pub fn depth_range(
        &self,
        bounds: Option<(DVec3, DVec3)>,
        navigation: Option<super::environment::Navigation>,
    ) -> (f32, f32) {
        let avatar = navigation
            .and_then(|n| n.avatar_size)
            .unwrap_or(DEFAULT_AVATAR_SIZE);
        let mut near = self
            .near_distance
            .map_or(f64::from(avatar) / 2.0, f64::from);
        let farthest = bounds.map(|(lo, hi)| {
            let pick = |e: f64, l: f64, h: f64| if (e - l).abs() > (e - h).abs() { l } else { h };
            let corner = DVec3::new(
                pick(self.eye.x, lo.x, hi.x),
                pick(self.eye.y, lo.y, hi.y),
                pick(self.eye.z, lo.z, hi.z),
            );
            (corner - self.eye).length() * 1.01
        });
        let limit = navigation.map_or(0.0, |n| n.visibility_limit);
        let mut far = match (self.far_distance, farthest) {
            (Some(d), _) => f64::from(d),
            _ if limit > 0.0 => f64::from(limit),
            (None, Some(f)) => f,
            (None, None) => 100.0,
        };
        if let (true, Some((_, hi))) = (self.framed, bounds) {
            // The framing looks down −Z: the depth of the bounds' front face.
            let front = (self.eye.z - hi.z) * 0.99;
            if front > 0.0 {
                near = near.min(front);
            }
        }
        if !(near > 0.0 && near.is_finite()) {
            near = f64::from(DEFAULT_AVATAR_SIZE) / 2.0;
        }
        if !(far > near && far.is_finite()) {
            far = near * 1e6;
        }
        (near as f32, (far as f32).max(near as f32 * 2.0))
    }
}

/// NavigationInfo.avatarSize[0] by default (23.4.4).
const DEFAULT_AVATAR_SIZE: f32 = 0.25;

impl Walker<'_> {
    /// A Billboard's rotation (in its own coordinates) that turns its local +Z towards
    /// the viewer about `axisOfRotation`, or, with a zero axis, makes it face the viewer
    /// with +Y along the viewer's up. Without a Viewpoint the automatic camera looks down
    /// −Z from far away, so the viewer lies along world +Z.
    pub(super) fn billboard_rotation(
        &mut self,
        context: Context,
        id: NodeId,
        world: DMat4,
    ) -> DMat4 {
        let doc = context.doc;
        let linear = DMat3::from_mat4(world);
        if linear.determinant() == 0.0 || !linear.is_finite() {
            return DMat4::IDENTITY;
        }
        let to_local = world.inverse();
        let (to_viewer, up) = match &self.viewpoint {
            Some(v) => (
                to_local.transform_point3(v.eye),
                to_local.transform_vector3(v.orientation * DVec3::Y),
            ),
            None => (
                to_local.transform_vector3(DVec3::Z),
                to_local.transform_vector3(DVec3::Y),
            ),
        };
        let axis =
            DVec3::from_array(vec3(doc, id, "axisOfRotation", [0.0, 1.0, 0.0]).map(f64::from));
        let rotation = if axis == DVec3::ZERO {
            let z = to_viewer.normalize_or_zero();
            let x = up.cross(z).normalize_or_zero();
            if z == DVec3::ZERO || x == DVec3::ZERO {
                return DMat4::IDENTITY;
            }
            DMat4::from_mat3(DMat3::from_cols(x, z.cross(x), z))
        } else {
            let axis = axis.normalize_or_zero();
            let flat = |v: DVec3| (v - axis * axis.dot(v)).normalize_or_zero();
            let (from, to) = (flat(DVec3::Z), flat(to_viewer));
            if from == DVec3::ZERO || to == DVec3::ZERO {
                return DMat4::IDENTITY;
            }
            let angle = from.cross(to).dot(axis).atan2(from.dot(to));
            DMat4::from_axis_angle(axis, angle)
        };
        if rotation.is_finite() {
            rotation
        } else {
            DMat4::IDENTITY
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::environment::Navigation;
    use super::*;

    fn roots(d: &Document) -> Vec<NodeId> {
        d.scene.iter().map(|c| c.node).collect()
    }

    fn doc(scene: &str) -> Document {
        let source = format!("<X3D version='4.0' profile='Full'><Scene>{scene}</Scene></X3D>");
        crate::parse::read(source.as_bytes()).document.unwrap()
    }

    #[test]
    fn the_first_viewpoint_in_traversal_order_with_its_transform() {
        let d = doc(
            "<Transform translation='10 0 0'><Viewpoint DEF='A' position='0 0 5'/></Transform>\
             <Viewpoint DEF='B' position='1 2 3'/>",
        );
        let first = find_viewpoint(&d, &roots(&d), None).unwrap();
        assert_eq!(first.eye, DVec3::new(10.0, 0.0, 5.0));
        let b = find_viewpoint(&d, &roots(&d), Some("B")).unwrap();
        assert_eq!(b.eye, DVec3::new(1.0, 2.0, 3.0));
        assert!(find_viewpoint(&d, &roots(&d), Some("C")).is_none());
        assert!(named_anywhere(&d, "C").is_err());
    }

    #[test]
    fn x3d_3_0_viewpoints_are_found() {
        let source = "<X3D version='3.0' profile='Immersive'><Scene>\
                      <Viewpoint position='1 2 3'/></Scene></X3D>";
        let d = crate::parse::read(source.as_bytes()).document.unwrap();
        let v = find_viewpoint(&d, &roots(&d), None).unwrap();
        assert_eq!(v.eye, DVec3::new(1.0, 2.0, 3.0));
    }

    /// The planes of the first viewpoint (or the framing) of `scene`, and its bounds.
    fn planes(scene: &str, bounds: (DVec3, DVec3), navigation: Option<Navigation>) -> (f32, f32) {
        let d = doc(scene);
        let viewpoint = find_viewpoint(&d, &roots(&d), None);
        View::choose(viewpoint.as_ref(), Some(bounds)).depth_range(Some(bounds), navigation)
    }

    fn navigation(avatar: Option<f32>, visibility_limit: f32) -> Option<Navigation> {
        Some(Navigation {
            headlight: true,
            avatar_size: avatar,
            visibility_limit,
        })
    }

    #[test]
    fn the_near_plane_is_half_the_avatar_size_by_default_not_the_bounds_distance() {
        // A unit box seen from (2, 0, 7.2): its front face is 6.7 ahead, nearer than the
        // distance to its nearest point (6.87); the default avatarSize puts near at 0.125.
        let unit_box = (DVec3::splat(-0.5), DVec3::splat(0.5));
        let (near, far) = planes("<Viewpoint position='2 0 7.2'/>", unit_box, None);
        assert_eq!(near, 0.125);
        assert!(far > 8.1, "{far}");
        // A NavigationInfo's avatarSize and visibilityLimit.
        let (near, far) = planes(
            "<Viewpoint position='2 0 7.2'/>",
            unit_box,
            navigation(Some(2.0), 50.0),
        );
        assert_eq!((near, far), (1.0, 50.0));
        // An empty avatarSize: the default.
        let (near, _) = planes("<Viewpoint/>", unit_box, navigation(None, 0.0));
        assert_eq!(near, 0.125);
        // X3D 4 nearDistance and farDistance come first; −1 leaves them to the defaults.
        let (near, far) = planes(
            "<Viewpoint nearDistance='0.01' farDistance='30'/>",
            unit_box,
            navigation(Some(2.0), 50.0),
        );
        assert_eq!((near, far), (0.01, 30.0));
        let (near, _) = planes("<Viewpoint nearDistance='-1'/>", unit_box, None);
        assert_eq!(near, 0.125);
    }

    #[test]
    fn a_framed_small_scene_keeps_its_near_plane_in_front_of_it() {
        // No viewpoint: x3dcheck frames the bounds; a 0.001-wide scene is framed from
        // about 0.003 away, so the near plane comes in front of it.
        let tiny = (DVec3::splat(-0.0005), DVec3::splat(0.0005));
        let (near, far) = planes("", tiny, None);
        let view = View::choose(None, Some(tiny));
        assert!(near < (view.eye.z - 0.0005) as f32, "{near}");
        assert!(near > 0.0 && far > near);
        // A large one keeps the default.
        let large = (DVec3::splat(-50.0), DVec3::splat(50.0));
        assert_eq!(planes("", large, None).0, 0.125);
    }

    #[test]
    fn ortho_viewpoints_keep_their_rectangle() {
        let d = doc("<OrthoViewpoint fieldOfView='-2 -1 2 1'/>");
        let v = find_viewpoint(&d, &roots(&d), None).unwrap();
        assert_eq!(
            v.projection,
            Projection::Orthographic {
                rectangle: [-2.0, -1.0, 2.0, 1.0]
            }
        );
    }
}
