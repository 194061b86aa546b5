//! [`Problem`]: a named, fully specified planning problem in `R^n`.

use mit_star_spaces::{RealVectorSpace, StateSpace, euclidean_distance};
use mit_star_validity::{StateValidity, World};

use crate::{Endpoint, ProblemError};

/// A named planning problem in `R^n`: a box world, one start, one or more goals, the
/// collision-check resolution, and the optimal cost when it is known exactly.
///
/// The state space is the world's bounds. A `Problem` is checked when it is made: the bounds
/// form a space, there is at least one goal, and the start and every goal have the world's
/// dimension, are finite, lie in the bounds and are valid in the world. Fields are private so
/// that this stays true; [`validate`](Self::validate) re-checks it.
///
/// ```
/// use mit_star_problems::Problem;
/// use mit_star_spaces::StateSpace;
/// use mit_star_validity::{AxisBox, StateValidity, World};
///
/// let world = World::new(vec![-0.5; 2], vec![0.5; 2])
///     .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, 0.8]))?;
/// let problem = Problem::new("wall", world, vec![-0.4, 0.0], vec![vec![0.4, 0.0]])?;
/// assert_eq!(problem.dimension(), 2);
/// assert!(problem.world().is_valid(problem.start()));
/// // Resolution 5e-6 of the diagonal √2.
/// assert!((problem.step() - 5e-6 * 2f64.sqrt()).abs() < 1e-18);
/// assert!((problem.straight_line_cost() - 0.8).abs() < 1e-12);
///
/// // A start inside the wall is refused, naming the start.
/// let world = problem.world().clone();
/// let err = Problem::new("bad", world, vec![0.0, 0.0], vec![vec![0.4, 0.0]]).unwrap_err();
/// assert_eq!(err.to_string(), "start [0.0, 0.0] is in collision");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    name: String,
    space: RealVectorSpace,
    world: World,
    start: Vec<f64>,
    goals: Vec<Vec<f64>>,
    resolution: f64,
    step: f64,
    optimum: Option<f64>,
    coarse_step_allowed: bool,
}

impl Problem {
    /// The collision-check resolution of PDT's simulation benchmarks: a fraction `5e-6` of the
    /// space's maximum extent (spec `mit-star.md` §2).
    pub const DEFAULT_RESOLUTION: f64 = 5e-6;

    /// A problem with the [default resolution](Self::DEFAULT_RESOLUTION) and no known optimum.
    ///
    /// # Errors
    /// [`ProblemError::Bounds`] if the world's bounds do not form a space,
    /// [`ProblemError::NoGoals`] if `goals` is empty, [`ProblemError::State`] if the start or a
    /// goal is malformed or out of bounds, [`ProblemError::InCollision`] if it is not valid in
    /// the world.
    pub fn new(
        name: impl Into<String>,
        world: World,
        start: Vec<f64>,
        goals: Vec<Vec<f64>>,
    ) -> Result<Self, ProblemError> {
        let space = RealVectorSpace::new(world.lower().to_vec(), world.upper().to_vec())
            .map_err(ProblemError::Bounds)?;
        let resolution = Self::DEFAULT_RESOLUTION;
        let step = mit_star_validity::step_from_resolution(&space, resolution)?;
        let problem = Self {
            name: name.into(),
            space,
            world,
            start,
            goals,
            resolution,
            step,
            optimum: None,
            coarse_step_allowed: false,
        };
        problem.validate()?;
        problem.world.build_indices();
        Ok(problem)
    }

    /// Sets the collision-check resolution, a fraction of the space's maximum extent.
    ///
    /// Whether the step it gives is fine enough for the world's thinnest obstacle is checked
    /// by [`check_step`](Self::check_step), which planners call before planning.
    ///
    /// # Errors
    /// [`ProblemError::Resolution`] unless `0 < resolution < 1`.
    pub fn with_resolution(mut self, resolution: f64) -> Result<Self, ProblemError> {
        if !(resolution > 0.0 && resolution < 1.0) {
            return Err(ProblemError::Resolution { value: resolution });
        }
        self.step = mit_star_validity::step_from_resolution(&self.space, resolution)?;
        self.resolution = resolution;
        Ok(self)
    }

    /// Allows (or forbids again) a collision-check step larger than the thinnest obstacle or
    /// anti-obstacle. With it allowed, edges can cross thin obstacles between two checked
    /// points: returned paths must then be validated exactly (the experiment harness does).
    pub fn allowing_coarse_step(mut self, allow: bool) -> Self {
        self.coarse_step_allowed = allow;
        self
    }

    /// `true` if a step coarser than the thinnest obstacle was allowed explicitly.
    pub fn coarse_step_allowed(&self) -> bool {
        self.coarse_step_allowed
    }

    /// The smallest side of any obstacle and of any anti-obstacle of the world.
    pub fn thinnest_extents(&self) -> (Option<f64>, Option<f64>) {
        (
            self.world.thinnest_obstacle(),
            self.world.thinnest_anti_obstacle(),
        )
    }

    /// `true` if the step is larger than the thinnest obstacle or anti-obstacle.
    pub fn step_is_coarse(&self) -> bool {
        let (obstacle, anti) = self.thinnest_extents();
        [obstacle, anti]
            .into_iter()
            .flatten()
            .any(|thinnest| self.step > thinnest)
    }

    /// Checks that the collision-check step is not larger than the world's thinnest obstacle
    /// or anti-obstacle, unless a coarse step was [allowed](Self::allowing_coarse_step).
    ///
    /// ```
    /// use mit_star_problems::Problem;
    /// let text = "name = 'thin'\nstart = [-0.3, 0.0]\ngoal = [0.3, 0.0]\n\
    ///             [bounds]\nlower = [-0.5, -0.5]\nupper = [0.5, 0.5]\n\
    ///             [[obstacles]]\ncenter = [0.0, 0.0]\nwidths = [1e-6, 1.0]\n";
    /// let problem = Problem::from_toml_str(text)?;
    /// let err = problem.check_step().unwrap_err().to_string();
    /// assert!(err.contains("step 7.071e-6") && err.contains("thinnest obstacle (1e-6)"), "{err}");
    /// assert!(problem.clone().with_resolution(5e-7)?.check_step().is_ok());
    /// assert!(problem.allowing_coarse_step(true).check_step().is_ok());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`ProblemError::StepTooCoarse`] naming the step and both extents.
    pub fn check_step(&self) -> Result<(), ProblemError> {
        if self.coarse_step_allowed || !self.step_is_coarse() {
            return Ok(());
        }
        let (obstacle, anti_obstacle) = self.thinnest_extents();
        let extent = self.space.maximum_extent();
        let thinnest = [obstacle, anti_obstacle]
            .into_iter()
            .flatten()
            .fold(f64::INFINITY, f64::min);
        Err(ProblemError::StepTooCoarse {
            step: self.step,
            resolution: self.resolution,
            extent,
            obstacle,
            anti_obstacle,
            largest_resolution: thinnest / extent,
        })
    }

    /// Records the optimal cost (or forgets it, with `None`). Only give a value that is known
    /// exactly; it is used to report how far a planner's cost is from the optimum.
    ///
    /// # Errors
    /// [`ProblemError::Optimum`] if the value is not finite or is below the straight-line
    /// distance from the start to the nearest goal.
    pub fn with_optimum(mut self, optimum: Option<f64>) -> Result<Self, ProblemError> {
        if let Some(value) = optimum {
            let lower_bound = self.straight_line_cost();
            // Allow for rounding in a closed-form optimum equal to the straight line.
            let slack = 1e-12 * lower_bound.max(1.0);
            if !value.is_finite() || value < lower_bound - slack {
                return Err(ProblemError::Optimum { value, lower_bound });
            }
        }
        self.optimum = optimum;
        Ok(self)
    }

    /// Renames the problem.
    pub fn with_name(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    /// The problem's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The state space: `R^n` within the world's bounds.
    pub fn space(&self) -> &RealVectorSpace {
        &self.space
    }

    /// The world: bounds, obstacles, anti-obstacles and lattices.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The start state.
    pub fn start(&self) -> &[f64] {
        &self.start
    }

    /// The goal states (at least one).
    pub fn goals(&self) -> &[Vec<f64>] {
        &self.goals
    }

    /// The collision-check resolution, a fraction of the space's maximum extent.
    pub fn resolution(&self) -> f64 {
        self.resolution
    }

    /// The known optimal cost (the infimum of the lengths of valid paths), if known exactly.
    pub fn optimum(&self) -> Option<f64> {
        self.optimum
    }

    /// The dimension `n` of the space.
    pub fn dimension(&self) -> usize {
        self.space.dimension()
    }

    /// The full-resolution collision-check step `L = resolution × maximum extent`
    /// ([`mit_star_validity::step_from_resolution`]).
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The straight-line distance from the start to the nearest goal: a lower bound on the
    /// cost of every path, and the cost of the best path when nothing is in the way.
    pub fn straight_line_cost(&self) -> f64 {
        self.goals
            .iter()
            .map(|goal| euclidean_distance(&self.start, goal))
            .fold(f64::INFINITY, f64::min)
    }

    /// Re-checks what [`new`](Self::new) checks: at least one goal, and the start and every
    /// goal of the right length, finite, in the bounds and valid in the world.
    ///
    /// # Errors
    /// The first problem found, naming the state ([`Endpoint`]).
    pub fn validate(&self) -> Result<(), ProblemError> {
        if self.goals.is_empty() {
            return Err(ProblemError::NoGoals);
        }
        let endpoints = std::iter::once((Endpoint::Start, &self.start)).chain(
            self.goals
                .iter()
                .enumerate()
                .map(|(i, goal)| (Endpoint::Goal(i), goal)),
        );
        for (endpoint, state) in endpoints {
            self.space
                .check_state(state)
                .map_err(|source| ProblemError::State { endpoint, source })?;
            if !self.world.is_valid(state) {
                return Err(ProblemError::InCollision {
                    endpoint,
                    state: state.clone(),
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::SpaceError;
    use mit_star_validity::AxisBox;

    fn wall_world() -> World {
        World::new(vec![-0.5; 2], vec![0.5; 2])
            .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, 0.8]))
            .unwrap()
    }

    fn wall() -> Problem {
        Problem::new("wall", wall_world(), vec![-0.4, 0.0], vec![vec![0.4, 0.0]]).unwrap()
    }

    #[test]
    fn accessors_report_what_was_given() {
        let p = wall();
        assert_eq!(p.name(), "wall");
        assert_eq!(p.dimension(), 2);
        assert_eq!(p.start(), &[-0.4, 0.0]);
        assert_eq!(p.goals(), &[vec![0.4, 0.0]]);
        assert_eq!(p.resolution(), 5e-6);
        assert_eq!(p.optimum(), None);
        assert_eq!(p.space().lower(), &[-0.5, -0.5]);
        assert!(p.validate().is_ok());
    }

    #[test]
    fn step_scales_with_resolution_and_extent() {
        let p = wall().with_resolution(1e-3).unwrap();
        assert!((p.step() - 1e-3 * 2f64.sqrt()).abs() < 1e-15);
        for bad in [0.0, -0.0, 1.0, 1e300, -1e-9, f64::NAN, f64::INFINITY] {
            let err = wall().with_resolution(bad).unwrap_err();
            assert!(matches!(err, ProblemError::Resolution { .. }), "{bad}");
            assert!(
                err.to_string().contains("strictly between 0 and 1"),
                "{err}"
            );
        }
    }

    #[test]
    fn a_step_coarser_than_the_thinnest_obstacle_is_refused_unless_allowed() {
        let world = World::new(vec![-0.5; 2], vec![0.5; 2])
            .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![1e-6, 1.0]))
            .unwrap()
            .with_anti_obstacle(AxisBox::new(vec![0.0, 0.3], vec![0.2, 2e-6]))
            .unwrap();
        let p = Problem::new("thin", world, vec![-0.3, 0.0], vec![vec![0.3, 0.0]]).unwrap();
        assert_eq!(p.thinnest_extents(), (Some(1e-6), Some(2e-6)));
        let err = p.check_step().unwrap_err().to_string();
        assert!(err.contains("thinnest obstacle (1e-6)"), "{err}");
        assert!(err.contains("anti-obstacle (2e-6)"), "{err}");
        assert!(err.contains("--allow-coarse-step"), "{err}");
        let fine = p.clone().with_resolution(5e-7).unwrap();
        assert!(fine.check_step().is_ok() && !fine.step_is_coarse());
        let allowed = p.allowing_coarse_step(true);
        assert!(allowed.check_step().is_ok() && allowed.step_is_coarse());
        let round_trip = Problem::from_toml_str(&allowed.to_toml_string()).unwrap();
        assert!(round_trip.coarse_step_allowed());
    }

    #[test]
    fn endpoints_are_checked_and_named() {
        let err = Problem::new("p", wall_world(), vec![-0.4, 0.0], vec![]).unwrap_err();
        assert_eq!(err, ProblemError::NoGoals);

        let err = Problem::new(
            "p",
            wall_world(),
            vec![-0.4, 0.0],
            vec![vec![0.4, 0.0], vec![0.4, 0.7]],
        )
        .unwrap_err();
        assert!(matches!(
            err,
            ProblemError::State {
                endpoint: Endpoint::Goal(1),
                source: SpaceError::OutOfBounds { index: 1, .. }
            }
        ));
        assert_eq!(
            err.to_string(),
            "goal 1: coordinate 1 of the state is 0.7, outside the bounds [-0.5, 0.5]"
        );

        let err = Problem::new("p", wall_world(), vec![-0.4], vec![vec![0.4, 0.0]]).unwrap_err();
        assert!(matches!(
            err,
            ProblemError::State {
                endpoint: Endpoint::Start,
                source: SpaceError::DimensionMismatch {
                    expected: 2,
                    got: 1
                }
            }
        ));

        let err =
            Problem::new("p", wall_world(), vec![-0.4, 0.0], vec![vec![0.0, 0.3]]).unwrap_err();
        assert!(matches!(
            err,
            ProblemError::InCollision {
                endpoint: Endpoint::Goal(0),
                ..
            }
        ));
    }

    #[test]
    fn malformed_bounds_are_refused() {
        let world = World::new(vec![0.0, 1.0], vec![1.0, 1.0]);
        let err = Problem::new("p", world, vec![0.5, 1.0], vec![vec![0.5, 1.0]]).unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Bounds(SpaceError::EmptyInterval { index: 1, .. })
        ));
    }

    #[test]
    fn optimum_cannot_beat_the_straight_line() {
        let p = wall();
        assert!((p.straight_line_cost() - 0.8).abs() < 1e-12);
        let err = p.clone().with_optimum(Some(0.7)).unwrap_err();
        assert!(matches!(err, ProblemError::Optimum { value: 0.7, .. }));
        assert!(p.clone().with_optimum(Some(f64::INFINITY)).is_err());
        let p = p.with_optimum(Some(0.9)).unwrap();
        assert_eq!(p.optimum(), Some(0.9));
        assert_eq!(p.with_optimum(None).unwrap().optimum(), None);
    }

    #[test]
    fn nearest_goal_sets_the_straight_line() {
        let p = Problem::new(
            "two goals",
            World::new(vec![-0.5; 2], vec![0.5; 2]),
            vec![0.0, 0.0],
            vec![vec![0.4, 0.0], vec![0.0, -0.3]],
        )
        .unwrap();
        assert!((p.straight_line_cost() - 0.3).abs() < 1e-12);
        assert_eq!(p.with_name("renamed").name(), "renamed");
    }
}
