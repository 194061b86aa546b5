//! [`check_trajectory`]: a sampled trajectory checked against the robot, its limits and the
//! scene — independently of how it was timed.

use spaces::{JointKind, Never, StateSpace};
use validity::{EdgeStatus, MotionProgress, StateValidity};

use crate::{
    ArmChecker, AuditVerdict, MotionAudit, MotionLimits, RobotModel, Scene, TrajectoryError,
    TrajectoryFile,
};

/// The configurations the audit of one motion between samples may evaluate.
const AUDIT_BUDGET: u64 = 1_000_000;

/// The relative tolerance of the limit checks.
pub const TRAJECTORY_TOLERANCE: f64 = 1e-9;

/// The most violations a check lists (it counts them all).
const LISTED: usize = 100;

/// One way a sampled trajectory breaks the rules.
#[derive(Debug, Clone, PartialEq)]
pub enum Violation {
    /// A position outside the joint's limits.
    Position {
        /// The sample.
        sample: usize,
        /// The joint.
        joint: String,
        /// Its value.
        value: f64,
    },
    /// A velocity or acceleration beyond the joint's limit (times `1 + 10⁻⁹`).
    Limit {
        /// The sample.
        sample: usize,
        /// The joint.
        joint: String,
        /// `velocity` or `acceleration`.
        what: &'static str,
        /// Its value.
        value: f64,
        /// The limit.
        limit: f64,
    },
    /// Two samples whose positions or velocities cannot both hold under the acceleration
    /// limit: from sample − 1 to sample, the position moved by more than the trapezoid rule
    /// on the velocities allows (`A Δt² / 4` off), or the velocity changed by more than
    /// `A Δt`.
    Discontinuity {
        /// The later sample.
        sample: usize,
        /// The joint.
        joint: String,
        /// `position` or `velocity`.
        what: &'static str,
        /// By how much the allowance is exceeded.
        excess: f64,
    },
    /// A value that is not finite.
    NotFinite {
        /// The sample.
        sample: usize,
    },
    /// The first or last sample not at rest.
    NotAtRest {
        /// The sample.
        sample: usize,
    },
    /// The straight motion from sample − 1 to sample could not be certified collision-free,
    /// and the independent continuous audit ([`MotionAudit`](crate::MotionAudit)) did not
    /// find it clear either.
    Collision {
        /// The later sample.
        sample: usize,
    },
}

/// What [`check_trajectory`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct TrajectoryCheck {
    /// The samples checked.
    pub samples: usize,
    /// The last sample's time.
    pub duration: f64,
    /// The largest `|v| / V − 1` over samples and joints (negative: within the limits).
    pub velocity_excess: f64,
    /// The largest `|a| / A − 1`.
    pub acceleration_excess: f64,
    /// The motions between samples certified collision-free.
    pub motions_certified: usize,
    /// The motions the certification refused that the audit found clear.
    pub motions_audited: usize,
    /// How many violations there are.
    pub violation_count: usize,
    /// The first hundred of them.
    pub violations: Vec<Violation>,
}

impl TrajectoryCheck {
    /// No violation.
    pub fn is_valid(&self) -> bool {
        self.violation_count == 0
    }
}

/// Checks `file` against `robot` (its joints, in order, and their position limits), `limits`
/// (relative tolerance [`TRAJECTORY_TOLERANCE`]) and `checker` (of `robot` in `scene`): times strictly increasing, finite values,
/// positions within the joint limits (continuous joints have none), velocities and
/// accelerations within the limits, consecutive samples consistent (positions with the
/// velocities, velocities with each other, under the acceleration limit), at rest at both
/// ends, and the straight motion between consecutive samples' positions certified
/// collision-free ([`StateValidity::certify_motion`]), or else found clear by the continuous
/// [`MotionAudit`] in `f64`.
///
/// The collision check is of the sampled polyline, not of the curve between samples: sample
/// densely (or at the knots of a stop-at-corner trajectory, whose motions are straight).
///
/// # Errors
/// [`TrajectoryError::JointNames`] when the file's joints are not the robot's;
/// [`TrajectoryError::TooShort`] for fewer than two samples;
/// [`TrajectoryError::TimeNotIncreasing`] when a time does not exceed the one before.
pub fn check_trajectory(
    file: &TrajectoryFile,
    robot: &RobotModel,
    scene: &Scene,
    limits: &MotionLimits,
    checker: &ArmChecker,
) -> Result<TrajectoryCheck, TrajectoryError> {
    if file.joints != robot.joint_names() || limits.names() != robot.joint_names() {
        return Err(TrajectoryError::JointNames {
            expected: robot.joint_names().join(","),
            found: file.joints.join(","),
        });
    }
    let samples = &file.samples;
    if samples.len() < 2 {
        return Err(TrajectoryError::TooShort {
            points: samples.len(),
        });
    }
    for (i, w) in samples.windows(2).enumerate() {
        if w[1].time.is_nan() || w[0].time.is_nan() || w[1].time <= w[0].time {
            return Err(TrajectoryError::TimeNotIncreasing {
                index: i + 1,
                previous: w[0].time,
                time: w[1].time,
            });
        }
    }
    let space = robot.joint_space();
    let mut auditor: Option<MotionAudit> = None;
    let names = robot.joint_names();
    let (v_max, a_max) = (limits.velocity(), limits.acceleration());
    let mut check = TrajectoryCheck {
        samples: samples.len(),
        duration: samples[samples.len() - 1].time,
        velocity_excess: f64::NEG_INFINITY,
        acceleration_excess: f64::NEG_INFINITY,
        motions_certified: 0,
        motions_audited: 0,
        violation_count: 0,
        violations: Vec::new(),
    };
    let note = |check: &mut TrajectoryCheck, v: Violation| {
        check.violation_count += 1;
        if check.violations.len() < LISTED {
            check.violations.push(v);
        }
    };
    for (i, s) in samples.iter().enumerate() {
        let values = s.position.iter().chain(&s.velocity).chain(&s.acceleration);
        if !s.time.is_finite() || values.clone().any(|x| !x.is_finite()) {
            note(&mut check, Violation::NotFinite { sample: i });
            continue;
        }
        if (i == 0 || i + 1 == samples.len()) && s.velocity.iter().any(|v| *v != 0.0) {
            note(&mut check, Violation::NotAtRest { sample: i });
        }
        for j in 0..names.len() {
            if !matches!(space.joints()[j].kind, JointKind::Continuous) {
                let (lo, hi) = (space.lower()[j], space.upper()[j]);
                let slack = TRAJECTORY_TOLERANCE * (hi - lo);
                if !(lo - slack..=hi + slack).contains(&s.position[j]) {
                    note(
                        &mut check,
                        Violation::Position {
                            sample: i,
                            joint: names[j].clone(),
                            value: s.position[j],
                        },
                    );
                }
            }
            for (what, value, limit) in [
                ("velocity", s.velocity[j], v_max[j]),
                ("acceleration", s.acceleration[j], a_max[j]),
            ] {
                let excess = value.abs() / limit - 1.0;
                let worst = if what == "velocity" {
                    &mut check.velocity_excess
                } else {
                    &mut check.acceleration_excess
                };
                *worst = worst.max(excess);
                if excess > TRAJECTORY_TOLERANCE {
                    note(
                        &mut check,
                        Violation::Limit {
                            sample: i,
                            joint: names[j].clone(),
                            what,
                            value,
                            limit,
                        },
                    );
                }
            }
        }
    }
    for (i, w) in samples.windows(2).enumerate() {
        let (p, s) = (&w[0], &w[1]);
        let dt = s.time - p.time;
        for j in 0..names.len() {
            let a = a_max[j] * (1.0 + TRAJECTORY_TOLERANCE);
            let rounding = 1e-9 * (1.0 + p.position[j].abs() + s.position[j].abs());
            let drift =
                (s.position[j] - p.position[j] - 0.5 * (p.velocity[j] + s.velocity[j]) * dt).abs();
            let allowed = 0.25 * a * dt * dt + rounding;
            if drift > allowed {
                note(
                    &mut check,
                    Violation::Discontinuity {
                        sample: i + 1,
                        joint: names[j].clone(),
                        what: "position",
                        excess: drift - allowed,
                    },
                );
            }
            let jump = (s.velocity[j] - p.velocity[j]).abs();
            let allowed = a * dt + 1e-9 * (1.0 + v_max[j]);
            if jump > allowed {
                note(
                    &mut check,
                    Violation::Discontinuity {
                        sample: i + 1,
                        joint: names[j].clone(),
                        what: "velocity",
                        excess: jump - allowed,
                    },
                );
            }
        }
        let mut progress = MotionProgress::default();
        let certified = if p.position == s.position {
            checker.is_valid(&p.position)
        } else {
            checker.certify_motion(space, &p.position, &s.position, &mut progress, &Never)
                == Some(EdgeStatus::Valid)
        };
        // The certification is conservative (it refuses configurations within 10 µm of
        // contact beyond its margin, which a sub-motion of a certified edge can come to):
        // a refusal is confirmed by the `f64` audit.
        let mut audit = || {
            let audit = auditor.get_or_insert_with(|| MotionAudit::new(robot, scene));
            matches!(
                audit.audit(&p.position, &s.position, AUDIT_BUDGET),
                AuditVerdict::Clear { .. }
            )
        };
        if certified {
            check.motions_certified += 1;
        } else if audit() {
            check.motions_audited += 1;
        } else {
            note(&mut check, Violation::Collision { sample: i + 1 });
        }
    }
    Ok(check)
}
