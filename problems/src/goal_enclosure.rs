//! [`GoalEnclosure`]: PDT's goal enclosure — the goal sits in a hollow cube opening away from
//! the start.

use crate::enclosure::Sizes;
use crate::family::{axis_point, check_dimension, check_point, on_axis, unit_world};
use crate::optimum::enclosure_escape;
use crate::{Parameter, Problem, ProblemError};

/// PDT's **goal enclosure** in `[-0.5, 0.5]^n`: the goal lies inside a hollow cube whose only
/// opening is in the face pointing to `+x`, away from the start, so a planner must go around.
///
/// The obstacle is a cube of side `outside` centred on the goal; the hollow is an anti-obstacle
/// cube of side `inside` centred on the goal; the opening is an anti-obstacle centred at
/// `x = goal_x + inside/2 + (outside − inside)/4` (other coordinates those of the goal),
/// `(outside − inside)/2` wide in `x` and `gap` wide in every other coordinate.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `outside` / `inside` / `gap` | 0.25 / 0.2 / 0.2 |
///
/// The paper's figure variant is `start (−0.4, 0)`, `goal (0.1, 0)` (its unit-square
/// `(0.1, 0.5)` / `(0.6, 0.5)`).
///
/// **Optimum.** When start and goal lie on the x-axis, the start left of the cube, the opening
/// no wider than the hollow and the cube clear of the bounds, the shortest path runs to the
/// cube's near top corner, along its top, down its `+x` face to the opening's edge and in to the
/// goal: `√(a² + h²) + 2h + (h − g) + √(h² + g²)` with `h = outside/2`, `g = gap/2` and `a` the
/// start's distance to the cube (≈ 0.7372 by default, in every dimension). Otherwise unknown.
///
/// ```
/// use problems::GoalEnclosure;
/// use validity::StateValidity;
///
/// let problem = GoalEnclosure::new(2).start(vec![-0.4, 0.0]).goal(vec![0.1, 0.0]).build()?;
/// assert!(!problem.world().is_valid(&[0.1, 0.11])); // the shell
/// assert!(problem.world().is_valid(&[0.21, 0.0])); // the opening
/// # Ok::<(), problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct GoalEnclosure {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    sizes: Sizes,
}

impl GoalEnclosure {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "goal-enclosure";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.2),
            goal: axis_point(n, 0.2),
            sizes: Sizes::PDT,
        }
    }

    /// Sets the start state.
    pub fn start(mut self, start: Vec<f64>) -> Self {
        self.start = start;
        self
    }

    /// Sets the goal state (the enclosure's centre).
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
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a size that is
    /// not finite and positive, `inside ≥ outside`, or a start or goal of the wrong length;
    /// [`ProblemError::State`] or [`ProblemError::InCollision`] for a start or goal out of
    /// bounds or in the shell.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_dimension(name, n)?;
        check_point(name, "start", &self.start, n)?;
        check_point(name, "goal", &self.goal, n)?;
        self.sizes.check(name)?;
        let mut world = unit_world(n);
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
            && sx < gx - h
            && gx + h < 0.5;
        applies
            .then(|| (gx - h - sx).hypot(h) + enclosure_escape(self.sizes.outside, self.sizes.gap))
    }
}

/// The parameter listing shared by the three enclosure families.
pub(crate) fn enclosure_parameters(start: &[f64], goal: &[f64], sizes: &Sizes) -> Vec<Parameter> {
    vec![
        Parameter::point("start", start, "start state"),
        Parameter::point("goal", goal, "goal state"),
        Parameter::number("outside", sizes.outside, "side of the enclosing cube"),
        Parameter::number("inside", sizes.inside, "side of the hollow"),
        Parameter::number("gap", sizes.gap, "width of the opening"),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use validity::StateValidity;

    #[test]
    fn goal_is_enclosed_with_an_opening_away_from_the_start() {
        let p = GoalEnclosure::new(3).build().unwrap();
        let w = p.world();
        // Shell x ∈ [0.075, 0.1] ∪ [0.3, 0.325], |y|, |z| ∈ [0.1, 0.125].
        assert!(!w.is_valid(&[0.09, 0.0, 0.0]));
        assert!(!w.is_valid(&[0.2, 0.11, 0.0]));
        assert!(!w.is_valid(&[0.2, 0.0, -0.11]));
        assert!(w.is_valid(&[0.31, 0.05, -0.05]));
        assert!(!w.is_valid(&[0.31, 0.05, -0.11]));
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = GoalEnclosure::new(2).build().unwrap();
        let d = 1e-9;
        let path = [
            vec![-0.2, 0.0],
            vec![0.075 - d, 0.125 + d],
            vec![0.325 + d, 0.125 + d],
            vec![0.325 + d, 0.1 - d],
            vec![0.2, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        assert!((optimum - 0.73715).abs() < 1e-5, "{optimum}");
        // The optimum of the 2-D problem holds in every dimension.
        let p8 = GoalEnclosure::new(8).build().unwrap();
        assert_eq!(p8.optimum(), Some(optimum));
    }

    #[test]
    fn parameters_are_checked() {
        assert!(matches!(
            GoalEnclosure::new(2).gap(f64::NAN).build(),
            Err(ProblemError::Parameter {
                parameter: "gap",
                ..
            })
        ));
        // The start inside the shell.
        assert!(matches!(
            GoalEnclosure::new(2).start(vec![0.09, 0.0]).build(),
            Err(ProblemError::InCollision { .. })
        ));
        // A goal near the bound: no room to reach the opening, no closed form.
        let p = GoalEnclosure::new(2).goal(vec![0.4, 0.0]).build().unwrap();
        assert_eq!(p.optimum(), None);
    }
}
