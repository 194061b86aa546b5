//! The [`StateValidity`] trait and the [`Counted`] wrapper that counts its calls.

use std::cell::Cell;

/// Decides whether a single state is valid (collision-free and within any constraints).
///
/// OMPL's `StateValidityChecker`. Kept separate from edge checking ([`EdgeChecker`](crate::EdgeChecker)),
/// which is built on top of it. Implementations must not allocate: this is the innermost call of
/// every planner. Object safe.
pub trait StateValidity {
    /// `true` if the state is valid.
    fn is_valid(&self, state: &[f64]) -> bool;
}

impl<V: StateValidity + ?Sized> StateValidity for &V {
    #[inline]
    fn is_valid(&self, state: &[f64]) -> bool {
        (**self).is_valid(state)
    }
}

impl<V: StateValidity + ?Sized> StateValidity for Box<V> {
    #[inline]
    fn is_valid(&self, state: &[f64]) -> bool {
        (**self).is_valid(state)
    }
}

/// Every state is valid (an empty world).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct AllValid;

impl StateValidity for AllValid {
    #[inline]
    fn is_valid(&self, _state: &[f64]) -> bool {
        true
    }
}

/// Wraps a validity checker and counts how many states it was asked about.
///
/// Counting is optional behaviour, so it is a wrapper (remove it and nothing is counted). The
/// counter is a [`Cell`]: one planner owns one checker, and the count costs one add.
///
/// ```
/// use validity::{AllValid, Counted, StateValidity};
/// let checker = Counted::new(AllValid);
/// assert!(checker.is_valid(&[0.0, 0.0]));
/// assert!(checker.is_valid(&[1.0, 0.0]));
/// assert_eq!(checker.count(), 2);
/// ```
#[derive(Debug, Clone, Default)]
pub struct Counted<V> {
    inner: V,
    count: Cell<u64>,
}

impl<V> Counted<V> {
    /// Wraps `inner` with a zero count.
    pub fn new(inner: V) -> Self {
        Self {
            inner,
            count: Cell::new(0),
        }
    }

    /// Number of states checked since creation or the last [`reset`](Self::reset).
    pub fn count(&self) -> u64 {
        self.count.get()
    }

    /// Sets the count back to zero.
    pub fn reset(&self) {
        self.count.set(0);
    }

    /// The wrapped checker.
    pub fn inner(&self) -> &V {
        &self.inner
    }

    /// Unwraps the checker.
    pub fn into_inner(self) -> V {
        self.inner
    }
}

impl<V: StateValidity> StateValidity for Counted<V> {
    #[inline]
    fn is_valid(&self, state: &[f64]) -> bool {
        self.count.set(self.count.get() + 1);
        self.inner.is_valid(state)
    }
}
