//! [`Trajectory`]: a timed joint-space motion, piecewise quadratic — knots of time, position,
//! velocity and acceleration, the acceleration constant from one knot to the next.

use crate::{MotionLimits, TrajectoryError};

/// One knot of a [`Trajectory`], or one sample of it: a time (seconds from the start), and per
/// coordinate a position, a velocity and an acceleration.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Seconds from the start.
    pub time: f64,
    /// Joint positions (rad or m).
    pub position: Vec<f64>,
    /// Joint velocities.
    pub velocity: Vec<f64>,
    /// Joint accelerations: at a knot, the constant acceleration until the next knot.
    pub acceleration: Vec<f64>,
}

/// A timed motion through a planned path, starting and ending at rest.
///
/// Piecewise quadratic: from knot `k` to knot `k + 1` every coordinate moves at the knot's
/// constant acceleration, `q(t) = q_k + v_k τ + a_k τ² / 2` with `τ = t − t_k`; the last
/// knot's velocity and acceleration are zero. Knot times strictly increase from 0. Built by
/// [`stop_at_corners`](Self::stop_at_corners) or [`blended`](Self::blended)
/// (`blend_timing.rs`).
///
/// # The guarantee
/// Let `path` be a polyline whose straight segments are collision-free for an
/// [`ArmChecker`](crate::ArmChecker) (as our planners certify every edge they return).
///
/// - [`Trajectory::stop_at_corners`]: every configuration of the trajectory is on a segment of
///   `path` (so collision-free), it passes through every waypoint at rest, and every
///   coordinate's velocity and acceleration stay within the [`MotionLimits`] at every instant
///   (velocity is piecewise linear and acceleration piecewise constant, and both are within
///   the limits at every knot). Each segment takes the least time any motion starting and
///   ending at rest along it, under those limits, can.
/// - [`Trajectory::blended`]: every configuration is either on a segment of `path` or on a
///   blend `q(t) = q₀ + v₀ t + a t² / 2`, `t ∈ [0, τ]`, that
///   [`BlendCertifier`](crate::BlendCertifier) certified: cut into `m` chords of time
///   `h = τ / m`, each chord certified (every configuration of it, not only grid points) by an
///   [`ArmChecker`](crate::ArmChecker) of the robot with every sphere grown by `δ`, where
///   `δ ≥ max_k Σ_j λ_kj |a_j| h² / 8` bounds how far any point of link `k`'s spheres can be
///   from where it is on the chord ([`LeverArms`](crate::LeverArms) `λ`). So at every
///   instant of the blend every sphere is clear of the scene and of the link pairs checked
///   by at least the checker's margin — the sense in which the planner's edges are
///   certified. The limits hold as above; a blend is in the convex hull of its ends (on the
///   segments) and its corner, so within the joint position limits. A blend that cannot be
///   certified is shrunk, then replaced by a stop at its corner.
///
/// "Exactly" is up to floating-point rounding: limits are rounded down and durations up by
/// a relative 10⁻¹², and evaluation rounds (the checks of the comparison with TOPP-RA
/// measured at most 10⁻¹⁰ relative, in finite differences of 1 ms samples).
///
/// Both start and end at rest at the path's ends. Continuous (wrapping) joints are taken as the
/// path gives them, unwrapped: no angle is wrapped by the timing.
///
/// # Jerk
/// Jerk limits are not offered. A jerk-limited profile (Ruckig's, say) has no constant
/// acceleration phases, so the exact piecewise-quadratic evaluation and the chord
/// certification of blends would have to be redone for cubic pieces; a crate such as
/// `rsruckig` would time single segments but not certify corner blends. A controller
/// needing bounded jerk can follow this trajectory through its own jerk-limited filter.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    names: Vec<String>,
    knots: Vec<Sample>,
}

impl Trajectory {
    /// A trajectory of the joints `names` with `knots` as the timing code builds them.
    pub(crate) fn from_knots(names: Vec<String>, knots: Vec<Sample>) -> Self {
        Self { names, knots }
    }

    /// The coordinates' names.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The knots: the times where the acceleration changes, with the state there.
    pub fn knots(&self) -> &[Sample] {
        &self.knots
    }

    /// How long it takes, in seconds.
    pub fn duration(&self) -> f64 {
        self.knots.last().map_or(0.0, |k| k.time)
    }

    /// The state at time `t` (clamped into `[0, duration]`), exactly as the polynomials give
    /// it, into `sample` (whose vectors are resized to the dimension once: no allocation on
    /// later calls).
    pub fn evaluate_into(&self, t: f64, sample: &mut Sample) {
        let n = self.names.len();
        for v in [
            &mut sample.position,
            &mut sample.velocity,
            &mut sample.acceleration,
        ] {
            v.resize(n, 0.0);
        }
        let t = if t.is_nan() {
            0.0
        } else {
            t.clamp(0.0, self.duration())
        };
        sample.time = t;
        let k = self
            .knots
            .partition_point(|k| k.time <= t)
            .saturating_sub(1);
        let knot = &self.knots[k];
        if k + 1 == self.knots.len() {
            sample.position.copy_from_slice(&knot.position);
            sample.velocity.fill(0.0);
            sample.acceleration.fill(0.0);
            return;
        }
        let tau = t - knot.time;
        for j in 0..n {
            let (q, v, a) = (knot.position[j], knot.velocity[j], knot.acceleration[j]);
            sample.position[j] = q + v * tau + 0.5 * a * tau * tau;
            sample.velocity[j] = v + a * tau;
            sample.acceleration[j] = a;
        }
    }

    /// The state at time `t` (clamped into `[0, duration]`).
    pub fn evaluate(&self, t: f64) -> Sample {
        let mut sample = Sample {
            time: 0.0,
            position: Vec::new(),
            velocity: Vec::new(),
            acceleration: Vec::new(),
        };
        self.evaluate_into(t, &mut sample);
        sample
    }

    /// Samples every `period` seconds from 0, and at the end.
    ///
    /// # Errors
    /// [`TrajectoryError::BadPeriod`] for a period that is not positive and finite, or so
    /// short that it would take over 10⁷ samples.
    pub fn sample(&self, period: f64) -> Result<Vec<Sample>, TrajectoryError> {
        let count = self.duration() / period;
        if !(period > 0.0 && period.is_finite() && count < 1e7) {
            return Err(TrajectoryError::BadPeriod { value: period });
        }
        let mut out: Vec<Sample> = (0_u32..)
            .map(|i| f64::from(i) * period)
            .take_while(|&t| t < self.duration())
            .map(|t| self.evaluate(t))
            .collect();
        out.push(self.evaluate(self.duration()));
        Ok(out)
    }

    /// Whether every velocity and acceleration of every knot (so, the pieces being linear in
    /// velocity, of every instant) is within `limits` times `1 + tolerance`.
    pub fn within(&self, limits: &MotionLimits, tolerance: f64) -> bool {
        let grow = 1.0 + tolerance;
        let pieces = self.knots.windows(2);
        pieces.clone().all(|w| {
            (0..self.names.len()).all(|j| {
                w[0].acceleration[j].abs() <= limits.acceleration()[j] * grow
                    && w[0].velocity[j].abs() <= limits.velocity()[j] * grow
                    && w[1].velocity[j].abs() <= limits.velocity()[j] * grow
            })
        })
    }
}

/// `path` without consecutive repeats: each waypoint equal (bit for bit) to the one before it
/// is dropped, for callers that choose to merge them rather than be refused
/// ([`TrajectoryError::RepeatedWaypoint`]).
pub fn merge_repeated_waypoints<P: AsRef<[f64]>>(path: &[P]) -> Vec<Vec<f64>> {
    let mut out: Vec<Vec<f64>> = Vec::with_capacity(path.len());
    for p in path {
        if out.last().is_none_or(|last| last.as_slice() != p.as_ref()) {
            out.push(p.as_ref().to_vec());
        }
    }
    out
}

/// Checks a path to time: at least two waypoints, each of `names.len()` finite coordinates,
/// none equal to the one before.
pub(crate) fn checked_path<P: AsRef<[f64]>>(
    path: &[P],
    names: &[String],
) -> Result<(), TrajectoryError> {
    if path.len() < 2 {
        return Err(TrajectoryError::TooShort { points: path.len() });
    }
    for (index, p) in path.iter().enumerate() {
        let p = p.as_ref();
        if p.len() != names.len() {
            return Err(TrajectoryError::WrongDimension {
                index,
                found: p.len(),
                expected: names.len(),
            });
        }
        if let Some(j) = p.iter().position(|x| !x.is_finite()) {
            return Err(TrajectoryError::NotFinite {
                index,
                joint: names[j].clone(),
                value: p[j],
            });
        }
        if index > 0 && path[index - 1].as_ref() == p {
            return Err(TrajectoryError::RepeatedWaypoint { index });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names() -> Vec<String> {
        vec!["a".into(), "b".into()]
    }

    #[test]
    fn refuses_bad_paths_by_name() {
        let n = names();
        assert_eq!(
            checked_path(&[[0.0, 0.0]], &n),
            Err(TrajectoryError::TooShort { points: 1 })
        );
        assert!(matches!(
            checked_path(&[[0.0, 0.0], [0.0, f64::NAN]], &n),
            Err(TrajectoryError::NotFinite { index: 1, joint, .. }) if joint == "b"
        ));
        assert_eq!(
            checked_path(&[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0]], &n),
            Err(TrajectoryError::RepeatedWaypoint { index: 2 })
        );
        assert!(matches!(
            checked_path(&[vec![0.0, 0.0], vec![1.0]], &n),
            Err(TrajectoryError::WrongDimension {
                index: 1,
                found: 1,
                expected: 2
            })
        ));
        let merged = merge_repeated_waypoints(&[[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]]);
        assert_eq!(merged, vec![vec![0.0, 0.0], vec![1.0, 0.0]]);
    }

    #[test]
    fn evaluates_the_pieces_exactly() {
        let knot = |time: f64, q: f64, v: f64, a: f64| Sample {
            time,
            position: vec![q, 0.0],
            velocity: vec![v, 0.0],
            acceleration: vec![a, 0.0],
        };
        let t = Trajectory::from_knots(
            names(),
            vec![
                knot(0.0, 0.0, 0.0, 2.0),
                knot(1.0, 1.0, 2.0, -2.0),
                knot(2.0, 2.0, 0.0, 0.0),
            ],
        );
        let s = t.evaluate(0.5);
        assert_eq!(
            (s.position[0], s.velocity[0], s.acceleration[0]),
            (0.25, 1.0, 2.0)
        );
        let s = t.evaluate(1.5);
        assert_eq!((s.position[0], s.velocity[0]), (1.75, 1.0));
        assert_eq!(t.evaluate(9.0).position[0], 2.0);
        assert_eq!(t.sample(0.75).unwrap().len(), 4);
        assert!(matches!(
            t.sample(0.0),
            Err(TrajectoryError::BadPeriod { .. })
        ));
    }
}
