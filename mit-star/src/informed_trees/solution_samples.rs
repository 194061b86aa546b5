//! States placed along the best path ([`Parameters::solution_samples`](crate::Parameters)):
//! once a solution exists, part of each batch lies on shortcuts of its path, so the forward
//! search can straighten it through the graph.

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
    /// each on the segment between two vertices of the path that are not neighbours on it, at
    /// a uniform place, half of them then displaced by a Gaussian step; kept if valid and
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
        let mut x = std::mem::take(&mut self.sample);
        let mut added = 0;
        for _ in 0..count * TRIES_PER_STATE {
            if added == count || stop.should_stop() {
                break;
            }
            let pulls = self.parameters.solution_corner_pulls;
            if pulls && self.path_rng.random_range(0..3) == 0 {
                self.corner_pull(&mut states, &mut x);
            } else {
                self.shortcut_state(&states, &mut x);
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
        self.counters.solution_samples += added as u64;
        added
    }

    /// A state on the segment between two vertices of the path (`states`, `m ≥ 3` of them)
    /// that are not neighbours on it, at a uniform place; half of the time displaced by a
    /// Gaussian step whose deviation is uniform up to [`DISPLACEMENT`] of the segment's length.
    fn shortcut_state(&mut self, states: &[f64], x: &mut [f64]) {
        let n = self.space.dimension();
        let m = states.len() / n;
        let i = self.path_rng.random_range(0..m - 2);
        let j = self.path_rng.random_range(i + 2..m);
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
    /// path): a corner cut partly, where cutting it whole collides.
    fn corner_pull(&mut self, states: &mut Vec<f64>, x: &mut [f64]) {
        let n = self.space.dimension();
        let m = states.len() / n;
        let k = self.path_rng.random_range(1..m - 1);
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

/// A standard normal draw (Box–Muller, one of the pair).
fn gaussian(rng: &mut mit_star_spaces::SeededRng) -> f64 {
    let u: f64 = 1.0 - rng.random::<f64>();
    let v: f64 = rng.random::<f64>();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}
