//! [`PathValidation`]: an independent check of a returned path — exact for box worlds,
//! continuous for arms.

use std::cell::Cell;

use mit_star_problems::Problem;
use mit_star_robot::{AuditVerdict, MotionAudit};
use mit_star_spaces::{StateSpace, euclidean_distance};
use mit_star_validity::{SegmentCause, SegmentVerdict, StateValidity, World};
use serde::{Deserialize, Serialize};

/// How a path was validated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum ValidationMethod {
    /// Every segment decided exactly against every box of the world (slab tests, no grid:
    /// [`World::segment_verdict`]). What the harness does for every benchmark problem.
    ExactBoxes,
    /// Every segment of an arm path proven collision-free continuously, in `f64`, by
    /// conservative advancement from parry distances and the audit's own bound on how fast
    /// each sphere moves ([`MotionAudit`]): no grid. What the harness does for arm problems.
    ContinuousArm {
        /// Configurations whose distances were computed, over the whole path.
        configurations: u64,
        /// The smallest distance between the robot and an obstacle or itself along the path
        /// (metres), an obstacle's less the padding.
        clearance: f64,
        /// The smallest distance between a robot sphere and an obstacle along the path
        /// (metres), the padding not subtracted.
        obstacle_clearance: f64,
        /// The padding the path had to keep from obstacles (metres).
        padding: f64,
    },
    /// Every segment re-checked at grid points `step` apart — at least 4× finer than the
    /// planner's step. A grid shares the planner's blind spot between points, so this is a
    /// cross-check, not a proof; for validity checkers with neither an exact nor a continuous
    /// check.
    Resampled {
        /// The re-check step.
        step: f64,
    },
}

impl ValidationMethod {
    /// One line for reports: what was done.
    pub fn describe(&self) -> String {
        match self {
            Self::ExactBoxes => "exactly against every box (segment slab tests, no grid)".into(),
            Self::ContinuousArm {
                configurations,
                clearance,
                padding,
                ..
            } if *padding == 0.0 => format!(
                "continuously in f64 (conservative advancement on parry distances, no grid: \
                 {configurations} configurations, clearance ≥ {} mm)",
                mit_star_spaces::short_number(clearance * 1e3)
            ),
            Self::ContinuousArm {
                configurations,
                clearance,
                obstacle_clearance,
                padding,
            } => format!(
                "continuously in f64 (conservative advancement on parry distances, no grid: \
                 {configurations} configurations, every sphere ≥ {} mm from obstacles with a \
                 padding of {} mm, clearance beyond it ≥ {} mm)",
                mit_star_spaces::short_number(obstacle_clearance * 1e3),
                mit_star_spaces::short_number(padding * 1e3),
                mit_star_spaces::short_number(clearance * 1e3)
            ),
            Self::Resampled { step } => format!(
                "at a step of {} (at least 4× finer than planning)",
                mit_star_spaces::short_number(*step)
            ),
        }
    }
}

impl PathValidation {
    /// What the check covered, in the method's own unit, for reports: segments and the path's
    /// states with [`ValidationMethod::ExactBoxes`]; segments with
    /// [`ValidationMethod::ContinuousArm`] (whose configurations [`ValidationMethod::describe`]
    /// names); segments and grid points with [`ValidationMethod::Resampled`].
    ///
    /// ```
    /// let problem = mit_star_problems::builtin("obstacle-free", 2, 0)?;
    /// let path = vec![problem.start().to_vec(), problem.goals()[0].clone()];
    /// let v = mit_star_benches::PathValidation::check(&problem, &path, problem.straight_line_cost());
    /// assert_eq!(v.coverage(), "1 segment, 2 path states");
    /// # Ok::<(), mit_star_problems::ProblemError>(())
    /// ```
    pub fn coverage(&self) -> String {
        let count =
            |n: u64, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        let segments = count(self.segments_checked, "segment", "segments");
        match self.method {
            ValidationMethod::ExactBoxes => format!(
                "{segments}, {}",
                count(self.states_checked, "path state", "path states")
            ),
            ValidationMethod::ContinuousArm { .. } => segments,
            ValidationMethod::Resampled { .. } => format!(
                "{segments}, {}",
                count(
                    self.states_checked,
                    "state on the grid",
                    "states on the grid"
                )
            ),
        }
    }
}

/// The result of re-checking a path independently of the planner: the path must start at the
/// start, end at a goal, every segment must be valid, and its length must match the cost the
/// planner reported.
///
/// Box worlds — every benchmark problem — are validated **exactly**
/// ([`ValidationMethod::ExactBoxes`]): a path the planner's grid let through a wall thinner
/// than its step fails here. Arm paths are proven collision-free continuously
/// ([`check_continuous`](Self::check_continuous)) by an audit that shares neither the
/// planner's `f32` arithmetic nor its certification. Other validity checkers can only be
/// re-checked on a finer grid ([`check_resampled`](Self::check_resampled)). `valid` is `true`
/// only if the chosen check passed; reports name the method.
///
/// ```
/// let problem = mit_star_problems::builtin("obstacle-free", 2, 0)?;
/// let path = vec![problem.start().to_vec(), problem.goals()[0].clone()];
/// let v = mit_star_benches::PathValidation::check(&problem, &path, problem.straight_line_cost());
/// assert!(v.valid, "{:?}", v.failure);
/// assert_eq!(v.method, mit_star_benches::ValidationMethod::ExactBoxes);
/// assert_eq!(v.segments_checked, 1);
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathValidation {
    /// `true` if every check passed.
    pub valid: bool,
    /// How the segments were checked.
    pub method: ValidationMethod,
    /// States tested with the point test: the path's states, plus the resampled points with
    /// [`ValidationMethod::Resampled`].
    pub states_checked: u64,
    /// Segments checked (exactly, with [`ValidationMethod::ExactBoxes`]).
    pub segments_checked: u64,
    /// The path's length, recomputed.
    pub length: f64,
    /// What failed first, if anything.
    pub failure: Option<String>,
    /// Wall-clock seconds the check took, apart from the planner's time (0 where not timed;
    /// [`InstanceProblem::validate`](crate::InstanceProblem::validate) times it).
    #[serde(default)]
    pub seconds: f64,
}

impl PathValidation {
    /// Checks `path` (states, start first) against `problem` exactly, and its length against
    /// `reported_cost`.
    pub fn check(problem: &Problem, path: &[Vec<f64>], reported_cost: f64) -> Self {
        let world = problem.world();
        Self::walk(
            (problem.start(), problem.goals()),
            path,
            reported_cost,
            ValidationMethod::ExactBoxes,
            (world, euclidean_distance),
            |a, b, _| match world.segment_verdict(a, b) {
                SegmentVerdict::Valid => Ok(0),
                SegmentVerdict::Invalid { t, cause } => Err(describe(world, t, cause)),
            },
        )
    }

    /// Checks an arm path continuously with `audit` (see [`MotionAudit`]): every state valid
    /// by the `f64` reference, every segment proven collision-free at every configuration, at
    /// most `budget` configurations per segment (a segment left undecided fails).
    pub fn check_continuous(
        audit: &MotionAudit,
        (start, goals): (&[f64], &[Vec<f64>]),
        path: &[Vec<f64>],
        reported_cost: f64,
        budget: u64,
    ) -> Self {
        let clearance = Cell::new(f64::INFINITY);
        let obstacle_clearance = Cell::new(f64::INFINITY);
        let padding = audit.padding().metres();
        let mut result = Self::walk(
            (start, goals),
            path,
            reported_cost,
            ValidationMethod::ContinuousArm {
                configurations: 0,
                clearance: f64::INFINITY,
                obstacle_clearance: f64::INFINITY,
                padding,
            },
            (audit, |a: &[f64], b: &[f64]| audit.space().distance(a, b)),
            |a, b, _| match audit.audit(a, b, budget) {
                AuditVerdict::Clear {
                    configurations,
                    clearance: c,
                    obstacle_clearance: o,
                } => {
                    clearance.set(clearance.get().min(c));
                    obstacle_clearance.set(obstacle_clearance.get().min(o));
                    Ok(configurations)
                }
                AuditVerdict::Collides {
                    t,
                    configuration,
                    contact,
                } => Err(format!(
                    "collides at t = {t:.9}: {contact} ({configuration:?})"
                )),
                AuditVerdict::Undecided { t, configurations } => Err(format!(
                    "is undecided: {configurations} configurations certified it only up to \
                     t = {t:.9} (it grazes an obstacle for a long way)"
                )),
            },
        );
        result.method = ValidationMethod::ContinuousArm {
            configurations: result.states_checked,
            clearance: clearance.get(),
            obstacle_clearance: obstacle_clearance.get(),
            padding,
        };
        result
    }

    /// Checks `path` against any validity checker by re-testing every segment at grid points
    /// `planning_step / 4` apart (or finer): a cross-check for checkers that can decide
    /// segments neither exactly nor continuously. Not independent of a grid-checking planner:
    /// both test points of the same straight lines and can miss what lies between them.
    pub fn check_resampled<V: StateValidity + ?Sized>(
        validity: &V,
        (start, goals): (&[f64], &[Vec<f64>]),
        path: &[Vec<f64>],
        reported_cost: f64,
        planning_step: f64,
    ) -> Self {
        let step = planning_step / 4.0;
        let mut point = Vec::new();
        Self::walk(
            (start, goals),
            path,
            reported_cost,
            ValidationMethod::Resampled { step },
            (validity, euclidean_distance),
            |a, b, d| {
                let pieces = (d / step).ceil().clamp(1.0, 1e12) as u64;
                point.resize(a.len(), 0.0);
                for k in 1..pieces {
                    let t = k as f64 / pieces as f64;
                    for (p, (x, y)) in point.iter_mut().zip(a.iter().zip(b)) {
                        *p = x + t * (y - x);
                    }
                    if !validity.is_valid(&point) {
                        return Err(format!("collides at t = {t:.9} ({point:?})"));
                    }
                }
                Ok(pieces - 1)
            },
        )
    }

    /// The checks shared by both methods: ends, states, segments (with `segment`, returning
    /// the points it tested or why it failed) and length (in the metric `distance`: an arm's
    /// joint space weighs prismatic joints and goes the short way round continuous ones).
    fn walk<V: StateValidity + ?Sized>(
        (start, goals): (&[f64], &[Vec<f64>]),
        path: &[Vec<f64>],
        reported_cost: f64,
        method: ValidationMethod,
        (validity, distance): (&V, impl Fn(&[f64], &[f64]) -> f64),
        mut segment: impl FnMut(&[f64], &[f64], f64) -> Result<u64, String>,
    ) -> Self {
        let mut result = Self {
            valid: false,
            method,
            states_checked: 0,
            segments_checked: 0,
            length: 0.0,
            failure: None,
            seconds: 0.0,
        };
        let fail = |mut result: Self, why: String| {
            result.failure = Some(why);
            result
        };
        let close = |a: &[f64], b: &[f64]| a.len() == b.len() && euclidean_distance(a, b) <= 1e-9;
        let (Some(first), Some(last)) = (path.first(), path.last()) else {
            return fail(result, "the path is empty".into());
        };
        if !close(first, start) {
            return fail(
                result,
                format!("the path starts at {first:?}, not at the start"),
            );
        }
        if !goals.iter().any(|g| close(last, g)) {
            return fail(result, format!("the path ends at {last:?}, not at a goal"));
        }
        let n = start.len();
        for (i, state) in path.iter().enumerate() {
            if state.len() != n || state.iter().any(|x| !x.is_finite()) {
                return fail(result, format!("state {i} is malformed: {state:?}"));
            }
            result.states_checked += 1;
            if !validity.is_valid(state) {
                return fail(result, format!("state {i} {state:?} is invalid"));
            }
            if i == 0 {
                continue;
            }
            let a = &path[i - 1];
            let d = distance(a, state);
            result.length += d;
            result.segments_checked += 1;
            match segment(a, state, d) {
                Ok(points) => result.states_checked += points,
                Err(why) => return fail(result, format!("segment {} → {i} {why}", i - 1)),
            }
        }
        if (result.length - reported_cost).abs() > 1e-9 * reported_cost.abs().max(1.0) {
            let why = format!(
                "the path's length {} differs from the reported cost {reported_cost}",
                result.length
            );
            return fail(result, why);
        }
        result.valid = true;
        result
    }
}

/// Why an exact segment check failed, in words.
fn describe(world: &World, t: f64, cause: SegmentCause) -> String {
    let at = format!("at t = {t:.9}");
    match cause {
        SegmentCause::Malformed => "has a malformed end".into(),
        SegmentCause::OutOfBounds => format!("leaves the bounds {at}"),
        SegmentCause::Obstacle(i) => {
            let b = &world.obstacles()[i];
            format!(
                "collides {at} with obstacle {i} (centre {:?}, widths {:?})",
                b.center, b.widths
            )
        }
        SegmentCause::Lattice(i) => format!("collides {at} with a cube of lattice {i}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wall() -> Problem {
        // A wall at x = 0 spanning the bounds except y > 0.3.
        mit_star_problems::builtin("wall-gap", 2, 0).unwrap()
    }

    #[test]
    fn a_path_through_a_wall_fails_both_ways() {
        let p = wall();
        let path = vec![p.start().to_vec(), p.goals()[0].clone()];
        let v = PathValidation::check(&p, &path, p.straight_line_cost());
        assert!(!v.valid);
        assert!(v.failure.as_deref().unwrap().contains("collides"), "{v:?}");
        assert!(
            v.failure.as_deref().unwrap().contains("obstacle 0"),
            "{v:?}"
        );
        let r = PathValidation::check_resampled(
            p.world(),
            (p.start(), p.goals()),
            &path,
            p.straight_line_cost(),
            p.step(),
        );
        assert!(!r.valid && r.failure.unwrap().contains("collides"));
        assert_eq!(
            r.method,
            ValidationMethod::Resampled {
                step: p.step() / 4.0
            }
        );
    }

    #[test]
    fn a_wall_thinner_than_any_step_is_found_exactly() {
        let text = "name = 'tw'\nstart = [-0.3, 0.0]\ngoal = [0.3, 0.0]\n\
                    [bounds]\nlower = [-0.5, -0.5]\nupper = [0.5, 0.5]\n\
                    [[obstacles]]\ncenter = [0.0, 0.0]\nwidths = [1e-6, 1.0]\n";
        let p = Problem::from_toml_str(text).unwrap();
        let path = vec![p.start().to_vec(), p.goals()[0].clone()];
        let v = PathValidation::check(&p, &path, 0.6);
        assert!(!v.valid, "{v:?}");
        // A grid of 179 pieces (odd: no point lands within 5e-7 of x = 0) walks through it.
        let coarse = PathValidation::check_resampled(
            p.world(),
            (p.start(), p.goals()),
            &path,
            0.6,
            4.0 * 0.6 / 178.5,
        );
        assert!(coarse.valid, "{coarse:?}");
    }

    #[test]
    fn wrong_ends_and_costs_fail() {
        let p = mit_star_problems::builtin("obstacle-free", 2, 0).unwrap();
        let (s, g) = (p.start().to_vec(), p.goals()[0].clone());
        let v = PathValidation::check(&p, &[g.clone(), s.clone()], 0.8);
        assert!(v.failure.unwrap().contains("starts at"));
        let v = PathValidation::check(&p, &[s.clone(), s.clone()], 0.0);
        assert!(v.failure.unwrap().contains("not at a goal"));
        let v = PathValidation::check(&p, &[s.clone(), g.clone()], 0.5);
        assert!(
            v.failure
                .unwrap()
                .contains("differs from the reported cost")
        );
        let v = PathValidation::check(&p, &[s, vec![0.0, 0.9], g], 2.0);
        assert!(
            v.failure.unwrap().contains("invalid"),
            "out of bounds is invalid"
        );
        assert!(!PathValidation::check(&p, &[], 0.0).valid);
    }

    #[test]
    fn resampling_is_at_least_four_times_finer() {
        let p = mit_star_problems::builtin("obstacle-free", 2, 0).unwrap();
        let path = vec![p.start().to_vec(), p.goals()[0].clone()];
        let v = PathValidation::check_resampled(
            p.world(),
            (p.start(), p.goals()),
            &path,
            p.straight_line_cost(),
            p.step(),
        );
        let needed = 4 * (p.straight_line_cost() / p.step()).floor() as u64;
        assert!(v.valid && v.states_checked >= needed, "{v:?}");
        assert!(v.method.describe().contains("4× finer"));
    }

    #[test]
    fn an_arm_path_is_measured_in_its_joint_space_metric() {
        // The hand-written test robot: a revolute joint and a prismatic one, weighted 1/R.
        let urdf = include_str!("../../robot/tests/data/two_link.urdf");
        let robot = mit_star_robot::RobotModel::from_urdf_str(urdf)
            .unwrap()
            .without_model_pairs();
        let audit = MotionAudit::new(&robot, &mit_star_robot::Scene::new(Vec::new()));
        let (start, goal) = (vec![0.0, 0.0], vec![0.5, 0.2]);
        let space = robot.joint_space();
        assert_ne!(space.joints()[1].weight, 1.0);
        let path = [start.clone(), goal.clone()];
        let cost = space.distance(&start, &goal);
        let budget = 100_000;
        let v = PathValidation::check_continuous(
            &audit,
            (&start, std::slice::from_ref(&goal)),
            &path,
            cost,
            budget,
        );
        assert!(v.valid, "{v:?}");
        assert_eq!(v.length, cost);
        let euclidean = euclidean_distance(&start, &goal);
        assert!((euclidean - cost).abs() > 1e-6, "{euclidean} {cost}");
        let v = PathValidation::check_continuous(
            &audit,
            (&start, std::slice::from_ref(&goal)),
            &path,
            euclidean,
            budget,
        );
        assert!(!v.valid, "{v:?}");
    }
}
