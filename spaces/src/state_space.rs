//! The [`StateSpace`] trait: the geometry every other building block is written against.

use rand::Rng;

use crate::SpaceError;

/// A configuration space: coordinates, a metric, interpolation, bounds and a measure.
///
/// States are plain coordinate slices (`&[f64]` of length [`dimension`](Self::dimension)); they
/// live in contiguous storage ([`States`](crate::States)) owned by whoever keeps them, so no call
/// here allocates. Outputs are written into caller-provided slices.
///
/// The trait is object safe: `Box<dyn StateSpace>` works for spaces chosen at run time.
///
/// # Laws (pinned by `tests/space_laws.rs` for every implementation)
/// - `distance` is symmetric, non-negative and zero on equal states;
/// - `interpolate(a, b, 0) == a`, `interpolate(a, b, 1) == b` (up to wrapping), and the result
///   of interpolating two states inside the bounds is inside the bounds;
/// - `enforce_bounds` and `reflect_into_bounds` leave a state for which `contains` holds;
/// - `sample_uniform` returns states for which `contains` holds.
pub trait StateSpace {
    /// Number of coordinates of a state.
    fn dimension(&self) -> usize;

    /// Length of the shortest path between two states, ignoring obstacles.
    fn distance(&self, a: &[f64], b: &[f64]) -> f64;

    /// Writes into `out` the state a fraction `t ∈ [0, 1]` of the way from `a` to `b` along the
    /// shortest path.
    fn interpolate(&self, a: &[f64], b: &[f64], t: f64, out: &mut [f64]);

    /// Lower bound of every coordinate.
    fn lower(&self) -> &[f64];

    /// Upper bound of every coordinate.
    fn upper(&self) -> &[f64];

    /// `true` if the state lies within the bounds (wrapping coordinates are always inside once
    /// normalised into their period).
    fn contains(&self, state: &[f64]) -> bool;

    /// Moves a state into the bounds: clamps bounded coordinates, wraps periodic ones.
    fn enforce_bounds(&self, state: &mut [f64]);

    /// Moves a state into the bounds by reflecting bounded coordinates at the bounds
    /// (`x → 2·lower − x` below, `x → 2·upper − x` above, repeated for an overshoot of more
    /// than the interval) and wrapping periodic ones. Unlike clamping, reflection puts no
    /// weight on the bounds themselves: a density that spills over a bound folds back inside.
    /// A non-finite coordinate is clamped as by [`enforce_bounds`](Self::enforce_bounds).
    ///
    /// The default is [`enforce_bounds`](Self::enforce_bounds), for spaces without box bounds
    /// to reflect at; [`RealVectorSpace`](crate::RealVectorSpace) and
    /// [`JointSpace`](crate::JointSpace) reflect.
    ///
    /// ```
    /// use mit_star_spaces::{RealVectorSpace, StateSpace};
    /// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
    /// let mut x = [-0.25, 3.5]; // 0.25 below the bounds, 2.5 above
    /// space.reflect_into_bounds(&mut x);
    /// assert_eq!(x, [0.25, 0.5]);
    /// # Ok::<(), mit_star_spaces::SpaceError>(())
    /// ```
    fn reflect_into_bounds(&self, state: &mut [f64]) {
        self.enforce_bounds(state);
    }

    /// Lebesgue measure (volume) of the space.
    fn measure(&self) -> f64;

    /// The largest distance between two states of the space (OMPL's `getMaximumExtent`). Edge
    /// checking resolutions are fractions of this number.
    fn maximum_extent(&self) -> f64;

    /// Writes a state drawn uniformly from the space into `out`.
    fn sample_uniform(&self, rng: &mut dyn Rng, out: &mut [f64]);

    /// `true` if `distance` is the Euclidean norm of the coordinate difference and
    /// `interpolate` is linear — the conditions under which the informed set of a path-length
    /// objective is a prolate hyperspheroid in coordinates, so direct informed sampling applies.
    fn is_euclidean(&self) -> bool;

    /// Per-coordinate scales `s` under which the metric is Euclidean, if it is a weighted
    /// Euclidean one: `distance(a, b) = ‖s ⊙ (b − a)‖` and `interpolate` linear. Nearest-neighbour
    /// structures then index `s ⊙ x` with kd-trees instead of scanning with `distance`. `None`
    /// (the default) for any other metric; a Euclidean space may answer either way.
    fn euclidean_scales(&self) -> Option<&[f64]> {
        None
    }

    /// Checks that a state has the right length, finite coordinates, and lies in the bounds.
    ///
    /// # Errors
    /// The first problem found, naming the coordinate.
    fn check_state(&self, state: &[f64]) -> Result<(), SpaceError> {
        if state.len() != self.dimension() {
            return Err(SpaceError::DimensionMismatch {
                expected: self.dimension(),
                got: state.len(),
            });
        }
        if let Some((index, &value)) = state.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(SpaceError::NonFiniteState { index, value });
        }
        if !self.contains(state) {
            let (lower, upper) = (self.lower(), self.upper());
            let index = (0..state.len())
                .find(|&i| state[i] < lower[i] || state[i] > upper[i])
                .unwrap_or(0);
            return Err(SpaceError::OutOfBounds {
                index,
                value: state[index],
                lower: lower[index],
                upper: upper[index],
            });
        }
        Ok(())
    }
}

impl<S: StateSpace + ?Sized> StateSpace for &S {
    fn dimension(&self) -> usize {
        (**self).dimension()
    }
    fn distance(&self, a: &[f64], b: &[f64]) -> f64 {
        (**self).distance(a, b)
    }
    fn interpolate(&self, a: &[f64], b: &[f64], t: f64, out: &mut [f64]) {
        (**self).interpolate(a, b, t, out);
    }
    fn lower(&self) -> &[f64] {
        (**self).lower()
    }
    fn upper(&self) -> &[f64] {
        (**self).upper()
    }
    fn contains(&self, state: &[f64]) -> bool {
        (**self).contains(state)
    }
    fn enforce_bounds(&self, state: &mut [f64]) {
        (**self).enforce_bounds(state);
    }
    fn reflect_into_bounds(&self, state: &mut [f64]) {
        (**self).reflect_into_bounds(state);
    }
    fn measure(&self) -> f64 {
        (**self).measure()
    }
    fn maximum_extent(&self) -> f64 {
        (**self).maximum_extent()
    }
    fn sample_uniform(&self, rng: &mut dyn Rng, out: &mut [f64]) {
        (**self).sample_uniform(rng, out);
    }
    fn is_euclidean(&self) -> bool {
        (**self).is_euclidean()
    }
    fn euclidean_scales(&self) -> Option<&[f64]> {
        (**self).euclidean_scales()
    }
}

/// `x` reflected into `[lower, upper]` (see [`StateSpace::reflect_into_bounds`]): unchanged
/// inside, folded back at the bounds with period `2·(upper − lower)` outside, clamped if not
/// finite.
///
/// ```
/// assert_eq!(mit_star_spaces::reflect_into_interval(1.25, 0.0, 1.0), 0.75);
/// assert_eq!(mit_star_spaces::reflect_into_interval(-2.25, 0.0, 1.0), 0.25);
/// assert_eq!(mit_star_spaces::reflect_into_interval(0.5, 0.0, 1.0), 0.5);
/// ```
#[inline]
pub fn reflect_into_interval(x: f64, lower: f64, upper: f64) -> f64 {
    if (lower..=upper).contains(&x) {
        return x;
    }
    let width = upper - lower;
    let folded = (x - lower).rem_euclid(2.0 * width);
    let y = lower
        + if folded > width {
            2.0 * width - folded
        } else {
            folded
        };
    // Rounding may land an ulp outside; a non-finite `x` (or width) clamps.
    if y.is_finite() {
        y.clamp(lower, upper)
    } else {
        x.clamp(lower, upper)
    }
}

/// Volume `ζ_n` of the unit ball in `R^n`: `π^(n/2) / Γ(n/2 + 1)`, by the recurrence
/// `ζ_n = ζ_{n-2} · 2π / n` (exact for every `n`, no gamma function needed).
pub fn unit_ball_measure(n: usize) -> f64 {
    let mut volume = if n.is_multiple_of(2) { 1.0 } else { 2.0 };
    let mut k = if n.is_multiple_of(2) { 2 } else { 3 };
    while k <= n {
        volume *= 2.0 * std::f64::consts::PI / k as f64;
        k += 2;
    }
    volume
}

#[cfg(test)]
mod tests {
    use super::{reflect_into_interval, unit_ball_measure};
    use std::f64::consts::PI;

    #[test]
    fn reflection_folds_with_twice_the_width_and_clamps_the_infinite() {
        let cases = [
            (0.3, 0.3),
            (-0.1, 0.1),
            (1.1, 0.9),
            (2.1, 0.1),
            (-1.1, 0.9),
            (4.0, 0.0),
            (5.0, 1.0),
            (-7.25, 0.75),
        ];
        for (x, expected) in cases {
            let y = reflect_into_interval(x, 0.0, 1.0);
            assert!((y - expected).abs() < 1e-12, "{x} -> {y}, not {expected}");
        }
        assert_eq!(reflect_into_interval(f64::INFINITY, -1.0, 2.0), 2.0);
        assert_eq!(reflect_into_interval(f64::NEG_INFINITY, -1.0, 2.0), -1.0);
        assert!(reflect_into_interval(f64::NAN, -1.0, 2.0).is_nan());
        // A huge overshoot still lands inside.
        assert!((-1.0..=2.0).contains(&reflect_into_interval(1e300, -1.0, 2.0)));
    }

    #[test]
    fn unit_ball_measure_matches_closed_forms() {
        let expected = [
            (0, 1.0),
            (1, 2.0),
            (2, PI),
            (3, 4.0 * PI / 3.0),
            (4, PI * PI / 2.0),
            (5, 8.0 * PI * PI / 15.0),
            (6, PI.powi(3) / 6.0),
        ];
        for (n, v) in expected {
            assert!((unit_ball_measure(n) - v).abs() < 1e-12, "n = {n}");
        }
    }
}
