//! Rigid body physics component (clause 37): what a RigidBodyCollection's joints refer to.

pub mod rigid_joint_body_outside_collection;

use super::Check;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&rigid_joint_body_outside_collection::CHECK];
