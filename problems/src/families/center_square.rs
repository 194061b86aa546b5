//! [`CenterSquare`]: one cube in the middle of the space.

use mit_star_validity::AxisBox;

use crate::families::optimum::slab_crossing;
use crate::families::shared::{axis_point, check_endpoints, check_positive, on_axis, unit_world};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **center square** in `[-0.5, 0.5]^n`: a single cube centred at the origin, between
/// start and goal.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.3, 0, …) / (0.3, 0, …) |
/// | `side` | 0.4 |
///
/// **Optimum.** When start and goal lie on the x-axis on either side of the cube and the cube
/// leaves room around it, the shortest path passes over one edge of the cube:
/// `√(a² + s²/4) + s + √(b² + s²/4)` with `s` the side and `a`, `b` the distances of start and
/// goal to the cube (`2√0.05 + 0.4 ≈ 0.8472` by default, in every dimension). Otherwise unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct CenterSquare {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    side: f64,
}

impl CenterSquare {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "center-square";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.3),
            goal: axis_point(n, 0.3),
            side: 0.4,
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

    /// Sets the cube's side.
    pub fn side(mut self, side: f64) -> Self {
        self.side = side;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::number("side", self.side, "side of the cube"),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a side that is
    /// not finite and positive, or a start or goal of the wrong length;
    /// [`ProblemError::State`] or [`ProblemError::InCollision`] for a start or goal out of
    /// bounds or in the cube.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        check_positive(name, "side", self.side)?;
        let world = unit_world(n).with_obstacle(AxisBox::cube(vec![0.0; n], self.side))?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum (type docs).
    fn optimum(&self) -> Option<f64> {
        let half = 0.5 * self.side;
        if !(on_axis(&self.start) && on_axis(&self.goal) && half < 0.5) {
            return None;
        }
        slab_crossing(&self.start, &self.goal, -half, half, half)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polyline_is_valid, polyline_length};

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = CenterSquare::new(2).build().unwrap();
        let d = 1e-9;
        let path = [
            vec![-0.3, 0.0],
            vec![-0.2, 0.2 + d],
            vec![0.2, 0.2 + d],
            vec![0.3, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        assert!((optimum - (2.0 * 0.05f64.sqrt() + 0.4)).abs() < 1e-12);
        assert_eq!(
            CenterSquare::new(5).build().unwrap().optimum(),
            Some(optimum)
        );
    }

    #[test]
    fn a_cube_filling_the_space_is_refused_at_the_start() {
        let err = CenterSquare::new(2).side(0.8).build().unwrap_err();
        assert!(matches!(err, ProblemError::InCollision { .. }));
        let err = CenterSquare::new(2).side(-1.0).build().unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "side",
                ..
            }
        ));
    }
}
