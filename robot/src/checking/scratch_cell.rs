//! [`ScratchCell`]: per-clone scratch buffers behind a mutex, shared by the arm checkers.

use std::sync::{Mutex, MutexGuard, PoisonError};

/// Scratch buffers a checker reuses on every check, behind a [`Mutex`] so that the checker is
/// `Sync` (problems holding one are shared across a benchmark's threads); each clone gets its
/// own copy, so concurrent planners never wait on each other's lock.
#[derive(Debug)]
pub(crate) struct ScratchCell<T>(Mutex<T>);

impl<T> ScratchCell<T> {
    pub(crate) fn new(value: T) -> Self {
        Self(Mutex::new(value))
    }

    /// The buffers (a poisoned lock is taken over: scratch holds no invariant).
    #[inline]
    pub(crate) fn lock(&self) -> MutexGuard<'_, T> {
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The buffers, through exclusive access (no locking).
    pub(crate) fn get_mut(&mut self) -> &mut T {
        self.0.get_mut().unwrap_or_else(PoisonError::into_inner)
    }
}

impl<T: Clone> Clone for ScratchCell<T> {
    fn clone(&self) -> Self {
        Self::new(self.lock().clone())
    }
}
