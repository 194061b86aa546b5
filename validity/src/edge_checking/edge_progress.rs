//! Per-edge memory of checking work ([`EdgeProgress`]) and what it says about the edge
//! ([`EdgeStatus`]).

use crate::EdgeGrid;

/// What is known about an edge after a check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EdgeStatus {
    /// Every grid point has been tested valid: the edge is whitelisted.
    Valid,
    /// Some grid points remain untested and none tested so far was invalid.
    Unknown,
    /// A grid point was invalid: the edge is blacklisted (both directions).
    Invalid,
}

/// Per-edge memory of checking work: how many positions of the edge's bisection order have been
/// tested (all valid), or that the edge is known invalid. Eight bytes; the planner stores one per
/// edge it has touched. `Default` is "nothing tested yet".
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EdgeProgress(pub(crate) u64);

impl EdgeProgress {
    pub(crate) const INVALID: u64 = u64::MAX;

    /// Nothing tested yet.
    pub const UNTESTED: Self = Self(0);

    /// Known invalid (an invalid point was found, by a check or a
    /// [certification](crate::GridWalker::certify)).
    pub const FOUND_INVALID: Self = Self(Self::INVALID);

    /// Number of grid points tested valid so far (0 if the edge is known invalid).
    #[inline]
    pub fn tested(&self) -> u64 {
        if self.is_invalid() { 0 } else { self.0 }
    }

    /// `true` once a tested grid point was invalid.
    #[inline]
    pub fn is_invalid(&self) -> bool {
        self.0 == Self::INVALID
    }

    /// The status of an edge with this progress on `grid`.
    #[inline]
    pub fn status(&self, grid: &EdgeGrid) -> EdgeStatus {
        if self.is_invalid() {
            EdgeStatus::Invalid
        } else if self.0 >= grid.points() {
            EdgeStatus::Valid
        } else {
            EdgeStatus::Unknown
        }
    }

    /// Grid points still to test on `grid` before the edge is whitelisted (0 if invalid: nothing
    /// more will be tested).
    #[inline]
    pub fn remaining(&self, grid: &EdgeGrid) -> u64 {
        if self.is_invalid() {
            0
        } else {
            grid.points().saturating_sub(self.0)
        }
    }
}
