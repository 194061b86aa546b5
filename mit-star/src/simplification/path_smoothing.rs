//! [`PathSmoothing`]: the smoothing pass of [`PathSimplifier`](super::PathSimplifier) — interior
//! states moved off the path to shorten it where shortcuts stall.

use mit_star_spaces::StateSpace;
use mit_star_spaces::rand::RngExt;
use mit_star_validity::{EdgeStatus, StateValidity};

use super::simplification_run::{NEGLIGIBLE_GAIN, SimplificationRun};

/// A move is tried only if it shortens its two edges by more than this fraction of them
/// (below it, rounding could make a "shorter" move longer).
const MINIMUM_GAIN: f64 = 1e-9;

/// How far a relaxing move goes towards the midpoint of a state's neighbours: half way, then,
/// if that fails its checks, an eighth.
const RELAX_FRACTIONS: [f64; 2] = [0.5, 0.125];

/// The first perturbation of a state is about this fraction of its shorter edge.
const INITIAL_SCALE: f64 = 0.1;

/// A state whose perturbations have shrunk below this fraction of its shorter edge is left
/// where it is.
const SMALLEST_SCALE: f64 = 1e-3;

/// Perturbations tried per state and sweep, until one is taken.
const PERTURBATIONS: usize = 3;

/// Which moves the smoothing pass tries on an interior state, in order, until one is taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SmoothingMoves {
    /// Towards the midpoint of its neighbours (half way, or an eighth of the way if half way
    /// fails: a step of B-spline smoothing, as OMPL's `smoothBSpline` without the
    /// subdivision), then a random perturbation.
    RelaxThenPerturb,
    /// Towards the midpoint of its neighbours only.
    Relax,
    /// A random perturbation only (the default, chosen by measurement on the Panda: it gains
    /// more in the same time): a step in a random direction, or the opposite step, whichever
    /// shortens the path, up to three tries per state and sweep; its size adapts per state
    /// (doubled after a taken move, halved after a refused one).
    #[default]
    Perturb,
}

/// What one smoothing pass did.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Smoothed {
    /// Moves taken.
    pub moves: u64,
    /// `true` if the stop ended it.
    pub stopped: bool,
}

/// The smoothing pass and its buffers (allocated once per pass, reused for every move).
pub(super) struct PathSmoothing {
    moves: SmoothingMoves,
    /// Midpoint of a state's neighbours.
    middle: Vec<f64>,
    /// The moved state being tried.
    candidate: Vec<f64>,
    /// A perturbation.
    step: Vec<f64>,
    /// Per interior state, the size of its next perturbation (a fraction of its shorter edge).
    scales: Vec<f64>,
}

impl PathSmoothing {
    /// Buffers for states of `dimension` coordinates.
    pub(super) fn new(moves: SmoothingMoves, dimension: usize) -> Self {
        Self {
            moves,
            middle: vec![0.0; dimension],
            candidate: vec![0.0; dimension],
            step: vec![0.0; dimension],
            scales: Vec::new(),
        }
    }

    /// Up to `sweeps` sweeps over the interior states of `states` (the ends stay), each state
    /// moved by the first of [`SmoothingMoves`] that shortens its two edges and whose two new
    /// edges pass `run`'s check and certification. Stops early when a sweep gains less than
    /// 10⁻⁴ of the path's length or the stop fires. The path never gets longer.
    ///
    /// Complexity: at most six edge checks per interior state and sweep with
    /// [`SmoothingMoves::Perturb`], four with [`SmoothingMoves::Relax`], ten with both.
    pub(super) fn smooth<S: StateSpace, V: StateValidity>(
        &mut self,
        run: &mut SimplificationRun<'_, S, V>,
        states: &mut [Vec<f64>],
        sweeps: usize,
    ) -> Smoothed {
        let mut done = Smoothed::default();
        self.scales.clear();
        self.scales.resize(states.len(), INITIAL_SCALE);
        for _ in 0..sweeps {
            let total = super::simplification_run::length(run.space, states);
            for i in 1..states.len().saturating_sub(1) {
                if run.stop.should_stop() {
                    done.stopped = true;
                    return done;
                }
                match self.move_state(run, states, i) {
                    Some(EdgeStatus::Unknown) => {
                        done.stopped = true;
                        return done;
                    }
                    Some(EdgeStatus::Valid) => done.moves += 1,
                    Some(EdgeStatus::Invalid) | None => {}
                }
            }
            let gained = total - super::simplification_run::length(run.space, states);
            if gained < NEGLIGIBLE_GAIN * total {
                break;
            }
        }
        done
    }

    /// Tries the moves of state `i` in order. `Some(Valid)` if one was taken, `Some(Unknown)`
    /// if the stop fired during a check, `Some(Invalid)` if every move tried failed its checks,
    /// `None` if no move was shorter.
    fn move_state<S: StateSpace, V: StateValidity>(
        &mut self,
        run: &mut SimplificationRun<'_, S, V>,
        states: &mut [Vec<f64>],
        i: usize,
    ) -> Option<EdgeStatus> {
        let space = run.space;
        let (before, after) = (&states[i - 1], &states[i + 1]);
        let now = space.distance(before, &states[i]) + space.distance(&states[i], after);
        let mut outcome = None;
        if self.moves != SmoothingMoves::Perturb {
            space.interpolate(before, after, 0.5, &mut self.middle);
            for fraction in RELAX_FRACTIONS {
                space.interpolate(&states[i], &self.middle, fraction, &mut self.candidate);
                outcome = self.try_candidate(run, states, i, now);
                if outcome != Some(EdgeStatus::Invalid) {
                    break;
                }
            }
            if matches!(outcome, Some(EdgeStatus::Valid | EdgeStatus::Unknown)) {
                return outcome;
            }
        }
        if self.moves != SmoothingMoves::Relax {
            for _ in 0..PERTURBATIONS {
                let perturbed = self.perturb(run, states, i, now);
                if perturbed.is_some() {
                    outcome = perturbed;
                }
                if matches!(outcome, Some(EdgeStatus::Valid | EdgeStatus::Unknown)) {
                    break;
                }
            }
        }
        outcome
    }

    /// A random step from state `i`, or the opposite step if that one is not shorter; sizes
    /// the next step by the outcome.
    fn perturb<S: StateSpace, V: StateValidity>(
        &mut self,
        run: &mut SimplificationRun<'_, S, V>,
        states: &mut [Vec<f64>],
        i: usize,
        now: f64,
    ) -> Option<EdgeStatus> {
        let space = run.space;
        let shorter_edge = space
            .distance(&states[i - 1], &states[i])
            .min(space.distance(&states[i], &states[i + 1]));
        // Uniform in a cube of half-width `scale · shorter_edge / √n`: a step of about that
        // fraction of the shorter edge.
        if self.scales[i] < SMALLEST_SCALE {
            return None;
        }
        let width = self.scales[i] * shorter_edge / (self.step.len() as f64).sqrt();
        // Not above zero, or not a number: no step.
        if width.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        for x in &mut self.step {
            *x = width * (2.0 * run.rng.random::<f64>() - 1.0);
        }
        let mut outcome = None;
        for sign in [1.0, -1.0] {
            for ((c, x), d) in self.candidate.iter_mut().zip(&states[i]).zip(&self.step) {
                *c = x + sign * d;
            }
            space.enforce_bounds(&mut self.candidate);
            outcome = self.try_candidate(run, states, i, now);
            if outcome.is_some() {
                break;
            }
        }
        match outcome {
            Some(EdgeStatus::Valid) => self.scales[i] = (2.0 * self.scales[i]).min(1.0),
            Some(EdgeStatus::Invalid) => self.scales[i] *= 0.5,
            _ => {}
        }
        outcome
    }

    /// Takes `candidate` as state `i` if its two edges are shorter than `now` and pass the
    /// check and certification. `None` if not shorter (nothing checked), else the first
    /// status that was not `Valid`, or `Valid` when taken.
    fn try_candidate<S: StateSpace, V: StateValidity>(
        &mut self,
        run: &mut SimplificationRun<'_, S, V>,
        states: &mut [Vec<f64>],
        i: usize,
        now: f64,
    ) -> Option<EdgeStatus> {
        let space = run.space;
        let (before, after) = (&states[i - 1], &states[i + 1]);
        let moved =
            space.distance(before, &self.candidate) + space.distance(&self.candidate, after);
        // Not shorter, or not a number: nothing to try.
        if moved.partial_cmp(&(now * (1.0 - MINIMUM_GAIN))) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        // Edge checks test an edge's interior only: the moved state itself first.
        if !run.state_is_valid(&self.candidate) {
            return Some(EdgeStatus::Invalid);
        }
        for (a, b) in [(before, &self.candidate), (&self.candidate, after)] {
            let status = run.edge(a, b);
            if status != EdgeStatus::Valid {
                return Some(status);
            }
        }
        states[i].copy_from_slice(&self.candidate);
        Some(EdgeStatus::Valid)
    }
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use mit_star_problems::Problem;
    use mit_star_spaces::StateSpace;
    use mit_star_validity::{AxisBox, World};

    use crate::{PathSimplifier, SmoothingMoves};

    /// The unit square with a thin wall from the floor to `y = 0.85` at `x = 0.5`.
    fn thin_wall() -> Problem {
        let mut world = World::new(vec![0.0, 0.0], vec![1.0, 1.0]);
        world
            .add_obstacle(AxisBox::new(vec![0.5, 0.425], vec![0.002, 0.85]))
            .unwrap();
        Problem::new("thin-wall", world, vec![0.2, 0.2], vec![vec![0.8, 0.2]])
            .unwrap()
            .with_resolution(1e-4)
            .unwrap()
    }

    /// Over the wall, with corners well above it (no state can be dropped: every chord
    /// crosses the wall), 1.587 long; around the wall's tip is 1.432.
    fn over_the_wall() -> Vec<Vec<f64>> {
        vec![
            vec![0.2, 0.2],
            vec![0.45, 0.9],
            vec![0.55, 0.9],
            vec![0.8, 0.2],
        ]
    }

    /// Smoothing alone: vertex reduction, no shortcuts.
    fn smoother(moves: SmoothingMoves, rounds: usize) -> PathSimplifier {
        PathSimplifier::new()
            .attempts(0)
            .seed(7)
            .smoothing_moves(moves)
            .smoothing_rounds(rounds)
    }

    fn length(problem: &Problem, path: &[Vec<f64>]) -> f64 {
        path.windows(2)
            .map(|w| problem.space().distance(&w[0], &w[1]))
            .sum()
    }

    #[test]
    fn smoothing_shortens_keeps_the_ends_and_never_cuts_through_a_thin_wall() {
        let problem = thin_wall();
        let path = over_the_wall();
        let never = mit_star_spaces::Never;
        let reduced = smoother(SmoothingMoves::Relax, 0)
            .simplify(&problem, &path, &never)
            .unwrap();
        assert_eq!(reduced.path, path, "no chord of this path is valid");
        for moves in [
            SmoothingMoves::Relax,
            SmoothingMoves::Perturb,
            SmoothingMoves::RelaxThenPerturb,
        ] {
            let smoothed = smoother(moves, 200)
                .simplify(&problem, &path, &never)
                .unwrap();
            assert_eq!(smoothed.path.first(), path.first(), "{moves:?}");
            assert_eq!(smoothed.path.last(), path.last(), "{moves:?}");
            assert!(smoothed.smoothing_moves > 0, "{moves:?}");
            assert!((length(&problem, &smoothed.path) - smoothed.cost).abs() < 1e-12);
            // Below the path given (well below with perturbations, which slide the corners
            // along the wall's tip where moves towards the neighbours stall), and no shorter
            // than around the tip.
            let around = 2.0 * (0.3f64.powi(2) + 0.65f64.powi(2)).sqrt();
            let factor = if moves == SmoothingMoves::Relax {
                0.96
            } else {
                0.93
            };
            eprintln!("{moves:?}: {} -> {}", smoothed.original_cost, smoothed.cost);
            assert!(
                smoothed.cost < factor * smoothed.original_cost,
                "{moves:?}: {}",
                smoothed.cost
            );
            assert!(smoothed.cost > around, "{moves:?}: {}", smoothed.cost);
            for w in smoothed.path.windows(2) {
                assert!(
                    problem.world().segment_verdict(&w[0], &w[1]).is_valid(),
                    "{moves:?}: {:?} -> {:?} crosses the wall",
                    w[0],
                    w[1]
                );
            }
            assert!(!smoothed.stopped);
        }
    }

    #[test]
    fn every_round_leaves_the_path_no_longer_than_the_one_before() {
        let problem = thin_wall();
        let path = over_the_wall();
        let mut previous = length(&problem, &path);
        for rounds in 1..12 {
            let smoothed = smoother(SmoothingMoves::RelaxThenPerturb, rounds)
                .simplify(&problem, &path, &mit_star_spaces::Never)
                .unwrap();
            assert!(smoothed.cost <= smoothed.original_cost);
            assert!(
                smoothed.cost <= previous + 1e-12,
                "{rounds}: {} > {previous}",
                smoothed.cost
            );
            previous = smoothed.cost;
        }
    }

    #[test]
    fn a_fired_stop_leaves_the_path_as_it_was() {
        let problem = thin_wall();
        let path = over_the_wall();
        let smoothed = smoother(SmoothingMoves::RelaxThenPerturb, 50)
            .simplify(&problem, &path, &|| true)
            .unwrap();
        assert!(smoothed.stopped);
        assert_eq!(smoothed.path, path);
        assert_eq!((smoothed.smoothing_moves, smoothed.edges_checked), (0, 0));
    }

    #[test]
    fn a_stop_during_the_sweeps_ends_them_with_a_valid_path() {
        let problem = thin_wall();
        let path = over_the_wall();
        // Polls of a whole run; a stop that fires after a quarter, a half, three quarters of
        // them fires during the sweeps (vertex reduction checks only three chords).
        let count = Cell::new(0);
        let counting = || {
            count.set(count.get() + 1);
            false
        };
        let whole = smoother(SmoothingMoves::RelaxThenPerturb, 1_000)
            .simplify(&problem, &path, &counting)
            .unwrap();
        assert!(!whole.stopped && whole.smoothing_moves > 0);
        let total = count.get();
        for polls in [total / 4, total / 2, 3 * total / 4] {
            let count = Cell::new(0);
            let stop = || {
                count.set(count.get() + 1);
                count.get() > polls
            };
            let smoothed = smoother(SmoothingMoves::RelaxThenPerturb, 1_000)
                .simplify(&problem, &path, &stop)
                .unwrap();
            assert!(smoothed.stopped, "{polls}");
            assert!(smoothed.cost <= smoothed.original_cost);
            assert_eq!(smoothed.path.first(), path.first());
            assert_eq!(smoothed.path.last(), path.last());
            for w in smoothed.path.windows(2) {
                assert!(problem.world().segment_verdict(&w[0], &w[1]).is_valid());
            }
            // No poll after the one that fired.
            assert_eq!(count.get(), polls + 1, "{polls}");
        }
    }
}
