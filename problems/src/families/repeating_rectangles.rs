//! [`RepeatingRectangles`]: a regular lattice of small cubes.

use mit_star_validity::Lattice;

use crate::families::shared::{axis_point, check_endpoints, check_positive, unit_world};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **repeating rectangles** in `[-0.5, 0.5]^n`: a regular grid of `count^n` cubes of side
/// `side`, centred at `−0.5 + (j + 1)/(count + 1)` along every coordinate for
/// `j = 0 … count − 1` (a [`Lattice`], checked in `O(n)` however many cubes there are).
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.25, 0, …) / (0.25, 0, …) |
/// | `count` | 49 |
/// | `side` | 0.01 |
///
/// The spec gives `count = 49` for 2-D only; the same default is kept in every dimension, which
/// keeps the pitch (0.02) and the cubes (0.01) — the local geometry around every state — the
/// same whatever `n`. With an odd count a row of cubes lies on the x-axis, so the straight line
/// from start to goal is blocked. The optimum is not known.
///
/// ```
/// use mit_star_problems::RepeatingRectangles;
/// use mit_star_validity::StateValidity;
///
/// let problem = RepeatingRectangles::new(8).build()?;
/// assert!(!problem.world().is_valid(&[0.0; 8])); // a cube's centre
/// assert!(problem.world().is_valid(&[0.01; 8])); // between cubes
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RepeatingRectangles {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    count: usize,
    side: f64,
}

impl RepeatingRectangles {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "repeating-rectangles";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.25),
            goal: axis_point(n, 0.25),
            count: 49,
            side: 0.01,
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

    /// Sets the number of cubes per coordinate, `k` (the spacing is `1/(k + 1)`).
    pub fn count(mut self, count: usize) -> Self {
        self.count = count;
        self
    }

    /// Sets the side of every cube (less than the spacing).
    pub fn side(mut self, side: f64) -> Self {
        self.side = side;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::integer("count", self.count, "cubes per coordinate"),
            Parameter::number("side", self.side, "side of every cube"),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a count of 0, a
    /// side that is not finite and positive or not below the spacing (the cubes would fuse
    /// into one block), or a start or goal of the wrong length; [`ProblemError::State`] or
    /// [`ProblemError::InCollision`] for a start or goal out of bounds or in a cube.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        if self.count == 0 {
            return Err(ProblemError::Parameter {
                problem: name,
                parameter: "count",
                reason: "is 0; there must be at least one cube per coordinate".to_owned(),
            });
        }
        check_positive(name, "side", self.side)?;
        let spacing = 1.0 / (self.count as f64 + 1.0);
        if self.side >= spacing {
            return Err(ProblemError::Parameter {
                problem: name,
                parameter: "side",
                reason: format!(
                    "is {}; it must be below the spacing 1/(count + 1) = {spacing}",
                    self.side
                ),
            });
        }
        let world = unit_world(n).with_lattice(Lattice {
            count: self.count,
            spacing,
            side: self.side,
        })?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_validity::StateValidity;

    #[test]
    fn planar_lattice_has_pitch_two_hundredths() {
        let p = RepeatingRectangles::new(2).build().unwrap();
        let w = p.world();
        let lattice = &w.lattices()[0];
        assert_eq!(lattice.count, 49);
        assert!((lattice.spacing - 0.02).abs() < 1e-15);
        // Cubes at −0.48, −0.46, …, 0.48 in both coordinates.
        assert!(!w.is_valid(&[-0.48, 0.48]));
        assert!(!w.is_valid(&[0.004, -0.004]));
        assert!(w.is_valid(&[0.01, 0.0]));
        assert!(w.is_valid(&[-0.49, -0.49]));
        assert!(w.is_valid(&[0.0, 0.495]));
    }

    #[test]
    fn bad_lattices_are_refused() {
        let err = RepeatingRectangles::new(2).count(0).build().unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "count",
                ..
            }
        ));
        let err = RepeatingRectangles::new(2).side(0.02).build().unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "side",
                ..
            }
        ));
        // Three cubes per coordinate are centred at −0.25, 0, 0.25: one sits on the start.
        let err = RepeatingRectangles::new(2)
            .count(3)
            .side(0.1)
            .build()
            .unwrap_err();
        assert!(matches!(err, ProblemError::InCollision { .. }));
    }
}
