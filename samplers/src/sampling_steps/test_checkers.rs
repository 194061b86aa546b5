//! A checker for the sampling steps' unit tests.

use std::cell::RefCell;

use mit_star_validity::StateValidity;

/// Valid when the first coordinate is at least one half; decides batches of a given width and
/// records the size of each batch it was asked about.
pub(crate) struct RightHalf {
    width: usize,
    batches: RefCell<Vec<usize>>,
}

impl RightHalf {
    pub(crate) fn new(width: usize) -> Self {
        Self {
            width,
            batches: RefCell::default(),
        }
    }

    /// The sizes of the batches asked about so far, in order.
    pub(crate) fn batches(&self) -> Vec<usize> {
        self.batches.borrow().clone()
    }
}

impl StateValidity for RightHalf {
    fn is_valid(&self, s: &[f64]) -> bool {
        s[0] >= 0.5
    }
    fn batch_width(&self) -> usize {
        self.width
    }
    fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
        self.batches.borrow_mut().push(states.len() / dimension);
        for (s, v) in states.chunks_exact(dimension).zip(valid) {
            *v = self.is_valid(s);
        }
    }
}
