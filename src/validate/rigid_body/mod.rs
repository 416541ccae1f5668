//! Rigid body physics component (clause 37): bodies' mass, what a RigidBodyCollection's
//! joints refer to, and the outputs a joint is asked for.

pub mod rigid_body_mass_zero;
pub mod rigid_joint_body_outside_collection;
pub mod rigid_joint_force_output_unknown;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &rigid_body_mass_zero::CHECK,
    &rigid_joint_body_outside_collection::CHECK,
    &rigid_joint_force_output_unknown::CHECK,
];
