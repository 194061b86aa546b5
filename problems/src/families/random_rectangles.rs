//! [`RandomRectangles`]: PDT's random rectangles — a seeded scatter of boxes.

use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::AxisBox;
use rand::{RngExt, SeedableRng};

use crate::families::shared::{check_endpoints, check_positive, unit_world};
use crate::{Parameter, Problem, ProblemError};

/// PDT's **random rectangles** in `[-0.5, 0.5]^n`: `count` axis-aligned boxes placed at random,
/// the layout a deterministic function of the seed.
///
/// Boxes are drawn one after another from a [`SeededRng`] seeded with `seed`: first the centre,
/// uniform over the bounds (one draw per coordinate, in order), then the side lengths, uniform
/// in `[min_side, max_side]` and independent per coordinate. A box containing the start or the
/// goal is rejected and the next one drawn, until `count` boxes are accepted. Boxes may overlap
/// and stick out of the bounds. At most `max_attempts` boxes are drawn in total; if that is not
/// enough, [`build`](Self::build) fails rather than loop for ever.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.1, …, −0.1) / (0.4, …, 0.4) |
/// | `count` | 35 |
/// | `min_side` / `max_side` | 0.1 / 0.2 |
/// | `seed` | 0 |
/// | `max_attempts` | 100 000 |
///
/// The optimum is not known.
///
/// ```
/// use mit_star_problems::RandomRectangles;
///
/// let a = RandomRectangles::new(4).seed(3).build()?;
/// let b = RandomRectangles::new(4).seed(3).build()?;
/// assert_eq!(a.world().obstacles().len(), 35);
/// assert_eq!(a, b);
/// assert_ne!(a.world(), RandomRectangles::new(4).seed(4).build()?.world());
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RandomRectangles {
    /// The family name: [`NAME`](Self::NAME) or [`CLUTTERED`](Self::CLUTTERED).
    family: &'static str,
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    count: usize,
    min_side: f64,
    max_side: f64,
    seed: u64,
    max_attempts: usize,
}

impl RandomRectangles {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = "random-rectangles";

    /// The name of the cluttered variant ([`cluttered`](Self::cluttered)).
    pub const CLUTTERED: &'static str = "cluttered-rectangles";

    /// The cluttered variant's box count and side range at its calibrated dimensions
    /// `(n, count, min_side, max_side)`: chosen so that the straight line from start to goal is
    /// blocked in at least 9 of the layouts 0–9, every layout is solvable, and EIT*'s final
    /// cost over the straight line comes near the paper's random-rectangles figures (the
    /// measurements are in `docs/guide/src/reference/experiment-files.md`). `n = 2` is PDT's own layout (uncalibrated).
    pub const CLUTTERED_CALIBRATION: [(usize, usize, f64, f64); 4] = [
        (2, 35, 0.1, 0.2),
        (4, 60, 0.2, 0.35),
        (8, 110, 0.5, 0.8),
        (16, 60, 0.7, 0.95),
    ];

    /// PDT's defaults in `n` dimensions with seed 0 (checked by [`build`](Self::build):
    /// `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            family: Self::NAME,
            n,
            start: vec![-0.1; n],
            goal: vec![0.4; n],
            count: 35,
            min_side: 0.1,
            max_side: 0.2,
            seed: 0,
            max_attempts: 100_000,
        }
    }

    /// The cluttered variant in `n` dimensions with seed 0: PDT's start, goal and bounds, with
    /// the box count and side range of [`CLUTTERED_CALIBRATION`](Self::CLUTTERED_CALIBRATION)
    /// — linear in `log2 n` between its dimensions, and those of `n = 16` above. PDT's own
    /// layout leaves the straight line free in most layouts (its boxes are far smaller than
    /// the space in `R^8` and above), so planners differ only in how fast they find it.
    ///
    /// ```
    /// use mit_star_problems::RandomRectangles;
    /// let p = RandomRectangles::cluttered(8).seed(1).build()?;
    /// assert_eq!(p.name(), "cluttered-rectangles-seed-1");
    /// assert_eq!(p.world().obstacles().len(), 110);
    /// # Ok::<(), mit_star_problems::ProblemError>(())
    /// ```
    pub fn cluttered(n: usize) -> Self {
        let (count, min_side, max_side) = Self::cluttered_parameters(n);
        Self {
            family: Self::CLUTTERED,
            count,
            min_side,
            max_side,
            ..Self::new(n)
        }
    }

    /// The cluttered variant's `(count, min_side, max_side)` in `n` dimensions.
    fn cluttered_parameters(n: usize) -> (usize, f64, f64) {
        let table = Self::CLUTTERED_CALIBRATION;
        let x = (n.max(2) as f64).log2();
        let last = table[table.len() - 1];
        let Some(i) = table.windows(2).position(|w| n <= w[1].0) else {
            return (last.1, last.2, last.3);
        };
        let (a, b) = (table[i], table[i + 1]);
        let f = (x - (a.0 as f64).log2()) / ((b.0 as f64).log2() - (a.0 as f64).log2());
        let lerp = |p: f64, q: f64| p + f.clamp(0.0, 1.0) * (q - p);
        (
            lerp(a.1 as f64, b.1 as f64).round() as usize,
            lerp(a.2, b.2),
            lerp(a.3, b.3),
        )
    }

    /// Sets the seed of the layout.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
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

    /// Sets the number of boxes.
    pub fn count(mut self, count: usize) -> Self {
        self.count = count;
        self
    }

    /// Sets the smallest side length.
    pub fn min_side(mut self, min_side: f64) -> Self {
        self.min_side = min_side;
        self
    }

    /// Sets the largest side length.
    pub fn max_side(mut self, max_side: f64) -> Self {
        self.max_side = max_side;
        self
    }

    /// Sets how many boxes may be drawn in total, rejected ones included.
    pub fn max_attempts(mut self, max_attempts: usize) -> Self {
        self.max_attempts = max_attempts;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::integer("count", self.count, "number of boxes"),
            Parameter::number("min_side", self.min_side, "smallest side length"),
            Parameter::number("max_side", self.max_side, "largest side length"),
            Parameter::integer("seed", self.seed, "seed of the layout"),
            Parameter::integer(
                "max_attempts",
                self.max_attempts,
                "boxes drawn at most, rejected ones included",
            ),
        ]
    }

    /// Builds the problem; its name is `random-rectangles-seed-<seed>` (or
    /// `cluttered-rectangles-seed-<seed>`).
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for side lengths
    /// that are not finite and positive or out of order, or a start or goal of the wrong
    /// length; [`ProblemError::RedrawLimit`] if `max_attempts` draws do not give `count`
    /// boxes; [`ProblemError::State`] for a start or goal out of bounds.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (self.family, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        check_positive(name, "min_side", self.min_side)?;
        check_positive(name, "max_side", self.max_side)?;
        if self.min_side > self.max_side {
            return Err(ProblemError::Parameter {
                problem: name,
                parameter: "min_side",
                reason: format!(
                    "is {}; it must not exceed `max_side` ({})",
                    self.min_side, self.max_side
                ),
            });
        }

        let mut world = unit_world(n);
        let space =
            mit_star_spaces::RealVectorSpace::new(world.lower().to_vec(), world.upper().to_vec())
                .map_err(ProblemError::Bounds)?;
        let mut rng = SeededRng::seed_from_u64(self.seed);
        let mut attempts = 0;
        while world.obstacles().len() < self.count {
            if attempts == self.max_attempts {
                return Err(ProblemError::RedrawLimit {
                    attempts,
                    accepted: world.obstacles().len(),
                    wanted: self.count,
                });
            }
            attempts += 1;
            let mut center = vec![0.0; n];
            space.sample_uniform(&mut rng, &mut center);
            let widths = (0..n)
                .map(|_| self.min_side + (self.max_side - self.min_side) * rng.random::<f64>())
                .collect();
            let candidate = AxisBox::new(center, widths);
            if !candidate.contains(&self.start) && !candidate.contains(&self.goal) {
                world.add_obstacle(candidate)?;
            }
        }
        let name = format!("{name}-seed-{}", self.seed);
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_validity::StateValidity;

    #[test]
    fn the_cluttered_variant_follows_its_calibration() {
        for &(n, count, min_side, max_side) in &RandomRectangles::CLUTTERED_CALIBRATION {
            let p = RandomRectangles::cluttered(n).seed(2).build().unwrap();
            assert_eq!(p.name(), "cluttered-rectangles-seed-2");
            let boxes = p.world().obstacles();
            assert_eq!(boxes.len(), count);
            assert!(
                boxes
                    .iter()
                    .flat_map(|b| &b.widths)
                    .all(|w| (min_side..=max_side).contains(w))
            );
        }
        // Between calibrated dimensions: in between; above the last: the last.
        let (count, lo, hi) = RandomRectangles::cluttered_parameters(6);
        assert!(
            (60..=110).contains(&count) && (0.2..0.5).contains(&lo) && (0.35..0.8).contains(&hi)
        );
        assert_eq!(
            RandomRectangles::cluttered_parameters(32),
            RandomRectangles::cluttered_parameters(16)
        );
        assert_eq!(RandomRectangles::cluttered_parameters(4), (60, 0.2, 0.35));
    }

    #[test]
    fn the_cluttered_variant_blocks_the_straight_line_where_pdts_does_not() {
        let blocked = |make: fn(usize) -> RandomRectangles, n: usize| {
            (0..10)
                .filter(|&seed| {
                    let p = make(n).seed(seed).build().unwrap();
                    !matches!(
                        p.world().segment_verdict(p.start(), &p.goals()[0]),
                        mit_star_validity::SegmentVerdict::Valid
                    )
                })
                .count()
        };
        for n in [4, 8, 16] {
            assert!(blocked(RandomRectangles::cluttered, n) >= 9, "R^{n}");
            assert!(blocked(RandomRectangles::new, n) <= 2, "R^{n}");
        }
    }

    #[test]
    fn boxes_follow_the_distribution() {
        let p = RandomRectangles::new(3).seed(11).build().unwrap();
        assert_eq!(p.name(), "random-rectangles-seed-11");
        let boxes = p.world().obstacles();
        assert_eq!(boxes.len(), 35);
        for b in boxes {
            assert!(b.center.iter().all(|c| (-0.5..=0.5).contains(c)));
            assert!(b.widths.iter().all(|w| (0.1..=0.2).contains(w)));
            assert!(!b.contains(p.start()) && !b.contains(&p.goals()[0]));
        }
        assert!(p.world().is_valid(p.start()));
    }

    #[test]
    fn impossible_layouts_fail_instead_of_looping() {
        // Boxes covering the whole space always contain the start.
        let err = RandomRectangles::new(2)
            .min_side(3.0)
            .max_side(3.0)
            .max_attempts(500)
            .build()
            .unwrap_err();
        assert_eq!(
            err,
            ProblemError::RedrawLimit {
                attempts: 500,
                accepted: 0,
                wanted: 35
            }
        );
    }

    #[test]
    fn side_lengths_are_checked() {
        let err = RandomRectangles::new(2).min_side(0.3).build().unwrap_err();
        assert!(matches!(
            err,
            ProblemError::Parameter {
                parameter: "min_side",
                ..
            }
        ));
        // Equal sides are fine: every box is a cube of that side.
        let p = RandomRectangles::new(2)
            .min_side(0.15)
            .max_side(0.15)
            .build()
            .unwrap();
        assert!(
            p.world()
                .obstacles()
                .iter()
                .all(|b| b.widths == [0.15, 0.15])
        );
        // No boxes at all.
        let p = RandomRectangles::new(2).count(0).build().unwrap();
        assert!(p.world().obstacles().is_empty());
    }
}
