//! [`PathSimplifier`]: vertex reduction, random shortcuts and smoothing of a path,
//! time-bounded.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use super::path_smoothing::{PathSmoothing, SmoothingMoves};
use super::simplification_run::{SimplificationRun, last_round, length};
use crate::BuildError;

/// Smoothing sweeps per smoothing round, before its shortcuts.
const SWEEPS_PER_ROUND: usize = 5;

/// Mixed into the seed of the stage of per-joint shortcuts that follows the whole ones in
/// [`PathSimplifier::simplify_in_stages`], so it does not repeat their draws.
const PARTIAL_STAGE_SEED: u64 = 0x6a09_e667_f3bc_c908;

/// Makes a valid path shorter, keeping its ends: OMPL's `PathSimplifier` steps (vertex
/// reduction, random shortcuts between points anywhere on the path and per-coordinate
/// shortcuts), then smoothing rounds that move interior states off the path where that
/// shortens it, each followed by shortcuts again
/// ([`smoothing_rounds`](Self::smoothing_rounds)), and vertex reduction of the corners left,
/// with every edge it adds checked on the problem's grid and certified as the problem asks
/// (for arms, every configuration of the edge proven collision-free), so the path stays as
/// valid as a planner's. The shortcuts stop after `attempts` in a row fail or would gain less
/// than 10⁻⁴ of the path's length (those are not checked), the smoothing rounds when one gains
/// less than that; everything
/// stops when the stop fires, which is polled before every edge check and inside it.
///
/// # Arguments
/// A problem (its space, validity checker, check step and certification), a path of at least
/// two states that starts and ends where the caller wants, and a [`Stop`].
///
/// # Returns
/// [`Simplified`]: the shorter path (never longer than the given one), its cost and what the
/// simplification did.
///
/// # Complexity
/// Vertex reduction checks `O(n²)` edges for `n` states in the worst case (usually `O(n)`);
/// each shortcut attempt checks one edge, each smoothing move of a state at most two (a
/// sweep at most six per interior state with the default [`SmoothingMoves`]).
///
/// ```
/// use mit_star::{FirstSolution, PathSimplifier, Planner, RrtConnect, TerminationExt, TimeLimit};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = RrtConnect::for_problem(&problem, &mit_star::Parameters::default())?;
/// let outcome = planner.solve(&FirstSolution.or(TimeLimit::seconds(5.0)))?;
/// let path: Vec<Vec<f64>> = outcome.solution().unwrap().path.iter().map(<[f64]>::to_vec).collect();
/// let simplified = PathSimplifier::new()
///     .seed(1)
///     .simplify(&problem, &path, &mit_star_spaces::Deadline::after(std::time::Duration::from_millis(100)))?;
/// assert!(simplified.cost <= simplified.original_cost);
/// assert_eq!(simplified.path.first(), path.first());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct PathSimplifier {
    seed: u64,
    attempts: usize,
    partial: bool,
    smoothing_rounds: usize,
    smoothing_moves: SmoothingMoves,
}

impl Default for PathSimplifier {
    fn default() -> Self {
        Self::new()
    }
}

/// What [`PathSimplifier::simplify`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct Simplified {
    /// The simplified path, from the given path's first state to its last.
    pub path: Vec<Vec<f64>>,
    /// Its length in the problem's space.
    pub cost: f64,
    /// The given path's length.
    pub original_cost: f64,
    /// States removed by vertex reduction (before the shortcuts, and of the corners they
    /// added after).
    pub vertices_removed: u64,
    /// Shortcuts taken.
    pub shortcuts: u64,
    /// Per-coordinate shortcuts taken.
    pub partial_shortcuts: u64,
    /// Interior states moved by the smoothing pass.
    pub smoothing_moves: u64,
    /// Edges checked (each also certified when the problem asks).
    pub edges_checked: u64,
    /// `true` if the stop ended it (else the attempts ran out).
    pub stopped: bool,
}

impl Simplified {
    /// The simplified path as a planner's [`Solution`](crate::Solution) in a space of
    /// `dimension` coordinates.
    pub fn solution(&self, dimension: usize) -> crate::Solution {
        let mut path = mit_star_spaces::States::with_capacity(dimension, self.path.len());
        for state in &self.path {
            path.push(state);
        }
        crate::Solution {
            path,
            cost: self.cost,
        }
    }
}

impl PathSimplifier {
    /// The smoothing rounds of [`new`](Self::new) (and of `simplify_smoothing`).
    pub const DEFAULT_SMOOTHING_ROUNDS: usize = 10;

    /// A simplifier with seed 0, partial shortcuts on, that gives up after 100 failed
    /// shortcuts in a row, then smooths for up to
    /// [`DEFAULT_SMOOTHING_ROUNDS`](Self::DEFAULT_SMOOTHING_ROUNDS) rounds.
    pub fn new() -> Self {
        Self {
            seed: 0,
            attempts: 100,
            partial: true,
            smoothing_rounds: Self::DEFAULT_SMOOTHING_ROUNDS,
            smoothing_moves: SmoothingMoves::default(),
        }
    }

    /// How many smoothing rounds follow the shortcuts (0: none). A round is up to five sweeps
    /// over the path's interior states, each state moved by the first of its
    /// [`SmoothingMoves`] that shortens the path and whose two new edges pass the check and
    /// certification (the sweeps end early when one gains less than 10⁻⁴ of the path's
    /// length), then shortcuts again, which the moved states open up; the rounds end when one
    /// gains less than 10⁻⁴ of the path's length, or moves nothing. Shortcuts only ever put
    /// new states on the path; smoothing moves states off it, which is what shortens a path
    /// that bends around an obstacle at a corner no shortcut can cut.
    #[must_use]
    pub fn smoothing_rounds(mut self, rounds: usize) -> Self {
        self.smoothing_rounds = rounds;
        self
    }

    /// Which moves the smoothing sweeps try ([`SmoothingMoves::Perturb`] by default).
    #[must_use]
    pub fn smoothing_moves(mut self, moves: SmoothingMoves) -> Self {
        self.smoothing_moves = moves;
        self
    }

    /// Half of the shortcut attempts move one coordinate only (`true`, the default: OMPL's
    /// partial shortcuts, which straighten one joint's motion over a stretch of the path where
    /// the whole configuration cannot shortcut); `false` tries whole shortcuts only.
    #[must_use]
    pub fn partial_shortcuts(mut self, on: bool) -> Self {
        self.partial = on;
        self
    }

    /// The seed of the random shortcuts.
    #[must_use]
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// How many shortcuts in a row may fail before it stops (0: vertex reduction only).
    #[must_use]
    pub fn attempts(mut self, attempts: usize) -> Self {
        self.attempts = attempts;
        self
    }

    /// Simplifies `path` for `problem` until `stop` fires or the attempts run out.
    ///
    /// # Errors
    /// [`BuildError::Problem`] if the problem refuses its check step; [`BuildError::BadPath`]
    /// for a path of fewer than two states, or with a state of the wrong dimension or not
    /// finite.
    pub fn simplify<P: mit_star_problems::PlanningProblem>(
        &self,
        problem: &P,
        path: &[Vec<f64>],
        stop: &dyn Stop,
    ) -> Result<Simplified, BuildError> {
        let parts = (problem.check_step()?, problem.certification());
        self.simplify_in(problem.space(), problem.validity(), parts, path, stop)
    }

    /// [`simplify`](Self::simplify) with the problem's parts given one by one: its space, its
    /// validity checker, and `(step, certification)` — the check step and how many times finer
    /// edges are certified (1: not at all).
    ///
    /// # Errors
    /// [`BuildError::Validity`] for a step that is not finite and positive;
    /// [`BuildError::BadPath`] as [`simplify`](Self::simplify).
    pub fn simplify_in<S: StateSpace, V: StateValidity>(
        &self,
        space: &S,
        validity: &V,
        checks: (f64, u32),
        path: &[Vec<f64>],
        stop: &dyn Stop,
    ) -> Result<Simplified, BuildError> {
        self.passes(space, validity, checks, path, stop, true)
    }

    /// [`simplify_in`](Self::simplify_in) that hands each stage's path to `report` as soon as
    /// it is ready: the path after shortcuts of whole configurations first, then (with
    /// [`partial_shortcuts`](Self::partial_shortcuts)) after shortcuts of whole
    /// configurations and single coordinates on it, then the path after each smoothing round (each
    /// [`Simplified`] starts from the previous stage's path, so its `original_cost` is that
    /// path's cost). A planner that reports its best path at any time (an anytime planner's
    /// trace) takes the shortcut path while it is smoothed. The rounds end as
    /// [`smoothing_rounds`](Self::smoothing_rounds) describes, or when the stop fires.
    ///
    /// # Returns
    /// The last stage's [`Simplified`], as `simplify_in` would return it (the round seeds
    /// differ, so the path may too).
    ///
    /// # Errors
    /// As [`simplify_in`](Self::simplify_in).
    pub fn simplify_in_stages<S: StateSpace, V: StateValidity>(
        &self,
        space: &S,
        validity: &V,
        checks: (f64, u32),
        path: &[Vec<f64>],
        stop: &dyn Stop,
        report: &mut dyn FnMut(&Simplified),
    ) -> Result<Simplified, BuildError> {
        // Whole shortcuts first (a few milliseconds on an arm), then, if asked, per-joint
        // ones on their result (several times longer), each stage reported when ready.
        let whole = self.clone().partial_shortcuts(false).smoothing_rounds(0);
        let mut current = whole.simplify_in(space, validity, checks, path, stop)?;
        report(&current);
        if self.partial && !current.stopped {
            let partial = self
                .clone()
                .seed(self.seed ^ PARTIAL_STAGE_SEED)
                .smoothing_rounds(0);
            let shortened = partial.simplify_in(space, validity, checks, &current.path, stop)?;
            report(&shortened);
            current = shortened;
        }
        for round in 0..self.smoothing_rounds {
            if current.stopped {
                break;
            }
            let one = self
                .clone()
                .seed(self.seed.wrapping_add(round as u64 + 1))
                .smoothing_rounds(1);
            let smoothed = one.smooth_in(space, validity, checks, &current.path, stop)?;
            report(&smoothed);
            let done = last_round(smoothed.smoothing_moves, current.cost, smoothed.cost);
            current = smoothed;
            if done {
                break;
            }
        }
        Ok(current)
    }

    /// The smoothing rounds alone (each followed by shortcuts, as in
    /// [`simplify`](Self::simplify)), then vertex reduction: for a path already simplified,
    /// so that its shortcut result can be used while it is smoothed. With no smoothing rounds
    /// it is vertex reduction only.
    ///
    /// # Arguments
    /// As [`simplify`](Self::simplify).
    ///
    /// # Returns
    /// [`Simplified`], its path never longer than `path`.
    ///
    /// # Errors
    /// As [`simplify`](Self::simplify).
    ///
    /// # Complexity
    /// At most six edge checks per interior state and sweep (with the default
    /// [`SmoothingMoves`]), five sweeps and the shortcuts' attempts per round.
    ///
    /// ```
    /// use mit_star::PathSimplifier;
    /// use mit_star_validity::{AxisBox, World};
    /// // A wall from the floor to y = 0.85, and a path high above it.
    /// let mut world = World::new(vec![0.0, 0.0], vec![1.0, 1.0]);
    /// world.add_obstacle(AxisBox::new(vec![0.5, 0.425], vec![0.002, 0.85]))?;
    /// let problem = mit_star_problems::Problem::new("wall", world, vec![0.2, 0.2], vec![vec![0.8, 0.2]])?
    ///     .with_resolution(1e-4)?;
    /// let path = vec![vec![0.2, 0.2], vec![0.45, 0.9], vec![0.55, 0.9], vec![0.8, 0.2]];
    /// let smoothed = PathSimplifier::new().smooth(&problem, &path, &mit_star_spaces::Never)?;
    /// assert!(smoothed.smoothing_moves > 0 && smoothed.cost < smoothed.original_cost);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn smooth<P: mit_star_problems::PlanningProblem>(
        &self,
        problem: &P,
        path: &[Vec<f64>],
        stop: &dyn Stop,
    ) -> Result<Simplified, BuildError> {
        let parts = (problem.check_step()?, problem.certification());
        self.smooth_in(problem.space(), problem.validity(), parts, path, stop)
    }

    /// [`smooth`](Self::smooth) with the problem's parts given one by one, as
    /// [`simplify_in`](Self::simplify_in).
    ///
    /// # Errors
    /// As [`simplify_in`](Self::simplify_in).
    pub fn smooth_in<S: StateSpace, V: StateValidity>(
        &self,
        space: &S,
        validity: &V,
        checks: (f64, u32),
        path: &[Vec<f64>],
        stop: &dyn Stop,
    ) -> Result<Simplified, BuildError> {
        self.passes(space, validity, checks, path, stop, false)
    }

    /// Vertex reduction and shortcuts (when `shortcut_first`), the smoothing rounds, vertex
    /// reduction.
    fn passes<S: StateSpace, V: StateValidity>(
        &self,
        space: &S,
        validity: &V,
        checks: (f64, u32),
        path: &[Vec<f64>],
        stop: &dyn Stop,
        shortcut_first: bool,
    ) -> Result<Simplified, BuildError> {
        let mut run = SimplificationRun::new((space, validity), checks, stop, self.seed)?;
        crate::path_check::check_states(space, path)?;
        let original_cost = length(space, path);
        let mut states = path.to_vec();
        let before = states.len();
        let mut stopped = shortcut_first
            && !(run.reduce(&mut states)
                && run.shortcuts(&mut states, self.attempts, self.partial));
        let mut smoothing_moves = 0;
        if !stopped {
            (smoothing_moves, stopped) = self.smoothing(&mut run, &mut states);
        }
        // The corners left, reduced again.
        stopped = stopped || !run.reduce(&mut states);
        let added = before + 2 * run.shortcuts as usize;
        let cost = length(space, &states);
        Ok(Simplified {
            vertices_removed: (added - states.len()) as u64,
            path: states,
            cost,
            original_cost,
            shortcuts: run.shortcuts,
            partial_shortcuts: run.partial_shortcuts,
            smoothing_moves,
            edges_checked: run.checked,
            stopped,
        })
    }

    /// The smoothing rounds: sweeps of smoothing moves, then shortcuts, until a round gains
    /// less than 10⁻⁴ of the path's length. The moves taken, and `true` if the stop fired.
    fn smoothing<S: StateSpace, V: StateValidity>(
        &self,
        run: &mut SimplificationRun<'_, S, V>,
        states: &mut Vec<Vec<f64>>,
    ) -> (u64, bool) {
        let mut smoothing = PathSmoothing::new(self.smoothing_moves, run.space.dimension());
        let mut moves = 0;
        for _ in 0..self.smoothing_rounds {
            let total = length(run.space, states);
            let smoothed = smoothing.smooth(run, states, SWEEPS_PER_ROUND);
            moves += smoothed.moves;
            if smoothed.stopped || !run.shortcuts(states, self.attempts, self.partial) {
                return (moves, true);
            }
            if last_round(smoothed.moves, total, length(run.space, states)) {
                break;
            }
        }
        (moves, false)
    }
}
