//! [`PoseGoalSource`]: a pose goal as a planner's goal region, and the planner that plans to
//! it.

use std::sync::{Arc, Mutex};

use glam::DAffine3;
use mit_star::{
    BuildError, Configuration, GoalSource, LazyGoals, Parameters, Planner, PlannerError,
};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, Kinematics, PoseGoal, PoseTarget};
use mit_star_spaces::Stop;

use crate::definition::problem_kind::InstanceProblem;
use crate::path_validation::PathValidation;

/// Consecutive draws that find nothing after which a pose is taken as out of reach.
const FAILED_DRAWS: usize = 4;

/// A pose goal as a planner's goal region: inverse-kinematics solutions that are valid and
/// joinable by certified motion, each new.
#[derive(Debug, Clone)]
pub struct PoseGoalSource {
    initial_goals: usize,
    max_goals: usize,
    goal: PoseGoal,
    original: PoseGoal,
    arm: Arc<ArmProblem>,
    given: Arc<Mutex<Vec<Vec<f64>>>>,
    /// Why the last draw found nothing, shared with the clones.
    failure: Arc<Mutex<Option<String>>>,
    failed: usize,
}

impl PoseGoalSource {
    /// The region of `goal`'s solutions valid and joinable in `arm`; a planner draws
    /// `initial_goals` of them before it starts, and at most `max_goals`.
    pub fn new(
        goal: PoseGoal,
        arm: Arc<ArmProblem>,
        (initial_goals, max_goals): (usize, usize),
    ) -> Self {
        Self {
            initial_goals: initial_goals.max(1),
            max_goals: max_goals.max(1),
            original: goal.clone(),
            goal,
            arm,
            given: Arc::new(Mutex::new(Vec::new())),
            failure: Arc::new(Mutex::new(None)),
            failed: 0,
        }
    }

    /// The most goals a planner should draw (`--ik-goals`).
    pub fn max_goals(&self) -> usize {
        self.max_goals
    }

    /// The goals a planner should draw before it starts (`--ik-initial-goals`).
    pub fn initial_goals(&self) -> usize {
        self.initial_goals
    }

    /// The goals given so far, shared: read them after planning.
    pub fn given(&self) -> Arc<Mutex<Vec<Vec<f64>>>> {
        Arc::clone(&self.given)
    }

    /// The target.
    pub fn target(&self) -> &PoseTarget {
        self.goal.target()
    }

    /// Why the last draw found nothing, if it did not.
    pub fn last_failure(&self) -> Option<String> {
        self.failure.lock().ok().and_then(|f| f.clone())
    }

    /// Judges a path to this region: its motion as `arm`'s with the goals given so far, and
    /// its last state's link pose, recomputed by forward kinematics apart from the solver,
    /// within the target's tolerances (1e-5 m and 1e-4 rad beyond them).
    pub fn validate(&self, path: &[Vec<f64>], cost: f64) -> PathValidation {
        let goals = self.given.lock().map(|g| g.clone()).unwrap_or_default();
        // Without a goal drawn no path exists; the problem's own goal then judges.
        let arm = (*self.arm)
            .clone()
            .with_goals(goals)
            .unwrap_or_else(|_| (*self.arm).clone());
        let mut validation = InstanceProblem::Arm(Arc::new(arm)).validate(path, cost);
        if validation.valid
            && let Some(last) = path.last()
            && let Some(failure) = self.pose_failure(last)
        {
            validation.valid = false;
            validation.failure = Some(failure);
        }
        validation
    }

    /// What is wrong with `q`'s pose, if anything.
    fn pose_failure(&self, q: &[f64]) -> Option<String> {
        let robot = self.arm.robot();
        let solver = self.goal.solver();
        let Some(link) = robot.link_index(solver.link()) else {
            return Some(format!("the robot has no link `{}`", solver.link()));
        };
        let fk = Kinematics::new(robot);
        let mut poses = vec![DAffine3::IDENTITY; fk.link_count()];
        fk.link_poses_f64(q, &mut poses);
        let frame = poses[link] * solver.tool_offset();
        let (position, orientation) = self.goal.target().errors(&frame);
        (position > 1e-5 || orientation > 1e-4).then(|| {
            format!(
                "the path ends {position:.3e} m and {orientation:.3e} rad from the pose target of `{}`",
                solver.link()
            )
        })
    }
}

impl GoalSource for PoseGoalSource {
    fn next_goal(&mut self, stop: &dyn Stop) -> Option<Vec<f64>> {
        while !stop.should_stop() {
            let Some(q) = self.goal.next_solution(self.arm.validity(), stop) else {
                self.failed += 1;
                if let Ok(mut failure) = self.failure.lock() {
                    *failure = self.goal.last_failure().map(ToString::to_string);
                }
                return None;
            };
            let q = q.to_vec();
            // A goal certified motion cannot reach (closer to an obstacle than every
            // certified edge keeps) would be refused by the planner: draw on.
            if self.arm.joinable(&q) {
                self.failed = 0;
                if let Ok(mut given) = self.given.lock() {
                    given.push(q.clone());
                }
                return Some(q);
            }
        }
        None
    }

    fn exhausted(&self) -> bool {
        self.failed >= FAILED_DRAWS
    }

    fn reset(&mut self) {
        self.goal = self.original.clone();
        self.failed = 0;
        if let Ok(mut given) = self.given.lock() {
            given.clear();
        }
        if let Ok(mut failure) = self.failure.lock() {
            *failure = None;
        }
    }
}

/// A planner of `configuration` with `parameters` towards the pose goal `source` supplies, over `arm`
/// otherwise ([`LazyGoals`]).
pub fn pose_goal_planner(
    arm: &Arc<mit_star_robot::ArmProblem>,
    source: PoseGoalSource,
    configuration: Configuration,
    parameters: Parameters,
) -> Box<dyn Planner + Send> {
    let arm = Arc::clone(arm);
    let build = move |goals: &[Vec<f64>]| {
        let problem = (*arm)
            .clone()
            .with_goals(goals.to_vec())
            .map_err(|e| match e {
                mit_star_robot::ArmError::Query { source, .. } => {
                    BuildError::Query(PlannerError::State {
                        endpoint: mit_star::Endpoint::Goal(goals.len().saturating_sub(1)),
                        source,
                    })
                }
                other => BuildError::Query(PlannerError::Internal(other.to_string())),
            })?;
        mit_star::build_planner(configuration, &problem, &parameters)
    };
    let (initial, maximum) = (source.initial_goals(), source.max_goals());
    Box::new(
        LazyGoals::new(build, source)
            .with_max_goals(maximum)
            .with_initial_goals(initial),
    )
}
