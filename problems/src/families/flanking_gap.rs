//! [`FlankingGap`]: PDT's flanking gap — a wall with a small square hole, flanked by corridors.

use crate::families::optimum::{distance_to_union, slab_crossing};
use crate::families::shared::{
    axis_point, check_endpoints, check_finite, check_positive, on_axis, unit_world, xy_box,
};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **flanking gap** in `[-0.5, 0.5]^n`: one wall across the x-axis that stops short of the
/// bounds, leaving corridors around it, with a small square hole (the gap) near its middle.
///
/// The wall is centred at the origin, `thickness` wide in `x` and `wall_width` in every other
/// coordinate. The gap is an anti-obstacle centred at `x = 0`,
/// `y = gap_offset + gap_width / 2`, other coordinates 0, `thickness` wide in `x` and
/// `gap_width` in every other coordinate.
///
/// | parameter | n = 2 | n ≥ 3 |
/// |---|---|---|
/// | `start` / `goal` | (−0.2, 0) / (0.2, 0) | (−0.2, 0, …) / (0.2, 0, …) |
/// | `thickness` | 0.1 | 0.1 |
/// | `wall_width` | 0.7 | 0.8 |
/// | `gap_offset` | 0.2 | 0.1 |
/// | `gap_width` | 0.03 | 0.01 |
///
/// **Optimum.** When start and goal lie on the x-axis on either side of the wall, a path
/// crosses the wall's slab either through the gap (at distance `gap_offset` from the axis, if
/// the gap lies above it) or around the wall (at distance `wall_width / 2`), so the optimum is
/// `√(a² + m²) + thickness + √(b² + m²)` with `m` the smaller of the two and `a`, `b` the
/// distances of start and goal to the wall: 0.6 in 2-D (around: ≈ 0.86) and
/// `2√(0.15² + 0.1²) + 0.1 ≈ 0.4606` for `n ≥ 3` (around: ≈ 0.95). Otherwise it is left
/// unknown.
///
/// ```
/// use mit_star_problems::FlankingGap;
/// use mit_star_validity::StateValidity;
///
/// let problem = FlankingGap::new(4).build()?;
/// assert!(problem.world().is_valid(&[0.0, 0.105, 0.0, 0.0])); // in the gap
/// assert!(!problem.world().is_valid(&[0.0, 0.0, 0.0, 0.0])); // in the wall
/// assert!((problem.optimum().unwrap() - 0.4606).abs() < 1e-4);
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FlankingGap {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    thickness: f64,
    wall_width: f64,
    gap_offset: f64,
    gap_width: f64,
}

impl FlankingGap {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "flanking-gap";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        let planar = n == 2;
        Self {
            n,
            start: axis_point(n, -0.2),
            goal: axis_point(n, 0.2),
            thickness: 0.1,
            wall_width: if planar { 0.7 } else { 0.8 },
            gap_offset: if planar { 0.2 } else { 0.1 },
            gap_width: if planar { 0.03 } else { 0.01 },
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

    /// Sets the wall's thickness in `x` (also the gap's).
    pub fn thickness(mut self, thickness: f64) -> Self {
        self.thickness = thickness;
        self
    }

    /// Sets the wall's width in every coordinate but `x`.
    pub fn wall_width(mut self, wall_width: f64) -> Self {
        self.wall_width = wall_width;
        self
    }

    /// Sets the `y` of the gap's lower edge.
    pub fn gap_offset(mut self, gap_offset: f64) -> Self {
        self.gap_offset = gap_offset;
        self
    }

    /// Sets the gap's width in every coordinate but `x`.
    pub fn gap_width(mut self, gap_width: f64) -> Self {
        self.gap_width = gap_width;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::number("thickness", self.thickness, "wall (and gap) thickness in x"),
            Parameter::number(
                "wall_width",
                self.wall_width,
                "wall width in every other coordinate",
            ),
            Parameter::number("gap_offset", self.gap_offset, "y of the gap's lower edge"),
            Parameter::number(
                "gap_width",
                self.gap_width,
                "gap width in every coordinate but x",
            ),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a width that is
    /// not finite and positive, a non-finite offset, or a start or goal of the wrong length;
    /// [`ProblemError::State`] or [`ProblemError::InCollision`] for a start or goal out of
    /// bounds or in the wall.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        check_positive(name, "thickness", self.thickness)?;
        check_positive(name, "wall_width", self.wall_width)?;
        check_finite(name, "gap_offset", self.gap_offset)?;
        check_positive(name, "gap_width", self.gap_width)?;

        let across = (0.0, self.thickness);
        let (wall, gap) = (self.wall_width, self.gap_width);
        let gap_center = self.gap_offset + 0.5 * gap;
        let world = unit_world(n)
            .with_obstacle(xy_box(n, across, (0.0, wall), wall))?
            .with_anti_obstacle(xy_box(n, across, (gap_center, gap), gap))?;
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum when start and goal lie on the x-axis (type docs).
    fn optimum(&self) -> Option<f64> {
        if !(on_axis(&self.start) && on_axis(&self.goal)) {
            return None;
        }
        let gap = (self.gap_offset, self.gap_offset + self.gap_width);
        let through = distance_to_union(0.0, &[gap], -0.5, 0.5);
        let half_wall = 0.5 * self.wall_width;
        let around = if half_wall < 0.5 {
            half_wall
        } else {
            f64::INFINITY
        };
        let half = 0.5 * self.thickness;
        slab_crossing(&self.start, &self.goal, -half, half, through.min(around))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_validity::StateValidity;

    #[test]
    fn planar_defaults_follow_pdt() {
        let p = FlankingGap::new(2).build().unwrap();
        let w = p.world();
        assert_eq!(w.obstacles()[0].widths, vec![0.1, 0.7]);
        assert_eq!(w.anti_obstacles()[0].widths, vec![0.1, 0.03]);
        assert!((w.anti_obstacles()[0].center[1] - 0.215).abs() < 1e-15);
        // Corridors beyond |y| = 0.35, gap y ∈ [0.2, 0.23].
        assert!(w.is_valid(&[0.0, 0.36]));
        assert!(!w.is_valid(&[0.0, 0.34]));
        assert!(w.is_valid(&[0.0, 0.22]));
        assert!(!w.is_valid(&[0.0, 0.19]));
        assert!((p.optimum().unwrap() - 0.6).abs() < 1e-12);
    }

    #[test]
    fn higher_dimensional_gap_is_a_small_square() {
        let p = FlankingGap::new(3).build().unwrap();
        let w = p.world();
        assert!(w.is_valid(&[0.0, 0.105, 0.004]));
        assert!(!w.is_valid(&[0.0, 0.105, 0.006]));
        let expected = 2.0 * (0.15f64 * 0.15 + 0.01).sqrt() + 0.1;
        assert!((p.optimum().unwrap() - expected).abs() < 1e-12);
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        // Through the gap, a hair inside its lower edge.
        let p = FlankingGap::new(2).build().unwrap();
        let y = 0.2 + 1e-9;
        let path = [
            vec![-0.2, 0.0],
            vec![-0.05, y],
            vec![0.05, y],
            vec![0.2, 0.0],
        ];
        let length = crate::test_support::polyline_length(&path);
        assert!(crate::test_support::polyline_is_valid(p.world(), &path));
        assert!((length - p.optimum().unwrap()).abs() < 1e-8);
    }

    #[test]
    fn wide_gap_offsets_make_the_corridor_optimal() {
        // A gap beyond the wall's end is no shortcut: the optimum goes around at |y| = 0.35.
        let p = FlankingGap::new(2).gap_offset(0.4).build().unwrap();
        let expected = 2.0 * (0.15f64 * 0.15 + 0.35 * 0.35).sqrt() + 0.1;
        assert!((p.optimum().unwrap() - expected).abs() < 1e-12);
        // Off-axis start: no closed form.
        let p = FlankingGap::new(2).start(vec![-0.2, 0.1]).build().unwrap();
        assert_eq!(p.optimum(), None);
    }

    #[test]
    fn bad_parameters_are_named() {
        let err = FlankingGap::new(1).build().unwrap_err();
        assert_eq!(
            err,
            ProblemError::Dimension {
                problem: "flanking-gap",
                n: 1
            }
        );
        let err = FlankingGap::new(2).gap_width(0.0).build().unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "gap_width",
                ..
            }
        ));
        let err = FlankingGap::new(2).goal(vec![0.2]).build().unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "goal",
                ..
            }
        ));
        let err = FlankingGap::new(2)
            .start(vec![0.0, 0.0])
            .build()
            .unwrap_err();
        assert!(matches!(err, ProblemError::InCollision { .. }));
    }
}
