//! [`NearTerminals`]: a wrapper that draws a fraction of the states close to the start and the
//! goals, at every scale.

use mit_star_spaces::{SeededRng, StateSpace, Stop};
use mit_star_validity::StateValidity;
use rand::RngExt;

use crate::sampling_steps::{InformedDraws, MOST_BATCHED};
use crate::{
    CostBound, GaussianStep, LazyPathFailure, SampleError, SampleOrigin, Sampler, SamplerCounters,
    SamplerError,
};
use rays::RayScratch;

/// Wraps any sampler and draws a fraction of the states from Gaussians around the start and the
/// goals, with a standard deviation drawn log-uniformly between two scales.
///
/// Uniform and informed samples cover the space evenly, so a start or goal at the bottom of a
/// narrow pocket (a grasp deep in a shelf slot) is seldom joined: in 7 dimensions the nearest
/// of a million uniform samples is still far away, and every edge that long collides with the
/// pocket's walls. States near the terminals at every scale, from a few check steps to a tenth
/// of the space, give the graph a way out of the pocket, one short edge at a time.
///
/// Per request: with probability `fraction`, pick the start or a goal (half the time the start,
/// else a goal uniformly), draw `σ` log-uniformly from `[smallest, largest]` and a state from
/// `N(terminal, σ² I)` reflected into the bounds (not clamped: no draws pile up on a joint
/// limit). If it is valid and inside the informed set of the effective bound — the planner's
/// bound if it has a cost, else the wrapped sampler's [`estimated_cost`](Sampler::estimated_cost)
/// (MIT*'s estimated informed set, when this wraps [`Estimated`](crate::Estimated)) — return
/// it; otherwise — and with probability `1 − fraction` — the wrapped sampler answers. Each
/// request therefore costs at most one extra draw and one validity check before the wrapped
/// sampler's own work, and the wrapped sampler still covers the whole set, so an
/// asymptotically optimal planner stays so. For a checker that decides states in batches
/// ([`batch_width`](StateValidity::batch_width) above 1, an arm's eight lanes for about the
/// price of one state), the draws near the terminals are made ahead, a batch at a time, and
/// decided in one call; one that tests a state at a time sees the draws and checks one by one,
/// as before (a draw outside the informed set is then not checked at all).
///
/// The connection rules see only the wrapped sampler's density: the r-disc measure is the
/// wrapped sampler's, and the states drawn here, marked [`SampleOrigin::NearTerminal`], are
/// left out of the sample count `q` of `k(q)` and `r(q)`
/// ([`SampleOrigin::counts_toward_density`]; the EIT* family counts its vertices by origin).
/// Counted in, a fraction `f` of clustered states would scale the r-disc radius's effective
/// rewire factor for the wrapped sampler's states by `(1 − f)^(1/n)` — `1.001 · 0.85^(1/7) ≈
/// 0.978 < 1` at `f = 0.15` in 7 dimensions, and less once pruning removes uniform states and
/// keeps the ones near the terminals.
///
/// A planner with a reverse search (MIT*, EIT*, AIT*) also tells the wrapper, at the end of
/// every batch without a solution, which states its search from the goals reached farthest
/// ([`observe_frontier`](Sampler::observe_frontier)). While it has such states, the wrapper
/// centres [`FRONTIER_SHARE`](Self::FRONTIER_SHARE) of its draws on one of them (uniformly)
/// instead of on a terminal, at the same scales: a goal in a pocket is then left one batch at
/// a time, the way RRT-Connect's goal tree grows out of it, where draws around the goal alone
/// keep filling the pocket. Without frontier states (before the first batch, once solved, or
/// for a planner that sends none) the draws are exactly those described above.
///
/// With [`with_frontier_rays`](Self::with_frontier_rays), while it has frontier states, half of
/// its draws first try straight lines from them and take two states of the first line found
/// free, as RRT-Connect's trees extend. Off unless asked for here; the planners' parameters
/// (`frontier_rays` in the `mit-star` crate) ask for it by default.
///
/// Removing the wrapper is the ablation; a fraction of 0 draws nothing and leaves the wrapped
/// sampler's random sequence untouched.
///
/// ```
/// use mit_star_samplers::{CostBound, NearTerminals, SampleOrigin, Sampler, UniformSampler};
/// use mit_star_spaces::{Never, RealVectorSpace, StateSpace, euclidean_distance};
/// use mit_star_validity::World;
///
/// let space = RealVectorSpace::cube(7, 0.0, 10.0)?;
/// let world = World::in_space(&space);
/// let (start, goal) = ([1.0; 7], [9.0; 7]);
/// let mut sampler = NearTerminals::new(UniformSampler::new(3), &space, &start, &[goal], 5)?
///     .with_fraction(0.5)?
///     .with_scales(0.05, 0.5)?;
/// let mut x = [0.0; 7];
/// let mut near = 0;
/// for _ in 0..1000 {
///     Sampler::<_, World>::sample(&mut sampler, &space, &world, CostBound::Unbounded, &Never, &mut x)?;
///     assert!(space.contains(&x));
///     if Sampler::<RealVectorSpace, World>::last_origin(&sampler) == SampleOrigin::NearTerminal {
///         near += 1;
///         // σ ≤ 0.5 in each of 7 coordinates: within 4 of its terminal, bar a 10⁻⁵ chance.
///         assert!(euclidean_distance(&x, &start).min(euclidean_distance(&x, &goal)) < 4.0);
///     }
/// }
/// // Half of the requests, in a world without obstacles.
/// assert!((430..570).contains(&near), "{near}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct NearTerminals<T> {
    inner: T,
    /// The informed set (for the bound), this wrapper's generator and counters.
    draws: InformedDraws,
    /// The start, then the goals, one after the other.
    terminals: Vec<f64>,
    fraction: f64,
    /// `ln σ` of the smallest and the largest scale.
    log_scales: (f64, f64),
    /// Whether the last state returned came from here.
    drew_last: bool,
    /// The planner's frontier states, one after the other (empty: none).
    frontier: Vec<f64>,
    /// What each candidate drawn ahead was centred on, in the order of its batch's draws
    /// (`None`: no candidate).
    centres: [Option<Centre>; MOST_BATCHED],
    /// States returned from near a frontier state.
    frontier_returned: u64,
    /// Whether frontier draws go along free lines first ([`with_frontier_rays`](Self::with_frontier_rays)).
    rays: bool,
    /// The line draws' scratch and the states of the last free line.
    ray: RayScratch,
}

impl<T> NearTerminals<T> {
    /// Default fraction of requests answered near a terminal.
    pub const DEFAULT_FRACTION: f64 = 0.15;
    /// Default smallest and largest `σ`, as fractions of the space's maximum extent (0.13 and
    /// 1.3 rad for the Panda). Chosen on the Panda problems MIT* failed without the wrapper
    /// (`docs/guide/src/reference/arm-planning.md`): a smallest `σ` of 0.001–0.002 wasted draws at the terminals.
    pub const DEFAULT_SCALES: (f64, f64) = (0.01, 0.1);
    /// Share of the draws centred on a frontier state while the planner has sent some (the
    /// rest stay centred on the terminals, which they must still join).
    /// A constant, not tuned by any shipped measurement.
    pub const FRONTIER_SHARE: f64 = 0.5;

    /// `inner` with states near `start` and `goals` in `space`, seeded with `seed` (its own
    /// generator; `inner` keeps its own), at the default fraction and scales.
    ///
    /// # Errors
    /// As [`InformedSet::new`](crate::InformedSet::new), and [`SamplerError::NotPositive`] if the
    /// space's extent is not finite and positive.
    pub fn new<S, G>(
        inner: T,
        space: &S,
        start: &[f64],
        goals: &[G],
        seed: u64,
    ) -> Result<Self, SamplerError>
    where
        S: StateSpace + ?Sized,
        G: AsRef<[f64]>,
    {
        let draws = InformedDraws::new(space, start, goals, mixed(seed))?;
        let terminals = std::iter::once(start)
            .chain(goals.iter().map(AsRef::as_ref))
            .flatten()
            .copied()
            .collect();
        let extent = space.maximum_extent();
        let (small, large) = Self::DEFAULT_SCALES;
        Self {
            inner,
            draws,
            terminals,
            fraction: Self::DEFAULT_FRACTION,
            log_scales: (0.0, 0.0),
            drew_last: false,
            frontier: Vec::new(),
            centres: [None; MOST_BATCHED],
            frontier_returned: 0,
            rays: false,
            ray: RayScratch::default(),
        }
        .with_scales(small * extent, large * extent)
    }

    /// Sets the fraction of requests answered near a terminal.
    ///
    /// # Errors
    /// [`SamplerError::Fraction`] unless `0 ≤ fraction < 1`.
    pub fn with_fraction(mut self, fraction: f64) -> Result<Self, SamplerError> {
        if !(0.0..1.0).contains(&fraction) {
            return Err(SamplerError::Fraction {
                name: "fraction of states near the terminals",
                value: fraction,
            });
        }
        self.fraction = fraction;
        Ok(self)
    }

    /// Sets the smallest and the largest standard deviation `σ`.
    ///
    /// # Errors
    /// [`SamplerError::NotPositive`] if either is not finite and positive, or the largest is
    /// below the smallest.
    pub fn with_scales(mut self, smallest: f64, largest: f64) -> Result<Self, SamplerError> {
        GaussianStep::new(smallest)?;
        GaussianStep::new(largest - smallest + f64::MIN_POSITIVE).map_err(|_| {
            SamplerError::NotPositive {
                name: "largest σ minus the smallest",
                value: largest - smallest,
            }
        })?;
        self.log_scales = (smallest.ln(), largest.ln());
        Ok(self)
    }

    /// Makes half of the draws, while there are frontier states, go along straight lines
    /// (`true`; `false`, the default, keeps every draw Gaussian): such a draw first tries up to
    /// [`RAY_TRIES`](Self::RAY_TRIES) lines from frontier states towards uniform states, each
    /// as long as the largest scale, and returns the midpoint, then the far end, of the first
    /// line found free at [`RAY_POINTS`](Self::RAY_POINTS) tested states (over two requests);
    /// if none is free, it draws as without the setting. Without frontier states nothing
    /// changes, and with `false` the random sequence is exactly the one without rays.
    ///
    /// What it buys: a goal deep in a pocket (the Fetch's shelf grasps) is left along the
    /// few directions that stay free for a full step, as RRT-Connect's goal tree leaves it,
    /// where Gaussian draws around the frontier keep landing against the pocket's walls.
    /// Measured in `docs/guide/src/your-own-robot.md`.
    pub fn with_frontier_rays(mut self, rays: bool) -> Self {
        self.rays = rays;
        self
    }

    /// The fraction of requests answered near a terminal.
    pub fn fraction(&self) -> f64 {
        self.fraction
    }

    /// The wrapped sampler.
    pub fn inner(&self) -> &T {
        &self.inner
    }
}

/// Draws one candidate near a terminal (`terminals`, one after the other) or a frontier state
/// (`frontier`, likewise) into `out` with `rng`, at a scale `σ` with `ln σ` uniform in
/// `log_scales`, and says which; `None` if it could not (a scale that rounds to no valid `σ`,
/// which the checks in [`NearTerminals::with_scales`] rule out).
fn draw_near<S: StateSpace + ?Sized>(
    (terminals, frontier, log_scales): (&[f64], &[f64], (f64, f64)),
    space: &S,
    rng: &mut SeededRng,
    out: &mut [f64],
) -> Option<Centre> {
    let n = out.len();
    let count = terminals.len() / n;
    let index = if count == 1 || rng.random_bool(0.5) {
        0
    } else {
        rng.random_range(1..count)
    };
    let (low, high) = log_scales;
    let sigma = if high > low {
        rng.random_range(low..high).exp()
    } else {
        low.exp()
    };
    // No draw for the choice without frontier states: the sequence stays the one of a
    // wrapper that never heard of them.
    let states = frontier.len() / n;
    let (centre, around) = if states > 0 && rng.random_bool(NearTerminals::<()>::FRONTIER_SHARE) {
        let k = rng.random_range(0..states);
        (Centre::Frontier, &frontier[k * n..(k + 1) * n])
    } else {
        (Centre::Terminal, &terminals[index * n..(index + 1) * n])
    };
    let step = GaussianStep::new(sigma).ok()?.reflecting();
    step.perturb(space, rng, around, out);
    Some(centre)
}

impl<T> NearTerminals<T> {
    /// Writes the next state left from the last free line into `out` and returns `true`, if
    /// one lies in the informed set of `cost` (those outside are dropped, counted as
    /// rejected).
    fn pop_ray<S: StateSpace + ?Sized>(
        &mut self,
        space: &S,
        cost: Option<f64>,
        out: &mut [f64],
    ) -> bool {
        let n = out.len();
        while self.ray.chain.len() >= n && n > 0 {
            let at = self.ray.chain.len() - n;
            out.copy_from_slice(&self.ray.chain[at..]);
            self.ray.chain.truncate(at);
            if self.draws.set.contains(space, cost, out) {
                return true;
            }
            self.draws.reject();
        }
        false
    }
}

/// What a draw of [`NearTerminals`] was centred on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Centre {
    /// The start or a goal.
    Terminal,
    /// A state of the planner's frontier.
    Frontier,
}

/// The wrapper's seed, decorrelated from the wrapped sampler's (which gets `seed` itself).
fn mixed(seed: u64) -> u64 {
    seed ^ 0xd1b5_4a32_d192_ed03
}

impl<S, V, T> Sampler<S, V> for NearTerminals<T>
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
    T: Sampler<S, V>,
{
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        self.drew_last = false;
        if self.fraction > 0.0 && self.draws.rng().random_bool(self.fraction) {
            if stop.should_stop() {
                return Err(SampleError::Stopped);
            }
            let expected = self.draws.set.dimension();
            if out.len() != expected || space.dimension() != expected {
                let got = if out.len() == expected {
                    space.dimension()
                } else {
                    out.len()
                };
                return Err(SampleError::DimensionMismatch { expected, got });
            }
            // Before a solution, the wrapped sampler's estimate bounds its draws (an estimate
            // whose set is empty is no bound, as `Estimated` treats it).
            let minimum = self.draws.set.minimum_cost();
            let cost = bound.cost().or_else(|| {
                self.inner
                    .estimated_cost()
                    .filter(|&estimate| estimate > minimum)
            });
            // The rest of the last free line first, then (with rays, on the frontier's share)
            // a new line.
            let mut lined = self.pop_ray(space, cost, out);
            if !lined
                && self.rays
                && !self.frontier.is_empty()
                && self.draws.rng().random_bool(Self::FRONTIER_SHARE)
                && self.draw_ray(space, validity)
            {
                lined = self.pop_ray(space, cost, out);
            }
            if lined {
                self.drew_last = true;
                self.frontier_returned += 1;
                return self.draws.returned();
            }
            let Self {
                draws,
                terminals,
                frontier,
                log_scales,
                centres,
                ..
            } = self;
            let parts = (terminals.as_slice(), frontier.as_slice(), *log_scales);
            let (centre, inside, valid) = if validity.batch_width() <= 1 {
                // One at a time: checked only inside the informed set, since a draw outside
                // it is turned down anyway.
                let centre = draw_near(parts, space, draws.rng(), out);
                draws.own_counters().drawn += 1;
                let inside = centre.is_some() && draws.set.contains(space, cost, out);
                (centre, inside, inside && draws.check(validity, out))
            } else {
                // Drawn and checked a batch of the checker at a time: a draw's law does not
                // depend on the bound (the informed set is tested when it is handed out), only
                // on the frontier, whose change drops the draws held.
                let mut drawn = 0;
                let valid = draws.next_checked(validity, out, |rng, x| {
                    if let Some(slot) = centres.get_mut(drawn) {
                        *slot = draw_near(parts, space, rng, x);
                    }
                    drawn += 1;
                    Ok(())
                })?;
                let centre = centres.get(draws.last_index()).copied().flatten();
                let inside = centre.is_some() && draws.set.contains(space, cost, out);
                (centre, inside, valid)
            };
            match centre {
                Some(centre) if inside => {
                    if valid {
                        self.drew_last = true;
                        self.frontier_returned += u64::from(centre == Centre::Frontier);
                        return self.draws.returned();
                    }
                }
                _ => self.draws.reject(),
            }
        }
        self.inner.sample(space, validity, bound, stop, out)
    }

    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64 {
        self.inner.sampled_measure(space, bound)
    }

    fn reseed(&mut self, seed: u64) {
        self.inner.reseed(seed);
        self.draws.reseed(mixed(seed));
        self.drew_last = false;
        self.frontier.clear();
        self.frontier_returned = 0;
        self.ray.chain.clear();
    }

    fn counters(&self) -> SamplerCounters {
        let inner = self.inner.counters();
        let own = self.draws.own();
        SamplerCounters {
            returned: inner.returned + own.returned,
            drawn: inner.drawn + own.drawn,
            rejected: inner.rejected + own.rejected,
            validity_checks: inner.validity_checks + own.validity_checks,
            near_terminals: own.returned,
            near_frontier: self.frontier_returned,
            ..inner
        }
    }

    fn observe_invalid_lazy_edge(&mut self, failure: LazyPathFailure) {
        self.inner.observe_invalid_lazy_edge(failure);
    }

    fn observe_batch_end(&mut self, solved: bool) {
        self.inner.observe_batch_end(solved);
    }

    /// Keeps `states` as the frontier the draws may centre on (replacing the last ones), and
    /// passes them on.
    fn observe_frontier(&mut self, states: &[f64]) {
        let n = self.draws.set.dimension();
        let whole = states.len() / n.max(1) * n;
        self.frontier.clear();
        self.frontier.extend_from_slice(&states[..whole]);
        // Candidates drawn ahead around the old frontier are dropped.
        self.draws.clear_ahead();
        self.inner.observe_frontier(states);
    }

    fn wants_batch(&self) -> bool {
        self.inner.wants_batch()
    }

    fn estimated_cost(&self) -> Option<f64> {
        self.inner.estimated_cost()
    }

    fn last_origin(&self) -> SampleOrigin {
        if self.drew_last {
            SampleOrigin::NearTerminal
        } else {
            self.inner.last_origin()
        }
    }
}

mod rays;

#[cfg(test)]
mod tests;
