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
}

/// The first Viewpoint or OrthoViewpoint of the scene in traversal order (the one a
/// browser binds first), or the one DEF'd `name`. Err when `name` names none.
pub fn find_viewpoint(
    doc: &Document,
    name: Option<&str>,
) -> Result<Option<ViewpointFound>, String> {
    let wanted = |id: NodeId| {
        let node = doc.node(id);
        is_viewpoint(node)
            && name.is_none_or(|n| node.def_name.as_ref().is_some_and(|d| d.text == n))
    };
    let mut stack: Vec<(NodeId, DMat4)> = doc
        .scene
        .iter()
        .rev()
        .map(|c| (c.node, DMat4::IDENTITY))
        .collect();
    let mut visited = 0;
    while let Some((id, world)) = stack.pop() {
        visited += 1;
        if visited > MAX_SEARCH {
            break;
        }
        if wanted(id) {
            return Ok(Some(viewpoint(doc, id, world)));
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
    match name {
        // Not on the scene graph (e.g. in a prototype): its own coordinates.
        Some(n) => doc
            .iter()
            .find(|(id, _)| wanted(*id))
            .map(|(id, _)| Some(viewpoint(doc, id, DMat4::IDENTITY)))
            .ok_or_else(|| format!("--camera {n}: the scene has no Viewpoint DEF'd `{n}`")),
        None => Ok(None),
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
    ViewpointFound {
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
}

impl View {
    /// The viewpoint, or a framing of the bounds from +Z (the default Viewpoint's
    /// direction) with the default field of view.
    pub fn choose(viewpoint: Option<&ViewpointFound>, bounds: Option<(DVec3, DVec3)>) -> View {
        let fov = std::f32::consts::FRAC_PI_4;
        let projection = Projection::Perspective { field_of_view: fov };
        match (viewpoint, bounds) {
            (Some(v), _) => View {
                eye: v.eye,
                orientation: v.orientation,
                projection: v.projection,
            },
            (None, Some((lo, hi))) => {
                let centre = (lo + hi) / 2.0;
                let radius = ((hi - lo).length() / 2.0).max(f64::MIN_POSITIVE);
                let distance = radius / (f64::from(fov) / 2.0).sin();
                View {
                    eye: centre + DVec3::new(0.0, 0.0, distance),
                    orientation: DQuat::IDENTITY,
                    projection,
                }
            }
            (None, None) => View {
                eye: DVec3::new(0.0, 0.0, 10.0),
                orientation: DQuat::IDENTITY,
                projection,
            },
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
}

/// Near and far: from NavigationInfo (avatarSize / 2, visibilityLimit) where the scene
/// has one, else from the distance of the scene's bounds.
pub fn depth_range(
    bounds: Option<(DVec3, DVec3)>,
    eye: DVec3,
    navigation: Option<super::environment::Navigation>,
) -> (f32, f32) {
    let (nearest, farthest) = match bounds {
        Some((lo, hi)) => {
            let closest = eye.clamp(lo, hi);
            let pick = |e: f64, l: f64, h: f64| if (e - l).abs() > (e - h).abs() { l } else { h };
            let corner = DVec3::new(
                pick(eye.x, lo.x, hi.x),
                pick(eye.y, lo.y, hi.y),
                pick(eye.z, lo.z, hi.z),
            );
            ((closest - eye).length(), (corner - eye).length())
        }
        None => (1.0, 100.0),
    };
    let mut far = (farthest * 1.01).max(f64::MIN_POSITIVE * 1e6);
    let mut near = (nearest * 0.99).max(far * 1e-6);
    if let Some(n) = navigation {
        if let Some(avatar) = n.avatar_size {
            near = f64::from(avatar) / 2.0;
        }
        if n.visibility_limit > 0.0 {
            far = f64::from(n.visibility_limit);
        }
    }
    if !(near > 0.0 && near.is_finite()) {
        near = 0.1;
    }
    if !(far > near && far.is_finite()) {
        far = near * 1e6;
    }
    (near as f32, (far as f32).max(near as f32 * 2.0))
}

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
    use super::*;

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
        let first = find_viewpoint(&d, None).unwrap().unwrap();
        assert_eq!(first.eye, DVec3::new(10.0, 0.0, 5.0));
        let b = find_viewpoint(&d, Some("B")).unwrap().unwrap();
        assert_eq!(b.eye, DVec3::new(1.0, 2.0, 3.0));
        assert!(find_viewpoint(&d, Some("C")).is_err());
    }

    #[test]
    fn x3d_3_0_viewpoints_are_found() {
        let source = "<X3D version='3.0' profile='Immersive'><Scene>\
                      <Viewpoint position='1 2 3'/></Scene></X3D>";
        let d = crate::parse::read(source.as_bytes()).document.unwrap();
        let v = find_viewpoint(&d, None).unwrap().unwrap();
        assert_eq!(v.eye, DVec3::new(1.0, 2.0, 3.0));
    }

    #[test]
    fn ortho_viewpoints_keep_their_rectangle() {
        let d = doc("<OrthoViewpoint fieldOfView='-2 -1 2 1'/>");
        let v = find_viewpoint(&d, None).unwrap().unwrap();
        assert_eq!(
            v.projection,
            Projection::Orthographic {
                rectangle: [-2.0, -1.0, 2.0, 1.0]
            }
        );
    }
}
