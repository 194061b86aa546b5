//! [`DividingWalls`]: PDT's dividing walls — three full walls cut by six slots.

use crate::families::optimum::{distance_to_union, slab_crossing};
use crate::families::shared::{FULL, axis_point, check_endpoints, unit_world, xy_box};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **dividing walls** in `[-0.5, 0.5]^n`: walls across the x-axis spanning the bounds in
/// every other coordinate, crossed only through slots (gaps) that cut through all of them.
///
/// Each wall `(x, thickness)` is an obstacle centred at `(x, 0, …)`, `thickness` wide in `x` and
/// spanning the bounds elsewhere. Each gap `(y, width)` is an anti-obstacle slab centred at
/// `(0, y, 0, …)`, `width` wide in `y` and spanning the bounds in every other coordinate (`x`
/// included), so it cuts through every wall.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.45, 0, …) / (0.45, 0, …) |
/// | `walls` (x, thickness) | (−0.25, 0.05), (0, 0.1), (0.25, 0.05) |
/// | `gaps` (y, width) | (−0.5 + j/7, w_j), j = 1 … 6, w = 0.05, 0.03, 0.01, 0.01, 0.03, 0.05 |
///
/// The straight line from start to goal runs between the two central gaps and is blocked.
///
/// **Optimum.** When start and goal differ only in `x` and lie on either side of all walls, every
/// path crosses the walls' span at heights in the gaps, so the optimum is
/// `√(a² + m²) + span + √(b² + m²)` with `m` the distance from the start's `y` to the nearest
/// gap: `2√(0.175² + m²) + 0.55 ≈ 0.9244` by default (`m = 1/14 − 0.005`). Otherwise unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct DividingWalls {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    walls: Vec<(f64, f64)>,
    gaps: Vec<(f64, f64)>,
}

impl DividingWalls {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "dividing-walls";

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        let widths = [0.05, 0.03, 0.01, 0.01, 0.03, 0.05];
        let gaps = widths
            .iter()
            .enumerate()
            .map(|(j, &w)| (-0.5 + (j + 1) as f64 / 7.0, w))
            .collect();
        Self {
            n,
            start: axis_point(n, -0.45),
            goal: axis_point(n, 0.45),
            walls: vec![(-0.25, 0.05), (0.0, 0.1), (0.25, 0.05)],
            gaps,
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

    /// Sets the walls as `(x of the centre, thickness)` pairs.
    pub fn walls(mut self, walls: Vec<(f64, f64)>) -> Self {
        self.walls = walls;
        self
    }

    /// Sets the gaps as `(y of the centre, width)` pairs.
    pub fn gaps(mut self, gaps: Vec<(f64, f64)>) -> Self {
        self.gaps = gaps;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::pairs("walls", &self.walls, "walls as (x, thickness in x)"),
            Parameter::pairs(
                "gaps",
                &self.gaps,
                "slots through all walls as (y, width in y)",
            ),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a non-finite
    /// centre, a thickness or width that is not finite and positive, or a start or goal of the
    /// wrong length; [`ProblemError::State`] or [`ProblemError::InCollision`] for a start or
    /// goal out of bounds or in a wall.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        check_pairs("walls", &self.walls)?;
        check_pairs("gaps", &self.gaps)?;

        let mut world = unit_world(n);
        for &wall in &self.walls {
            world.add_obstacle(xy_box(n, wall, (0.0, FULL), FULL))?;
        }
        for &gap in &self.gaps {
            world.add_anti_obstacle(xy_box(n, (0.0, FULL), gap, FULL))?;
        }
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum when start and goal differ only in `x` (type docs).
    fn optimum(&self) -> Option<f64> {
        if self.walls.is_empty() {
            return Some(mit_star_spaces::euclidean_distance(&self.start, &self.goal));
        }
        let x_lo = self
            .walls
            .iter()
            .map(|&(x, t)| x - 0.5 * t)
            .fold(f64::INFINITY, f64::min);
        let x_hi = self
            .walls
            .iter()
            .map(|&(x, t)| x + 0.5 * t)
            .fold(f64::NEG_INFINITY, f64::max);
        let slots: Vec<(f64, f64)> = self
            .gaps
            .iter()
            .map(|&(y, w)| (y - 0.5 * w, y + 0.5 * w))
            .collect();
        let m = distance_to_union(self.start[1], &slots, -0.5, 0.5);
        slab_crossing(&self.start, &self.goal, x_lo, x_hi, m)
    }
}

/// Checks `(centre, width)` pairs: centres finite, widths finite and positive.
fn check_pairs(parameter: &'static str, pairs: &[(f64, f64)]) -> Result<(), ProblemError> {
    for (i, &(center, width)) in pairs.iter().enumerate() {
        let reason = if !center.is_finite() {
            format!("has entry {i} centred at {center}; centres must be finite")
        } else if !(width.is_finite() && width > 0.0) {
            format!("has entry {i} of width {width}; widths must be finite and positive")
        } else {
            continue;
        };
        return Err(ProblemError::Parameter {
            problem: DividingWalls::NAME,
            parameter,
            reason,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use mit_star_validity::StateValidity;

    #[test]
    fn walls_are_cut_by_every_gap() {
        let p = DividingWalls::new(3).build().unwrap();
        let w = p.world();
        assert_eq!(w.obstacles().len(), 3);
        assert_eq!(w.anti_obstacles().len(), 6);
        for x in [-0.25, 0.0, 0.25] {
            assert!(!w.is_valid(&[x, 0.0, 0.3]));
            // The central gaps: y = ±1/14, 0.01 wide.
            assert!(w.is_valid(&[x, 1.0 / 14.0 + 0.004, -0.49]));
            assert!(!w.is_valid(&[x, 1.0 / 14.0 + 0.006, -0.49]));
        }
        assert!(w.is_valid(&[0.125, 0.0, 0.0])); // between walls
    }

    #[test]
    fn optimum_matches_the_spec_and_a_valid_path() {
        let p = DividingWalls::new(2).build().unwrap();
        let optimum = p.optimum().unwrap();
        assert!((optimum - 0.924).abs() < 1e-3, "{optimum}");
        let y = 1.0 / 14.0 - 0.005 + 1e-9;
        let path = [
            vec![-0.45, 0.0],
            vec![-0.275, y],
            vec![0.275, y],
            vec![0.45, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
    }

    #[test]
    fn custom_walls_and_gaps() {
        let p = DividingWalls::new(2)
            .walls(vec![(0.0, 0.2)])
            .gaps(vec![(0.0, 0.1)])
            .build()
            .unwrap();
        // A gap on the axis: the straight line is free and optimal.
        assert!((p.optimum().unwrap() - 0.9).abs() < 1e-12);
        let p = DividingWalls::new(2).walls(vec![]).build().unwrap();
        assert!((p.optimum().unwrap() - 0.9).abs() < 1e-12);
        // No gap at all: no path, no optimum.
        let p = DividingWalls::new(2).gaps(vec![]).build().unwrap();
        assert_eq!(p.optimum(), None);
    }

    #[test]
    fn bad_pairs_are_named() {
        let err = DividingWalls::new(2)
            .walls(vec![(0.0, 0.1), (0.2, -0.1)])
            .build()
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "dividing-walls: `walls` has entry 1 of width -0.1; widths must be finite and positive"
        );
        let err = DividingWalls::new(2)
            .gaps(vec![(f64::NAN, 0.1)])
            .build()
            .unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "gaps",
                ..
            }
        ));
    }
}
