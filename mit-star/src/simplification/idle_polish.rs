//! [`IdlePolish`]: when, and for how long, a planner that has stopped improving its best path
//! polishes it.

use super::PathSimplifier;
use super::path_smoothing::SmoothingMoves;

/// Iterations without a cheaper path before the first polish (`polish_when_idle`).
pub(crate) const FIRST_POLISH_AFTER: u64 = 2_000;

/// The polish schedule of an anytime planner's best path: after
/// [`FIRST_POLISH_AFTER`] iterations in which the planner found nothing cheaper, the path is
/// polished (whole and per-joint shortcuts, then smoothing rounds of midpoint relaxation and
/// random perturbations, every new edge checked and certified), with as many polls of its stop
/// as those iterations (about one per edge check: a count, not a time, so that runs under an
/// iteration limit repeat). A polish that gains nothing doubles the wait before the next one;
/// a cheaper path, found or polished, resets it.
#[derive(Debug, Clone)]
pub(crate) struct IdlePolish {
    seed: u64,
    /// Idle iterations before the next polish.
    wait: u64,
    /// Polishes run.
    count: u64,
}

impl IdlePolish {
    /// A schedule whose polishes draw from seeds derived from `seed`.
    pub(crate) fn new(seed: u64) -> Self {
        Self {
            seed,
            wait: FIRST_POLISH_AFTER,
            count: 0,
        }
    }

    /// Idle iterations before the next polish.
    pub(crate) fn wait(&self) -> u64 {
        self.wait
    }

    /// Polishes run so far.
    pub(crate) fn count(&self) -> u64 {
        self.count
    }

    /// The simplifier of the next polish (a seed of its own each time); counts it.
    pub(crate) fn next_simplifier(&mut self) -> PathSimplifier {
        self.count += 1;
        PathSimplifier::new()
            .seed(self.seed.wrapping_add(self.count.wrapping_mul(0x9e37_79b9)))
            .smoothing_moves(SmoothingMoves::RelaxThenPerturb)
    }

    /// After a polish: `paid` (it shortened the path) resets the wait, else doubles it.
    pub(crate) fn polished(&mut self, paid: bool) {
        self.wait = if paid {
            FIRST_POLISH_AFTER
        } else {
            self.wait.saturating_mul(2)
        };
    }

    /// A cheaper path found by the planner: the wait starts over.
    pub(crate) fn improved(&mut self) {
        self.wait = FIRST_POLISH_AFTER;
    }

    /// Back to the state of [`new`](Self::new).
    pub(crate) fn reset(&mut self) {
        *self = Self::new(self.seed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wait_doubles_after_each_polish_that_fails_and_resets_after_one_that_pays() {
        let mut polish = IdlePolish::new(1);
        assert_eq!(polish.wait(), FIRST_POLISH_AFTER);
        let first = format!("{:?}", polish.next_simplifier());
        polish.polished(false);
        let second = format!("{:?}", polish.next_simplifier());
        polish.polished(false);
        assert_eq!(polish.wait(), 4 * FIRST_POLISH_AFTER);
        assert_ne!(first, second, "each polish has a seed of its own");
        polish.polished(true);
        assert_eq!(polish.wait(), FIRST_POLISH_AFTER);
        polish.polished(false);
        polish.improved();
        assert_eq!(polish.wait(), FIRST_POLISH_AFTER);
        assert_eq!(polish.count(), 2);
        polish.reset();
        assert_eq!((polish.wait(), polish.count()), (FIRST_POLISH_AFTER, 0));
    }
}
