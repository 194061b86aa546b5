//! Frontier rays: [`NearTerminals`]'s draws along free straight lines out of the planner's
//! frontier ([`with_frontier_rays`](NearTerminals::with_frontier_rays)).

use mit_star_spaces::StateSpace;
use mit_star_validity::{EdgeGrid, StateValidity};
use rand::RngExt;

use super::NearTerminals;

impl<T> NearTerminals<T> {
    /// Lines tried per frontier draw before the draw falls back to a Gaussian one.
    pub const RAY_TRIES: usize = 8;
    /// States tested along a line.
    pub const RAY_POINTS: usize = 32;

    /// Tries up to [`RAY_TRIES`](Self::RAY_TRIES) straight lines from a frontier state (one
    /// chosen uniformly per line) towards a state drawn uniformly in the space, each over the
    /// largest scale `σ` (or up to the target, if nearer), tested at
    /// [`RAY_POINTS`](Self::RAY_POINTS) evenly spaced states in bisection order, a checker's
    /// batch at a time. The first line whose every tested state is valid leaves its far end
    /// and its midpoint in `chain` (the midpoint last, so it is returned first); `false` if
    /// every line met an invalid state, or there is no frontier.
    ///
    /// This is RRT-Connect's extension, made a sample: a tree grows out of a pocket along
    /// the few directions that stay free for a full step, which Gaussian draws around the
    /// frontier seldom find in 7 or 8 dimensions. The planner still checks every edge it
    /// builds; the line's test only chooses where the states go.
    pub(super) fn draw_ray<S, V>(&mut self, space: &S, validity: &V) -> bool
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let n = space.dimension();
        let frontier = self.frontier.len() / n.max(1);
        if frontier == 0 {
            return false;
        }
        let m = Self::RAY_POINTS;
        let width = validity.batch_width().clamp(1, m);
        self.ray.target.resize(n, 0.0);
        self.ray.states.resize(m * n, 0.0);
        let largest = self.log_scales.1.exp();
        // The interior points of a line of `m` intervals in the edge checkers' bisection order,
        // then its far end, so a checker's first batch spreads over the whole line.
        let grid = EdgeGrid::with_intervals(m as u64);
        for _ in 0..Self::RAY_TRIES {
            let from = self.draws.rng().random_range(0..frontier) * n;
            let centre = &self.frontier[from..from + n];
            space.sample_uniform(self.draws.rng(), &mut self.ray.target);
            let distance = space.distance(centre, &self.ray.target);
            // A target on the centre (or a NaN distance) gives no line.
            if distance.is_nan() || distance <= 0.0 {
                continue;
            }
            let reach = distance.min(largest) / distance;
            // A batch's states are placed just before it is tested: most lines end at their
            // first batch.
            let mut free = true;
            for (b, batch) in self.ray.states.chunks_mut(width * n).enumerate() {
                for (j, state) in batch.chunks_exact_mut(n).enumerate() {
                    let k = b * width + j;
                    let along = if k + 1 < m {
                        grid.fraction(grid.point(k as u64))
                    } else {
                        1.0
                    };
                    space.interpolate(centre, &self.ray.target, reach * along, state);
                }
                self.draws.own_counters().validity_checks += (batch.len() / n) as u64;
                if validity.any_invalid(batch, n).is_some() {
                    free = false;
                    break;
                }
            }
            if free {
                // The far end is the last state in bisection order, the midpoint the first;
                // the midpoint goes last, so it is returned first.
                self.ray.chain.clear();
                self.ray
                    .chain
                    .extend_from_slice(&self.ray.states[(m - 1) * n..m * n]);
                self.ray.chain.extend_from_slice(&self.ray.states[..n]);
                return true;
            }
        }
        false
    }
}

/// The scratch of the ray draws (kept so a draw allocates nothing once warm).
#[derive(Debug, Clone, Default)]
pub(super) struct RayScratch {
    /// The uniform state a line heads for.
    target: Vec<f64>,
    /// The line's tested states, in bisection order.
    states: Vec<f64>,
    /// States of the last free line still to be returned, the next one last.
    pub(super) chain: Vec<f64>,
}
