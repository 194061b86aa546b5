//! [`PathSimplifier`]: vertex reduction and random shortcuts of a path, time-bounded.

use spaces::rand::{RngExt, SeedableRng};
use spaces::{SeededRng, StateSpace, Stop};
use validity::{DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::BuildError;

/// Makes a valid path shorter, keeping its ends: OMPL's `PathSimplifier` steps (vertex
/// reduction, random shortcuts between points anywhere on the path and per-coordinate
/// shortcuts, vertex reduction of the corners they leave), with every edge it
/// adds checked on the problem's grid and certified as the problem asks (for arms, every
/// configuration of the edge proven collision-free), so the path stays as valid as a
/// planner's. Stops when the stop fires or after `attempts` shortcuts in a row fail or gain
/// less than 10⁻⁴ of the path's length; polls the stop before every edge check and inside it.
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
/// each shortcut attempt checks one edge.
///
/// ```
/// use mit_star::{FirstSolution, PathSimplifier, Planner, RrtConnect, TerminationExt, TimeLimit};
/// let problem = problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = RrtConnect::for_problem(&problem, &mit_star::Parameters::default())?;
/// let outcome = planner.solve(&FirstSolution.or(TimeLimit::seconds(5.0)))?;
/// let path: Vec<Vec<f64>> = outcome.solution().unwrap().path.iter().map(<[f64]>::to_vec).collect();
/// let simplified = PathSimplifier::new()
///     .seed(1)
///     .simplify(&problem, &path, &spaces::Deadline::after(std::time::Duration::from_millis(100)))?;
/// assert!(simplified.cost <= simplified.original_cost);
/// assert_eq!(simplified.path.first(), path.first());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct PathSimplifier {
    seed: u64,
    attempts: usize,
    partial: bool,
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
    /// Edges checked (each also certified when the problem asks).
    pub edges_checked: u64,
    /// `true` if the stop ended it (else the attempts ran out).
    pub stopped: bool,
}

impl PathSimplifier {
    /// A simplifier with seed 0, partial shortcuts on, that gives up after 100 failed
    /// shortcuts in a row.
    pub fn new() -> Self {
        Self {
            seed: 0,
            attempts: 100,
            partial: true,
        }
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
    pub fn simplify<P: problems::PlanningProblem>(
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
        (step, certification): (f64, u32),
        path: &[Vec<f64>],
        stop: &dyn Stop,
    ) -> Result<Simplified, BuildError> {
        let checker = DenseChecker::new(step)?;
        let dimension = space.dimension();
        crate::path_check::check_states(space, path)?;
        let mut run = Run {
            space,
            validity,
            checker,
            certification,
            stop,
            checked: 0,
        };
        let original_cost = length(space, path);
        let mut states = path.to_vec();
        let before = states.len();
        let mut stopped = !run.reduce(&mut states);
        // Random shortcuts between two points on different edges.
        let mut rng = SeededRng::seed_from_u64(self.seed);
        let (mut failures, mut shortcuts) = (0, 0);
        let mut a = vec![0.0; dimension];
        let mut b = vec![0.0; dimension];
        let mut partial = 0;
        let mut lengths = Vec::with_capacity(states.len());
        while !stopped && failures < self.attempts && states.len() >= 3 {
            lengths.clear();
            lengths.extend(states.windows(2).map(|w| space.distance(&w[0], &w[1])));
            let total: f64 = lengths.iter().sum();
            // A shortcut that gains less than this is taken but counts as a failure: the
            // search ends when shortcuts stop paying.
            let negligible = 1e-4 * total;
            if self.partial && rng.random::<bool>() {
                match run.partial_shortcut(&mut states, &lengths, &mut rng) {
                    Some((EdgeStatus::Valid, gain)) => {
                        partial += 1;
                        failures = if gain < negligible { failures + 1 } else { 0 };
                    }
                    Some((EdgeStatus::Unknown, _)) => stopped = true,
                    Some((EdgeStatus::Invalid, _)) | None => failures += 1,
                }
                continue;
            }
            let (mut s, mut t) = (rng.random::<f64>() * total, rng.random::<f64>() * total);
            if s > t {
                std::mem::swap(&mut s, &mut t);
            }
            let (ea, fa) = locate(&lengths, s);
            let (eb, fb) = locate(&lengths, t);
            if ea == eb {
                failures += 1;
                continue;
            }
            space.interpolate(&states[ea], &states[ea + 1], fa, &mut a);
            space.interpolate(&states[eb], &states[eb + 1], fb, &mut b);
            let direct = space.distance(&a, &b);
            let along = (lengths[ea] * (1.0 - fa))
                + lengths[ea + 1..eb].iter().sum::<f64>()
                + lengths[eb] * fb;
            if direct >= along * (1.0 - 1e-9) {
                failures += 1;
                continue;
            }
            match run.edge(&a, &b) {
                EdgeStatus::Valid => {
                    // The pieces from the edges' starts to `a` and from `b` to their ends are
                    // parts of edges already valid.
                    let tail = states.split_off(eb + 1);
                    states.truncate(ea + 1);
                    states.push(a.clone());
                    states.push(b.clone());
                    states.extend(tail);
                    shortcuts += 1;
                    failures = if along - direct < negligible {
                        failures + 1
                    } else {
                        0
                    };
                }
                EdgeStatus::Invalid => failures += 1,
                EdgeStatus::Unknown => stopped = true,
            }
        }
        // The shortcuts' corners, reduced again.
        stopped = stopped || !run.reduce(&mut states);
        let vertices_removed = (before + 2 * shortcuts as usize - states.len()) as u64;
        let cost = length(space, &states);
        Ok(Simplified {
            path: states,
            cost,
            original_cost,
            vertices_removed,
            shortcuts,
            partial_shortcuts: partial,
            edges_checked: run.checked,
            stopped,
        })
    }
}

/// The parts an edge check uses.
struct Run<'a, S, V> {
    space: &'a S,
    validity: &'a V,
    checker: DenseChecker,
    certification: u32,
    stop: &'a dyn Stop,
    checked: u64,
}

impl<S: StateSpace, V: StateValidity> Run<'_, S, V> {
    /// Vertex reduction: from each state, joins the farthest later state it reaches directly
    /// and drops the states between. `false` if the stop fired.
    fn reduce(&mut self, states: &mut Vec<Vec<f64>>) -> bool {
        let mut i = 0;
        while i + 2 < states.len() {
            for j in (i + 2..states.len()).rev() {
                match self.edge(&states[i], &states[j]) {
                    EdgeStatus::Valid => {
                        states.drain(i + 1..j);
                        break;
                    }
                    EdgeStatus::Unknown => return false,
                    EdgeStatus::Invalid => {}
                }
            }
            i += 1;
        }
        true
    }

    /// Checks `a → b` on the grid, then certifies it.
    fn edge(&mut self, a: &[f64], b: &[f64]) -> EdgeStatus {
        if self.stop.should_stop() {
            return EdgeStatus::Unknown;
        }
        self.checked += 1;
        let mut progress = EdgeProgress::default();
        let (space, validity) = (self.space, self.validity);
        match self
            .checker
            .check_full(space, validity, a, b, &mut progress, self.stop)
        {
            EdgeStatus::Valid => {
                self.checker
                    .certify(space, validity, a, b, self.certification, self.stop)
            }
            other => other,
        }
    }
}

impl<S: StateSpace, V: StateValidity> Run<'_, S, V> {
    /// A per-coordinate shortcut (`lengths`: the path's edge lengths): between two random
    /// states `i < j` of the path, one random coordinate of every state strictly between them
    /// is blended linearly (by arc length) from its value at `i` to its value at `j`; taken if
    /// the stretch gets shorter and all its new edges pass. `None` if it was not shorter (nothing checked), else the first
    /// status that was not `Valid`, or `Valid` when taken, with the length gained.
    fn partial_shortcut(
        &mut self,
        states: &mut [Vec<f64>],
        lengths: &[f64],
        rng: &mut SeededRng,
    ) -> Option<(EdgeStatus, f64)> {
        let n = states.len();
        let i = rng.random_range(0..n - 2);
        let j = rng.random_range(i + 2..n);
        let k = rng.random_range(0..self.space.dimension());
        let pieces = &lengths[i..j];
        let total: f64 = pieces.iter().sum();
        if total <= 0.0 {
            return None;
        }
        let (from, to) = (states[i][k], states[j][k]);
        let mut stretch = states[i..=j].to_vec();
        let mut along = 0.0;
        let inner = stretch.len() - 1;
        for (state, piece) in stretch[1..inner].iter_mut().zip(pieces) {
            along += piece;
            state[k] = from + (to - from) * along / total;
        }
        let shorter = length(self.space, &stretch);
        if shorter >= total * (1.0 - 1e-9) {
            return None;
        }
        for w in stretch.windows(2) {
            let status = self.edge(&w[0], &w[1]);
            if status != EdgeStatus::Valid {
                return Some((status, 0.0));
            }
        }
        states[i..=j].clone_from_slice(&stretch);
        Some((EdgeStatus::Valid, total - shorter))
    }
}

/// The edge holding arc length `s` among edges of `lengths`, and the fraction along it.
fn locate(lengths: &[f64], mut s: f64) -> (usize, f64) {
    for (i, &l) in lengths.iter().enumerate() {
        if s <= l || i + 1 == lengths.len() {
            return (
                i,
                if l > 0.0 {
                    (s / l).clamp(0.0, 1.0)
                } else {
                    0.0
                },
            );
        }
        s -= l;
    }
    (0, 0.0)
}

/// The length of `path` in `space`.
fn length<S: StateSpace>(space: &S, path: &[Vec<f64>]) -> f64 {
    path.windows(2).map(|w| space.distance(&w[0], &w[1])).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arc_lengths_locate_their_edge() {
        assert_eq!(locate(&[1.0, 2.0], 0.5), (0, 0.5));
        assert_eq!(locate(&[1.0, 2.0], 2.0), (1, 0.5));
        assert_eq!(locate(&[1.0, 2.0], 3.5), (1, 1.0));
    }
}
