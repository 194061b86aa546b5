//! [`check_trajectory`]: a sampled trajectory checked against the robot, its limits and the
//! scene — independently of how it was timed.

use mit_star_spaces::{JointKind, Never, StateSpace};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};

use crate::{
    ArmChecker, AuditVerdict, BlendCertifier, MotionAudit, MotionLimits, RobotModel, Scene,
    TrajectoryError, TrajectoryFile,
};

/// The configurations the audit of one motion between samples may evaluate.
const AUDIT_BUDGET: u64 = 1_000_000;

/// The clearance (metres) the audit must see along a chord taken as a motion that is
/// straight within rounding ([`parallel`]'s 1e-7 rad): well beyond how far such a motion
/// strays from its chord.
const STRAIGHT_CLEARANCE: f64 = 1e-6;

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
/// [`MotionAudit`] in `f64` — both keeping the checker's [padding](ArmChecker::padding) from
/// the scene, as do the blends' certifications.
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
    let auditor: std::cell::OnceCell<MotionAudit> = std::cell::OnceCell::new();
    let blends = BlendCertifier::padded(robot, scene, checker.padding());
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
    // A straight motion (a stop-at-corner segment, or a piece of one): the edge
    // certification, and a refusal confirmed by the `f64` audit (it refuses configurations
    // within 10 µm of contact beyond its margin, which a sub-motion of a certified edge can
    // come to).
    let along_chord = |a: &[f64], b: &[f64]| {
        let mut progress = MotionProgress::default();
        let certified = if a == b {
            checker.is_valid(a)
        } else {
            checker.certify_motion(space, a, b, &mut progress, &Never) == Some(EdgeStatus::Valid)
        };
        if certified {
            return Verdict::Certified;
        }
        let audit = auditor.get_or_init(|| MotionAudit::padded(robot, scene, checker.padding()));
        if matches!(
            audit.audit(a, b, AUDIT_BUDGET),
            AuditVerdict::Clear { clearance, .. } if clearance >= STRAIGHT_CLEARANCE
        ) {
            Verdict::Audited
        } else {
            Verdict::Refused
        }
    };
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
        // The motion between the samples: one or two parabolas of the samples'
        // accelerations (a file of ours, at its knots or at a period), else the quintic their
        // positions, velocities and accelerations determine (a controller's quintic spline).
        let verdict = match parabolas(p, s) {
            Some(pieces) => {
                let mut verdict = Verdict::Certified;
                for (entry, duration) in &pieces {
                    let end = entry_at(entry, *duration);
                    let piece = if parallel_motion(entry, &end) {
                        along_chord(&entry.position, &end.position)
                    } else if blends.certify_blend(entry, *duration) {
                        Verdict::Certified
                    } else {
                        Verdict::Refused
                    };
                    verdict = verdict.and(piece);
                }
                verdict
            }
            None => {
                let quintic = Quintic::new(p, s);
                if blends.certify_curve(&|t, q| quintic.at(t, q), dt, quintic.bounds()) {
                    Verdict::Certified
                } else if quintic.straight {
                    along_chord(&p.position, &s.position)
                } else {
                    Verdict::Refused
                }
            }
        };
        match verdict {
            Verdict::Certified => check.motions_certified += 1,
            Verdict::Audited => check.motions_audited += 1,
            Verdict::Refused => note(&mut check, Violation::Collision { sample: i + 1 }),
        }
    }
    Ok(check)
}

/// How the motion between two samples was proven collision-free, or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Verdict {
    Certified,
    Audited,
    Refused,
}

impl Verdict {
    /// Both motions proven: refused if either is, audited if either needed the audit.
    fn and(self, other: Self) -> Self {
        match (self, other) {
            (Self::Refused, _) | (_, Self::Refused) => Self::Refused,
            (Self::Audited, _) | (_, Self::Audited) => Self::Audited,
            _ => Self::Certified,
        }
    }
}

/// The state `duration` after `entry` at its constant acceleration.
fn entry_at(entry: &crate::Sample, duration: f64) -> crate::Sample {
    let n = entry.position.len();
    crate::Sample {
        time: entry.time + duration,
        position: (0..n)
            .map(|j| {
                entry.position[j]
                    + entry.velocity[j] * duration
                    + 0.5 * entry.acceleration[j] * duration * duration
            })
            .collect(),
        velocity: (0..n)
            .map(|j| entry.velocity[j] + entry.acceleration[j] * duration)
            .collect(),
        acceleration: entry.acceleration.clone(),
    }
}

/// Whether a piece of constant acceleration from `entry` to `end` stays on their chord: its
/// acceleration along the chord (then so is its velocity, and every configuration is on the
/// chord's line), and its velocity never pointing backwards along it (then it moves
/// monotonically from one end to the other; a backward speed below 1e-9 of the mean is taken
/// as rounding, its overshoot below 1e-9 of the chord).
fn parallel_motion(entry: &crate::Sample, end: &crate::Sample) -> bool {
    let duration = end.time - entry.time;
    let chord: Vec<f64> = entry
        .position
        .iter()
        .zip(&end.position)
        .map(|(a, b)| b - a)
        .collect();
    let length2: f64 = chord.iter().map(|x| x * x).sum();
    let forward = |v: &[f64]| {
        let along: f64 = chord.iter().zip(v).map(|(c, x)| c * x).sum();
        along >= -1e-9 * length2 / duration
    };
    length2 > 0.0
        && parallel(&chord, &entry.acceleration)
        && forward(&entry.velocity)
        && forward(&end.velocity)
}

/// Whether `a` and `b` agree within the rounding of a file (relative 1e-9).
fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + scale)
}

/// The motion from `p` to `s` as pieces of constant acceleration, `(entry, duration)`: `p`'s
/// acceleration held to `s` (or `s`'s, for a sample at a knot that records the acceleration
/// after it), or `p`'s until a switch time and `s`'s after it (an interval holding one
/// knot). `None` if neither explains the samples.
fn parabolas(p: &crate::Sample, s: &crate::Sample) -> Option<Vec<(crate::Sample, f64)>> {
    let h = s.time - p.time;
    let n = p.position.len();
    let reaches = |end: &crate::Sample| {
        (0..n).all(|j| {
            let scale = p.position[j].abs() + p.velocity[j].abs() + s.position[j].abs();
            close(end.position[j], s.position[j], scale)
                && close(end.velocity[j], s.velocity[j], scale + s.velocity[j].abs())
        })
    };
    for a in [&p.acceleration, &s.acceleration] {
        let entry = crate::Sample {
            acceleration: a.clone(),
            ..p.clone()
        };
        if reaches(&entry_at(&entry, h)) {
            return Some(vec![(entry, h)]);
        }
    }
    // One switch at τ: v_p + a_p τ + a_s (h − τ) = v_s, in the coordinate whose
    // accelerations differ most.
    let j = (0..n).max_by(|&x, &y| {
        let dx = (p.acceleration[x] - s.acceleration[x]).abs();
        let dy = (p.acceleration[y] - s.acceleration[y]).abs();
        dx.total_cmp(&dy)
    })?;
    let jump = p.acceleration[j] - s.acceleration[j];
    if jump == 0.0 {
        return None;
    }
    let tau = (s.velocity[j] - p.velocity[j] - s.acceleration[j] * h) / jump;
    if !(tau > 0.0 && tau < h) {
        return None;
    }
    let middle = entry_at(p, tau);
    let second = crate::Sample {
        acceleration: s.acceleration.clone(),
        ..middle
    };
    reaches(&entry_at(&second, h - tau)).then(|| vec![(p.clone(), tau), (second, h - tau)])
}

/// The quintic from sample `p` to sample `s` matching both ends' positions, velocities and
/// accelerations (a controller's quintic spline), per coordinate, in time since `p`: the
/// motion between samples that no parabola of theirs explains ([`parabolas`]).
struct Quintic {
    coefficients: Vec<[f64; 6]>,
    duration: f64,
    /// The ends' velocities and accelerations all along the chord: the motion stays on the
    /// line through the two positions.
    straight: bool,
    bend: Vec<f64>,
    speed: Vec<f64>,
}

impl Quintic {
    fn new(p: &crate::Sample, s: &crate::Sample) -> Self {
        let h = s.time - p.time;
        let coefficients: Vec<[f64; 6]> = (0..p.position.len())
            .map(|j| {
                let (p0, v0, a0) = (p.position[j], p.velocity[j], p.acceleration[j]);
                let (p1, v1, a1) = (s.position[j], s.velocity[j], s.acceleration[j]);
                let d = p1 - p0;
                [
                    p0,
                    v0,
                    0.5 * a0,
                    (20.0 * d - (8.0 * v1 + 12.0 * v0) * h - (3.0 * a0 - a1) * h * h)
                        / (2.0 * h.powi(3)),
                    (-30.0 * d + (14.0 * v1 + 16.0 * v0) * h + (3.0 * a0 - 2.0 * a1) * h * h)
                        / (2.0 * h.powi(4)),
                    (12.0 * d - 6.0 * (v1 + v0) * h - (a0 - a1) * h * h) / (2.0 * h.powi(5)),
                ]
            })
            .collect();
        // Sound bounds over [0, h]: each term at its largest.
        let bend = coefficients
            .iter()
            .map(|c| {
                2.0 * c[2].abs()
                    + 6.0 * c[3].abs() * h
                    + 12.0 * c[4].abs() * h * h
                    + 20.0 * c[5].abs() * h.powi(3)
            })
            .collect();
        let speed = coefficients
            .iter()
            .map(|c| {
                c[1].abs()
                    + 2.0 * c[2].abs() * h
                    + 3.0 * c[3].abs() * h * h
                    + 4.0 * c[4].abs() * h.powi(3)
                    + 5.0 * c[5].abs() * h.powi(4)
            })
            .collect();
        let chord: Vec<f64> = p
            .position
            .iter()
            .zip(&s.position)
            .map(|(a, b)| b - a)
            .collect();
        let straight = [&p.velocity, &s.velocity, &p.acceleration, &s.acceleration]
            .iter()
            .all(|v| parallel(&chord, v));
        Self {
            coefficients,
            duration: h,
            straight,
            bend,
            speed,
        }
    }

    fn at(&self, t: f64, q: &mut [f64]) {
        let t = t.clamp(0.0, self.duration);
        for (x, c) in q.iter_mut().zip(&self.coefficients) {
            *x = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
        }
    }

    fn bounds(&self) -> (&[f64], &[f64]) {
        (&self.bend, &self.speed)
    }
}

/// Whether `v` is a multiple of `d` within about 1e-7 rad, zero included: the test's own
/// rounding (`|d|²|v|² − (d·v)²` cancels) leaves about 1e-8 rad between vectors a timing made
/// parallel. A motion that far off its chord strays from it by at most 1e-7 of its length
/// times the robot's reach (0.1 µm over a radian of the Panda), which the certification's
/// margin (20 µm) and the audit's required clearance ([`STRAIGHT_CLEARANCE`]) cover.
fn parallel(d: &[f64], v: &[f64]) -> bool {
    let dd: f64 = d.iter().map(|x| x * x).sum();
    let vv: f64 = v.iter().map(|x| x * x).sum();
    let dv: f64 = d.iter().zip(v).map(|(a, b)| a * b).sum();
    vv == 0.0 || (dd > 0.0 && (dd * vv - dv * dv) <= 1e-14 * dd * vv)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Sample;

    fn sample(time: f64, position: Vec<f64>, velocity: Vec<f64>, acceleration: Vec<f64>) -> Sample {
        Sample {
            time,
            position,
            velocity,
            acceleration,
        }
    }

    #[test]
    fn the_quintic_meets_both_ends_and_is_the_parabola_of_a_constant_acceleration() {
        // A parabola: x = 1 + 2t − 1.5t², y = −t + 0.5t², from t = 0.5 to 1.25.
        let at = |t: f64| {
            sample(
                t,
                vec![1.0 + 2.0 * t - 1.5 * t * t, -t + 0.5 * t * t],
                vec![2.0 - 3.0 * t, -1.0 + t],
                vec![-3.0, 1.0],
            )
        };
        let (p, s) = (at(0.5), at(1.25));
        let quintic = Quintic::new(&p, &s);
        assert!(!quintic.straight);
        let mut q = [0.0; 2];
        for k in 0..=10 {
            let t = 0.75 * f64::from(k) / 10.0;
            quintic.at(t, &mut q);
            let exact = at(0.5 + t).position;
            assert!((q[0] - exact[0]).abs() < 1e-12 && (q[1] - exact[1]).abs() < 1e-12);
        }
        // The bend bound is the acceleration (the higher terms vanish).
        assert!((quintic.bend[0] - 3.0).abs() < 1e-9 && (quintic.bend[1] - 1.0).abs() < 1e-9);
        // A knot recording the next piece's acceleration: the parabola is still found.
        let mut knot = at(1.25);
        knot.acceleration = vec![0.0, 0.0];
        let pieces = parabolas(&at(0.5), &knot).expect("one parabola");
        assert_eq!(pieces.len(), 1);
        assert_eq!(pieces[0].0.acceleration, vec![-3.0, 1.0]);
        // A knot inside the interval: two parabolas, switching at it.
        let before = at(0.5);
        let mid = entry_at(&before, 0.25);
        let end = entry_at(
            &sample(mid.time, mid.position, mid.velocity, vec![1.0, -2.0]),
            0.5,
        );
        let end = sample(1.25, end.position, end.velocity, vec![1.0, -2.0]);
        let pieces = parabolas(&before, &end).expect("two parabolas");
        assert_eq!(pieces.len(), 2);
        assert!((pieces[0].1 - 0.25).abs() < 1e-9 && (pieces[1].1 - 0.5).abs() < 1e-9);
        // Ends of another kind: positions and velocities met.
        let (p, s) = (
            sample(0.0, vec![0.0], vec![1.0], vec![0.0]),
            sample(2.0, vec![1.0], vec![0.0], vec![-1.0]),
        );
        let quintic = Quintic::new(&p, &s);
        let mut q = [0.0];
        quintic.at(2.0, &mut q);
        assert!((q[0] - 1.0).abs() < 1e-12);
        assert!(quintic.straight, "one coordinate: always along the chord");
    }

    #[test]
    fn parallel_vectors_are_told_apart() {
        assert!(parallel(&[1.0, 2.0], &[-2.0, -4.0]));
        assert!(parallel(&[1.0, 2.0], &[0.0, 0.0]));
        assert!(!parallel(&[1.0, 2.0], &[2.0, -1.0]));
        assert!(!parallel(&[0.0, 0.0], &[1.0, 0.0]));
    }
}
