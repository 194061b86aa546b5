//! [`FixedSparseChecker`]: EIT*'s sparse levels of 1, 3, 7, 15, … checks per edge.

use mit_star_spaces::StateSpace;

use crate::{EdgeChecker, GridWalker, StateValidity, ValidityError};

/// EIT*'s sparse collision checking: at level `k` a sparse check tests the first `2^(k+1) − 1`
/// points of the edge's bisection order (1, 3, 7, 15, …), whatever the edge's length.
///
/// ```
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AllValid, EdgeChecker, EdgeProgress, FixedSparseChecker};
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let mut checker = FixedSparseChecker::new(1e-3).unwrap();
/// let mut progress = EdgeProgress::default();
/// let (a, b) = ([0.1, 0.1], [0.9, 0.9]);
/// EdgeChecker::<RealVectorSpace, AllValid>::refine(&mut checker); // level 1: 3 checks
/// checker.check_sparse(&space, &AllValid, &a, &b, &mut progress, &Never);
/// assert_eq!(progress.tested(), 3);
/// # Ok::<(), mit_star_spaces::SpaceError>(())
/// ```
#[derive(Debug, Clone)]
pub struct FixedSparseChecker {
    walker: GridWalker,
    level: u32,
}

impl FixedSparseChecker {
    /// A checker with full-resolution step `step`, at level 0.
    ///
    /// # Errors
    /// If `step` is not finite and positive.
    pub fn new(step: f64) -> Result<Self, ValidityError> {
        Ok(Self {
            walker: GridWalker::new(step)?,
            level: 0,
        })
    }

    /// A checker whose step is `resolution × maximum extent` of `space`.
    ///
    /// # Errors
    /// If `resolution` is not finite and positive.
    pub fn from_resolution<S: StateSpace + ?Sized>(
        space: &S,
        resolution: f64,
    ) -> Result<Self, ValidityError> {
        Self::new(crate::step_from_resolution(space, resolution)?)
    }

    /// The checker with [acceleration](crate::GridWalker#acceleration) on (the default) or
    /// off (one state at a time, as OMPL checks).
    #[must_use]
    pub fn with_acceleration(mut self, accelerated: bool) -> Self {
        self.walker.set_accelerated(accelerated);
        self
    }
}

impl<S: StateSpace + ?Sized, V: StateValidity + ?Sized> EdgeChecker<S, V> for FixedSparseChecker {
    fn sparse_budget(&self, _length: f64) -> u64 {
        // 2^(k+1) − 1, saturating for absurd levels.
        1u64.checked_shl(self.level + 1).map_or(u64::MAX, |p| p - 1)
    }
    fn level(&self) -> u32 {
        self.level
    }
    fn refine(&mut self) {
        self.level = self.level.saturating_add(1);
    }
    fn reset(&mut self) {
        self.level = 0;
    }
    fn walker(&self) -> &GridWalker {
        &self.walker
    }
    fn walker_mut(&mut self) -> &mut GridWalker {
        &mut self.walker
    }
}
