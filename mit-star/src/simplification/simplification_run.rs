//! [`SimplificationRun`]: what one simplification of a path shares — its edge check (on the
//! problem's grid, then certified), its random draws and counts — and the steps built on the
//! check alone: vertex reduction and the shortcuts.

use mit_star_spaces::rand::{RngExt, SeedableRng};
use mit_star_spaces::{SeededRng, StateSpace, Stop};
use mit_star_validity::{DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::BuildError;

/// A step of simplification — a shortcut, a sweep of smoothing moves, a smoothing round —
/// that gains less than this fraction of the path's length is not worth another.
pub(super) const NEGLIGIBLE_GAIN: f64 = 1e-4;

/// `true` once a smoothing round is not worth another: it made `moves` moves and took the
/// path from length `before` to `after`, and either moved nothing or gained less than
/// [`NEGLIGIBLE_GAIN`] of it.
pub(super) fn last_round(moves: u64, before: f64, after: f64) -> bool {
    moves == 0 || before - after < NEGLIGIBLE_GAIN * before
}

/// One simplification of a path: the problem's parts, the stop, the random draws, what was
/// done, and buffers reused by every shortcut.
pub(super) struct SimplificationRun<'a, S, V> {
    pub(super) space: &'a S,
    validity: &'a V,
    checker: DenseChecker,
    certification: u32,
    pub(super) stop: &'a dyn Stop,
    pub(super) rng: SeededRng,
    /// Edges checked (and certified).
    pub(super) checked: u64,
    /// Whole shortcuts taken (each adds two states).
    pub(super) shortcuts: u64,
    /// Per-coordinate shortcuts taken.
    pub(super) partial_shortcuts: u64,
    /// A shortcut's ends.
    ends: (Vec<f64>, Vec<f64>),
    /// The path's edge lengths.
    lengths: Vec<f64>,
    /// A per-coordinate shortcut's stretch of the path.
    stretch: Vec<Vec<f64>>,
}

impl<'a, S: StateSpace, V: StateValidity> SimplificationRun<'a, S, V> {
    /// A run in `space` with `validity`, edges checked at `step` and certified
    /// `certification` times finer, polling `stop`, its draws seeded by `seed`.
    ///
    /// # Errors
    /// [`BuildError::Validity`] for a step that is not finite and positive.
    pub(super) fn new(
        (space, validity): (&'a S, &'a V),
        (step, certification): (f64, u32),
        stop: &'a dyn Stop,
        seed: u64,
    ) -> Result<Self, BuildError> {
        let n = space.dimension();
        Ok(Self {
            space,
            validity,
            checker: DenseChecker::new(step)?,
            certification,
            stop,
            rng: SeededRng::seed_from_u64(seed),
            checked: 0,
            shortcuts: 0,
            partial_shortcuts: 0,
            ends: (vec![0.0; n], vec![0.0; n]),
            lengths: Vec::new(),
            stretch: Vec::new(),
        })
    }

    /// `true` if `x`, a state that was on no checked edge (a smoothing move's), is valid: edge
    /// checks test an edge's interior, its ends being known valid.
    pub(super) fn state_is_valid(&self, x: &[f64]) -> bool {
        self.validity.is_valid(x)
    }

    /// Checks `a → b` on the grid, then certifies it: the one check of every edge a
    /// simplification adds. `Unknown` if the stop fired (polled first, and inside the walks).
    pub(super) fn edge(&mut self, a: &[f64], b: &[f64]) -> EdgeStatus {
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

    /// Vertex reduction: from each state, joins the farthest later state it reaches directly
    /// and drops the states between. `false` if the stop fired.
    pub(super) fn reduce(&mut self, states: &mut Vec<Vec<f64>>) -> bool {
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

    /// Random shortcuts between two points on different edges (and, with `partial`, half of
    /// the time per-coordinate shortcuts) until `attempts` in a row fail or would gain less
    /// than 10⁻⁴ of the path's length (those are not checked). `false` if the stop fired.
    pub(super) fn shortcuts(
        &mut self,
        states: &mut Vec<Vec<f64>>,
        attempts: usize,
        partial: bool,
    ) -> bool {
        let space = self.space;
        let mut failures = 0;
        while failures < attempts && states.len() >= 3 {
            self.lengths.clear();
            self.lengths
                .extend(states.windows(2).map(|w| space.distance(&w[0], &w[1])));
            let total: f64 = self.lengths.iter().sum();
            // A shortcut that would gain less than this is not checked and counts as a
            // failure: the search ends when shortcuts stop paying, and checks (certification
            // above all) go to the ones that pay.
            let negligible = NEGLIGIBLE_GAIN * total;
            let outcome = if partial && self.rng.random::<bool>() {
                self.partial_shortcut(states, negligible)
            } else {
                self.shortcut(states, (total, negligible))
            };
            match outcome {
                Some((EdgeStatus::Valid, _)) => failures = 0,
                Some((EdgeStatus::Unknown, _)) => return false,
                Some((EdgeStatus::Invalid, _)) | None => failures += 1,
            }
        }
        true
    }

    /// A whole shortcut between two random points on different edges of the path (its
    /// length `total`, its edge lengths in `self.lengths`). `None` if the points were on one
    /// edge or the shortcut would gain less than `negligible` (nothing checked), else the
    /// status of its edge, with the length gained when taken.
    fn shortcut(
        &mut self,
        states: &mut Vec<Vec<f64>>,
        (total, negligible): (f64, f64),
    ) -> Option<(EdgeStatus, f64)> {
        let space = self.space;
        let (mut s, mut t) = (
            self.rng.random::<f64>() * total,
            self.rng.random::<f64>() * total,
        );
        if s > t {
            std::mem::swap(&mut s, &mut t);
        }
        let lengths = &self.lengths;
        let (ea, fa) = locate(lengths, s);
        let (eb, fb) = locate(lengths, t);
        if ea == eb {
            return None;
        }
        let (a, b) = &mut self.ends;
        space.interpolate(&states[ea], &states[ea + 1], fa, a);
        space.interpolate(&states[eb], &states[eb + 1], fb, b);
        let direct = space.distance(a, b);
        let along =
            (lengths[ea] * (1.0 - fa)) + lengths[ea + 1..eb].iter().sum::<f64>() + lengths[eb] * fb;
        if along - direct < negligible.max(along * 1e-9) {
            return None;
        }
        // The ends are taken out for the check (no allocation) and put back.
        let (a, b) = std::mem::take(&mut self.ends);
        let status = self.edge(&a, &b);
        let gain = if status == EdgeStatus::Valid {
            // The pieces from the edges' starts to `a` and from `b` to their ends are parts
            // of edges already valid.
            states.splice(ea + 1..=eb, [a.clone(), b.clone()]);
            self.shortcuts += 1;
            along - direct
        } else {
            0.0
        };
        self.ends = (a, b);
        Some((status, gain))
    }

    /// A per-coordinate shortcut: between two random states `i < j` of the path, one random
    /// coordinate of every state strictly between them is blended linearly (by arc length)
    /// from its value at `i` to its value at `j`; taken if the stretch gets shorter and all
    /// its new edges pass. `None` if it would gain less than `negligible` (nothing checked),
    /// else the first status that was not `Valid`, or `Valid` when taken, with the length
    /// gained.
    fn partial_shortcut(
        &mut self,
        states: &mut [Vec<f64>],
        negligible: f64,
    ) -> Option<(EdgeStatus, f64)> {
        let n = states.len();
        let i = self.rng.random_range(0..n - 2);
        let j = self.rng.random_range(i + 2..n);
        let k = self.rng.random_range(0..self.space.dimension());
        let pieces = &self.lengths[i..j];
        let total: f64 = pieces.iter().sum();
        if total <= 0.0 {
            return None;
        }
        let (from, to) = (states[i][k], states[j][k]);
        let count = j - i + 1;
        // The stretch's buffer is taken out for the checks (no allocation) and put back; it
        // grows to the longest stretch tried, then is reused.
        let mut buffer = std::mem::take(&mut self.stretch);
        if buffer.len() < count {
            buffer.resize(count, vec![0.0; self.space.dimension()]);
        }
        let stretch = &mut buffer[..count];
        for (copy, state) in stretch.iter_mut().zip(&states[i..=j]) {
            copy.copy_from_slice(state);
        }
        let mut along = 0.0;
        for (state, piece) in stretch[1..count - 1].iter_mut().zip(pieces) {
            along += piece;
            state[k] = from + (to - from) * along / total;
        }
        let shorter = length(self.space, stretch);
        let outcome = if total - shorter < negligible.max(total * 1e-9) {
            None
        } else {
            let failed = stretch
                .windows(2)
                .map(|w| self.edge(&w[0], &w[1]))
                .find(|status| *status != EdgeStatus::Valid);
            match failed {
                Some(status) => Some((status, 0.0)),
                None => {
                    for (state, copy) in states[i..=j].iter_mut().zip(stretch.iter()) {
                        state.copy_from_slice(copy);
                    }
                    self.partial_shortcuts += 1;
                    Some((EdgeStatus::Valid, total - shorter))
                }
            }
        };
        self.stretch = buffer;
        outcome
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
pub(super) fn length<S: StateSpace>(space: &S, path: &[Vec<f64>]) -> f64 {
    path.windows(2).map(|w| space.distance(&w[0], &w[1])).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shortcuts_that_would_gain_a_negligible_length_are_not_checked() {
        let space = mit_star_spaces::RealVectorSpace::new(vec![0.0; 2], vec![1.0; 2]).unwrap();
        let validity = mit_star_validity::AllValid;
        let stop = mit_star_spaces::Never;
        // A path 0.8 long with a bump of 10⁻³: any shortcut gains a few 10⁻⁶, under 10⁻⁴ of
        // the length.
        let path = vec![
            vec![0.1, 0.5],
            vec![0.3, 0.5],
            vec![0.5, 0.501],
            vec![0.7, 0.5],
            vec![0.9, 0.5],
        ];
        let mut run = SimplificationRun::new((&space, &validity), (1e-3, 1), &stop, 1).unwrap();
        let mut states = path.clone();
        assert!(run.shortcuts(&mut states, 50, true));
        assert_eq!(
            (run.checked, run.shortcuts, run.partial_shortcuts),
            (0, 0, 0)
        );
        assert_eq!(states, path);
        // A bump of 0.1 pays: shortcuts are checked and taken.
        let mut states = path;
        states[2][1] = 0.6;
        assert!(run.shortcuts(&mut states, 50, true));
        assert!(run.checked > 0 && run.shortcuts + run.partial_shortcuts > 0);
    }

    #[test]
    fn arc_lengths_locate_their_edge() {
        assert_eq!(locate(&[1.0, 2.0], 0.5), (0, 0.5));
        assert_eq!(locate(&[1.0, 2.0], 2.0), (1, 0.5));
        assert_eq!(locate(&[1.0, 2.0], 3.5), (1, 1.0));
    }
}
