//! [`InformedSet`]: the informed set of a path-length objective, and how to sample it uniformly.

use rand::{Rng, RngExt};
use std::sync::Arc;

use mit_star_spaces::{StateSpace, Stop};

use crate::informed_sets::hyperspheroid::{
    dense_rotation, ln_unit_ball_measure, push_plane_rotation, rotate_about_centre,
    sample_unit_ball,
};
use crate::{SampleError, SamplerCounters, SamplerError, prolate_hyperspheroid_measure};

/// The informed set of a path-length objective: every state that could lie on a path from the
/// start to one of the goals cheaper than a cost `c`,
/// `{x : d(start, x) + d(x, goal_i) < c for some i}`, intersected with the space's bounds.
///
/// For one goal in a Euclidean space this is a prolate hyperspheroid with foci at the start and
/// the goal (spec §7, Gammell et al.); for several goals it is the union of one hyperspheroid per
/// goal. Under a weighted Euclidean metric, `d(a, b) = ‖s ⊙ (b − a)‖`
/// ([`StateSpace::euclidean_scales`]: a joint space with a weighted prismatic joint), it is
/// the same hyperspheroid in the scaled coordinates `s ⊙ x`, so it is drawn there and scaled
/// back. Everything that does not depend on the cost — per goal the minimum cost
/// `s_min = d(start, goal)`, the centre and the rotation `R` taking the first axis onto the
/// start→goal direction — is computed once at construction. Draws allocate nothing: the scratch
/// buffers live in the struct, which is why [`draw`](Self::draw) takes `&mut self`.
///
/// ```
/// use rand::SeedableRng;
/// use mit_star_samplers::InformedSet;
/// use mit_star_spaces::{Never, RealVectorSpace, SeededRng, StateSpace};
///
/// let space = RealVectorSpace::cube(3, -1.0, 1.0)?;
/// let mut set = InformedSet::new(&space, &[-0.5, 0.0, 0.0], &[[0.5, 0.0, 0.0]])?;
/// let mut rng = SeededRng::seed_from_u64(1);
/// let mut x = [0.0; 3];
/// set.draw(&space, &mut rng, Some(1.5), &Never, &mut x)?;
/// assert!(set.contains(&space, Some(1.5), &x) && space.contains(&x));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct InformedSet {
    dimension: usize,
    start: Vec<f64>,
    /// Everything per goal, fixed at construction and shared by clones (a planner keeps a
    /// copy of its sampler to start again from: with 20 000 goals in R^32 a deep copy was
    /// 20 MB and a third of the planner's construction).
    per_goal: Arc<GoalGeometry>,
    /// The smallest `s_min`.
    minimum: f64,
    /// How the metric relates to the coordinates, which decides how the set is sampled.
    metric: Metric,
    /// `ln ζ_n`, the log-volume of the unit `n`-ball.
    ln_unit_ball: f64,
    /// Scratch: the unit-ball sample of a draw.
    ball: Vec<f64>,
    /// Per-goal selection weights of the cost in `weighted` (recomputed when the cost
    /// changes, not per draw: `O(goals)` logarithms and exponentials each time).
    weights: Vec<f64>,
    /// The cost `weights` were computed for (its bits; NaN's at first), with the number of
    /// non-empty hyperspheroids, the log of their summed measure and the weights' sum.
    weighted: (u64, usize, f64, f64),
    counters: SamplerCounters,
}

/// The per-goal geometry of an [`InformedSet`], fixed at construction.
#[derive(Debug, Default)]
struct GoalGeometry {
    /// `m × n` goal coordinates.
    goals: Vec<f64>,
    /// `m × n` hyperspheroid centres, `(start + goal) / 2`.
    centres: Vec<f64>,
    /// Under a weighted metric, the centres in scaled coordinates, `s ⊙ centre` (else empty).
    scaled_centres: Vec<f64>,
    /// Per goal, `s_min = d(start, goal)`.
    minimum_costs: Vec<f64>,
    /// Per goal, the plane rotation taking `e1` onto the start→goal direction: its unit axis
    /// `w` (`m × n`) and `(cos, sin)` of its angle (`O(n)` each; see `push_plane_rotation`).
    axes: Vec<f64>,
    turns: Vec<(f64, f64)>,
}

impl InformedSet {
    /// The informed-set geometry for `start` and `goals` in `space`.
    ///
    /// # Errors
    /// [`SamplerError`] if there is no goal, the start or a goal has the wrong dimension or a
    /// non-finite coordinate.
    pub fn new<S, G>(space: &S, start: &[f64], goals: &[G]) -> Result<Self, SamplerError>
    where
        S: StateSpace + ?Sized,
        G: AsRef<[f64]>,
    {
        let n = space.dimension();
        if start.len() != n {
            return Err(SamplerError::StartDimension {
                expected: n,
                got: start.len(),
            });
        }
        if let Some((coordinate, &value)) = start.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(SamplerError::NonFiniteStart { coordinate, value });
        }
        if goals.is_empty() {
            return Err(SamplerError::NoGoals);
        }
        let m = goals.len();
        let mut set = Self {
            dimension: n,
            start: start.to_vec(),
            per_goal: Arc::default(),
            minimum: f64::INFINITY,
            metric: Metric::of(space),
            ln_unit_ball: ln_unit_ball_measure(n),
            ball: vec![0.0; n],
            weights: vec![0.0; m],
            weighted: (f64::NAN.to_bits(), 0, 0.0, 0.0),
            counters: SamplerCounters::default(),
        };
        let mut geometry = GoalGeometry {
            goals: Vec::with_capacity(m * n),
            centres: Vec::with_capacity(m * n),
            scaled_centres: Vec::new(),
            minimum_costs: Vec::with_capacity(m),
            axes: Vec::with_capacity(m * n),
            turns: Vec::with_capacity(m),
        };
        let mut direction = vec![0.0; n];
        for (index, goal) in goals.iter().enumerate() {
            let goal = goal.as_ref();
            if goal.len() != n {
                return Err(SamplerError::GoalDimension {
                    goal: index,
                    expected: n,
                    got: goal.len(),
                });
            }
            if let Some((coordinate, &value)) =
                goal.iter().enumerate().find(|(_, v)| !v.is_finite())
            {
                return Err(SamplerError::NonFiniteGoal {
                    goal: index,
                    coordinate,
                    value,
                });
            }
            let s_min = space.distance(start, goal);
            geometry.goals.extend_from_slice(goal);
            geometry
                .centres
                .extend(start.iter().zip(goal).map(|(a, b)| 0.5 * (a + b)));
            if let Metric::Weighted(scales) = &set.metric {
                let centre = &geometry.centres[index * n..];
                geometry
                    .scaled_centres
                    .extend(centre.iter().zip(scales).map(|(m, s)| m * s));
            }
            geometry.minimum_costs.push(s_min);
            set.minimum = set.minimum.min(s_min);
            // The major axis in the coordinates the metric is Euclidean in (scaled ones under
            // a weighted metric), where direct sampling draws.
            let mut norm = 0.0;
            for (i, ((d, a), b)) in direction.iter_mut().zip(start).zip(goal).enumerate() {
                *d = set.metric.scale(i) * (b - a);
                norm += *d * *d;
            }
            let norm = norm.sqrt();
            if norm > 0.0 {
                direction.iter_mut().for_each(|d| *d /= norm);
            } else {
                // Start and goal coincide: the hyperspheroid is a ball, any rotation will do.
                direction.iter_mut().enumerate().for_each(|(i, d)| {
                    *d = if i == 0 { 1.0 } else { 0.0 };
                });
            }
            let turn = push_plane_rotation(&mut geometry.axes, &direction);
            geometry.turns.push(turn);
        }
        set.per_goal = Arc::new(geometry);
        Ok(set)
    }

    /// Dimension of the space this set was built for.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The start state.
    pub fn start(&self) -> &[f64] {
        &self.start
    }

    /// Number of goals.
    pub fn goal_count(&self) -> usize {
        self.per_goal.minimum_costs.len()
    }

    /// Goal `index`, `None` if out of range.
    pub fn goal(&self, index: usize) -> Option<&[f64]> {
        self.row(&self.per_goal.goals, index, self.dimension)
    }

    /// Centre `(start + goal) / 2` of goal `index`'s hyperspheroid, `None` if out of range.
    pub fn centre(&self, index: usize) -> Option<&[f64]> {
        self.row(&self.per_goal.centres, index, self.dimension)
    }

    /// Rotation `R` of goal `index`'s hyperspheroid as a row-major `n × n` matrix (built on
    /// request, `O(n²)`; draws apply it implicitly in `O(n)`), `None` if out of range. Under a
    /// weighted metric it acts in the scaled coordinates `s ⊙ x`.
    ///
    /// `R` turns the plane of `e1` and `k1`, the unit start→goal vector, by their angle and fixes
    /// the orthogonal complement: orthonormal, `det R = +1`, and `R e1 = k1` for `n ≥ 2` (in one
    /// dimension no rotation takes `e1` to `−e1`; the interval is symmetric, so sampling is
    /// unaffected). The identity when start and goal coincide.
    pub fn rotation(&self, index: usize) -> Option<Vec<f64>> {
        let axis = self.row(&self.per_goal.axes, index, self.dimension)?;
        let (c, s) = self.per_goal.turns[index];
        Some(dense_rotation((c, s, axis)))
    }

    /// `s_min = d(start, goal)` of goal `index`, `None` if out of range.
    pub fn goal_minimum_cost(&self, index: usize) -> Option<f64> {
        self.per_goal.minimum_costs.get(index).copied()
    }

    /// The smallest cost any solution can have: `min_i d(start, goal_i)`. The informed set of a
    /// cost at or below it is empty.
    pub fn minimum_cost(&self) -> f64 {
        self.minimum
    }

    /// Draw counters so far: `drawn` raw candidates, `rejected` candidates (outside the bounds,
    /// the set, or thinned for the union), `returned` states written by [`draw`](Self::draw).
    pub fn counters(&self) -> SamplerCounters {
        self.counters
    }

    /// `own` counters with this set's `drawn` and `rejected` added: a sampler's total work.
    pub(crate) fn with_own(&self, own: SamplerCounters) -> SamplerCounters {
        SamplerCounters {
            drawn: own.drawn + self.counters.drawn,
            rejected: own.rejected + self.counters.rejected,
            ..own
        }
    }

    fn row<'a>(&self, data: &'a [f64], index: usize, width: usize) -> Option<&'a [f64]> {
        data.get(index * width..(index + 1) * width)
    }

    /// `true` if `x` lies in the informed set of `cost` (ignoring bounds): for some goal,
    /// `d(start, x) + d(x, goal) < cost` in the space's metric. `None` means unbounded (always
    /// `true`); a NaN cost gives `false`.
    pub fn contains<S: StateSpace + ?Sized>(
        &self,
        space: &S,
        cost: Option<f64>,
        x: &[f64],
    ) -> bool {
        let Some(cost) = cost else {
            return true;
        };
        let to_start = space.distance(&self.start, x);
        self.per_goal
            .goals
            .chunks_exact(self.dimension)
            .any(|goal| to_start + space.distance(x, goal) < cost)
    }

    /// Lebesgue measure of the informed set of `cost` (in the metric's units: in scaled
    /// coordinates under a weighted metric, as [`StateSpace::measure`] is):
    /// `ζ_n · (c/2) · (√(c² − s_min²)/2)^(n−1)`
    /// for one goal, the sum over goals (an upper bound of the union) for several, capped by the
    /// space's measure. The space's measure for `None` or an infinite cost; 0 for an empty set
    /// (cost at or below [`minimum_cost`](Self::minimum_cost), or NaN).
    pub fn measure<S: StateSpace + ?Sized>(&self, space: &S, cost: Option<f64>) -> f64 {
        let whole = space.measure();
        match cost {
            None => whole,
            Some(c) if c == f64::INFINITY => whole,
            Some(c) => {
                let sum: f64 = self
                    .per_goal
                    .minimum_costs
                    .iter()
                    .map(|&s| prolate_hyperspheroid_measure(self.dimension, s, c))
                    .sum();
                sum.min(whole)
            }
        }
    }

    /// Writes into `out` a state drawn uniformly from the informed set of `cost` intersected
    /// with the space's bounds. The state is **not** validity-checked.
    ///
    /// - `None` (or an infinite cost): uniform over the space.
    /// - Cost at or below every goal's `s_min`: [`SampleError::EmptySet`] at once.
    /// - Euclidean or weighted Euclidean metric and hyperspheroids smaller than the space: direct
    ///   sampling, `x = R L x_ball + centre` (divided by the scales `s` under a weighted
    ///   metric), rejecting states outside the bounds. With several goals a
    ///   hyperspheroid is chosen with probability proportional to its measure and the sample is
    ///   kept with probability `1 / (number of hyperspheroids containing it)`, which makes the
    ///   union uniform.
    /// - Otherwise (non-Euclidean metric, or hyperspheroids larger than the space): uniform
    ///   samples of the space, rejected until one lies in the set.
    ///
    /// # Errors
    /// [`SampleError::Stopped`] once `stop` fires (polled before every candidate),
    /// [`SampleError::EmptySet`] for an empty set, [`SampleError::DimensionMismatch`] if `space`
    /// or `out` does not have this set's dimension.
    pub fn draw<S: StateSpace + ?Sized>(
        &mut self,
        space: &S,
        rng: &mut dyn Rng,
        cost: Option<f64>,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        self.check_dimensions(space, out)?;
        let cost = match cost {
            Some(c) if c != f64::INFINITY => c,
            _ => {
                if stop.should_stop() {
                    return Err(SampleError::Stopped);
                }
                space.sample_uniform(rng, out);
                self.counters.drawn += 1;
                self.counters.returned += 1;
                return Ok(());
            }
        };
        // NaN compares false: a NaN bound is empty too.
        if cost.is_nan() || cost <= self.minimum {
            return Err(SampleError::EmptySet {
                bound: cost,
                minimum: self.minimum,
            });
        }
        let (active, ln_total) = self.selection_weights(cost);
        if self.metric.direct() && ln_total <= space.measure().ln() {
            self.draw_direct(space, rng, cost, active, stop, out)
        } else {
            self.draw_rejection(space, rng, cost, stop, out)
        }
    }

    /// Checks that `space` and `out` have this set's dimension.
    ///
    /// # Errors
    /// [`SampleError::DimensionMismatch`] naming the length found.
    pub fn check_dimensions<S: StateSpace + ?Sized>(
        &self,
        space: &S,
        out: &[f64],
    ) -> Result<(), SampleError> {
        for got in [space.dimension(), out.len()] {
            if got != self.dimension {
                return Err(SampleError::DimensionMismatch {
                    expected: self.dimension,
                    got,
                });
            }
        }
        Ok(())
    }

    /// Fills `weights` with each goal's hyperspheroid measure relative to the largest (0 for
    /// goals whose set is empty), in log space so nothing underflows in high dimension. Returns
    /// the number of non-empty hyperspheroids and the log of their summed measure.
    fn selection_weights(&mut self, cost: f64) -> (usize, f64) {
        let (bits, active, ln_total, _) = self.weighted;
        if bits == cost.to_bits() {
            return (active, ln_total);
        }
        let n = self.dimension;
        let mut largest = f64::NEG_INFINITY;
        let mut active = 0;
        for (w, &s) in self.weights.iter_mut().zip(&self.per_goal.minimum_costs) {
            *w = f64::NEG_INFINITY;
            if cost > s {
                let b = ((cost - s) * (cost + s)).sqrt() / 2.0;
                let minor_axes = if n > 1 {
                    (n as f64 - 1.0) * b.ln()
                } else {
                    0.0
                };
                *w = self.ln_unit_ball + (cost / 2.0).ln() + minor_axes;
                largest = largest.max(*w);
                active += 1;
            }
        }
        let mut sum = 0.0;
        for (w, &s) in self.weights.iter_mut().zip(&self.per_goal.minimum_costs) {
            *w = if cost <= s {
                0.0
            } else if largest == f64::NEG_INFINITY {
                // Every non-empty hyperspheroid is degenerate (measure underflows to zero):
                // choose among them evenly.
                1.0
            } else {
                (*w - largest).exp()
            };
            sum += *w;
        }
        let ln_total = largest + sum.ln();
        self.weighted = (cost.to_bits(), active, ln_total, sum);
        (active, ln_total)
    }

    /// Direct sampling of the hyperspheroid(s), rejecting states outside the bounds.
    fn draw_direct<S: StateSpace + ?Sized>(
        &mut self,
        space: &S,
        rng: &mut dyn Rng,
        cost: f64,
        active: usize,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        let n = self.dimension;
        let total = self.weighted.3;
        loop {
            if stop.should_stop() {
                return Err(SampleError::Stopped);
            }
            let goal = self.pick_goal(rng, total);
            sample_unit_ball(rng, &mut self.ball);
            let s = self.per_goal.minimum_costs[goal];
            let major = cost / 2.0;
            let minor = ((cost - s) * (cost + s)).sqrt() / 2.0;
            self.ball[0] *= major;
            self.ball[1..].iter_mut().for_each(|v| *v *= minor);
            let (c, sin) = self.per_goal.turns[goal];
            let axis = &self.per_goal.axes[goal * n..(goal + 1) * n];
            let centre = &self.per_goal.centres[goal * n..(goal + 1) * n];
            match &self.metric {
                Metric::Weighted(scales) => {
                    // Drawn in scaled coordinates about the scaled centre, then scaled back.
                    let scaled = &self.per_goal.scaled_centres[goal * n..(goal + 1) * n];
                    rotate_about_centre((c, sin, axis), &self.ball, scaled, out);
                    out.iter_mut().zip(scales).for_each(|(o, s)| *o /= s);
                }
                _ => rotate_about_centre((c, sin, axis), &self.ball, centre, out),
            }
            self.counters.drawn += 1;
            if !space.contains(out) {
                self.counters.rejected += 1;
                continue;
            }
            if active > 1 {
                let to_start = space.distance(&self.start, out);
                let others = self
                    .per_goal
                    .goals
                    .chunks_exact(n)
                    .enumerate()
                    .filter(|&(j, g)| {
                        j != goal
                            && self.weights[j] > 0.0
                            && to_start + space.distance(out, g) < cost
                    })
                    .count();
                if others > 0 && rng.random::<f64>() * (others + 1) as f64 >= 1.0 {
                    self.counters.rejected += 1;
                    continue;
                }
            }
            self.counters.returned += 1;
            return Ok(());
        }
    }

    /// Rejection sampling: uniform states of the space until one lies in the set.
    fn draw_rejection<S: StateSpace + ?Sized>(
        &mut self,
        space: &S,
        rng: &mut dyn Rng,
        cost: f64,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        loop {
            if stop.should_stop() {
                return Err(SampleError::Stopped);
            }
            space.sample_uniform(rng, out);
            self.counters.drawn += 1;
            if self.contains(space, Some(cost), out) {
                self.counters.returned += 1;
                return Ok(());
            }
            self.counters.rejected += 1;
        }
    }

    /// A goal index drawn with probability proportional to `weights`.
    fn pick_goal(&self, rng: &mut dyn Rng, total: f64) -> usize {
        if self.weights.len() == 1 {
            return 0;
        }
        let mut u = rng.random::<f64>() * total;
        let mut last = 0;
        for (index, &w) in self.weights.iter().enumerate() {
            if w > 0.0 {
                if u < w {
                    return index;
                }
                u -= w;
                last = index;
            }
        }
        // Rounding left `u` a hair above the sum: the last non-empty hyperspheroid.
        last
    }
}

/// How a space's metric relates to its coordinates.
#[derive(Debug, Clone, PartialEq)]
enum Metric {
    /// The Euclidean norm of the coordinate difference.
    Euclidean,
    /// `‖s ⊙ (b − a)‖` for these per-coordinate scales.
    Weighted(Vec<f64>),
    /// Anything else: only rejection sampling applies.
    Other,
}

impl Metric {
    /// The metric of `space`, as it reports it.
    fn of<S: StateSpace + ?Sized>(space: &S) -> Self {
        if space.is_euclidean() {
            Self::Euclidean
        } else {
            match space.euclidean_scales() {
                Some(scales)
                    if scales.len() == space.dimension()
                        && scales.iter().all(|s| s.is_finite() && *s > 0.0) =>
                {
                    Self::Weighted(scales.to_vec())
                }
                _ => Self::Other,
            }
        }
    }

    /// `true` if the set is a hyperspheroid in some coordinates, so it can be drawn directly.
    fn direct(&self) -> bool {
        !matches!(self, Self::Other)
    }

    /// The scale of coordinate `i` (1 but under a weighted metric).
    fn scale(&self, i: usize) -> f64 {
        match self {
            Self::Weighted(scales) => scales[i],
            _ => 1.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::{Never, RealVectorSpace, SeededRng};
    use rand::SeedableRng;
    use std::f64::consts::PI;

    #[test]
    fn clones_share_the_per_goal_geometry_and_draw_alike() {
        // A planner keeps a clone of its sampler to start again from: the per-goal arrays
        // (4 × m × n values) are shared, not copied.
        let space = RealVectorSpace::cube(3, -1.0, 1.0).unwrap();
        let goals: Vec<[f64; 3]> = (0..100)
            .map(|i| [0.5, 0.01 * f64::from(i) - 0.5, 0.0])
            .collect();
        let mut set = InformedSet::new(&space, &[-0.5, 0.0, 0.0], &goals).unwrap();
        let mut copy = set.clone();
        assert!(Arc::ptr_eq(&set.per_goal, &copy.per_goal));
        let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
        let (mut r1, mut r2) = (SeededRng::seed_from_u64(4), SeededRng::seed_from_u64(4));
        for _ in 0..50 {
            set.draw(&space, &mut r1, Some(1.4), &Never, &mut a)
                .unwrap();
            copy.draw(&space, &mut r2, Some(1.4), &Never, &mut b)
                .unwrap();
            assert_eq!(a, b);
        }
    }

    #[test]
    fn rejects_malformed_problems() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let none: [[f64; 2]; 0] = [];
        assert_eq!(
            InformedSet::new(&space, &[0.0, 0.0], &none).unwrap_err(),
            SamplerError::NoGoals
        );
        assert!(matches!(
            InformedSet::new(&space, &[0.0], &[[1.0, 0.0]]),
            Err(SamplerError::StartDimension {
                expected: 2,
                got: 1
            })
        ));
        assert!(matches!(
            InformedSet::new(&space, &[0.0, 0.0], &[vec![1.0, 0.0], vec![1.0]]),
            Err(SamplerError::GoalDimension {
                goal: 1,
                got: 1,
                ..
            })
        ));
        assert!(matches!(
            InformedSet::new(&space, &[0.0, f64::NAN], &[[1.0, 0.0]]),
            Err(SamplerError::NonFiniteStart { coordinate: 1, .. })
        ));
        assert!(matches!(
            InformedSet::new(&space, &[0.0, 0.0], &[[f64::INFINITY, 0.0]]),
            Err(SamplerError::NonFiniteGoal {
                goal: 0,
                coordinate: 0,
                ..
            })
        ));
    }

    #[test]
    fn set_measure_is_capped_and_zero_when_empty() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let set = InformedSet::new(&space, &[-0.3, 0.0], &[[0.3, 0.0]]).unwrap();
        assert_eq!(set.measure(&space, Some(0.6)), 0.0);
        assert_eq!(set.measure(&space, Some(100.0)), 4.0);
        assert_eq!(set.measure(&space, None), 4.0);
        let ellipse = PI * 0.5 * 0.4;
        assert!((set.measure(&space, Some(1.0)) - ellipse).abs() < 1e-12);
    }

    #[test]
    fn empty_set_is_reported_not_looped_on() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let mut set = InformedSet::new(&space, &[-0.3, 0.0], &[[0.3, 0.0], [0.0, 0.5]]).unwrap();
        assert!((set.minimum_cost() - 0.3f64.hypot(0.5)).abs() < 1e-12);
        let mut rng = SeededRng::seed_from_u64(3);
        let mut x = [0.0; 2];
        let err = set
            .draw(&space, &mut rng, Some(0.5), &Never, &mut x)
            .unwrap_err();
        assert_eq!(
            err,
            SampleError::EmptySet {
                bound: 0.5,
                minimum: set.minimum_cost()
            }
        );
        assert!(matches!(
            set.draw(&space, &mut rng, Some(f64::NAN), &Never, &mut x),
            Err(SampleError::EmptySet { .. })
        ));
        assert_eq!(set.counters().drawn, 0);
    }

    #[test]
    fn coincident_start_and_goal_sample_a_ball() {
        let space = RealVectorSpace::cube(3, -1.0, 1.0).unwrap();
        let mut set = InformedSet::new(&space, &[0.1; 3], &[[0.1; 3]]).unwrap();
        let identity: Vec<f64> = (0..9).map(|k| if k % 4 == 0 { 1.0 } else { 0.0 }).collect();
        assert_eq!(set.rotation(0), Some(identity));
        let mut rng = SeededRng::seed_from_u64(5);
        let mut x = [0.0; 3];
        for _ in 0..500 {
            set.draw(&space, &mut rng, Some(0.8), &Never, &mut x)
                .unwrap();
            assert!(mit_star_spaces::euclidean_distance(&x, &[0.1; 3]) < 0.4 + 1e-12);
        }
    }

    #[test]
    fn huge_sets_fall_back_to_rejection_inside_the_bounds() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let mut set = InformedSet::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]]).unwrap();
        let mut rng = SeededRng::seed_from_u64(9);
        let mut x = [0.0; 2];
        for _ in 0..200 {
            set.draw(&space, &mut rng, Some(2.9), &Never, &mut x)
                .unwrap();
            assert!(space.contains(&x) && set.contains(&space, Some(2.9), &x));
        }
        // Rejection drew from the square: the only rejections are the square's corners outside
        // the ellipse, so well under half of the candidates.
        let counters = set.counters();
        assert_eq!(counters.returned, 200);
        assert!(counters.rejected * 2 < counters.drawn, "{counters:?}");
    }

    #[test]
    fn dimension_mismatch_is_an_error() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let mut set = InformedSet::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]]).unwrap();
        let mut rng = SeededRng::seed_from_u64(9);
        let mut x = [0.0; 3];
        assert_eq!(
            set.draw(&space, &mut rng, None, &Never, &mut x),
            Err(SampleError::DimensionMismatch {
                expected: 2,
                got: 3
            })
        );
    }
}
