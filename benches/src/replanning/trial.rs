//! [`Trial`]: one re-planning trial — plan, monitor, execute and judge on a simulated clock
//! until the legs are done, the arm touches an obstacle, or time runs out.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use mit_star::{IterationLimit, Planner, TerminationExt as _, TimeLimit};
use mit_star_robot::{ArmProblem, Scene};

use crate::definition::planner_spec::PlannerSpec;
use crate::error::HarnessError;
use crate::execution::run_job::Interrupted;
use crate::replanning::motion_judge::{MotionJudge, path_is_clear};
use crate::replanning::replanning_scene::ReplanningSetup;
use crate::replanning::rules::{PlanningBudget, ReplanningRules};
use crate::replanning::timed_path::{Piece, TimedPath};
use crate::replanning::trial_record::{TrialEnd, TrialRecord};

/// Slack for comparing simulated times that are sums of floating-point steps.
const TIME_SLACK: f64 = 1e-9;

/// One re-planning trial: a planner, a scene, the rules and a seed.
///
/// The loop, on a simulated clock `t` in control cycles of `cycle` seconds (the rules are
/// stated in words in the user guide's reference page on arm planning, "Re-planning among
/// moving obstacles"). At the start of each cycle:
///
/// 1. **Predict** where the arm will be at `t + cycle`: along its path, or where it holds.
///    The plan is for the leg it will be on then (the next leg if the path reaches its goal
///    within the cycle).
/// 2. **Plan** from that configuration to the leg's goal, concurrently with the motion: a
///    planner built afresh (`build_planner`, as the command line builds planners) for an
///    [`ArmProblem`] among the fixed obstacles and the moving ones *swept* over
///    `[t, t + cycle + look_ahead]` — from now until `look_ahead` seconds after the new path
///    is taken up. While the predicted configuration or the goal lies in that sweep, the
///    look-ahead is halved, down to one cycle; if they are inside even then, the plan is made
///    against the obstacles where they will be at `t + cycle` (`unpadded_plans`).
/// 3. **Execute** the current path for the cycle at the joint speeds (or hold still
///    without one); the motion is **judged** continuously against the moving obstacles
///    ([`MotionJudge`]): a contact ends the trial as a collision. Reaching the goal ends the
///    leg; reaching the last leg's goal ends the trial as a success.
/// 4. **Switch** at `t + cycle`: the rest of the current path is checked (certified) in the
///    planning scene of step 2. The new path is taken if the rest is blocked or the new path
///    is shorter; a blocked path with no new path is dropped and the arm stops at once (no
///    deceleration is modelled: `dropped`).
///
/// A trial not done within `time_limit` times out.
#[derive(Debug)]
pub struct Trial<'a> {
    setup: &'a ReplanningSetup,
    planner: &'a PlannerSpec,
    rules: &'a ReplanningRules,
    interrupt: &'a AtomicBool,
}

/// The flag of a trial nobody interrupts.
static NEVER: AtomicBool = AtomicBool::new(false);

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
            interrupt: &NEVER,
        }
    }

    /// The trial stopping its plans, and itself, when `interrupt` is raised (SIGINT or
    /// SIGTERM): the record of a trial interrupted is incomplete, and its caller drops it.
    pub fn interrupted_by(mut self, interrupt: &'a AtomicBool) -> Self {
        self.interrupt = interrupt;
        self
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
        let cycle = rules.cycle;
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
            adopted: 0,
            dropped: 0,
            unpadded_plans: 0,
            held: 0.0,
            wall_seconds: 0.0,
            trajectory: vec![(0.0, setup.start.clone())],
            plan_times: Vec::new(),
        };
        let (mut t, mut q) = (0.0, setup.start.clone());
        let mut path: Option<TimedPath> = None;
        record.end = loop {
            if t >= rules.time_limit - TIME_SLACK || self.interrupt.load(Ordering::SeqCst) {
                break TrialEnd::Timeout;
            }
            let next = t + cycle;
            // 1. Where the arm will be, and on which leg.
            let arrives = path
                .as_ref()
                .is_some_and(|p| p.end_time() <= next + TIME_SLACK);
            let leg = record.legs_done + usize::from(arrives);
            let predicted = path.as_ref().map_or(q.clone(), |p| p.state_at(next));
            // 2. Plan (not after the last leg), and judge the current path's rest.
            let mut planned = None;
            if leg < rules.legs {
                let target = &ends[leg % 2];
                let scene = self.planning_scene(t, &predicted, target);
                record.unpadded_plans += usize::from(!scene.1);
                let found = self.plan(
                    &scene.0,
                    &predicted,
                    target,
                    seed.wrapping_add(record.plans as u64),
                )?;
                record.plans += 1;
                record.plan_times.push((t, found.is_some()));
                record.failed_plans += usize::from(found.is_none());
                let rest = match &path {
                    Some(p) if !arrives => Some(p.remaining(next)),
                    _ => None,
                };
                let rest_clear = rest
                    .as_ref()
                    .is_some_and(|r| path_is_clear(&setup.robot, &scene.0, r));
                let rest_length = rest.as_ref().map_or(f64::INFINITY, |r| length(&space, r));
                planned = Some((found, rest.is_some(), rest_clear, rest_length));
            }
            // 3. Execute the cycle.
            let pieces = match &path {
                Some(p) => {
                    let mut pieces = p.pieces(t, next);
                    let arrival = p.end_time().max(t);
                    if arrival < next {
                        pieces.push(Piece::hold(arrival, next, p.last()));
                    }
                    pieces
                }
                None => {
                    record.held += cycle;
                    vec![Piece::hold(t, next, &q)]
                }
            };
            if let Some(time) = judge.first_contact(&pieces) {
                break TrialEnd::Collision { time };
            }
            for piece in &pieces {
                record.travelled += robot_distance(&space, &piece.a, &piece.b);
                record.trajectory.push((piece.t1, piece.b.clone()));
            }
            if arrives {
                let arrival = path.as_ref().map_or(t, TimedPath::end_time).max(t);
                record.legs_done += 1;
                path = None;
                if record.legs_done == rules.legs {
                    t = arrival;
                    break TrialEnd::Success;
                }
            }
            t = next;
            q = predicted;
            // 4. Switch.
            if let Some((found, had_rest, rest_clear, rest_length)) = planned {
                match found {
                    Some(states) if !rest_clear || length(&space, &states) < rest_length => {
                        path = Some(TimedPath::new(&space, &states, &speeds, t));
                        record.adopted += 1;
                    }
                    None if had_rest && !rest_clear => {
                        path = None;
                        record.dropped += 1;
                    }
                    _ => {}
                }
            }
        };
        record.time = match record.end {
            TrialEnd::Collision { time } => time,
            _ => t,
        };
        record.wall_seconds = started.elapsed().as_secs_f64();
        Ok(record)
    }

    /// The scene a plan made at `t` for the arm at `q` at `t + cycle` sees: the obstacles
    /// swept over `[t, t + cycle + h]` for the longest look-ahead `h` (the rules'
    /// `look_ahead`, halved down to one cycle) whose sweep leaves `q` and `target` free
    /// (`true`), else the obstacles where they will be at `t + cycle` (`false`).
    fn planning_scene(&self, t: f64, q: &[f64], target: &[f64]) -> (Scene, bool) {
        let (setup, cycle) = (self.setup, self.rules.cycle);
        let clear = |scene: &Scene| {
            path_is_clear(&setup.robot, scene, &[q.to_vec()])
                && path_is_clear(&setup.robot, scene, &[target.to_vec()])
        };
        let mut h = self.rules.look_ahead.max(cycle);
        loop {
            let swept = setup.scene.swept(t, t + cycle + h);
            if clear(&swept) {
                return (swept, true);
            }
            if h <= cycle {
                return (setup.scene.at(t + cycle), false);
            }
            h = (0.5 * h).max(cycle);
        }
    }

    /// One plan from `q` to `target` in `scene`: the path found, if any (none if `q` or
    /// `target` is not free there).
    fn plan(
        &self,
        scene: &Scene,
        q: &[f64],
        target: &[f64],
        seed: u64,
    ) -> Result<Option<Vec<Vec<f64>>>, HarnessError> {
        let started = Instant::now();
        let setup = self.setup;
        if !path_is_clear(&setup.robot, scene, &[q.to_vec()])
            || !path_is_clear(&setup.robot, scene, &[target.to_vec()])
        {
            return Ok(None);
        }
        let name = format!("{}-replanning", setup.name);
        let problem = ArmProblem::new(
            name.clone(),
            setup.robot.clone(),
            scene.clone(),
            q.to_vec(),
            target.to_vec(),
        )
        .map_err(|source| HarnessError::Arm { name, source })?;
        let planner_name = self.planner.name().to_owned();
        let parameters = self.planner.parameters_for_seed(seed);
        let mut planner =
            mit_star::build_planner(self.planner.configuration(), &problem, &parameters).map_err(
                |source| HarnessError::Build {
                    planner: planner_name.clone(),
                    source,
                },
            )?;
        let outcome = match self.rules.budget {
            PlanningBudget::WallClock(seconds) => {
                let budget = crate::budget::budget_duration(seconds).map_err(|source| {
                    HarnessError::Budget {
                        what: "re-planning budget".to_owned(),
                        source,
                    }
                })?;
                planner.solve(&TimeLimit::until(started + budget).or(Interrupted(self.interrupt)))
            }
            PlanningBudget::Iterations(n) => {
                planner.solve(&IterationLimit::new(n).or(Interrupted(self.interrupt)))
            }
        }
        .map_err(|source| HarnessError::Planning {
            planner: planner_name,
            source,
        })?;
        Ok(outcome
            .solution()
            .map(|s| s.path.iter().map(<[f64]>::to_vec).collect()))
    }
}

/// The joint-space length of `path`.
fn length(space: &mit_star_spaces::JointSpace, path: &[Vec<f64>]) -> f64 {
    path.windows(2)
        .map(|w| robot_distance(space, &w[0], &w[1]))
        .sum()
}

/// The joint-space distance the planners' cost measures.
fn robot_distance(space: &mit_star_spaces::JointSpace, a: &[f64], b: &[f64]) -> f64 {
    mit_star_spaces::StateSpace::distance(space, a, b)
}

#[cfg(test)]
mod tests {
    use glam::DVec3;
    use mit_star_robot::{MovingObstacle, MovingScene};

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
        assert_eq!(
            (record.legs_done, record.dropped, record.failed_plans),
            (2, 0, 0)
        );
        // One plan per cycle until the last leg is on its way.
        assert!(record.plans >= 2 && record.adopted >= 2);
        // The arm went there and back: at least twice the straight line.
        let straight = mit_star_spaces::StateSpace::distance(
            setup.robot.joint_space(),
            &setup.start,
            &setup.goal,
        );
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
        // Held only for the first cycle, while the first plan was made.
        assert!((record.held - 0.1).abs() < 1e-9, "{}", record.held);
        assert!(record.time > 1.0 && record.time < rules.time_limit);
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
