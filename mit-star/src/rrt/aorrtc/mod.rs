//! [`Aorrtc`]: AORRTC (Wilson, Thomason, Kingston and Gammell, 2025) — RRT-Connect made almost
//! surely asymptotically optimal by repeated cost-bounded searches.

mod search;
#[cfg(test)]
mod tests;

use mit_star_samplers::{InformedSampler, Sampler};
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{SeededRng, StateSpace, States};
use mit_star_validity::{Counted, DenseChecker, EdgeChecker, StateValidity};

use crate::rrt::rrt_core::{RrtCore, problem_parts};
use crate::simplification::IdlePolish;
use crate::termination::SolveStop;
use crate::{
    BuildError, Counters, Outcome, PathSimplifier, Planner, PlannerError, Progress, RrtConnect,
    Snapshot, Termination, Trace,
};
use search::{AoxTrees, Found};

/// A search whose trees hold this many states without finding a cheaper path starts afresh
/// under the same bound (VAMP's AORRTC caps a search at 100 000 samples and iterations): the
/// cost of an iteration stays bounded once the best path is near the optimum, where searches
/// seldom succeed.
const MAX_SEARCH_STATES: usize = 10_000;

/// AORRTC (Wilson et al., "AORRTC: Almost-surely asymptotically optimal planning with
/// RRT-Connect", 2025): [`RrtConnect`] finds a first solution; then, again and again, a fresh
/// pair of trees searches for a path cheaper than the best one, and every path found becomes the
/// new bound.
///
/// Each search is the AO-x meta-algorithm applied to RRT-Connect: samples are drawn from the
/// informed set of the best cost `c` (direct informed sampling), each with a cost bound drawn
/// uniformly between the least cost a path through it could have to come (its distance to the
/// tree's root) and what `c` leaves after the distance to the other tree's root. The tree grows
/// from the nearest state whose cost-to-come plus distance stays within that bound — among the
/// 32 nearest states closer than the root, else the root — by at most [`range`](Self::range)
/// (VAMP's AORRTC looks through every state closer than the root, at a cost linear in the tree
/// per query); the new state then seeks cheaper parents under
/// redrawn bounds (`aorrtc_resamples`). The other tree is joined, step by step, from the new
/// state to its nearest state that keeps the path under `c`. A path found is certified, then
/// shortened by a [`PathSimplifier`] (`aorrtc_simplify`: shortcuts, then smoothing rounds
/// if `simplify_smoothing` is on and `polish_when_idle` off — the polishes smooth otherwise —
/// each stage a point of the trace), and the next search
/// starts under its cost. A search whose trees reach 10 000 states without success starts
/// afresh under the same bound. While the searches find nothing cheaper, the best path is
/// polished from time to time (`polish_when_idle`, on by default; not in AORRTC's paper: per-joint
/// shortcuts and random perturbations, for at most about one edge check per idle iteration).
/// The searches stop when the best cost reaches the straight-line lower bound.
///
/// RRT-Connect's switches (`rrt_dynamic_domain`, `rrt_balance`, `rrt_forced_redraws`,
/// `rrt_halton`, `rrt_halton_shift`, `rrt_valid_samples`) apply to the first search, and the
/// first two to the cost-bounded ones (where a tree that balancing forces to grow steps
/// towards every draw). Certification follows RRT-Connect: only the edges of a path found are
/// certified, and the simplifier certifies each edge it adds.
///
/// # Arguments
/// A query (space, validity checker, start, goals) and [`Parameters`](crate::Parameters):
/// `resolution`, `range` (as RRT-Connect's), `seed`, `certification`, `aorrtc_simplify`,
/// `simplify_smoothing`, `polish_when_idle`, `aorrtc_resamples`.
///
/// # Returns
/// From [`solve`](Planner::solve): the best path so far; the trace has a point for every
/// improvement (the path as found, then simplified). Later calls go on improving it.
///
/// # Complexity
/// Per iteration: one informed draw, two or three radius queries in trees that each search
/// restarts (small: a search ends at its first path), one motion check of at most
/// `range / step` states and the join's steps.
///
/// ```
/// use mit_star::{Aorrtc, Parameters, Planner, TimeLimit};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = Aorrtc::for_problem(&problem, &Parameters::default())?;
/// let outcome = planner.solve(&TimeLimit::seconds(0.2))?;
/// // It keeps improving after the first solution.
/// assert!(planner.trace().len() > 1);
/// assert!(outcome.cost() < planner.trace().points()[0].cost);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Aorrtc<S, V, E = DenseChecker> {
    /// The first search, and the owner of the parts, the solution and the records.
    connect: RrtConnect<S, V, E>,
    /// Informed samples for the cost-bounded searches.
    informed: InformedSampler,
    /// The informed sampler as built, restored by `clear`.
    initial_informed: InformedSampler,
    /// The cost bounds drawn per sample.
    rng: SeededRng,
    search: AoxTrees,
    simplifier: PathSimplifier,
    /// The straight-line lower bound of any solution.
    minimum: f64,
    /// Scratch: the two ends of a join.
    ends: (Vec<f64>, Vec<f64>),
    /// Cost-bounded searches started, and paths simplified.
    searches: u64,
    simplified: u64,
    /// When the best path is polished.
    polish: IdlePolish,
    /// Search iterations since the best cost last fell or the last polish.
    idle: u64,
}

impl<S, V, E> Aorrtc<S, V, E>
where
    S: StateSpace,
    V: StateValidity,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    /// A planner for the query with ready-made checker `checker` and `parameters` (validated
    /// here, as RRT-Connect's).
    ///
    /// # Errors
    /// [`BuildError::Parameter`] for a parameter out of range, [`BuildError::Query`] for a
    /// malformed query, [`BuildError::Sampler`] if the informed set cannot be built.
    pub fn with_checker(
        space: S,
        validity: V,
        query: (Vec<f64>, Vec<Vec<f64>>),
        checker: E,
        parameters: crate::Parameters,
    ) -> Result<Self, BuildError> {
        let (seed, smoothing) = (parameters.seed, Self::smooths_solutions(&parameters));
        let n = space.dimension();
        let (start, goals) = (&query.0, &query.1);
        let informed = InformedSampler::new(&space, start, goals, seed)?;
        let minimum = goals
            .iter()
            .map(|g| space.distance(start, g))
            .fold(f64::INFINITY, f64::min);
        let mut connect = RrtConnect::with_checker(space, validity, query, checker, parameters)?;
        connect.set_name("AORRTC");
        Ok(Self {
            connect,
            initial_informed: informed.clone(),
            informed,
            rng: SeededRng::seed_from_u64(seed ^ 0x5eed_a0cc_2025),
            search: AoxTrees::new(n),
            simplifier: Self::default_simplifier(seed, smoothing),
            minimum,
            ends: (vec![0.0; n], vec![0.0; n]),
            searches: 0,
            simplified: 0,
            polish: IdlePolish::new(seed),
            idle: 0,
        })
    }

    /// Whether the simplification of each new solution ends with smoothing rounds: with
    /// `simplify_smoothing` on and `polish_when_idle` off. With the polishes on (the default),
    /// smoothing is left to them: on the Panda's cage problems, smoothing every new path kept
    /// the cost at 10 ms at a median of 7.0 over 100 runs (20 problems, 5 seeds), against 5.8
    /// without it, for the same cost at 100 ms (`robot/examples/anytime_arm.rs … seed=K`, this
    /// rule's commit against the one before it; the guide's page "Arm planning beside VAMP",
    /// "Repeated runs").
    pub fn smooths_solutions(parameters: &crate::Parameters) -> bool {
        parameters.simplify_smoothing && !parameters.polish_when_idle
    }

    /// The simplifier AORRTC uses unless [`set_simplifier`](Self::set_simplifier) replaces it,
    /// after its authors' (VAMP's shortcuts, then up to five rounds of B-spline steps): whole
    /// shortcuts only, ending after 30 failures in a row, then, if `smoothing`
    /// ([`smooths_solutions`](Self::smooths_solutions)), up to five smoothing rounds of
    /// [`SmoothingMoves::Relax`](crate::SmoothingMoves::Relax) moves. Per-joint shortcuts
    /// make the shortcuts of a first RRT-Connect path on the Panda take 1.7–13 ms instead of
    /// 0.6–2.5 ms (`robot/examples/simplify_paths.rs … smooth=0`, with and without `whole`),
    /// for paths the following searches shorten anyway; the polishes
    /// (`polish_when_idle`) use them. The smoothing moves were chosen on the Panda's
    /// seven MotionBenchMaker scenes (`robot/examples/anytime_arm.rs`, `aorrtc_moves=`):
    /// relaxing towards the neighbours' midpoint keeps the cost at 10 ms where random
    /// perturbations raise it; after 100 ms the choice, smoothing or none, moves the median
    /// cost by 0.3 % at most.
    pub fn default_simplifier(seed: u64, smoothing: bool) -> PathSimplifier {
        PathSimplifier::new()
            .seed(seed)
            .partial_shortcuts(false)
            .attempts(30)
            .smoothing_rounds(if smoothing { 5 } else { 0 })
            .smoothing_moves(crate::SmoothingMoves::Relax)
    }

    /// Replaces the simplifier of each solution (`aorrtc_simplify` still turns it off).
    pub fn set_simplifier(&mut self, simplifier: PathSimplifier) {
        self.simplifier = simplifier;
    }

    /// The maximum length of one extension.
    pub fn range(&self) -> f64 {
        self.connect.range()
    }

    /// Sets the name reports print (default `AORRTC`).
    pub fn set_name(&mut self, name: impl Into<String>) {
        self.connect.set_name(name);
    }

    /// Whether the best cost is the straight-line lower bound (nothing left to improve).
    fn is_optimal(&self) -> bool {
        self.best_cost() - self.minimum <= 1e-9 * self.minimum.max(1.0)
    }

    /// Takes `path` if it beats the best solution (RRT-Connect's first path is already
    /// taken: `before` is the best cost before it), then simplifies it (when asked) under a
    /// stop that sees the cost before it, so a first-solution condition still lets it run.
    fn improve(
        &mut self,
        path: States,
        before: f64,
        termination: &dyn Termination,
        stop: &SolveStop<'_>,
    ) {
        let core = &mut self.connect.core;
        core.record(path, stop);
        if !core.parameters.aorrtc_simplify || core.best_cost() >= before {
            return;
        }
        self.simplified += 1;
        let simplifier = self.simplifier.clone();
        self.simplify_best(&simplifier, (before, None), termination, stop);
    }

    /// Polishes the best path after the searches failed to beat it for `budget` iterations
    /// ([`IdlePolish`]): with per-joint shortcuts and random perturbations, which the
    /// simplification of a new path leaves out for speed.
    fn polish(&mut self, budget: u64, termination: &dyn Termination, stop: &SolveStop<'_>) {
        let before = self.best_cost();
        let simplifier = self.polish.next_simplifier();
        self.simplify_best(&simplifier, (before, Some(budget)), termination, stop);
        self.polish.polished(self.best_cost() < before);
    }

    /// Runs `simplifier` on the best path in stages, each stage taken if cheaper, under a stop
    /// that sees the cost `before` and fires after `budget` polls (if any): a count, not a
    /// time, so that runs under an iteration limit repeat.
    fn simplify_best(
        &mut self,
        simplifier: &PathSimplifier,
        (before, budget): (f64, Option<u64>),
        termination: &dyn Termination,
        stop: &SolveStop<'_>,
    ) {
        let core = &mut self.connect.core;
        let Some(best) = &core.solution else {
            return;
        };
        let states: Vec<Vec<f64>> = best.path.iter().map(<[f64]>::to_vec).collect();
        let step = <E as EdgeChecker<S, Counted<V>>>::step(&core.checker);
        let certification = core.certification();
        let started = std::time::Instant::now();
        let elapsed = stop.elapsed();
        let polls = std::cell::Cell::new(0_u64);
        let halt = || {
            polls.set(polls.get() + 1);
            let progress = Progress::new(elapsed + started.elapsed(), 0, before);
            termination.should_terminate(&progress) || budget.is_some_and(|b| polls.get() > b)
        };
        let RrtCore {
            space,
            validity,
            solution,
            trace,
            elapsed,
            ..
        } = core;
        let _ = simplifier.simplify_in_stages(
            space,
            validity,
            (step, certification),
            &states,
            &halt,
            &mut |stage| {
                let best = (&mut *solution, &mut *trace);
                let time = *elapsed + stop.elapsed();
                crate::planner::keep_if_cheaper(best, time, stage.solution(space.dimension()));
            },
        );
    }

    /// One iteration: RRT-Connect's until the first solution, then the cost-bounded search's.
    /// `false` once the best solution is optimal.
    fn iterate(&mut self, termination: &dyn Termination, stop: &SolveStop<'_>) -> bool {
        if self.connect.core.solution.is_none() {
            self.connect.iterate(stop);
            if let Some(solution) = &self.connect.core.solution {
                let path = solution.path.clone();
                self.improve(path, f64::INFINITY, termination, stop);
            }
            return true;
        }
        if self.is_optimal() {
            return false;
        }
        self.connect.core.counters.iterations += 1;
        let best = self.best_cost();
        let p = &self.connect.core.parameters;
        if self.search.bound != best {
            self.idle = 0;
            self.polish.improved();
        } else if p.aorrtc_simplify && p.polish_when_idle {
            self.idle += 1;
            if self.idle >= self.polish.wait() {
                // The searches have not beaten the best path for a while: polish it.
                let budget = std::mem::take(&mut self.idle);
                self.polish(budget, termination, stop);
                if self.best_cost() < best {
                    return true;
                }
            }
        }
        if self.search.bound != best || self.search.size() >= MAX_SEARCH_STATES {
            let core = &self.connect.core;
            self.search.restart(&core.start, &core.goals, best);
            self.searches += 1;
        }
        match self.search_iteration(stop) {
            Found::Nothing => true,
            Found::Optimal => false,
            Found::Path(path) => {
                self.improve(path, best, termination, stop);
                true
            }
        }
    }
}

impl<S, V, E> Planner for Aorrtc<S, V, E>
where
    S: StateSpace,
    V: StateValidity,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    fn name(&self) -> &str {
        self.connect.name()
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let stop = SolveStop::new(termination);
        if !self.connect.setup(&stop) || self.connect.core.record_if_start_is_a_goal(&stop) {
            return Ok(self.connect.core.finish(&stop));
        }
        let mut iterations = 0;
        loop {
            stop.update(iterations, self.best_cost());
            let checks = self.connect.core.validity.count();
            if stop.should_stop_iteration(checks) || !self.iterate(termination, &stop) {
                break;
            }
            iterations += 1;
        }
        Ok(self.connect.core.finish(&stop))
    }

    fn clear(&mut self) {
        self.connect.clear();
        self.informed = self.initial_informed.clone();
        self.rng = SeededRng::seed_from_u64(self.connect.core.parameters.seed ^ 0x5eed_a0cc_2025);
        self.search = AoxTrees::new(self.connect.core.space.dimension());
        self.searches = 0;
        self.simplified = 0;
        self.polish.reset();
        self.idle = 0;
    }

    fn offer_solution(&mut self, solution: &crate::Solution) -> bool {
        self.connect.core.offer(solution)
    }

    fn best_cost(&self) -> f64 {
        self.connect.best_cost()
    }

    fn trace(&self) -> &Trace {
        self.connect.trace()
    }

    fn counters(&self) -> Counters {
        let mut c = self.connect.counters();
        let informed = Sampler::<S, Counted<V>>::counters(&self.informed);
        c.samples_drawn += informed.drawn;
        if self.connect.core.solution.is_some() {
            let states = self.search.trees.iter().map(|t| t.parents.len() as u64);
            c.vertices = states.sum();
            c.edges = c
                .vertices
                .saturating_sub(1 + self.connect.core.goals.len() as u64);
            c.peak_vertices = c.peak_vertices.max(c.vertices);
            c.peak_edges = c.peak_edges.max(c.edges);
        }
        c
    }

    fn settings(&self) -> Vec<(String, String)> {
        self.connect.core.settings(
            crate::Configuration::Aorrtc,
            vec![
                ("searches", self.searches.to_string()),
                ("simplified_solutions", self.simplified.to_string()),
                ("polished_solutions", self.polish.count().to_string()),
            ],
        )
    }

    fn snapshot(&self) -> Option<Snapshot> {
        if self.connect.core.solution.is_none() || self.searches == 0 {
            return self.connect.snapshot();
        }
        Some(crate::rrt::tree::snapshot_of(
            &self.search.trees,
            self.best_cost(),
        ))
    }
}

impl<S: StateSpace, V: StateValidity> Aorrtc<S, V, DenseChecker> {
    /// AORRTC with full checks at `parameters.resolution`
    /// ([`with_checker`](Self::with_checker) and a [`DenseChecker`]).
    ///
    /// # Errors
    /// As [`with_checker`](Self::with_checker), and [`BuildError::Validity`] for a resolution
    /// the checker refuses.
    pub fn new(
        space: S,
        validity: V,
        query: (Vec<f64>, Vec<Vec<f64>>),
        parameters: crate::Parameters,
    ) -> Result<Self, BuildError> {
        let checker = DenseChecker::from_resolution(&space, parameters.resolution)?
            .with_acceleration(parameters.accelerated_checks);
        Self::with_checker(space, validity, query, checker, parameters)
    }
}

impl<S, V> Aorrtc<S, V, DenseChecker>
where
    S: StateSpace + Clone,
    V: StateValidity + Clone,
{
    /// AORRTC for `problem` with `parameters` (the problem's resolution replaces
    /// `parameters.resolution`; its certification applies unless `parameters` sets one).
    ///
    /// # Errors
    /// [`BuildError::Problem`] if the problem refuses its check step, else as
    /// [`new`](Self::new).
    pub fn for_problem<P>(problem: &P, parameters: &crate::Parameters) -> Result<Self, BuildError>
    where
        P: mit_star_problems::PlanningProblem<Space = S, Validity = V>,
    {
        let (space, validity, query, parameters) = problem_parts(problem, parameters)?;
        Self::new(space, validity, query, parameters)
    }
}
