//! [`JointSpace`]: the configuration space of a serial robot, one coordinate per joint.

use std::f64::consts::{PI, TAU};

use rand::{Rng, RngExt};

use crate::{SpaceError, StateSpace, euclidean_distance, reflect_into_interval};

/// How a joint moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointKind {
    /// A hinge with position limits, in radians.
    Revolute {
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
    },
    /// A slider with position limits, in metres.
    Prismatic {
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
    },
    /// A hinge without limits: its coordinate wraps around at `±π` (SO(2)).
    Continuous,
}

/// One joint of a [`JointSpace`]: its kind and its weight in the metric.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Joint name (free text, e.g. the URDF joint name).
    pub name: String,
    /// How the joint moves.
    pub kind: JointKind,
    /// Weight of this joint's displacement in the distance (default 1).
    pub weight: f64,
}

impl Joint {
    /// A revolute joint with limits `[lower, upper]` (radians) and weight 1.
    pub fn revolute(name: impl Into<String>, lower: f64, upper: f64) -> Self {
        Self::with_kind(name, JointKind::Revolute { lower, upper })
    }

    /// A prismatic joint with limits `[lower, upper]` and weight 1.
    pub fn prismatic(name: impl Into<String>, lower: f64, upper: f64) -> Self {
        Self::with_kind(name, JointKind::Prismatic { lower, upper })
    }

    /// A continuous (wrapping) joint with weight 1.
    pub fn continuous(name: impl Into<String>) -> Self {
        Self::with_kind(name, JointKind::Continuous)
    }

    /// Sets the joint's weight in the metric.
    #[must_use]
    pub fn weight(mut self, weight: f64) -> Self {
        self.weight = weight;
        self
    }

    fn with_kind(name: impl Into<String>, kind: JointKind) -> Self {
        Self {
            name: name.into(),
            kind,
            weight: 1.0,
        }
    }
}

/// A joint space built from a list of joints.
///
/// Bounded joints (revolute with limits, prismatic) behave like an interval of `R`; continuous
/// joints are SO(2): their coordinate lives in `[-π, π]`, distances take the shorter way round,
/// and interpolation crosses `±π` when that is shorter. The metric is the weighted Euclidean norm
/// of per-joint displacements, `sqrt(Σ (w_i · δ_i)²)`; [`measure`](StateSpace::measure) and
/// [`maximum_extent`](StateSpace::maximum_extent) are taken in that metric.
///
/// ```
/// use mit_star_spaces::{Joint, JointSpace, StateSpace};
/// use std::f64::consts::PI;
/// let space = JointSpace::new(vec![
///     Joint::revolute("shoulder", -2.0, 2.0),
///     Joint::continuous("wrist"),
/// ])?;
/// // The wrist goes the short way round, across ±π.
/// let d = space.distance(&[0.0, 3.0], &[0.0, -3.0]);
/// assert!((d - (2.0 * PI - 6.0)).abs() < 1e-12);
/// # Ok::<(), mit_star_spaces::SpaceError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct JointSpace {
    joints: Vec<Joint>,
    /// Per-joint weights, contiguous for the distance loop.
    weights: Vec<f64>,
    /// Per-joint `true` if continuous.
    wraps: Vec<bool>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    measure: f64,
    extent: f64,
    euclidean: bool,
}

impl JointSpace {
    /// A joint space over the given joints, in order.
    ///
    /// # Errors
    /// [`SpaceError`] if there are no joints, a limit is not finite, a lower limit is not below
    /// its upper limit, or a weight is not finite and positive.
    pub fn new(joints: Vec<Joint>) -> Result<Self, SpaceError> {
        if joints.is_empty() {
            return Err(SpaceError::ZeroDimension);
        }
        let n = joints.len();
        let (mut lower, mut upper) = (Vec::with_capacity(n), Vec::with_capacity(n));
        let (mut measure, mut extent_sq) = (1.0, 0.0);
        for (index, joint) in joints.iter().enumerate() {
            if !(joint.weight.is_finite() && joint.weight > 0.0) {
                return Err(SpaceError::BadWeight {
                    index,
                    weight: joint.weight,
                });
            }
            let (lo, hi, reach) = match joint.kind {
                JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper } => {
                    for value in [lower, upper] {
                        if !value.is_finite() {
                            return Err(SpaceError::NonFiniteBound { index, value });
                        }
                    }
                    if lower >= upper {
                        return Err(SpaceError::EmptyInterval {
                            index,
                            lower,
                            upper,
                        });
                    }
                    (lower, upper, upper - lower)
                }
                JointKind::Continuous => (-PI, PI, PI),
            };
            lower.push(lo);
            upper.push(hi);
            measure *= joint.weight * (hi - lo);
            extent_sq += (joint.weight * reach).powi(2);
        }
        let weights: Vec<f64> = joints.iter().map(|j| j.weight).collect();
        let wraps: Vec<bool> = joints
            .iter()
            .map(|j| matches!(j.kind, JointKind::Continuous))
            .collect();
        let euclidean = !wraps.iter().any(|&w| w) && weights.iter().all(|&w| w == 1.0);
        for (quantity, value) in [("diagonal", extent_sq.sqrt()), ("volume", measure)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(SpaceError::UnrepresentableSize { quantity, value });
            }
        }
        Ok(Self {
            joints,
            weights,
            wraps,
            lower,
            upper,
            measure,
            extent: extent_sq.sqrt(),
            euclidean,
        })
    }

    /// The joints, in coordinate order.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }
}

/// Wraps an angle into `[-π, π)`.
#[inline]
pub fn wrap_angle(x: f64) -> f64 {
    let y = x - TAU * ((x + PI) / TAU).floor();
    // Guard against rounding pushing `y` onto the excluded end.
    if y >= PI { y - TAU } else { y }
}

/// Signed shortest angular displacement from `a` to `b`, in `[-π, π)`.
#[inline]
fn angular_delta(a: f64, b: f64) -> f64 {
    wrap_angle(b - a)
}

impl StateSpace for JointSpace {
    #[inline]
    fn dimension(&self) -> usize {
        self.joints.len()
    }

    #[inline]
    fn distance(&self, a: &[f64], b: &[f64]) -> f64 {
        if self.euclidean {
            // Unit weights, no wrapping: the same sums in the same order, without the
            // per-joint tests.
            return euclidean_distance(a, b);
        }
        let mut sum = 0.0;
        for i in 0..a.len() {
            let delta = if self.wraps[i] {
                angular_delta(a[i], b[i])
            } else {
                b[i] - a[i]
            };
            let weighted = self.weights[i] * delta;
            sum += weighted * weighted;
        }
        sum.sqrt()
    }

    #[inline]
    fn interpolate(&self, a: &[f64], b: &[f64], t: f64, out: &mut [f64]) {
        for i in 0..a.len() {
            out[i] = if self.wraps[i] {
                wrap_angle(a[i] + angular_delta(a[i], b[i]) * t)
            } else {
                a[i] + (b[i] - a[i]) * t
            };
        }
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    #[inline]
    fn contains(&self, state: &[f64]) -> bool {
        state
            .iter()
            .zip(self.lower.iter().zip(&self.upper))
            .all(|(&x, (&lo, &hi))| x >= lo && x <= hi)
    }

    /// As the default, naming the joint: [`SpaceError::JointNotFinite`] and
    /// [`SpaceError::JointOutsideLimits`] instead of a coordinate's index alone.
    fn check_state(&self, state: &[f64]) -> Result<(), SpaceError> {
        if state.len() != self.dimension() {
            return Err(SpaceError::DimensionMismatch {
                expected: self.dimension(),
                got: state.len(),
            });
        }
        let joint = |index: usize| self.joints[index].name.clone();
        if let Some((index, &value)) = state.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(SpaceError::JointNotFinite {
                joint: joint(index),
                index,
                value,
            });
        }
        let outside =
            (0..state.len()).find(|&i| !(self.lower[i]..=self.upper[i]).contains(&state[i]));
        match outside {
            Some(index) => Err(SpaceError::JointOutsideLimits {
                joint: joint(index),
                index,
                value: state[index],
                lower: self.lower[index],
                upper: self.upper[index],
            }),
            None => Ok(()),
        }
    }

    fn enforce_bounds(&self, state: &mut [f64]) {
        for (i, x) in state.iter_mut().enumerate() {
            *x = if self.wraps[i] {
                wrap_angle(*x)
            } else {
                x.clamp(self.lower[i], self.upper[i])
            };
        }
    }

    fn reflect_into_bounds(&self, state: &mut [f64]) {
        for (i, x) in state.iter_mut().enumerate() {
            *x = if self.wraps[i] {
                wrap_angle(*x)
            } else {
                reflect_into_interval(*x, self.lower[i], self.upper[i])
            };
        }
    }

    fn measure(&self) -> f64 {
        self.measure
    }

    fn maximum_extent(&self) -> f64 {
        self.extent
    }

    fn sample_uniform(&self, rng: &mut dyn Rng, out: &mut [f64]) {
        for (x, (&lo, &hi)) in out.iter_mut().zip(self.lower.iter().zip(&self.upper)) {
            *x = lo + (hi - lo) * rng.random::<f64>();
        }
    }

    fn is_euclidean(&self) -> bool {
        self.euclidean
    }

    /// The joint weights, when no joint wraps around (a weighted Euclidean metric).
    fn euclidean_scales(&self) -> Option<&[f64]> {
        (!self.wraps.iter().any(|&w| w)).then_some(self.weights.as_slice())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_angle_lands_in_half_open_period() {
        for x in [-10.0, -PI, -1.0, 0.0, 1.0, PI, 3.5, 10.0, 7.0 * PI] {
            let y = wrap_angle(x);
            assert!((-PI..PI).contains(&y), "{x} -> {y}");
            assert!((((x - y) / TAU).round() * TAU - (x - y)).abs() < 1e-9);
        }
    }

    #[test]
    fn unit_weights_measure_the_weighted_sum_to_the_last_bit() {
        let joints = |w: f64| {
            (0..7)
                .map(|i| Joint::revolute(format!("j{i}"), -3.0, 3.0).weight(w))
                .collect::<Vec<_>>()
        };
        let unit = JointSpace::new(joints(1.0)).unwrap();
        let doubled = JointSpace::new(joints(2.0)).unwrap();
        assert!(unit.is_euclidean() && !doubled.is_euclidean());
        let a = [0.3, -1.7, 2.9, 0.0, -0.1, 1.1, -2.5];
        let b = [-2.2, 0.4, 1.3, -3.0, 0.7, 1.1, 2.75];
        let mut sum = 0.0;
        for (x, y) in a.iter().zip(&b) {
            let delta = 1.0 * (y - x);
            sum += delta * delta;
        }
        assert_eq!(unit.distance(&a, &b).to_bits(), sum.sqrt().to_bits());
        // Doubling every weight doubles the distance exactly (powers of two scale exactly).
        assert_eq!(doubled.distance(&a, &b), 2.0 * unit.distance(&a, &b));
    }

    #[test]
    fn a_state_outside_a_limit_or_not_finite_names_the_joint() {
        let space = JointSpace::new(vec![
            Joint::revolute("shoulder", -1.0, 1.0),
            Joint::continuous("wrist"),
        ])
        .unwrap();
        assert!(space.check_state(&[0.5, -PI]).is_ok());
        let e = space.check_state(&[0.0, 4.0]).unwrap_err();
        assert!(
            matches!(&e, SpaceError::JointOutsideLimits { joint, index: 1, .. } if joint == "wrist"),
            "{e}"
        );
        assert!(
            e.to_string()
                .starts_with("joint `wrist` (coordinate 1) is 4"),
            "{e}"
        );
        let e = space.check_state(&[f64::NAN, 0.0]).unwrap_err();
        assert!(e.to_string().contains("joint `shoulder`"), "{e}");
        assert!(matches!(
            space.check_state(&[0.0]),
            Err(SpaceError::DimensionMismatch { .. })
        ));
    }

    #[test]
    fn continuous_joint_interpolates_across_the_seam() {
        let space = JointSpace::new(vec![Joint::continuous("c")]).unwrap();
        let mut out = [0.0];
        space.interpolate(&[3.0], &[-3.0], 0.5, &mut out);
        // Halfway the short way round is ±π.
        assert!((out[0].abs() - PI).abs() < 1e-12);
    }

    #[test]
    fn weights_scale_the_metric_and_measure() {
        let space = JointSpace::new(vec![
            Joint::prismatic("p", 0.0, 1.0).weight(2.0),
            Joint::continuous("c"),
        ])
        .unwrap();
        assert!((space.distance(&[0.0, 0.0], &[0.5, 0.0]) - 1.0).abs() < 1e-12);
        assert!((space.measure() - 2.0 * TAU).abs() < 1e-12);
        assert!((space.maximum_extent() - (4.0 + PI * PI).sqrt()).abs() < 1e-12);
        assert!(!space.is_euclidean());
    }

    #[test]
    fn rejects_bad_joints() {
        assert!(matches!(
            JointSpace::new(vec![Joint::revolute("r", 1.0, -1.0)]),
            Err(SpaceError::EmptyInterval { index: 0, .. })
        ));
        assert!(matches!(
            JointSpace::new(vec![
                Joint::continuous("c"),
                Joint::continuous("d").weight(0.0)
            ]),
            Err(SpaceError::BadWeight { index: 1, .. })
        ));
        assert_eq!(JointSpace::new(vec![]), Err(SpaceError::ZeroDimension));
    }
}
