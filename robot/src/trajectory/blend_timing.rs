//! The timing of a polyline: per corner a passing speed and a constant-acceleration blend,
//! per segment a bang-coast-bang speed profile between its corners, the knots they make, and
//! the two constructors of [`Trajectory`].
//!
//! # The scheme
//! Segment `i` runs from waypoint `w_i` to `w_{i+1}` along `d_i = w_{i+1} − w_i`; on it the
//! configuration is `w_i + σ d_i`, and the *speed* `σ̇` is at most `S_i = min_j V_j / |d_ij|`
//! and changes at most at `α_i = min_j A_j / |d_ij|`: so every coordinate keeps its limits.
//!
//! At corner `k` the motion arrives along `d_{k−1}` at speed `e_k` and leaves along `d_k` at
//! `x_k`: `e_k = c_k S_{k−1} min(1, r_k)` and `x_k = c_k S_k min(1, 1 / r_k)` for a *corner
//! factor* `c_k ∈ [0, 1]` (0 at the path's ends: at rest) and a ratio `r_k` that slows one
//! side more than the other. The velocity changes from `e_k d_{k−1}` to `x_k d_k` at constant
//! acceleration over `τ_k = max_j |x_k d_kj − e_k d_{k−1,j}| / A_j`, centred on the waypoint:
//! the blend runs from `w_k − e_k d_{k−1} τ_k / 2` to `w_k + x_k d_k τ_k / 2`, a parabola (a
//! quadratic Bézier curve with control points these two and `w_k`). `c_k = 0` is a stop at
//! `w_k`. Between its two blends a segment has the length `L_i = 1 − x_i τ_i / 2 − e_{i+1}
//! τ_{i+1} / 2` left, crossed by the fastest profile from `x_i` to `e_{i+1}`: speed up at
//! `α_i`, cruise at the peak (at most `S_i`), slow down at `α_i` — feasible when
//! `|e_{i+1}² − x_i²| ≤ 2 α_i L_i`. A segment between two stops is then the time-optimal
//! synchronized trapezoid (or triangle).
//!
//! Corner factors start at 1 (or their caps) and ratios at 1; while a segment is infeasible
//! the factor of the corner at its faster end shrinks by a tenth. Then two sweeps over the
//! corners each try the factors 1, 0.9, …, 0 (within the caps) with the ratios 1, 0.7, 0.5,
//! 1/0.7, 2 and keep the pair that takes least time, the other corners fixed (on the Panda's
//! simplified MotionBenchMaker paths the ratios took the median duration from 1.086 to 1.084
//! times TOPP-RA's, and the factors' grid from 0.2 to 0.1 took it from 1.099 to 1.086). Velocity is linear in a blend between two velocities within the limits
//! and each blend's acceleration is `(v_out − v_in) / τ_k`: the limits hold exactly (limits
//! rounded down, durations up, by a relative 10⁻¹²).

use crate::trajectory::trajectory::checked_path;
use crate::{BlendCertifier, MotionLimits, Sample, Trajectory, TrajectoryError};

/// The relative rounding of limits and durations that keeps the limits through the
/// floating-point arithmetic.
const ROUNDING: f64 = 1e-12;

/// Shrinks of a blend (its corner factor times [`SHRINK`]) before its corner becomes a stop.
const SHRINKS: u32 = 12;

/// What a shrink multiplies a corner factor by: the blend's distance from its corner by
/// about a half.
const SHRINK: f64 = 0.7;

/// The corner factors tried by the sweeps, as shares of the corner's cap.
const FACTORS: [f64; 11] = [1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.0];

/// The ratios of a corner's speed in to its speed out tried by the sweeps.
const RATIOS: [f64; 5] = [1.0, 0.7, 0.5, 1.0 / 0.7, 2.0];

/// Sweeps of the corner factors.
const SWEEPS: usize = 2;

/// How a blended trajectory came out: what became of its interior corners, and the blend
/// certifications it took.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BlendReport {
    /// Interior corners passed by a blend certified as first timed.
    pub blended: usize,
    /// Interior corners passed by a blend certified after shrinking.
    pub shrunk: usize,
    /// Interior corners where the motion stops.
    pub stopped: usize,
    /// Blend certifications asked of the certifier.
    pub certifications: usize,
}

/// The polyline to time.
struct Polyline<'a> {
    points: Vec<&'a [f64]>,
    directions: Vec<Vec<f64>>,
    /// Per segment, its speed and speed-change limits `S_i`, `α_i`.
    speed: Vec<(f64, f64)>,
    limits: &'a MotionLimits,
}

/// One segment's speed profile: from `x` speeding up to `peak`, cruising, slowing to `e`,
/// over the length `length` starting at `from` (fractions of the segment).
#[derive(Debug, Clone, Copy)]
struct Profile {
    from: f64,
    x: f64,
    peak: f64,
    accelerate: f64,
    cruise: f64,
    decelerate: f64,
}

impl Polyline<'_> {
    fn segments(&self) -> usize {
        self.directions.len()
    }

    /// Corner `k`'s speeds in and out at `corner`.
    fn corner_speeds(&self, k: usize, corner: Corner) -> (f64, f64) {
        let m = self.segments();
        if k == 0 || k == m {
            return (0.0, 0.0);
        }
        let Corner { factor, ratio } = corner;
        (
            factor * self.speed[k - 1].0 * ratio.min(1.0),
            factor * self.speed[k].0 * ratio.recip().min(1.0),
        )
    }

    /// The blend duration at corner `k` with speeds `(e, x)`.
    fn blend(&self, k: usize, (e, x): (f64, f64)) -> f64 {
        let a = self.limits.acceleration();
        let mut tau = 0.0_f64;
        for (j, limit) in a.iter().enumerate() {
            let vin = if k > 0 {
                e * self.directions[k - 1][j]
            } else {
                0.0
            };
            let vout = if k < self.segments() {
                x * self.directions[k][j]
            } else {
                0.0
            };
            tau = tau.max((vout - vin).abs() / limit);
        }
        tau * (1.0 + ROUNDING)
    }

    /// Segment `i`'s profile between corner factors `ci` and `cj` (`None`: infeasible).
    fn profile(&self, i: usize, ci: Corner, cj: Corner) -> Option<Profile> {
        let (_, x) = self.corner_speeds(i, ci);
        let (e, _) = self.corner_speeds(i + 1, cj);
        let (top, alpha) = self.speed[i];
        let from = 0.5 * x * self.blend(i, self.corner_speeds(i, ci));
        let length = 1.0 - from - 0.5 * e * self.blend(i + 1, self.corner_speeds(i + 1, cj));
        if length.is_nan() || length < 0.0 || (e * e - x * x).abs() > 2.0 * alpha * length {
            return None;
        }
        let peak = (alpha * length + 0.5 * (x * x + e * e))
            .sqrt()
            .min(top)
            .max(x)
            .max(e);
        let accelerate = (peak - x) / alpha;
        let decelerate = (peak - e) / alpha;
        let ramps = (2.0 * peak * peak - x * x - e * e) / (2.0 * alpha);
        let cruise = if peak > 0.0 {
            ((length - ramps) / peak).max(0.0)
        } else {
            0.0
        };
        Some(Profile {
            from,
            x,
            peak,
            accelerate,
            cruise,
            decelerate,
        })
    }

    /// The time from corner `k`'s blend through segment `k` (`None`: infeasible).
    fn time(&self, c: &[Corner], i: usize) -> Option<f64> {
        let p = self.profile(i, c[i], c[i + 1])?;
        Some(
            0.5 * self.blend(i, self.corner_speeds(i, c[i]))
                + p.accelerate
                + p.cruise
                + p.decelerate
                + 0.5 * self.blend(i + 1, self.corner_speeds(i + 1, c[i + 1])),
        )
    }

    /// Corners within `caps` (ends at rest) that make every segment feasible, tuned for time
    /// as the module docs say.
    fn factors(&self, caps: &[f64]) -> Vec<Corner> {
        let m = self.segments();
        let mut c: Vec<Corner> = caps
            .iter()
            .map(|&factor| Corner { factor, ratio: 1.0 })
            .collect();
        c[0].factor = 0.0;
        c[m].factor = 0.0;
        for _ in 0..100_000 {
            let Some(i) = (0..m).find(|&i| self.profile(i, c[i], c[i + 1]).is_none()) else {
                break;
            };
            // Shrink the faster end (an end at rest cannot be the cause alone).
            let (_, x) = self.corner_speeds(i, c[i]);
            let (e, _) = self.corner_speeds(i + 1, c[i + 1]);
            let k = if (x >= e && i > 0) || i + 1 == m {
                i
            } else {
                i + 1
            };
            let f = &mut c[k].factor;
            *f = if *f < 1e-6 { 0.0 } else { *f * 0.9 };
        }
        if (0..m).any(|i| self.profile(i, c[i], c[i + 1]).is_none()) {
            c.iter_mut().for_each(|corner| corner.factor = 0.0);
        }
        for _ in 0..SWEEPS {
            for k in 1..m {
                let local =
                    |c: &[Corner]| -> Option<f64> { Some(self.time(c, k - 1)? + self.time(c, k)?) };
                let mut best = (local(&c).unwrap_or(f64::INFINITY), c[k]);
                for f in FACTORS {
                    for ratio in RATIOS {
                        let corner = Corner {
                            factor: f * caps[k],
                            ratio,
                        };
                        let mut trial = c.clone();
                        trial[k] = corner;
                        if let Some(t) = local(&trial)
                            && t < best.0
                        {
                            best = (t, corner);
                        }
                    }
                }
                c[k] = best.1;
            }
        }
        c
    }
}

/// How a corner is passed: its factor `c_k` of the segments' top speeds, and the ratio of
/// the speed in to the speed out (1: both at `c_k` of their top speeds; below 1 the speed in
/// is lowered, above 1 the speed out).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Corner {
    factor: f64,
    ratio: f64,
}

/// The knots of the polyline with corner factors `c` (feasible), and per interior blend its
/// corner and the index of its first knot.
fn knots(line: &Polyline<'_>, c: &[Corner]) -> (Vec<Sample>, Vec<(usize, usize)>) {
    let n = line.limits.names().len();
    let m = line.segments();
    let mut out = Vec::new();
    let mut blends = Vec::new();
    let mut t = 0.0;
    let zero = vec![0.0; n];
    let along =
        |i: usize, s: f64| -> Vec<f64> { line.directions[i].iter().map(|d| s * d).collect() };
    let point = |i: usize, f: f64| -> Vec<f64> {
        let (w, d) = (line.points[i], &line.directions[i]);
        (0..n).map(|j| w[j] + f * d[j]).collect()
    };
    for k in 0..=m {
        let (e, x) = line.corner_speeds(k, c[k]);
        let tau = line.blend(k, (e, x));
        // A phase too short to advance the clock is left out (its motion is below rounding).
        if t + tau > t {
            let vin = if k > 0 { along(k - 1, e) } else { zero.clone() };
            let vout = if k < m { along(k, x) } else { zero.clone() };
            let entry = if k > 0 {
                point(k - 1, 1.0 - 0.5 * e * tau)
            } else {
                line.points[0].to_vec()
            };
            let acceleration = (0..n).map(|j| (vout[j] - vin[j]) / tau).collect();
            if k > 0 && k < m {
                blends.push((k, out.len()));
            }
            out.push(Sample {
                time: t,
                position: entry,
                velocity: vin,
                acceleration,
            });
            t += tau;
        }
        if k == m {
            break;
        }
        let Some(p) = line.profile(k, c[k], c[k + 1]) else {
            continue;
        };
        let alpha = line.speed[k].1;
        let mut at = p.from;
        for (duration, v0, a) in [
            (p.accelerate, p.x, alpha),
            (p.cruise, p.peak, 0.0),
            (p.decelerate, p.peak, -alpha),
        ] {
            if t + duration > t {
                out.push(Sample {
                    time: t,
                    position: point(k, at),
                    velocity: along(k, v0),
                    acceleration: along(k, a),
                });
                t += duration;
                at += v0 * duration + 0.5 * a * duration * duration;
            }
        }
    }
    out.push(Sample {
        time: t,
        position: line.points[m].to_vec(),
        velocity: zero.clone(),
        acceleration: zero,
    });
    (out, blends)
}

impl Trajectory {
    /// The motion along `path` (rows of the robot's coordinates, as the planner returned it)
    /// that stops at every waypoint: each segment the time-optimal synchronized
    /// bang-coast-bang profile (a trapezoid, or a triangle when the segment is too short to
    /// reach its top speed) under every coordinate's velocity and acceleration limit. Every
    /// configuration is on a segment of `path`; the limits hold exactly.
    ///
    /// Continuous joints are taken as given: a segment from 3 to −3 rad turns 6 rad the long
    /// way (our planners return unwrapped paths).
    ///
    /// # Errors
    /// [`TrajectoryError::TooShort`], [`WrongDimension`](TrajectoryError::WrongDimension),
    /// [`NotFinite`](TrajectoryError::NotFinite) and
    /// [`RepeatedWaypoint`](TrajectoryError::RepeatedWaypoint) (see
    /// [`merge_repeated_waypoints`](crate::merge_repeated_waypoints)).
    pub fn stop_at_corners<P: AsRef<[f64]>>(
        path: &[P],
        limits: &MotionLimits,
    ) -> Result<Self, TrajectoryError> {
        let line = polyline(path, limits)?;
        Ok(timed(&line, &vec![0.0; line.segments() + 1]).0)
    }

    /// The motion along `path` with parabolic blends at its corners (module docs of
    /// `blend_timing.rs`), each blend certified collision-free by `certifier`: a blend it
    /// cannot certify is shrunk (its corner factor times 0.7, up to twelve times) and then made a
    /// stop. Returns the faster of that and [`stop_at_corners`](Self::stop_at_corners), with
    /// what became of the corners.
    ///
    /// Every configuration is on a segment of `path` or on a certified blend; the limits hold
    /// exactly. See [`Trajectory`]'s docs for the guarantee.
    ///
    /// # Errors
    /// As [`stop_at_corners`](Self::stop_at_corners).
    pub fn blended<P: AsRef<[f64]>>(
        path: &[P],
        limits: &MotionLimits,
        certifier: &BlendCertifier,
    ) -> Result<(Self, BlendReport), TrajectoryError> {
        let line = polyline(path, limits)?;
        let m = line.segments();
        let mut caps = vec![1.0; m + 1];
        let mut shrinks = vec![0_u32; m + 1];
        let mut report = BlendReport::default();
        let mut certified = std::collections::HashMap::new();
        let trajectory = loop {
            let (trajectory, blends) = timed(&line, &caps);
            let mut failed = None;
            for (k, at) in blends {
                let (entry, exit) = (&trajectory.knots()[at], &trajectory.knots()[at + 1]);
                let key: Vec<u64> = entry
                    .velocity
                    .iter()
                    .chain(&exit.velocity)
                    .map(|v| v.to_bits())
                    .collect();
                let ok = *certified.entry((k, key)).or_insert_with(|| {
                    report.certifications += 1;
                    certifier.certify_blend(entry, exit.time - entry.time)
                });
                if !ok {
                    failed = Some(k);
                    break;
                }
            }
            let Some(k) = failed else { break trajectory };
            let current = line.factors(&caps)[k].factor;
            if shrinks[k] < SHRINKS {
                shrinks[k] += 1;
                caps[k] = SHRINK * current;
            } else {
                caps[k] = 0.0;
            }
        };
        let factors = line.factors(&caps);
        for k in 1..m {
            match (factors[k].factor == 0.0, shrinks[k]) {
                (true, _) => report.stopped += 1,
                (false, 0) => report.blended += 1,
                (false, _) => report.shrunk += 1,
            }
        }
        let stopping = timed(&line, &vec![0.0; m + 1]).0;
        if stopping.duration() < trajectory.duration() {
            report = BlendReport {
                stopped: m - 1,
                certifications: report.certifications,
                ..BlendReport::default()
            };
            return Ok((stopping, report));
        }
        Ok((trajectory, report))
    }
}

/// The polyline of a checked `path`.
fn polyline<'a, P: AsRef<[f64]>>(
    path: &'a [P],
    limits: &'a MotionLimits,
) -> Result<Polyline<'a>, TrajectoryError> {
    checked_path(path, limits.names())?;
    let points: Vec<&[f64]> = path.iter().map(AsRef::as_ref).collect();
    let directions: Vec<Vec<f64>> = points
        .windows(2)
        .map(|w| w[0].iter().zip(w[1]).map(|(a, b)| b - a).collect())
        .collect();
    let speed = directions
        .iter()
        .map(|d: &Vec<f64>| {
            let bound = |limit: &[f64]| {
                (0..d.len())
                    .filter(|&j| d[j] != 0.0)
                    .map(|j| limit[j] / d[j].abs())
                    .fold(f64::INFINITY, f64::min)
                    * (1.0 - ROUNDING)
            };
            (bound(limits.velocity()), bound(limits.acceleration()))
        })
        .collect();
    Ok(Polyline {
        points,
        directions,
        speed,
        limits,
    })
}

/// The trajectory with corner factors tuned within `caps`, and its interior blends as
/// [`knots`] lists them.
fn timed(line: &Polyline<'_>, caps: &[f64]) -> (Trajectory, Vec<(usize, usize)>) {
    let factors = line.factors(caps);
    let (knots, blends) = knots(line, &factors);
    (
        Trajectory::from_knots(line.limits.names().to_vec(), knots),
        blends,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one_joint() -> MotionLimits {
        MotionLimits::new(vec!["a".into()], vec![1.0], vec![1.0]).unwrap()
    }

    #[test]
    fn a_segment_takes_the_time_optimal_trapezoid_or_triangle() {
        // 3 rad at 1 rad/s and 1 rad/s²: 1 s up (0.5 rad), 2 s cruising 2 rad, 1 s down.
        let t = Trajectory::stop_at_corners(&[[0.0], [3.0]], &one_joint()).unwrap();
        assert!((t.duration() - 4.0).abs() < 1e-9, "{}", t.duration());
        // 0.25 rad never reaches 1 rad/s: a triangle of 2·√0.25 s.
        let t = Trajectory::stop_at_corners(&[[0.0], [0.25]], &one_joint()).unwrap();
        assert!((t.duration() - 1.0).abs() < 1e-9, "{}", t.duration());
        // A two-joint segment is as slow as its slowest joint, both synchronized.
        let limits =
            MotionLimits::new(vec!["a".into(), "b".into()], vec![1.0, 0.5], vec![1.0, 1.0])
                .unwrap();
        let t = Trajectory::stop_at_corners(&[[0.0, 0.0], [3.0, 3.0]], &limits).unwrap();
        // Joint b: 0.5 s up (0.125 rad), 5.5 s cruising 2.75 rad, 0.5 s down.
        assert!((t.duration() - 6.5).abs() < 1e-9, "{}", t.duration());
        let middle = t.evaluate(3.25);
        assert!((middle.position[0] - middle.position[1]).abs() < 1e-12);
    }

    #[test]
    fn a_straight_corner_is_passed_at_full_speed() {
        // Two collinear segments: blending does not slow down at the middle waypoint.
        let limits = one_joint();
        let line = polyline(&[[0.0], [3.0], [6.0]], &limits).unwrap();
        let factors = line.factors(&[1.0, 1.0, 1.0]);
        assert_eq!(factors[1].factor, 1.0);
        let (t, _) = timed(&line, &[1.0, 1.0, 1.0]);
        assert!((t.duration() - 7.0).abs() < 1e-9, "{}", t.duration());
    }
}
