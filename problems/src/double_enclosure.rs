//! [`DoubleEnclosure`]: start and goal each sit in a hollow cube opening away from the other.

use crate::enclosure::Sizes;
use crate::family::{axis_point, check_dimension, check_point, on_axis, unit_world};
use crate::goal_enclosure::enclosure_parameters;
use crate::optimum::enclosure_escape;
use crate::{Parameter, Problem, ProblemError};

/// PDT's **double enclosure** in `[-0.5, 0.5]^n`: [`StartEnclosure`](crate::StartEnclosure)
/// and [`GoalEnclosure`](crate::GoalEnclosure) together. Both cubes have the same sizes; the
/// start's opens to `−x`, the goal's to `+x`.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `outside` / `inside` / `gap` | 0.25 / 0.2 / 0.2 |
///
/// **Optimum.** When start and goal lie on the x-axis, the cubes are disjoint and clear of the
/// bounds and the openings no wider than the hollows, the shortest path leaves the start's cube,
/// runs along the tops of both cubes and enters the goal's:
/// `2(√(h² + g²) + (h − g) + 2h) + d` with `h = outside/2`, `g = gap/2` and `d` the distance
/// between the cubes (≈ 1.0202 by default). Otherwise unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct DoubleEnclosure {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    sizes: Sizes,
}

impl DoubleEnclosure {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "double-enclosure";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.2),
            goal: axis_point(n, 0.2),
            sizes: Sizes::PDT,
        }
    }

    /// Sets the start state (the centre of one cube).
    pub fn start(mut self, start: Vec<f64>) -> Self {
        self.start = start;
        self
    }

    /// Sets the goal state (the centre of the other cube).
    pub fn goal(mut self, goal: Vec<f64>) -> Self {
        self.goal = goal;
        self
    }

    /// Sets the side of the enclosing cubes.
    pub fn outside(mut self, outside: f64) -> Self {
        self.sizes.outside = outside;
        self
    }

    /// Sets the side of the hollows (less than `outside`).
    pub fn inside(mut self, inside: f64) -> Self {
        self.sizes.inside = inside;
        self
    }

    /// Sets the width of the openings in every coordinate but `x`.
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
        self.sizes.add_to(&mut world, &self.goal, 1.0)?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum (type docs).
    fn optimum(&self) -> Option<f64> {
        let (sx, gx, h) = (self.start[0], self.goal[0], self.sizes.half());
        let applies = on_axis(&self.start)
            && on_axis(&self.goal)
            && self.sizes.has_closed_form()
            && sx + h < gx - h
            && sx - h > -0.5
            && gx + h < 0.5;
        applies.then(|| {
            2.0 * enclosure_escape(self.sizes.outside, self.sizes.gap) + (gx - h) - (sx + h)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use validity::StateValidity;

    #[test]
    fn both_ends_are_enclosed() {
        let p = DoubleEnclosure::new(4).build().unwrap();
        let w = p.world();
        assert_eq!(w.obstacles().len(), 2);
        assert!(w.is_valid(&[-0.31, 0.0, 0.0, 0.0]));
        assert!(!w.is_valid(&[-0.09, 0.0, 0.0, 0.0]));
        assert!(w.is_valid(&[0.31, 0.0, 0.0, 0.0]));
        assert!(!w.is_valid(&[0.09, 0.0, 0.0, 0.0]));
        assert!(w.is_valid(&[0.0, 0.0, 0.0, 0.0]));
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = DoubleEnclosure::new(2).build().unwrap();
        let d = 1e-9;
        let (top, edge) = (0.125 + d, 0.1 - d);
        let path = [
            vec![-0.2, 0.0],
            vec![-0.325 - d, edge],
            vec![-0.325 - d, top],
            vec![0.325 + d, top],
            vec![0.325 + d, edge],
            vec![0.2, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        assert!((optimum - 1.02016).abs() < 1e-5, "{optimum}");
    }

    #[test]
    fn overlapping_cubes_have_no_closed_form() {
        let p = DoubleEnclosure::new(2)
            .start(vec![-0.1, 0.0])
            .goal(vec![0.1, 0.0])
            .build()
            .unwrap();
        assert_eq!(p.optimum(), None);
    }
}
