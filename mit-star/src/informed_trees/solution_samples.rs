//! States placed along the best path ([`Parameters::solution_samples`](crate::Parameters)):
//! once a solution exists, part of each batch lies on shortcuts of its path, so the forward
//! search can straighten it through the graph. With
//! [`Parameters::solution_corner_weights`](crate::Parameters) a share of them gather where the
//! path bends, in proportion to the length a bend adds.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::{SampleOrigin, Sampler};
use mit_star_spaces::rand::RngExt;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, StateValidity};

use crate::VertexKind;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::Guidance;

/// Candidates drawn per state wanted before the batch gives up on the rest (most candidates
/// on a shortcut that passes through an obstacle are invalid).
const TRIES_PER_STATE: usize = 4;

/// The largest Gaussian step of a displaced state, as a fraction of its shortcut's length
/// (the step's standard deviation is uniform between 0 and this).
const DISPLACEMENT: f64 = 0.2;

/// The excess length, as a fraction of its two legs, below which a vertex counts as lying on a
/// straight stretch of the path (rounding's residue, not a corner).
const CORNER_TOLERANCE: f64 = 1e-12;

impl<S, V, Smp, E, H, G, N> Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule,
{
    /// The states of `size` a batch places along the best path: none without a solution or
    /// with a path of fewer than three states (a straight one cannot be shortened).
    pub(crate) fn solution_sample_count(&self, size: usize) -> usize {
        let fraction = self.parameters.solution_samples.unwrap_or(0.0);
        if fraction <= 0.0 || !self.best_cost.is_finite() || self.best_goal == crate::graph::NONE {
            return 0;
        }
        ((fraction * size as f64).round() as usize).min(size)
    }

    /// Adds up to `count` valid states near the best path to the graph, their ids to `ids`:
    /// each on the segment between two vertices of the path that are not neighbours on it
    /// (both uniform, or, for a share of them, on either side of a corner drawn by its weight),
    /// at a uniform place, half of them then displaced by a Gaussian step; kept if valid and
    /// inside the informed set of the best cost. Returns the number added (fewer than `count`
    /// if the candidates run out or `stop` fires).
    pub(crate) fn add_solution_samples(
        &mut self,
        count: usize,
        stop: &dyn Stop,
        ids: &mut Vec<u32>,
    ) -> usize {
        let path = self.solution_vertices();
        let m = path.len();
        if count == 0 || m < 3 {
            return 0;
        }
        let mut states = std::mem::take(&mut self.path_states);
        states.clear();
        for v in &path {
            states.extend_from_slice(self.graph.state(v.0));
        }
        let mut corners = std::mem::take(&mut self.corner_weights);
        corners.clear();
        let share = self.parameters.solution_corner_weights;
        if share > 0.0 {
            cumulative_corner_weights(&self.space, &states, &mut corners);
        }
        let mut x = std::mem::take(&mut self.sample);
        let mut added = 0;
        for _ in 0..count * TRIES_PER_STATE {
            if added == count || stop.should_stop() {
                break;
            }
            // This state's weights: all of them, or none (uniform), by `share`; no draw at
            // 0 or 1, so those shares take the decisions they took before there was a share.
            let weighted = share >= 1.0 || (share > 0.0 && self.path_rng.random::<f64>() < share);
            let weights = if weighted { &corners[..] } else { &[] };
            let pulls = self.parameters.solution_corner_pulls;
            if pulls && self.path_rng.random_range(0..3) == 0 {
                self.corner_pull(&mut states, weights, &mut x);
            } else {
                self.shortcut_state(&states, weights, &mut x);
            }
            let (space, h) = (&self.space, &self.heuristic);
            let through =
                h.cost_to_come(space, &self.start, &x) + h.cost_to_go(space, &x, &self.goals);
            if through >= self.best_cost || !self.validity.is_valid(&x) {
                continue;
            }
            let mut vertex = self.new_vertex(VertexKind::Sample, &x);
            vertex.origin = SampleOrigin::NearSolution;
            ids.push(self.graph.add_vertex(&x, vertex));
            added += 1;
        }
        self.sample = x;
        self.path_states = states;
        self.corner_weights = corners;
        self.counters.solution_samples += added as u64;
        added
    }

    /// A state on the segment between two vertices of the path (`states`, `m ≥ 3` of them)
    /// that are not neighbours on it, at a uniform place; half of the time displaced by a
    /// Gaussian step whose deviation is uniform up to [`DISPLACEMENT`] of the segment's length.
    /// The two vertices are uniform, or, with `corners` (cumulative weights of the interior
    /// vertices) summing above zero, one uniform on each side of a corner drawn by weight.
    fn shortcut_state(&mut self, states: &[f64], corners: &[f64], x: &mut [f64]) {
        let n = self.space.dimension();
        let m = states.len() / n;
        let (i, j) = match draw_corner(corners, &mut self.path_rng) {
            Some(k) => (
                self.path_rng.random_range(0..k),
                self.path_rng.random_range(k + 1..m),
            ),
            None => {
                let i = self.path_rng.random_range(0..m - 2);
                (i, self.path_rng.random_range(i + 2..m))
            }
        };
        let (a, b) = (&states[i * n..(i + 1) * n], &states[j * n..(j + 1) * n]);
        let t = self.path_rng.random::<f64>();
        self.space.interpolate(a, b, t, x);
        if self.path_rng.random::<bool>() {
            let sigma = DISPLACEMENT * self.path_rng.random::<f64>() * self.space.distance(a, b);
            for xi in x.iter_mut() {
                *xi += sigma * gaussian(&mut self.path_rng);
            }
            self.space.enforce_bounds(x);
        }
    }

    /// An interior vertex of the path moved a uniform part of the way towards the chord of
    /// its two neighbours on it (the chord's point as far along as the vertex is along the
    /// path): a corner cut partly, where cutting it whole collides. The vertex is uniform, or
    /// drawn by its weight in `corners` as in [`shortcut_state`](Self::shortcut_state).
    fn corner_pull(&mut self, states: &mut Vec<f64>, corners: &[f64], x: &mut [f64]) {
        let n = self.space.dimension();
        let m = states.len() / n;
        let k = match draw_corner(corners, &mut self.path_rng) {
            Some(k) => k,
            None => self.path_rng.random_range(1..m - 1),
        };
        let (before, after) = {
            let state = |i: usize| &states[i * n..(i + 1) * n];
            let (a, corner, b) = (state(k - 1), state(k), state(k + 1));
            (
                self.space.distance(a, corner),
                self.space.distance(corner, b),
            )
        };
        let t = if before + after > 0.0 {
            before / (before + after)
        } else {
            0.5
        };
        // The chord's point, written after the path's states for the moment.
        self.space.interpolate(
            &states[(k - 1) * n..k * n],
            &states[(k + 1) * n..(k + 2) * n],
            t,
            x,
        );
        states.extend_from_slice(x);
        let s = self.path_rng.random::<f64>();
        self.space
            .interpolate(&states[k * n..(k + 1) * n], &states[m * n..], s, x);
        states.truncate(m * n);
        self.space.enforce_bounds(x);
    }
}

/// Writes to `out` the running sums of the corner weights of the interior vertices of the
/// path `states` (`m ≥ 3` states): entry `k - 1` sums, over vertices `1..=k`, how much longer
/// the path is through each than along the chord of its two neighbours (zero where that is
/// within [`CORNER_TOLERANCE`] of the legs' length).
pub(super) fn cumulative_corner_weights<S: StateSpace>(
    space: &S,
    states: &[f64],
    out: &mut Vec<f64>,
) {
    let n = space.dimension();
    let m = states.len() / n;
    let state = |i: usize| &states[i * n..(i + 1) * n];
    let mut total = 0.0;
    for k in 1..m - 1 {
        let (a, corner, b) = (state(k - 1), state(k), state(k + 1));
        let legs = space.distance(a, corner) + space.distance(corner, b);
        let excess = legs - space.distance(a, b);
        // Rounding leaves a straight stretch a few ulps of excess: not a corner.
        if excess > CORNER_TOLERANCE * legs {
            total += excess;
        }
        out.push(total);
    }
}

/// An interior vertex (`1..m - 1`) drawn with probability proportional to its weight, from
/// the running sums `cumulative`; `None` when there are none or they sum to zero (a straight
/// path), so the caller draws uniformly.
pub(super) fn draw_corner(
    cumulative: &[f64],
    rng: &mut mit_star_spaces::SeededRng,
) -> Option<usize> {
    let total = *cumulative.last()?;
    if total <= 0.0 || !total.is_finite() {
        return None;
    }
    Some(corner_at(cumulative, rng.random::<f64>() * total))
}

/// The interior vertex whose running sum is the first above `u ∈ [0, total]`: a vertex of
/// weight zero is never drawn, not even when rounding makes `u` the total (then the last
/// vertex that adds length).
pub(super) fn corner_at(cumulative: &[f64], u: f64) -> usize {
    let total = cumulative.last().copied().unwrap_or(0.0);
    let last = cumulative.partition_point(|&c| c < total);
    cumulative.partition_point(|&c| c <= u).min(last) + 1
}

/// A standard normal draw (Box–Muller, one of the pair).
fn gaussian(rng: &mut mit_star_spaces::SeededRng) -> f64 {
    let u: f64 = 1.0 - rng.random::<f64>();
    let v: f64 = rng.random::<f64>();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}
