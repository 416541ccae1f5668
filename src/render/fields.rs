//! Reading the fields the renderer needs, with schema defaults, as plain numbers.

use std::borrow::Cow;

use crate::model::{Document, NodeId, Value};

pub fn floats<'d>(doc: &'d Document, node: NodeId, name: &str) -> Cow<'d, [f32]> {
    match doc.value_of(node, name) {
        Some(Cow::Borrowed(Value::Floats(v))) => Cow::Borrowed(v),
        Some(Cow::Owned(Value::Floats(v))) => Cow::Owned(v),
        _ => Cow::Borrowed(&[]),
    }
}

pub fn ints<'d>(doc: &'d Document, node: NodeId, name: &str) -> Cow<'d, [i32]> {
    match doc.value_of(node, name) {
        Some(Cow::Borrowed(Value::Int32s(v))) => Cow::Borrowed(v),
        Some(Cow::Owned(Value::Int32s(v))) => Cow::Owned(v),
        _ => Cow::Borrowed(&[]),
    }
}

pub fn float(doc: &Document, node: NodeId, name: &str, fallback: f32) -> f32 {
    doc.f32_of(node, name)
        .filter(|v| v.is_finite())
        .unwrap_or(fallback)
}

pub fn boolean(doc: &Document, node: NodeId, name: &str, fallback: bool) -> bool {
    doc.bool_of(node, name).unwrap_or(fallback)
}

pub fn vec3(doc: &Document, node: NodeId, name: &str, fallback: [f32; 3]) -> [f32; 3] {
    match floats(doc, node, name).as_ref() {
        [x, y, z, ..] if x.is_finite() && y.is_finite() && z.is_finite() => [*x, *y, *z],
        _ => fallback,
    }
}

/// A colour clamped to [0, 1] (NaN becomes the fallback's component).
pub fn color(doc: &Document, node: NodeId, name: &str, fallback: [f32; 3]) -> [f32; 3] {
    let c = vec3(doc, node, name, fallback);
    [unit(c[0]), unit(c[1]), unit(c[2])]
}

/// Clamps to [0, 1]; NaN becomes 0.
pub fn unit(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, 1.0)
    }
}

/// An SFRotation as a unit quaternion (f64); a zero or non-finite axis is no rotation.
pub fn rotation(doc: &Document, node: NodeId, name: &str) -> glam::DQuat {
    match floats(doc, node, name).as_ref() {
        [x, y, z, angle, ..] => rotation_of([*x, *y, *z, *angle]),
        _ => glam::DQuat::IDENTITY,
    }
}

pub fn rotation_of([x, y, z, angle]: [f32; 4]) -> glam::DQuat {
    let axis = glam::DVec3::new(f64::from(x), f64::from(y), f64::from(z));
    let length = axis.length();
    let angle = f64::from(angle);
    if length > 0.0 && length.is_finite() && angle.is_finite() {
        glam::DQuat::from_axis_angle(axis / length, angle)
    } else {
        glam::DQuat::IDENTITY
    }
}

/// The first node of an SFNode field; for a ProtoInstance, the node it builds.
pub fn child(doc: &Document, node: NodeId, name: &str) -> Option<NodeId> {
    doc.child_of(node, name).map(|c| doc.built(c).unwrap_or(c))
}

pub fn type_is(doc: &Document, node: NodeId, name: &str) -> bool {
    doc.node(node).def().is_some_and(|d| d.name == name)
}
