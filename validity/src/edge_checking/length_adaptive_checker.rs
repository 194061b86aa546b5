//! [`LengthAdaptiveChecker`]: MIT*'s length-related adaptive sparse collision checks (spec §5).

use mit_star_spaces::StateSpace;

use crate::{EdgeChecker, GridWalker, StateValidity, ValidityError};

/// MIT*'s sparse checking: the number of sparse checks grows with the edge's length.
///
/// At level `k` the sparse spacing is `Δ_k = max(Ω^k · Δ₀, Δ_min)` and an edge of length `d`
/// gets `Θ_k = ⌊d / Δ_k + 1⌋` checks — at least its midpoint — taken as the first `Θ_k` points of
/// its bisection order on the canonical grid. Defaults (the authors' constants): `Δ₀ = 2000 L`,
/// `Ω = 0.5`, `Δ_min = 10 L`.
///
/// ```
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AllValid, EdgeChecker, EdgeProgress, LengthAdaptiveChecker};
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let checker = LengthAdaptiveChecker::new(1e-4).unwrap(); // Δ₀ = 0.2
/// let budget = |d| EdgeChecker::<RealVectorSpace, AllValid>::sparse_budget(&checker, d);
/// assert_eq!(budget(0.1), 1);
/// assert_eq!(budget(0.5), 3);
/// # Ok::<(), mit_star_spaces::SpaceError>(())
/// ```
#[derive(Debug, Clone)]
pub struct LengthAdaptiveChecker {
    walker: GridWalker,
    level: u32,
    initial_spacing: f64,
    min_spacing: f64,
    factor: f64,
    spacing: f64,
}

impl LengthAdaptiveChecker {
    /// Default `Δ₀ / L`.
    pub const DEFAULT_INITIAL_STEPS: f64 = 2000.0;
    /// Default `Δ_min / L`.
    pub const DEFAULT_MIN_STEPS: f64 = 10.0;
    /// Default refinement factor `Ω`.
    pub const DEFAULT_FACTOR: f64 = 0.5;

    /// A checker with full-resolution step `step` and the default constants.
    ///
    /// # Errors
    /// If `step` is not finite and positive.
    pub fn new(step: f64) -> Result<Self, ValidityError> {
        Self::with_parameters(
            step,
            Self::DEFAULT_INITIAL_STEPS * step,
            Self::DEFAULT_FACTOR,
            Self::DEFAULT_MIN_STEPS * step,
        )
    }

    /// A checker whose step is `resolution × maximum extent` of `space`, default constants.
    ///
    /// # Errors
    /// If `resolution` is not finite and positive.
    pub fn from_resolution<S: StateSpace + ?Sized>(
        space: &S,
        resolution: f64,
    ) -> Result<Self, ValidityError> {
        Self::new(crate::step_from_resolution(space, resolution)?)
    }

    /// A checker with every constant given: step `L`, initial spacing `Δ₀`, refinement factor
    /// `Ω ∈ (0, 1)`, and the floor `Δ_min` the spacing never goes below.
    ///
    /// # Errors
    /// If a length is not finite and positive, or `Ω` is outside `(0, 1)`.
    pub fn with_parameters(
        step: f64,
        initial_spacing: f64,
        factor: f64,
        min_spacing: f64,
    ) -> Result<Self, ValidityError> {
        for (name, value) in [
            ("initial sparse spacing Δ₀", initial_spacing),
            ("minimum sparse spacing", min_spacing),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ValidityError::NotPositive { name, value });
            }
        }
        if !(factor > 0.0 && factor < 1.0) {
            return Err(ValidityError::RefinementFactor(factor));
        }
        Ok(Self {
            walker: GridWalker::new(step)?,
            level: 0,
            initial_spacing,
            min_spacing,
            factor,
            spacing: initial_spacing.max(min_spacing),
        })
    }

    /// Current sparse spacing `Δ_k`.
    pub fn spacing(&self) -> f64 {
        self.spacing
    }

    /// The checker with [acceleration](crate::GridWalker#acceleration) on (the default) or
    /// off (one state at a time, as OMPL checks).
    #[must_use]
    pub fn with_acceleration(mut self, accelerated: bool) -> Self {
        self.walker.set_accelerated(accelerated);
        self
    }
}

impl<S: StateSpace + ?Sized, V: StateValidity + ?Sized> EdgeChecker<S, V>
    for LengthAdaptiveChecker
{
    fn sparse_budget(&self, length: f64) -> u64 {
        // ⌊d / Δ_k + 1⌋; `as` saturates for huge ratios.
        (length / self.spacing + 1.0).floor().max(1.0) as u64
    }
    fn level(&self) -> u32 {
        self.level
    }
    fn refine(&mut self) {
        self.level = self.level.saturating_add(1);
        self.spacing = (self.spacing * self.factor).max(self.min_spacing);
    }
    fn reset(&mut self) {
        self.level = 0;
        self.spacing = self.initial_spacing.max(self.min_spacing);
    }
    fn walker(&self) -> &GridWalker {
        &self.walker
    }
    fn walker_mut(&mut self) -> &mut GridWalker {
        &mut self.walker
    }
}
