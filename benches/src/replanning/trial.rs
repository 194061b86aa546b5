//! [`Trial`]: one re-planning trial — plan, monitor, execute and judge on a simulated clock
//! until the legs are done, the arm touches an obstacle, or time runs out.

use std::time::Instant;

use mit_star::{IterationLimit, Planner, TimeLimit};
use robot::{ArmProblem, Scene};

use crate::definition::planner_spec::PlannerSpec;
use crate::error::HarnessError;
use crate::replanning::motion_judge::{MotionJudge, path_is_clear};
use crate::replanning::replanning_scene::ReplanningSetup;
use crate::replanning::rules::{PlanningBudget, ReplanningRules};
use crate::replanning::timed_path::{Piece, TimedPath};
use crate::replanning::trial_record::{TrialEnd, TrialRecord};

/// Slack for comparing simulated times that are sums of floating-point steps.
const TIME_SLACK: f64 = 1e-9;

/// One re-planning trial: a planner, a scene, the rules and a seed.
///
/// The loop, on a simulated clock `t` (the rules are stated in the user guide's reference
/// page on arm planning, "Re-planning among moving obstacles"):
///
/// 1. **Plan** when the arm has no path (at the start of each leg, after a failed plan, or
///    after the monitor dropped its path). The planner is built afresh (`build_planner`, as
///    the command line builds planners) for an [`ArmProblem`] from the arm's configuration to
///    the leg's goal among the fixed obstacles and the moving ones *swept* over
///    `[t, t + plan_time + window]` — where they may be until the monitor's first look at the
///    new path. If the arm or the goal lies in that sweep, the plan is made against the
///    obstacles where they are at `t` (counted as `unpadded_plans`). The arm holds still for
///    `plan_time`, judged like any motion; a plan without a path leaves it holding.
/// 2. **Monitor** before each window: the rest of the path is checked (certified) against
///    the obstacles where they are now; a path an obstacle has moved onto is dropped (the
///    arm stops at once: no deceleration is modelled) and a new plan is asked for.
/// 3. **Execute** the path for one `window` (or until it ends) at the joint speeds, the
///    motion **judged** continuously against the moving obstacles ([`MotionJudge`]): a
///    contact ends the trial as a collision.
///
/// The trial succeeds when the last leg's goal is reached within `time_limit`.
#[derive(Debug)]
pub struct Trial<'a> {
    setup: &'a ReplanningSetup,
    planner: &'a PlannerSpec,
    rules: &'a ReplanningRules,
}

impl<'a> Trial<'a> {
    /// A trial of `planner` in `setup` under `rules` (checked by the caller).
    pub fn new(
        setup: &'a ReplanningSetup,
        planner: &'a PlannerSpec,
        rules: &'a ReplanningRules,
    ) -> Self {
        Self {
            setup,
            planner,
            rules,
        }
    }

    /// Runs trial number `trial` with plans seeded `seed`, `seed + 1`, ….
    ///
    /// # Errors
    /// A planner that refuses the problem or fails while planning ([`HarnessError::Build`],
    /// [`HarnessError::Planning`]); not a failed plan, which is part of the trial.
    pub fn run(&self, trial: usize, seed: u64) -> Result<TrialRecord, HarnessError> {
        let started = Instant::now();
        let (setup, rules) = (self.setup, self.rules);
        let space = setup.robot.joint_space().clone();
        let speeds = rules.joint_speeds();
        let mut judge = MotionJudge::new(&setup.robot, &setup.scene, rules.contact_floor);
        let ends = [setup.goal.clone(), setup.start.clone()];
        let mut record = TrialRecord {
            scene: setup.name.to_owned(),
            planner: self.planner.name().to_owned(),
            trial,
            seed,
            end: TrialEnd::Timeout,
            time: 0.0,
            legs_done: 0,
            travelled: 0.0,
            plans: 0,
            failed_plans: 0,
            invalidations: 0,
            unpadded_plans: 0,
            held: 0.0,
            wall_seconds: 0.0,
            trajectory: vec![(0.0, setup.start.clone())],
            plan_times: Vec::new(),
        };
        let (mut t, mut q) = (0.0, setup.start.clone());
        let mut path: Option<TimedPath> = None;
        record.end = loop {
            if record.legs_done == rules.legs {
                break TrialEnd::Success;
            }
            if t >= rules.time_limit - TIME_SLACK {
                break TrialEnd::Timeout;
            }
            let target = &ends[record.legs_done % 2];
            let Some(current) = &path else {
                let plan_seed = seed.wrapping_add(record.plans as u64);
                let (found, padded) = self.plan(t, &q, target, plan_seed)?;
                record.plans += 1;
                record.unpadded_plans += usize::from(!padded);
                record.plan_times.push((t, found.is_some()));
                let hold = Piece::hold(t, t + rules.plan_time, &q);
                if let Some(time) = judge.first_contact(&[hold]) {
                    break TrialEnd::Collision { time };
                }
                t += rules.plan_time;
                record.held += rules.plan_time;
                record.trajectory.push((t, q.clone()));
                match found {
                    Some(states) => path = Some(TimedPath::new(&space, &states, &speeds, t)),
                    None => record.failed_plans += 1,
                }
                continue;
            };
            let now = setup.scene.at(t);
            if !path_is_clear(&setup.robot, &now, &current.remaining(t)) {
                record.invalidations += 1;
                path = None;
                continue;
            }
            let until = (t + rules.window).min(current.end_time());
            let pieces = current.pieces(t, until);
            if let Some(time) = judge.first_contact(&pieces) {
                break TrialEnd::Collision { time };
            }
            for piece in &pieces {
                record.travelled += robot_distance(&space, &piece.a, &piece.b);
                record.trajectory.push((piece.t1, piece.b.clone()));
            }
            t = until;
            q = current.state_at(t);
            if t >= current.end_time() - TIME_SLACK {
                q = current.last().to_vec();
                record.legs_done += 1;
                path = None;
            }
        };
        record.time = match record.end {
            TrialEnd::Collision { time } => time,
            _ => t,
        };
        record.wall_seconds = started.elapsed().as_secs_f64();
        Ok(record)
    }

    /// One plan from `q` at time `t` to `target`: the path found (if any), and whether it was
    /// planned against the obstacles' sweep (`true`) or where they are (`false`).
    fn plan(
        &self,
        t: f64,
        q: &[f64],
        target: &[f64],
        seed: u64,
    ) -> Result<(Option<Vec<Vec<f64>>>, bool), HarnessError> {
        let started = Instant::now();
        let (setup, rules) = (self.setup, self.rules);
        let ends_clear = |scene: &Scene| {
            path_is_clear(&setup.robot, scene, &[q.to_vec()])
                && path_is_clear(&setup.robot, scene, &[target.to_vec()])
        };
        let swept = setup.scene.swept(t, t + rules.plan_time + rules.window);
        let (scene, padded) = if ends_clear(&swept) {
            (swept, true)
        } else {
            (setup.scene.at(t), false)
        };
        if !ends_clear(&scene) {
            return Ok((None, padded));
        }
        let name = format!("{}@{t:.3}", setup.name);
        let arm = |source| HarnessError::Arm {
            name: name.clone(),
            source,
        };
        let problem = ArmProblem::new(
            name.clone(),
            setup.robot.clone(),
            scene,
            q.to_vec(),
            target.to_vec(),
        )
        .map_err(arm)?;
        let planner_name = self.planner.name().to_owned();
        let parameters = self.planner.parameters_for_seed(seed);
        let mut planner =
            mit_star::build_planner(self.planner.configuration(), &problem, &parameters).map_err(
                |source| HarnessError::Build {
                    planner: planner_name.clone(),
                    source,
                },
            )?;
        let outcome = match rules.budget {
            PlanningBudget::WallClock(seconds) => {
                let budget = crate::budget::budget_duration(seconds).map_err(|source| {
                    HarnessError::Budget {
                        what: "re-planning budget".to_owned(),
                        source,
                    }
                })?;
                planner.solve(&TimeLimit::until(started + budget))
            }
            PlanningBudget::Iterations(n) => planner.solve(&IterationLimit::new(n)),
        }
        .map_err(|source| HarnessError::Planning {
            planner: planner_name,
            source,
        })?;
        let path = outcome
            .solution()
            .map(|s| s.path.iter().map(<[f64]>::to_vec).collect());
        Ok((path, padded))
    }
}

/// The joint-space distance the planners' cost measures.
fn robot_distance(space: &spaces::JointSpace, a: &[f64], b: &[f64]) -> f64 {
    spaces::StateSpace::distance(space, a, b)
}

#[cfg(test)]
mod tests {
    use glam::DVec3;
    use robot::{MovingObstacle, MovingScene};

    use super::*;
    use crate::definition::parameter_overrides::ParameterOverrides;
    use crate::replanning::replanning_scene::ReplanningScene;

    fn rules() -> ReplanningRules {
        ReplanningRules {
            budget: PlanningBudget::Iterations(2000),
            legs: 2,
            time_limit: 20.0,
            ..ReplanningRules::default()
        }
    }

    fn rrt_connect() -> PlannerSpec {
        let overrides = ParameterOverrides::default()
            .with_assignment("range=1.0")
            .unwrap();
        PlannerSpec::new(mit_star::Configuration::RrtConnect, None, &overrides).unwrap()
    }

    /// The horizontal scene with its slider moved far away (behind the robot).
    fn far_setup() -> ReplanningSetup {
        let mut setup = ReplanningScene::Horizontal.setup().unwrap();
        let far = MovingObstacle::new(
            "far",
            DVec3::splat(0.05),
            (DVec3::new(-1.5, -0.5, 0.5), DVec3::new(-1.5, 0.5, 0.5)),
            0.3,
            0.0,
        )
        .unwrap();
        setup.scene = MovingScene::new(setup.scene.fixed().to_vec(), vec![far]);
        setup
    }

    #[test]
    fn a_trial_among_far_obstacles_succeeds_and_measures_what_it_travelled() {
        let setup = far_setup();
        let (planner, rules) = (rrt_connect(), rules());
        let record = Trial::new(&setup, &planner, &rules).run(1, 7).unwrap();
        assert_eq!(record.end, TrialEnd::Success, "{record:?}");
        assert_eq!((record.legs_done, record.invalidations), (2, 0));
        assert_eq!(record.plans, 2 + record.failed_plans);
        // The arm went there and back: at least twice the straight line.
        let straight =
            spaces::StateSpace::distance(setup.robot.joint_space(), &setup.start, &setup.goal);
        assert!(
            record.travelled >= 2.0 * straight - 1e-9,
            "{}",
            record.travelled
        );
        // The trajectory ends where it started, and its length is what was travelled.
        let trajectory = &record.trajectory;
        assert_eq!(trajectory.last().unwrap().1, setup.start);
        let length: f64 = trajectory
            .windows(2)
            .map(|w| robot_distance(setup.robot.joint_space(), &w[0].1, &w[1].1))
            .sum();
        assert!((length - record.travelled).abs() < 1e-9);
        // Held while planning, moved at the joint speeds otherwise.
        assert!((record.held - 0.1 * record.plans as f64).abs() < 1e-9);
        assert!(record.time > record.held && record.time < rules.time_limit);
        // The same seed plans the same trial (an iteration budget is deterministic).
        let again = Trial::new(&setup, &planner, &rules).run(1, 7).unwrap();
        assert_eq!(
            (again.travelled, again.plans),
            (record.travelled, record.plans)
        );
    }

    #[test]
    fn an_obstacle_driven_through_the_arm_ends_the_trial_as_a_collision() {
        let mut setup = far_setup();
        // A block sweeping along y through the arm's start at 1 m/s, reaching it while the
        // first plan is being made or soon after.
        let ram = MovingObstacle::new(
            "ram",
            DVec3::splat(0.08),
            (DVec3::new(0.5, -0.75, 0.25), DVec3::new(0.5, 0.05, 0.25)),
            1.0,
            0.3,
        )
        .unwrap();
        setup.scene = MovingScene::new(setup.scene.fixed().to_vec(), vec![ram]);
        let (planner, rules) = (rrt_connect(), rules());
        let record = Trial::new(&setup, &planner, &rules).run(1, 7).unwrap();
        let time = record
            .collision_time()
            .unwrap_or_else(|| panic!("{record:?}"));
        assert!(time < 0.5, "{time}");
        assert_eq!(record.cost(), f64::INFINITY);
    }

    #[test]
    fn a_trial_that_cannot_finish_in_time_times_out() {
        let setup = far_setup();
        let rules = ReplanningRules {
            time_limit: 0.25,
            ..rules()
        };
        let planner = rrt_connect();
        let record = Trial::new(&setup, &planner, &rules).run(1, 7).unwrap();
        assert_eq!(record.end, TrialEnd::Timeout);
        assert!(record.time >= 0.25 - 1e-9);
    }
}
