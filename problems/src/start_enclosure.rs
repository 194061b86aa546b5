//! [`StartEnclosure`]: goal enclosure mirrored — the start sits in a hollow cube opening away
//! from the goal.

use crate::enclosure::Sizes;
use crate::family::{axis_point, check_dimension, check_point, on_axis, unit_world};
use crate::goal_enclosure::enclosure_parameters;
use crate::optimum::enclosure_escape;
use crate::{Parameter, Problem, ProblemError};

/// PDT's **start enclosure** in `[-0.5, 0.5]^n`: the mirror image of
/// [`GoalEnclosure`](crate::GoalEnclosure). The start lies inside a hollow cube whose only
/// opening is in the face pointing to `−x`, away from the goal.
///
/// The obstacle is a cube of side `outside` centred on the start, the hollow a cube of side
/// `inside`, the opening centred at `x = start_x − inside/2 − (outside − inside)/4`,
/// `(outside − inside)/2` wide in `x` and `gap` wide in every other coordinate.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `outside` / `inside` / `gap` | 0.25 / 0.2 / 0.2 |
///
/// **Optimum.** The goal enclosure's, mirrored: `√(h² + g²) + (h − g) + 2h + √(b² + h²)` with
/// `h = outside/2`, `g = gap/2` and `b` the goal's distance to the cube, under the mirrored
/// conditions (≈ 0.7372 by default). Otherwise unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct StartEnclosure {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    sizes: Sizes,
}

impl StartEnclosure {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "start-enclosure";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.2),
            goal: axis_point(n, 0.2),
            sizes: Sizes::PDT,
        }
    }

    /// Sets the start state (the enclosure's centre).
    pub fn start(mut self, start: Vec<f64>) -> Self {
        self.start = start;
        self
    }

    /// Sets the goal state.
    pub fn goal(mut self, goal: Vec<f64>) -> Self {
        self.goal = goal;
        self
    }

    /// Sets the side of the enclosing cube.
    pub fn outside(mut self, outside: f64) -> Self {
        self.sizes.outside = outside;
        self
    }

    /// Sets the side of the hollow (less than `outside`).
    pub fn inside(mut self, inside: f64) -> Self {
        self.sizes.inside = inside;
        self
    }

    /// Sets the width of the opening in every coordinate but `x`.
    pub fn gap(mut self, gap: f64) -> Self {
        self.sizes.gap = gap;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        enclosure_parameters(&self.start, &self.goal, &self.sizes)
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// As [`GoalEnclosure::build`](crate::GoalEnclosure::build).
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_dimension(name, n)?;
        check_point(name, "start", &self.start, n)?;
        check_point(name, "goal", &self.goal, n)?;
        self.sizes.check(name)?;
        let mut world = unit_world(n);
        self.sizes.add_to(&mut world, &self.start, -1.0)?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum (type docs).
    fn optimum(&self) -> Option<f64> {
        let (sx, gx, h) = (self.start[0], self.goal[0], self.sizes.half());
        let applies = on_axis(&self.start)
            && on_axis(&self.goal)
            && self.sizes.has_closed_form()
            && gx > sx + h
            && sx - h > -0.5;
        applies
            .then(|| enclosure_escape(self.sizes.outside, self.sizes.gap) + (gx - sx - h).hypot(h))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::GoalEnclosure;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use validity::StateValidity;

    #[test]
    fn start_is_enclosed_with_an_opening_away_from_the_goal() {
        let p = StartEnclosure::new(2).build().unwrap();
        let w = p.world();
        assert!(w.is_valid(&[-0.31, 0.0]));
        assert!(!w.is_valid(&[-0.09, 0.0]));
        assert!(!w.is_valid(&[-0.2, 0.11]));
    }

    #[test]
    fn optimum_mirrors_the_goal_enclosure() {
        let p = StartEnclosure::new(2).build().unwrap();
        let optimum = p.optimum().unwrap();
        let mirrored = GoalEnclosure::new(2).build().unwrap().optimum().unwrap();
        assert!((optimum - mirrored).abs() < 1e-12);
        let d = 1e-9;
        let path = [
            vec![-0.2, 0.0],
            vec![-0.325 - d, 0.1 - d],
            vec![-0.325 - d, 0.125 + d],
            vec![-0.075 + d, 0.125 + d],
            vec![0.2, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
    }
}
