//! [`MotionProgress`]: how far the certification of one motion has come, so that a stopped
//! certification resumes instead of starting over.

/// How far a certification of the motion between two states has come: every state of the
/// motion up to the fraction [`certified`](Self::certified) is proven valid, and the checker's
/// own position in its work (a step length, or an index into its obstacles) is kept in
/// [`cursor`](Self::cursor).
///
/// A certification the stop interrupts returns [`EdgeStatus::Unknown`](crate::EdgeStatus) and
/// leaves its progress here; handing the same progress back (for the same motion) goes on from
/// there. `Default` is "nothing certified yet". 24 bytes; the
/// [`GridWalker`](crate::GridWalker) keeps the progress of the last motion it was stopped on.
///
/// ```
/// let fresh = mit_star_validity::MotionProgress::default();
/// assert_eq!(fresh.certified(), 0.0);
/// assert!(!fresh.is_complete());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MotionProgress {
    certified: f64,
    cursor: f64,
    evaluations: u64,
}

impl MotionProgress {
    /// Progress with the motion proven valid up to the fraction `certified` (clamped to
    /// `[0, 1]`; a NaN is taken as 0) and the checker's `cursor`.
    pub fn new(certified: f64, cursor: f64) -> Self {
        let certified = if certified.is_nan() {
            0.0
        } else {
            certified.clamp(0.0, 1.0)
        };
        Self {
            certified,
            cursor,
            evaluations: 0,
        }
    }

    /// The same progress, moved to `certified` and `cursor` (as [`new`](Self::new)), with the
    /// evaluation count kept.
    #[must_use]
    pub fn advanced(self, certified: f64, cursor: f64) -> Self {
        Self {
            evaluations: self.evaluations,
            ..Self::new(certified, cursor)
        }
    }

    /// Configurations (or other units of work) the checker evaluated for this motion so far.
    #[inline]
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    /// Counts `n` more evaluations.
    #[inline]
    pub fn count(&mut self, n: u64) {
        self.evaluations += n;
    }

    /// The fraction of the motion, from its first state, proven valid.
    #[inline]
    pub fn certified(&self) -> f64 {
        self.certified
    }

    /// The checker's own position (its meaning is the checker's: the arm checker keeps the
    /// length of its next step, a box world the units of work it has done, its place among
    /// its boxes kept in the caller's scratch). 0 when fresh.
    #[inline]
    pub fn cursor(&self) -> f64 {
        self.cursor
    }

    /// `true` once the whole motion is proven valid.
    #[inline]
    pub fn is_complete(&self) -> bool {
        self.certified >= 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fractions_are_clamped() {
        assert_eq!(MotionProgress::new(1.5, 2.0).certified(), 1.0);
        assert!(MotionProgress::new(1.5, 2.0).is_complete());
        assert_eq!(MotionProgress::new(-1.0, 0.0).certified(), 0.0);
        assert_eq!(MotionProgress::new(f64::NAN, 0.0).certified(), 0.0);
        assert_eq!(MotionProgress::new(0.25, 0.125).cursor(), 0.125);
        let mut p = MotionProgress::default();
        p.count(3);
        let p = p.advanced(0.5, 1.0);
        assert_eq!((p.certified(), p.cursor(), p.evaluations()), (0.5, 1.0, 3));
    }
}
