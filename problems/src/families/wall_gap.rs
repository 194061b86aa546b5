//! [`WallGap`]: a wall with a slot, and a corridor past its end.

use crate::families::optimum::{distance_to_union, slab_crossing};
use crate::families::shared::{
    FULL, HALF, axis_point, check_endpoints, check_finite, check_positive, unit_world, xy_box,
};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **wall gap** in `[-0.5, 0.5]^n`: a wall across the x-axis from the lower bound of `y`
/// up to `wall_top`, spanning every other coordinate, with a slot through it; above the wall a
/// corridor is left.
///
/// The wall is an obstacle `thickness` wide in `x` covering `y ∈ [−0.5, wall_top]`; the slot an
/// anti-obstacle centred at `(0, gap_center, 0, …)`, `thickness` wide in `x`, `gap_width` in `y`
/// and spanning every other coordinate.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.3, 0, …) / (0.3, 0, …) |
/// | `thickness` | 0.2 |
/// | `wall_top` | 0.3 |
/// | `gap_center` / `gap_width` | 0.1 / 0.04 |
///
/// **Optimum.** When start and goal differ only in `x` and lie on either side of the wall, the
/// path crosses at the height nearest the start's `y` that is in the slot or above the wall:
/// `√(a² + m²) + thickness + √(b² + m²)`, `2√(0.2² + 0.08²) + 0.2 ≈ 0.6308` by default.
/// Otherwise unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct WallGap {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    thickness: f64,
    wall_top: f64,
    gap_center: f64,
    gap_width: f64,
}

impl WallGap {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "wall-gap";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.3),
            goal: axis_point(n, 0.3),
            thickness: 0.2,
            wall_top: 0.3,
            gap_center: 0.1,
            gap_width: 0.04,
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

    /// Sets the `y` at which the wall ends (it starts at the lower bound, −0.5).
    pub fn wall_top(mut self, wall_top: f64) -> Self {
        self.wall_top = wall_top;
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
            Parameter::number("wall_top", self.wall_top, "y at which the wall ends"),
            Parameter::number("gap_center", self.gap_center, "y of the slot's centre"),
            Parameter::number("gap_width", self.gap_width, "slot width in y"),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a width that is
    /// not finite and positive, a `wall_top` not above −0.5, a non-finite centre, or a start or
    /// goal of the wrong length; [`ProblemError::State`] or [`ProblemError::InCollision`] for a
    /// start or goal out of bounds or in the wall.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        check_positive(name, "thickness", self.thickness)?;
        if !(self.wall_top.is_finite() && self.wall_top > -HALF) {
            return Err(ProblemError::Parameter {
                problem: name,
                parameter: "wall_top",
                reason: format!("is {}; it must be finite and above -0.5", self.wall_top),
            });
        }
        check_finite(name, "gap_center", self.gap_center)?;
        check_positive(name, "gap_width", self.gap_width)?;

        let across = (0.0, self.thickness);
        let wall = (0.5 * (self.wall_top - HALF), self.wall_top + HALF);
        let world = unit_world(n)
            .with_obstacle(xy_box(n, across, wall, FULL))?
            .with_anti_obstacle(xy_box(n, across, (self.gap_center, self.gap_width), FULL))?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum (type docs).
    fn optimum(&self) -> Option<f64> {
        let half_gap = 0.5 * self.gap_width;
        let mut free = vec![(self.gap_center - half_gap, self.gap_center + half_gap)];
        if self.wall_top < HALF {
            free.push((self.wall_top, HALF));
        }
        let m = distance_to_union(self.start[1], &free, -HALF, HALF);
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
    fn wall_slot_and_corridor() {
        let p = WallGap::new(3).build().unwrap();
        let w = p.world();
        assert!(!w.is_valid(&[0.0, -0.49, 0.4]));
        assert!(!w.is_valid(&[0.0, 0.29, 0.0]));
        assert!(w.is_valid(&[0.0, 0.31, 0.0]));
        assert!(w.is_valid(&[0.09, 0.1, -0.45]));
        assert!(!w.is_valid(&[0.09, 0.125, -0.45]));
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = WallGap::new(2).build().unwrap();
        let y = 0.08 + 1e-9;
        let path = [vec![-0.3, 0.0], vec![-0.1, y], vec![0.1, y], vec![0.3, 0.0]];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        // Starting high, the corridor above the wall is nearer than the slot.
        let p = WallGap::new(2)
            .start(vec![-0.3, 0.25])
            .goal(vec![0.3, 0.25])
            .build()
            .unwrap();
        let expected = 2.0 * (0.2f64 * 0.2 + 0.05 * 0.05).sqrt() + 0.2;
        assert!((p.optimum().unwrap() - expected).abs() < 1e-12);
    }

    #[test]
    fn wall_top_must_be_above_the_bound() {
        let err = WallGap::new(2).wall_top(-0.6).build().unwrap_err();
        assert_eq!(
            err.to_string(),
            "wall-gap: `wall_top` is -0.6; it must be finite and above -0.5"
        );
    }
}
