//! [`ObstacleFree`]: the empty unit cube.

use crate::families::shared::{axis_point, check_endpoints, unit_world};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **obstacle-free** problem: the empty `[-0.5, 0.5]^n`.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.4, 0, …) / (0.4, 0, …) |
///
/// **Optimum.** The straight line, 0.8 by default.
///
/// ```
/// let problem = mit_star_problems::ObstacleFree::new(16).build()?;
/// assert_eq!(problem.optimum(), Some(0.8));
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ObstacleFree {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
}

impl ObstacleFree {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "obstacle-free";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.4),
            goal: axis_point(n, 0.4),
        }
    }

    /// Sets the start state.
    pub fn start(mut self, start: Vec<f64>) -> Self {
        self.start = start;
        self
    }

    /// Sets the goal state.
    pub fn goal(mut self, goal: Vec<f64>) -> Self {
        self.goal = goal;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a start or goal
    /// of the wrong length or not finite; [`ProblemError::State`] for one out of bounds.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        let problem = Problem::new(
            name,
            unit_world(n),
            self.start.clone(),
            vec![self.goal.clone()],
        )?;
        let optimum = problem.straight_line_cost();
        problem.with_optimum(Some(optimum))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn optimum_is_the_straight_line() {
        let p = ObstacleFree::new(2).build().unwrap();
        assert!((p.optimum().unwrap() - 0.8).abs() < 1e-15);
        assert!(p.world().obstacles().is_empty());
        let p = ObstacleFree::new(3)
            .start(vec![0.0, 0.0, 0.0])
            .goal(vec![0.3, 0.4, 0.0])
            .build()
            .unwrap();
        assert!((p.optimum().unwrap() - 0.5).abs() < 1e-15);
        assert!(matches!(
            ObstacleFree::new(2).goal(vec![0.6, 0.0]).build(),
            Err(ProblemError::State { .. })
        ));
    }
}
