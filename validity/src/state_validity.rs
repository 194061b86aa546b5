//! The [`StateValidity`] trait and the [`Counted`] wrapper that counts its calls.

use std::cell::Cell;

use mit_star_spaces::{StateSpace, Stop};

use crate::{EdgeStatus, MotionProgress, Preparation, Segment};

/// Decides whether a single state is valid (collision-free and within any constraints).
///
/// OMPL's `StateValidityChecker`. Kept separate from edge checking ([`EdgeChecker`](crate::EdgeChecker)),
/// which is built on top of it. Implementations must not allocate: this is the innermost call of
/// every planner. Object safe.
pub trait StateValidity {
    /// `true` if the state is valid.
    fn is_valid(&self, state: &[f64]) -> bool;

    /// How many states [`first_invalid`](Self::first_invalid) likes to receive at once: the
    /// lane count of a SIMD checker (8 for an arm checked in `f32x8`), 1 (the default) for
    /// a checker that gains nothing from batches. Edge checks group up to this many grid
    /// points of the bisection order into one call.
    #[inline]
    fn batch_width(&self) -> usize {
        1
    }

    /// The index of the first invalid state among `states` — consecutive states of
    /// `dimension` coordinates each — or `None` if all are valid.
    ///
    /// Must answer exactly what testing the states one by one with
    /// [`is_valid`](Self::is_valid) in order would: a batched implementation may test every
    /// state at once, but reports the *first* invalid one. The default does exactly that,
    /// stopping at the first invalid state.
    ///
    /// ```
    /// use mit_star_validity::{AllValid, StateValidity};
    /// struct RightHalf;
    /// impl StateValidity for RightHalf {
    ///     fn is_valid(&self, s: &[f64]) -> bool { s[0] >= 0.5 }
    /// }
    /// let states = [0.9, 0.0, 0.7, 0.0, 0.2, 0.0, 0.1, 0.0];
    /// assert_eq!(RightHalf.first_invalid(&states, 2), Some(2));
    /// assert_eq!(AllValid.first_invalid(&states, 2), None);
    /// ```
    #[inline]
    fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        states
            .chunks_exact(dimension.max(1))
            .position(|s| !self.is_valid(s))
    }

    /// The index of *an* invalid state among `states` (laid out as for
    /// [`first_invalid`](Self::first_invalid)), or `None` if all are valid: for checks that
    /// only ask whether a batch is free — an edge check, whose grid points go out in batches.
    /// A batched implementation may stop at the first invalid state it meets in any lane
    /// instead of deciding every state before it. `None` exactly when `first_invalid` is
    /// `None`. The default is [`first_invalid`](Self::first_invalid).
    #[inline]
    fn any_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        self.first_invalid(states, dimension)
    }

    /// Decides every state of `states` (laid out as for
    /// [`first_invalid`](Self::first_invalid)): `valid[i]` becomes whether state `i` is valid,
    /// for the first `valid.len()` states at most. For callers that need each answer, not only
    /// the first invalid state — a sampler drawing candidates a batch at a time. A batched
    /// checker answers up to [`batch_width`](Self::batch_width) states in one pass; the default
    /// asks [`is_valid`](Self::is_valid) of each in turn.
    ///
    /// ```
    /// use mit_star_validity::StateValidity;
    /// struct RightHalf;
    /// impl StateValidity for RightHalf {
    ///     fn is_valid(&self, s: &[f64]) -> bool { s[0] >= 0.5 }
    /// }
    /// let mut valid = [false; 3];
    /// RightHalf.are_valid(&[0.9, 0.2, 0.7], 1, &mut valid);
    /// assert_eq!(valid, [true, false, true]);
    /// ```
    #[inline]
    fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
        for (state, answer) in states.chunks_exact(dimension.max(1)).zip(valid) {
            *answer = self.is_valid(state);
        }
    }

    /// Certifies the motion from `a` to `b` — every state the space's interpolation passes
    /// through, not only grid points — if this checker can (`None`, the default, when it can
    /// only test states; the [`GridWalker`](crate::GridWalker) then certifies on a finer grid).
    ///
    /// - `Some(EdgeStatus::Valid)`: every state of the motion is valid.
    /// - `Some(EdgeStatus::Invalid)`: a state of the motion is invalid, or the checker could
    ///   not prove one valid (a certification may be conservative, never the other way).
    /// - `Some(EdgeStatus::Unknown)`: `stop` fired first; `progress` holds how far the
    ///   certification came, and a later call with the same motion and progress goes on from
    ///   there. A checker polls `stop` often enough that a stopped certification returns within
    ///   about the time of [`STOP_POLL`](crate::STOP_POLL) state checks.
    ///
    /// A box [`World`](crate::World) decides straight segments exactly with its slab tests (in
    /// spaces whose edges are straight, [`StateSpace::is_euclidean`]); the `robot` crate's arm
    /// checker bounds how far its spheres can move over an interval of the motion and tests
    /// them grown by that bound. Both catch a contact between two grid points, whatever the
    /// step.
    #[inline]
    fn certify_motion(
        &self,
        _space: &dyn StateSpace,
        _a: &[f64],
        _b: &[f64],
        _progress: &mut MotionProgress,
        _stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        None
    }

    /// [`certify_motion`](Self::certify_motion) of the motion `ends` (`a`, `b`) with a
    /// `scratch` segment the caller keeps: a checker may leave there what a stopped
    /// certification found so far, and goes on from it when called again with the same
    /// motion, scratch and progress. The [`GridWalker`](crate::GridWalker) keeps one for the
    /// certification it was last stopped on. A box [`World`](crate::World) keeps its place
    /// among its boxes there, so that it can poll however many boxes it has; the default
    /// ignores the scratch and calls `certify_motion`.
    #[inline]
    fn certify_motion_in(
        &self,
        space: &dyn StateSpace,
        (a, b): (&[f64], &[f64]),
        _scratch: &mut Segment,
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        self.certify_motion(space, a, b, progress, stop)
    }

    /// Prepares the straight segment in `segment` (set by the caller to `a → b`) for testing
    /// its points with [`first_invalid_on`](Self::first_invalid_on): a checker may keep in
    /// `segment` only what can meet the segment (a per-edge broad phase), or find that no
    /// point of it can be invalid ([`Preparation::AllValid`]).
    ///
    /// The [`GridWalker`](crate::GridWalker) prepares each edge it walks in a space with
    /// straight edges, unless acceleration is off. The default prepares nothing
    /// ([`Preparation::Unprepared`]). A checker that prepares must answer, through
    /// `first_invalid_on`, exactly what [`is_valid`](Self::is_valid) says of each point.
    #[inline]
    fn prepare_segment(&self, _segment: &mut Segment) -> Preparation {
        Preparation::Unprepared
    }

    /// The index of the first invalid point among the points at `fractions` of a segment
    /// prepared by [`prepare_segment`](Self::prepare_segment) (`a + (b − a)·t` for each `t`),
    /// or `None` if all are valid — exactly what testing them in order with
    /// [`is_valid`](Self::is_valid) would answer. The default does just that.
    #[inline]
    fn first_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        segment.first_invalid_by(fractions, |state| self.is_valid(state))
    }

    /// The index of *an* invalid point among the points at `fractions` of a prepared segment,
    /// or `None` if all are valid: to [`first_invalid_on`](Self::first_invalid_on) what
    /// [`any_invalid`](Self::any_invalid) is to [`first_invalid`](Self::first_invalid) (an
    /// edge check only asks whether its points are free). `None` exactly when
    /// `first_invalid_on` is `None`. The default is [`first_invalid_on`](Self::first_invalid_on).
    #[inline]
    fn any_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.first_invalid_on(segment, fractions)
    }
}

/// Implements [`StateValidity`] for a pointer type by forwarding every method to the pointee,
/// so that a wrapper's overrides (batches, prepared segments, segment decisions) are kept.
macro_rules! forward_state_validity {
    ($($pointer:ty),*) => {$(
        impl<V: StateValidity + ?Sized> StateValidity for $pointer {
            #[inline]
            fn is_valid(&self, state: &[f64]) -> bool {
                (**self).is_valid(state)
            }

            #[inline]
            fn batch_width(&self) -> usize {
                (**self).batch_width()
            }

            #[inline]
            fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
                (**self).first_invalid(states, dimension)
            }

            #[inline]
            fn any_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
                (**self).any_invalid(states, dimension)
            }

            #[inline]
            fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
                (**self).are_valid(states, dimension, valid)
            }

            #[inline]
            fn certify_motion(
                &self,
                space: &dyn StateSpace,
                a: &[f64],
                b: &[f64],
                progress: &mut MotionProgress,
                stop: &dyn Stop,
            ) -> Option<EdgeStatus> {
                (**self).certify_motion(space, a, b, progress, stop)
            }

            #[inline]
            fn certify_motion_in(
                &self,
                space: &dyn StateSpace,
                ends: (&[f64], &[f64]),
                scratch: &mut Segment,
                progress: &mut MotionProgress,
                stop: &dyn Stop,
            ) -> Option<EdgeStatus> {
                (**self).certify_motion_in(space, ends, scratch, progress, stop)
            }

            #[inline]
            fn prepare_segment(&self, segment: &mut Segment) -> Preparation {
                (**self).prepare_segment(segment)
            }

            #[inline]
            fn first_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
                (**self).first_invalid_on(segment, fractions)
            }

            #[inline]
            fn any_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
                (**self).any_invalid_on(segment, fractions)
            }
        }
    )*};
}

forward_state_validity!(&V, Box<V>);

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
/// use mit_star_validity::{AllValid, Counted, StateValidity};
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

impl<V: StateValidity> Counted<V> {
    /// A batch question (`ask`: the inner checker's `first_invalid` or `any_invalid`), counted:
    /// one by one up to the first invalid state for a checker without batches, the whole batch
    /// for a batched checker.
    #[inline]
    fn batch(
        &self,
        states: &[f64],
        dimension: usize,
        ask: fn(&V, &[f64], usize) -> Option<usize>,
    ) -> Option<usize> {
        if self.inner.batch_width() <= 1 {
            return states
                .chunks_exact(dimension.max(1))
                .position(|s| !self.is_valid(s));
        }
        let n = states.len() / dimension.max(1);
        self.count.set(self.count.get() + n as u64);
        ask(&self.inner, states, dimension)
    }
}

impl<V: StateValidity> StateValidity for Counted<V> {
    #[inline]
    fn is_valid(&self, state: &[f64]) -> bool {
        self.count.set(self.count.get() + 1);
        self.inner.is_valid(state)
    }

    #[inline]
    fn batch_width(&self) -> usize {
        self.inner.batch_width()
    }

    /// Counts the states tested: one by one up to the first invalid for a checker without
    /// batches, the whole batch for a batched checker (it tests them all).
    #[inline]
    fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        self.batch(states, dimension, V::first_invalid)
    }

    /// Counted as [`first_invalid`](Self::first_invalid).
    #[inline]
    fn any_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        self.batch(states, dimension, V::any_invalid)
    }

    /// Counts every state decided.
    #[inline]
    fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
        let n = (states.len() / dimension.max(1)).min(valid.len());
        self.count.set(self.count.get() + n as u64);
        self.inner.are_valid(states, dimension, valid);
    }

    /// Not counted: a motion certification is no state check (the walker counts the
    /// configurations it evaluates, `EdgeCounters::certification_points`).
    #[inline]
    fn certify_motion(
        &self,
        space: &dyn StateSpace,
        a: &[f64],
        b: &[f64],
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        self.inner.certify_motion(space, a, b, progress, stop)
    }

    /// Not counted, as [`certify_motion`](Self::certify_motion).
    #[inline]
    fn certify_motion_in(
        &self,
        space: &dyn StateSpace,
        ends: (&[f64], &[f64]),
        scratch: &mut Segment,
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        self.inner
            .certify_motion_in(space, ends, scratch, progress, stop)
    }

    /// Prepared like the wrapped checker.
    #[inline]
    fn prepare_segment(&self, segment: &mut Segment) -> Preparation {
        self.inner.prepare_segment(segment)
    }

    /// Counts every point of the call, as the batched `first_invalid` does.
    #[inline]
    fn first_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.count.set(self.count.get() + fractions.len() as u64);
        self.inner.first_invalid_on(segment, fractions)
    }

    /// Counts every point of the call, as [`first_invalid_on`](Self::first_invalid_on).
    #[inline]
    fn any_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.count.set(self.count.get() + fractions.len() as u64);
        self.inner.any_invalid_on(segment, fractions)
    }
}
