//! [`GaussianStep`]: the Gaussian perturbation shared by the Gaussian, bridge-test and adaptive
//! samplers.

use mit_star_spaces::StateSpace;
use rand::Rng;
use rand_distr::{Distribution, StandardNormal};

use crate::SamplerError;

/// Draws a state from `N(x, σ² I)` around a state `x` and moves it into the bounds.
///
/// The perturbation is isotropic in coordinates; the result is clamped into the bounds (wrapping
/// coordinates are wrapped) with the space's `enforce_bounds`, so it always lies in the space —
/// as OMPL's `sampleGaussian` does for the Gaussian, bridge-test and adaptive samplers. A
/// [`reflecting`](Self::reflecting) step reflects at the bounds instead
/// ([`StateSpace::reflect_into_bounds`]), so no draws pile up on them (a joint limit next to a
/// terminal would otherwise collect every draw that spills over it): the step of
/// [`NearTerminals`](crate::NearTerminals).
///
/// ```
/// use rand::SeedableRng;
/// use mit_star_samplers::GaussianStep;
/// use mit_star_spaces::{RealVectorSpace, SeededRng, StateSpace};
///
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let step = GaussianStep::for_space(&space)?; // σ = 10 % of the diagonal
/// assert!((step.std_dev() - 0.1 * 2f64.sqrt()).abs() < 1e-12);
/// let mut rng = SeededRng::seed_from_u64(0);
/// let mut x = [0.0; 2];
/// step.perturb(&space, &mut rng, &[0.0, 1.0], &mut x);
/// assert!(space.contains(&x));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussianStep {
    std_dev: f64,
    /// Reflect at the bounds rather than clamp onto them.
    reflect: bool,
}

impl GaussianStep {
    /// Default standard deviation as a fraction of the space's maximum extent (spec §9: 10 %).
    pub const DEFAULT_EXTENT_FRACTION: f64 = 0.1;

    /// A step with standard deviation `std_dev`.
    ///
    /// # Errors
    /// [`SamplerError::NotPositive`] if `std_dev` is not finite and positive.
    pub fn new(std_dev: f64) -> Result<Self, SamplerError> {
        if !(std_dev.is_finite() && std_dev > 0.0) {
            return Err(SamplerError::NotPositive {
                name: "Gaussian standard deviation",
                value: std_dev,
            });
        }
        Ok(Self {
            std_dev,
            reflect: false,
        })
    }

    /// This step, reflecting its draws at the bounds ([`StateSpace::reflect_into_bounds`])
    /// instead of clamping them onto the bounds.
    #[must_use]
    pub fn reflecting(mut self) -> Self {
        self.reflect = true;
        self
    }

    /// `true` if draws are reflected at the bounds, `false` if clamped onto them.
    pub fn reflects(&self) -> bool {
        self.reflect
    }

    /// The default step for `space`: `σ = 0.1 ·` its maximum extent.
    ///
    /// # Errors
    /// [`SamplerError::NotPositive`] if the space's extent is not finite and positive.
    pub fn for_space<S: StateSpace + ?Sized>(space: &S) -> Result<Self, SamplerError> {
        Self::new(Self::DEFAULT_EXTENT_FRACTION * space.maximum_extent())
    }

    /// The standard deviation `σ`.
    pub fn std_dev(&self) -> f64 {
        self.std_dev
    }

    /// Writes `from + σ · N(0, I)`, moved into the bounds (clamped, or reflected by a
    /// [`reflecting`](Self::reflecting) step), into `out`.
    pub fn perturb<S: StateSpace + ?Sized>(
        &self,
        space: &S,
        rng: &mut dyn Rng,
        from: &[f64],
        out: &mut [f64],
    ) {
        for (o, &x) in out.iter_mut().zip(from) {
            let z: f64 = StandardNormal.sample(rng);
            *o = x + self.std_dev * z;
        }
        if self.reflect {
            space.reflect_into_bounds(out);
        } else {
            space.enforce_bounds(out);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::{RealVectorSpace, SeededRng};
    use rand::SeedableRng;

    #[test]
    fn rejects_bad_standard_deviations() {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                GaussianStep::new(bad),
                Err(SamplerError::NotPositive { .. })
            ));
        }
    }

    #[test]
    fn steps_have_the_requested_spread() {
        let space = RealVectorSpace::cube(1, -100.0, 100.0).unwrap();
        let step = GaussianStep::new(0.5).unwrap();
        let mut rng = SeededRng::seed_from_u64(11);
        let mut x = [0.0];
        let count = 20_000;
        let (mut sum, mut sum_sq) = (0.0, 0.0);
        for _ in 0..count {
            step.perturb(&space, &mut rng, &[3.0], &mut x);
            sum += x[0] - 3.0;
            sum_sq += (x[0] - 3.0) * (x[0] - 3.0);
        }
        let mean = sum / f64::from(count);
        let sd = (sum_sq / f64::from(count) - mean * mean).sqrt();
        // Standard errors: 0.5/√20000 ≈ 0.0035 for the mean, ≈ 0.0025 for σ.
        assert!(mean.abs() < 0.02, "mean {mean}");
        assert!((sd - 0.5).abs() < 0.02, "σ {sd}");
    }

    #[test]
    fn steps_are_clamped_into_the_bounds() {
        let space = RealVectorSpace::cube(3, 0.0, 1.0).unwrap();
        let step = GaussianStep::new(5.0).unwrap();
        let mut rng = SeededRng::seed_from_u64(2);
        let mut x = [0.0; 3];
        for _ in 0..100 {
            step.perturb(&space, &mut rng, &[0.5; 3], &mut x);
            assert!(space.contains(&x));
        }
    }

    #[test]
    fn reflecting_steps_fold_back_inside_and_leave_the_bounds_empty() {
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let step = GaussianStep::new(0.3).unwrap().reflecting();
        assert!(step.reflects() && !GaussianStep::new(0.3).unwrap().reflects());
        let mut rng = SeededRng::seed_from_u64(5);
        let mut x = [0.0; 2];
        let mut near_edge = 0;
        for _ in 0..2000 {
            // From a corner: about three quarters of the raw draws leave the square.
            step.perturb(&space, &mut rng, &[0.0, 0.0], &mut x);
            assert!(space.contains(&x));
            assert!(x.iter().all(|&c| c > 0.0 && c < 1.0), "{x:?} on a bound");
            near_edge += usize::from(x[0] < 0.1);
        }
        // Folded: |N(0, 0.3²)| puts about 26 % below 0.1.
        assert!((400..650).contains(&near_edge), "{near_edge}");
    }
}
