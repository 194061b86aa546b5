//! [`PoseGoal`]: a pose target as a source of goal configurations for planners.

use mit_star_spaces::Stop;
use mit_star_validity::StateValidity;

use crate::{IkError, IkSolver, PoseTarget};

/// A pose target turned into goal configurations: each call of
/// [`next_solution`](Self::next_solution) returns a new collision-free configuration placing
/// the solver's frame at the target, at least the solver's
/// [`distinct_distance`](IkSolver::distinct_distance) from every earlier one, until the
/// attempt budget or the stop condition runs out.
///
/// For a planner with a goal region: ask for a first goal before planning, and for more
/// while planning (each call is bounded by the solver's [`restarts`](IkSolver::restarts) and
/// the given stop condition); [`solutions`](Self::solutions) are the goals so far.
///
/// ```
/// use mit_star_robot::{ArmChecker, IkSolver, PoseGoal, PoseTarget, Scene, ShippedRobot};
/// let panda = ShippedRobot::find("panda").expect("shipped").model(false)?;
/// let checker = ArmChecker::new(&panda, &Scene::new(Vec::new()));
/// let mut solver = IkSolver::new(&panda, "panda_hand")?.seed(3);
/// let target = PoseTarget::from_pose(&solver.frame_pose(&panda.default_configuration())?)?;
/// let mut goal = PoseGoal::new(solver, target);
/// let deadline = mit_star_spaces::Deadline::after(std::time::Duration::from_secs(5));
/// let first = goal.next_solution(&checker, &deadline).expect("reachable").to_vec();
/// let second = goal.next_solution(&checker, &deadline).expect("a redundant arm");
/// assert_ne!(first, second);
/// assert_eq!(goal.solutions().len(), 2);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct PoseGoal {
    solver: IkSolver,
    target: PoseTarget,
    start: Option<Vec<f64>>,
    solutions: Vec<Vec<f64>>,
    failure: Option<IkError>,
}

impl PoseGoal {
    /// The goal `target` for `solver`'s frame; every attempt starts from a random
    /// configuration.
    pub fn new(solver: IkSolver, target: PoseTarget) -> Self {
        Self {
            solver,
            target,
            start: None,
            solutions: Vec::new(),
            failure: None,
        }
    }

    /// Makes the first attempt of every call start from `start` (a planner's start
    /// configuration, for goals near it), the restarts from random configurations.
    ///
    /// # Errors
    /// [`IkError::WrongLength`] or [`IkError::NonFiniteCoordinate`] for a bad `start`.
    pub fn with_start(mut self, start: &[f64]) -> Result<Self, IkError> {
        self.solver.check_configuration(start)?;
        self.start = Some(start.to_vec());
        Ok(self)
    }

    /// The next new solution: valid by `validity`, within the limits, at the target within
    /// its tolerances, and distinct from every earlier solution; `None` when the solver's
    /// attempts ran out or `stop` fired first ([`last_failure`](Self::last_failure) says
    /// which, with the best errors reached). A later call tries again with fresh random
    /// restarts.
    pub fn next_solution(
        &mut self,
        validity: &dyn StateValidity,
        stop: &dyn Stop,
    ) -> Option<&[f64]> {
        let result = match &self.start {
            Some(start) => {
                self.solver
                    .solve_avoiding(&self.target, start, &self.solutions, validity, stop)
            }
            None => {
                let mut start = vec![0.0; self.solver.limits.len()];
                mit_star_spaces::StateSpace::sample_uniform(
                    &self.solver.space,
                    &mut self.solver.rng,
                    &mut start,
                );
                self.solver
                    .solve_avoiding(&self.target, &start, &self.solutions, validity, stop)
            }
        };
        match result {
            Ok(solution) => {
                self.failure = None;
                self.solutions.push(solution.configuration);
                self.solutions.last().map(Vec::as_slice)
            }
            Err(e) => {
                self.failure = Some(e);
                None
            }
        }
    }

    /// Why the last call of [`next_solution`](Self::next_solution) returned `None`
    /// ([`IkError::Unreachable`] or [`IkError::Stopped`], with the best errors reached);
    /// `None` after a success.
    pub fn last_failure(&self) -> Option<&IkError> {
        self.failure.as_ref()
    }

    /// The solutions found so far, in the order found.
    pub fn solutions(&self) -> &[Vec<f64>] {
        &self.solutions
    }

    /// The target.
    pub fn target(&self) -> &PoseTarget {
        &self.target
    }

    /// The solver (its settings, and [`IkSolver::frame_pose`] through
    /// [`solver_mut`](Self::solver_mut)).
    pub fn solver(&self) -> &IkSolver {
        &self.solver
    }

    /// The solver, mutably (to compute frame poses).
    pub fn solver_mut(&mut self) -> &mut IkSolver {
        &mut self.solver
    }
}
