//! [`DenseChecker`]: OMPL-style fixed-resolution edge checking, no sparse phase.

use mit_star_spaces::StateSpace;

use crate::{EdgeChecker, GridWalker, StateValidity, ValidityError};

/// Checks every grid point at the full resolution, every time: a sparse check *is* a full check.
///
/// This is OMPL's `DiscreteMotionValidator` on the canonical grid. Planners without lazy
/// collision checking use it; for lazy planners it is the "no sparse checks" ablation.
///
/// ```
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AllValid, DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus};
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let mut checker = DenseChecker::from_resolution(&space, 0.01).unwrap();
/// let mut progress = EdgeProgress::default();
/// let status = checker.check_sparse(&space, &AllValid, &[0.0, 0.0], &[1.0, 1.0], &mut progress, &Never);
/// assert_eq!(status, EdgeStatus::Valid);
/// assert_eq!(progress.tested(), 99); // N = ceil(√2 / (0.01·√2)) = 100 intervals
/// # Ok::<(), mit_star_spaces::SpaceError>(())
/// ```
#[derive(Debug, Clone)]
pub struct DenseChecker {
    walker: GridWalker,
}

impl DenseChecker {
    /// A checker with full-resolution step `step` (the length `L`).
    ///
    /// # Errors
    /// If `step` is not finite and positive.
    pub fn new(step: f64) -> Result<Self, ValidityError> {
        Ok(Self {
            walker: GridWalker::new(step)?,
        })
    }

    /// A checker whose step is `resolution × maximum extent` of `space` (OMPL's convention).
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

impl<S: StateSpace + ?Sized, V: StateValidity + ?Sized> EdgeChecker<S, V> for DenseChecker {
    fn sparse_budget(&self, _length: f64) -> u64 {
        u64::MAX
    }
    fn level(&self) -> u32 {
        0
    }
    fn refine(&mut self) {}
    fn reset(&mut self) {}
    fn walker(&self) -> &GridWalker {
        &self.walker
    }
    fn walker_mut(&mut self) -> &mut GridWalker {
        &mut self.walker
    }
}
