//! Particle systems component (clause 40): a ParticleSystem's ramps against their keys,
//! and the order of its colour keys.

pub mod particle_color_ramp_short;
pub mod particle_key_decreasing;
pub mod particle_texcoord_ramp_short;

use std::collections::HashSet;

use super::events::wiring::{routed_fields, set_elsewhere};
use super::Check;
use crate::model::{Document, NodeId, Span};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &particle_color_ramp_short::CHECK,
    &particle_texcoord_ramp_short::CHECK,
    &particle_key_decreasing::CHECK,
];

/// A ParticleSystem's ramp (colours or texture coordinates) and the keys it is read at.
pub(crate) struct Ramp {
    pub system: NodeId,
    /// `colorKey` or `texCoordKey`.
    pub key_field: &'static str,
    pub keys: usize,
    /// The ramp field as this version names it: `colorRamp`/`texCoordRamp` in 3.x,
    /// `color`/`texCoord` in 4.x.
    pub ramp_field: &'static str,
    /// The type of the ramp's node (`Color`, `ColorRGBA`, `TextureCoordinate`).
    pub ramp_type: String,
    /// How many values (colours, points) the ramp's node holds.
    pub values: usize,
    /// Where the ramp's values are written, else the ramp node.
    pub span: Span,
}

/// Every ParticleSystem with keys in `key_field` and a ramp node in whichever of
/// `ramp_fields` its version has, whose values the scene does not replace (no ROUTE into
/// and no `IS` on the keys, the ramp field or the ramp node's values). The ramp node is
/// read when it is one of `ramp_types`, through its field `values_field`.
pub(crate) fn ramps(
    doc: &Document,
    key_field: &'static str,
    ramp_fields: [&'static str; 2],
    ramp_types: &[&str],
    values_field: &str,
) -> Vec<Ramp> {
    let routed = routed_fields(doc);
    doc.nodes_of_type("ParticleSystem")
        .filter_map(|system| {
            let def = doc.node(system).def()?;
            let ramp_field = ramp_fields.into_iter().find(|f| def.field(f).is_some())?;
            ramp(
                doc,
                &routed,
                system,
                key_field,
                ramp_field,
                ramp_types,
                values_field,
            )
        })
        .collect()
}

fn ramp(
    doc: &Document,
    routed: &HashSet<(NodeId, String)>,
    system: NodeId,
    key_field: &'static str,
    ramp_field: &'static str,
    ramp_types: &[&str],
    values_field: &str,
) -> Option<Ramp> {
    let holder = doc.child_of(system, ramp_field)?;
    let ramp_node = doc.node(holder);
    if !ramp_types.contains(&ramp_node.type_name())
        || set_elsewhere(doc, routed, system, key_field)
        || set_elsewhere(doc, routed, system, ramp_field)
        || set_elsewhere(doc, routed, holder, values_field)
    {
        return None;
    }
    let arity = ramp_node.def()?.field(values_field)?.ty.arity();
    let numbers = doc.value_of(holder, values_field)?.len();
    let span = ramp_node
        .entry(values_field)
        .map_or(ramp_node.name_span, |e| e.span);
    Some(Ramp {
        system,
        key_field,
        keys: doc.value_of(system, key_field)?.len(),
        ramp_field,
        ramp_type: ramp_node.type_name().to_string(),
        values: numbers / arity.max(1),
        span,
    })
}
