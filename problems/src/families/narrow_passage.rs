//! [`NarrowPassage`]: a full wall with one slot.

use crate::families::optimum::{distance_to_union, slab_crossing};
use crate::families::shared::{
    FULL, HALF, axis_point, check_endpoints, check_finite, check_positive, unit_world, xy_box,
};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **narrow passage** in `[-0.5, 0.5]^n`: a wall across the x-axis spanning the bounds in
/// every other coordinate, crossed only through one slot.
///
/// The wall is an obstacle centred at the origin, `thickness` wide in `x` and spanning the
/// bounds elsewhere; the slot an anti-obstacle centred at `(0, gap_center, 0, …)`, `thickness`
/// wide in `x`, `gap_width` in `y` and spanning every other coordinate.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `thickness` | 0.2 |
/// | `gap_center` / `gap_width` | 0.1 / 0.1 |
///
/// **Optimum.** When start and goal differ only in `x` and lie on either side of the wall:
/// `√(a² + m²) + thickness + √(b² + m²)` with `m` the distance from the start's `y` to the slot,
/// `2√(0.1² + 0.05²) + 0.2 ≈ 0.4236` by default. Otherwise unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct NarrowPassage {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    thickness: f64,
    gap_center: f64,
    gap_width: f64,
}

impl NarrowPassage {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "narrow-passage";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.2),
            goal: axis_point(n, 0.2),
            thickness: 0.2,
            gap_center: 0.1,
            gap_width: 0.1,
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

    /// Sets the wall's thickness in `x`.
    pub fn thickness(mut self, thickness: f64) -> Self {
        self.thickness = thickness;
        self
    }

    /// Sets the `y` of the slot's centre.
    pub fn gap_center(mut self, gap_center: f64) -> Self {
        self.gap_center = gap_center;
        self
    }

    /// Sets the slot's width in `y`.
    pub fn gap_width(mut self, gap_width: f64) -> Self {
        self.gap_width = gap_width;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::number("thickness", self.thickness, "wall thickness in x"),
            Parameter::number("gap_center", self.gap_center, "y of the slot's centre"),
            Parameter::number("gap_width", self.gap_width, "slot width in y"),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a width that is
    /// not finite and positive, a non-finite centre, or a start or goal of the wrong length;
    /// [`ProblemError::State`] or [`ProblemError::InCollision`] for a start or goal out of
    /// bounds or in the wall.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        check_positive(name, "thickness", self.thickness)?;
        check_finite(name, "gap_center", self.gap_center)?;
        check_positive(name, "gap_width", self.gap_width)?;

        let across = (0.0, self.thickness);
        let world = unit_world(n)
            .with_obstacle(xy_box(n, across, (0.0, FULL), FULL))?
            .with_anti_obstacle(xy_box(n, across, (self.gap_center, self.gap_width), FULL))?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum (type docs).
    fn optimum(&self) -> Option<f64> {
        let half_gap = 0.5 * self.gap_width;
        let slot = (self.gap_center - half_gap, self.gap_center + half_gap);
        let m = distance_to_union(self.start[1], &[slot], -HALF, HALF);
        let half = 0.5 * self.thickness;
        slab_crossing(&self.start, &self.goal, -half, half, m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use mit_star_validity::StateValidity;

    #[test]
    fn only_the_slot_crosses_the_wall() {
        let p = NarrowPassage::new(3).build().unwrap();
        let w = p.world();
        assert!(w.is_valid(&[0.0, 0.1, 0.49]));
        assert!(!w.is_valid(&[0.0, 0.16, 0.0]));
        assert!(!w.is_valid(&[0.0, 0.49, 0.49]));
        assert!(!w.is_valid(&[0.0, -0.3, 0.0]));
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = NarrowPassage::new(2).build().unwrap();
        let y = 0.05 + 1e-9;
        let path = [vec![-0.2, 0.0], vec![-0.1, y], vec![0.1, y], vec![0.2, 0.0]];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        assert!((optimum - 0.4236).abs() < 1e-4);
    }
}
