//! [`FilterReport`]: what a filter did and how long it took.

use std::time::{Duration, Instant};

/// What one filter did to a cloud: the points before and after, and its wall-clock time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FilterReport {
    /// Points before the filter.
    pub before: usize,
    /// Points it kept.
    pub after: usize,
    /// How long it took.
    pub elapsed: Duration,
}

impl FilterReport {
    /// Points it removed.
    pub fn removed(&self) -> usize {
        self.before - self.after
    }

    /// The report of a filter that started at `start` with `before` points and left `after`.
    pub(super) fn since(start: Instant, before: usize, after: usize) -> Self {
        Self {
            before,
            after,
            elapsed: start.elapsed(),
        }
    }
}
