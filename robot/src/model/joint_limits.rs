//! What a URDF joint's numbers may be: limits within sane bounds, mimic multipliers and
//! offsets within bounds, and a mimic follower's own limits kept by shrinking its leader's
//! range.

use std::f64::consts::PI;

use mit_star_spaces::JointKind;

use crate::model::model_joint::ModelJoint;
use crate::{ModelError, ModelWarning, RobotModel};

impl RobotModel {
    /// The largest magnitude of a prismatic joint's limit, in metres. No robot's slide is
    /// longer; a larger limit is a unit error (millimetres written as metres), and the
    /// checker's margin grows with the reach of a slide until every state collides.
    pub const MAX_PRISMATIC_LIMIT: f64 = 100.0;

    /// The largest magnitude of a revolute joint's limit, in radians: two turns either way
    /// (4π). Multi-turn joints (±2π) fit; a larger limit is a unit error (degrees written as
    /// radians).
    pub const MAX_REVOLUTE_LIMIT: f64 = 4.0 * PI;

    /// The largest magnitude of a mimic multiplier. Real couplings (fingers, gears, parallel
    /// grippers) are within a few units; at 10³ a milliradian of the leader moves the
    /// follower by a radian (or a metre), beyond what a collision margin can usefully bound,
    /// and larger values overflow the kinematics (a multiplier of 10³⁰⁰ gave contacts metres
    /// deep and infinite gaps).
    pub const MAX_MIMIC_MULTIPLIER: f64 = 1e3;

    /// The largest magnitude of a mimic offset, in metres or radians (the prismatic bound).
    pub const MAX_MIMIC_OFFSET: f64 = Self::MAX_PRISMATIC_LIMIT;
}

/// The limits of revolute or `prismatic` joint `name` as written, checked: finite,
/// `lower < upper`, and within the kind's bound.
pub(super) fn checked_limits(
    name: &str,
    prismatic: bool,
    lower: f64,
    upper: f64,
) -> Result<(f64, f64), ModelError> {
    if !(lower.is_finite() && upper.is_finite() && lower < upper) {
        return Err(ModelError::BadLimits {
            joint: name.to_owned(),
            lower,
            upper,
        });
    }
    let (kind, bound) = if prismatic {
        ("prismatic", RobotModel::MAX_PRISMATIC_LIMIT)
    } else {
        ("revolute", RobotModel::MAX_REVOLUTE_LIMIT)
    };
    if lower < -bound || upper > bound {
        return Err(ModelError::LimitsTooWide {
            joint: name.to_owned(),
            kind,
            lower,
            upper,
            bound,
        });
    }
    Ok((lower, upper))
}

/// Mimic joint `name`'s multiplier and offset, checked against their bounds.
pub(super) fn checked_mimic(name: &str, multiplier: f64, offset: f64) -> Result<(), ModelError> {
    for (what, value, bound) in [
        ("multiplier", multiplier, RobotModel::MAX_MIMIC_MULTIPLIER),
        ("offset", offset, RobotModel::MAX_MIMIC_OFFSET),
    ] {
        if value.is_nan() || value.abs() > bound {
            return Err(ModelError::BadMimic {
                joint: name.to_owned(),
                what,
                value,
                bound,
            });
        }
    }
    Ok(())
}

/// Shrinks each leader's range so that every mimic follower with limits stays within them:
/// the leader's range becomes the intersection of its own limits and, for each follower
/// `f = m·leader + o` (through chains of mimic joints), the preimage of the follower's limits.
/// A continuous leader whose range shrinks becomes a revolute coordinate within `[-π, π]`.
/// Records a [`ModelWarning::MimicRange`] for each range that shrinks.
///
/// # Errors
/// [`ModelError::MimicLimits`] when a follower's limits cannot be kept (an empty
/// intersection, or a constant follower outside them); [`ModelError::MimicLeader`] for a
/// leader that is not a moving joint, or a cycle.
pub(super) fn keep_mimic_limits(
    joints: &mut [ModelJoint],
    warnings: &mut Vec<ModelWarning>,
) -> Result<(), ModelError> {
    for f in 0..joints.len() {
        let Some((lower, upper)) = joints[f].limits else {
            continue;
        };
        if joints[f].mimic.is_none() {
            continue;
        }
        // Follow the chain to the joint that leads it, composing `m·x + o`.
        let (mut at, mut m, mut o) = (f, 1.0, 0.0);
        for _ in 0..=joints.len() {
            let Some((leader, multiplier, offset)) = &joints[at].mimic else {
                break;
            };
            let unknown = || ModelError::MimicLeader {
                joint: joints[at].name.clone(),
                leader: leader.clone(),
            };
            (m, o) = (m * multiplier, o + m * offset);
            at = joints
                .iter()
                .position(|j| &j.name == leader)
                .ok_or_else(unknown)?;
        }
        if joints[at].mimic.is_some() {
            // A cycle: `rebuild` names it.
            continue;
        }
        let (follower, leader) = (joints[f].name.clone(), joints[at].name.clone());
        let refuse = || ModelError::MimicLimits {
            joint: follower.clone(),
            leader: leader.clone(),
            lower,
            upper,
        };
        if m == 0.0 {
            if (lower..=upper).contains(&o) {
                continue;
            }
            return Err(refuse());
        }
        let (from, to) = preimage(m, o, lower, upper);
        let joint = &mut joints[at];
        let Some(spec) = joint.spec.as_mut() else {
            continue;
        };
        let (own, prismatic) = match spec.kind {
            JointKind::Revolute { lower, upper } => ((lower, upper), false),
            JointKind::Prismatic { lower, upper } => ((lower, upper), true),
            JointKind::Continuous => ((-PI, PI), false),
        };
        let (new_lower, new_upper) = (own.0.max(from), own.1.min(to));
        if new_lower == own.0 && new_upper == own.1 {
            continue;
        }
        if new_lower >= new_upper || new_lower.is_nan() || new_upper.is_nan() {
            return Err(refuse());
        }
        spec.kind = if prismatic {
            JointKind::Prismatic {
                lower: new_lower,
                upper: new_upper,
            }
        } else {
            JointKind::Revolute {
                lower: new_lower,
                upper: new_upper,
            }
        };
        joint.value = joint.default_value();
        warnings.push(ModelWarning::MimicRange {
            leader,
            follower,
            lower: new_lower,
            upper: new_upper,
        });
    }
    Ok(())
}

/// The leader values `x` with `m·x + o` within `[lower, upper]` (`m ≠ 0`), rounded inwards so
/// that the follower's value computed from either end is within its limits.
fn preimage(m: f64, o: f64, lower: f64, upper: f64) -> (f64, f64) {
    let (a, b) = ((lower - o) / m, (upper - o) / m);
    let (mut from, mut to) = if m > 0.0 { (a, b) } else { (b, a) };
    let inside = |x: f64| (lower..=upper).contains(&(m * x + o));
    for _ in 0..64 {
        if inside(from) {
            break;
        }
        from += from.abs().max(f64::MIN_POSITIVE) * f64::EPSILON;
    }
    for _ in 0..64 {
        if inside(to) {
            break;
        }
        to -= to.abs().max(f64::MIN_POSITIVE) * f64::EPSILON;
    }
    (from, to)
}
