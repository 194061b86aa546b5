//! The timing of a polyline: per corner a passing speed and a constant-acceleration blend,
//! per segment a bang-coast-bang speed profile between its corners, the knots they make, and
//! the two constructors of [`Trajectory`].
//!
//! # The scheme
//! Segment `i` runs from waypoint `w_i` to `w_{i+1}` along `d_i = w_{i+1} − w_i`; on it the
//! configuration is `w_i + σ d_i`, and the *speed* `σ̇` is at most `S_i = min_j V_j / |d_ij|`
//! and changes at most at `α_i = min_j A_j / |d_ij|`: so every coordinate keeps its limits.
//!
//! At corner `k` the motion arrives along `d_{k−1}` at speed `e_k = u_k S_{k−1}` and leaves
//! along `d_k` at `x_k = v_k S_k`, for shares `u_k, v_k ∈ [0, 1]` (0 at the path's ends: at
//! rest). The velocity changes from `e_k d_{k−1}` to `x_k d_k` at constant acceleration over
//! `τ_k = max_j |x_k d_kj − e_k d_{k−1,j}| / A_j` (the least time any motion takes between
//! these velocities), centred on the waypoint: the blend runs from `w_k − e_k d_{k−1} τ_k / 2`
//! to `w_k + x_k d_k τ_k / 2`, a parabola (a quadratic Bézier curve with control points these
//! two and `w_k`). `u_k = v_k = 0` is a stop at `w_k`. Between its two blends a segment has
//! the length `L_i = 1 − x_i τ_i / 2 − e_{i+1} τ_{i+1} / 2` left — a blend may take any part
//! of its segments, up to all of it shared with the next blend — crossed by the fastest
//! profile from `x_i` to `e_{i+1}`: speed up at `α_i`, cruise at the peak (at most `S_i`),
//! slow down at `α_i` — feasible when `L_i ≥ 0` and `|e_{i+1}² − x_i²| ≤ 2 α_i L_i`. A
//! segment between two stops is then the time-optimal synchronized trapezoid (or triangle).
//!
//! Given the shares, everything else is the fastest it can be; the shares are chosen by
//! `corner_search.rs`: exactly the best over a grid (dynamic programming along the chain of
//! corners), refined around the best. On the Panda's simplified MotionBenchMaker paths this
//! took the median duration from 1.084 times TOPP-RA's (coordinate sweeps over corner factors
//! and speed ratios, as before) to 1.041 (`benches/peers/toppra/README.md`); most of what is
//! left is blends shrunk where the simplified path wraps a corner tightly around an obstacle,
//! and with a path simplified keeping 1 cm of room from obstacles (`mit-star plan
//! --blend-room`) the median is 0.992. Velocity is
//! linear in a blend between two velocities within the limits and each blend's acceleration
//! is `(v_out − v_in) / τ_k`: the limits hold exactly (limits rounded down, durations up, by
//! a relative 10⁻¹²).

use super::corner_search::{Corner, best_corners};
use crate::trajectory::trajectory::checked_path;
use crate::{BlendCertifier, MotionLimits, Sample, Trajectory, TrajectoryError};

/// The relative rounding of limits and durations that keeps the limits through the
/// floating-point arithmetic.
const ROUNDING: f64 = 1e-12;

/// Rounds of shrinking a corner's blend after a failed certification before the corner
/// becomes a stop.
const SHRINKS: u32 = 12;

/// What a shrink multiplies a corner's speeds by (the blend's distance from its corner by
/// about a half), until the blend is certified.
const SHRINK: f64 = 0.7;

/// Bisections of the scale between the last shrink certified and the one before it.
const BISECTIONS: u32 = 4;

/// What the largest certified scale of a refused blend is multiplied by to cap its corner. A
/// blend bisected to the edge of what can be certified passes within micrometres of an
/// obstacle, where a check cutting it into other chords (a file sampled every millisecond,
/// checked piece by piece by `check_trajectory`) may fail to certify it, though it is
/// certified as timed. On the 175 Panda paths of `benches/peers/toppra`, 4 such files failed
/// that check without backing off, 1 at 0.97, none at 0.95 or 0.9 (median duration ratios to
/// TOPP-RA 1.031, 1.034, 1.041, 1.045).
const BACK_OFF: f64 = 0.95;

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
pub(super) struct Polyline<'a> {
    points: Vec<&'a [f64]>,
    directions: Vec<Vec<f64>>,
    /// Per segment, its speed and speed-change limits `S_i`, `α_i`.
    pub(super) speed: Vec<(f64, f64)>,
    limits: &'a MotionLimits,
}

/// One segment's speed profile: from `x` speeding up to `peak`, cruising, slowing to `e`,
/// over the length `length` starting at `from` (fractions of the segment).
#[derive(Debug, Clone, Copy)]
pub(super) struct Profile {
    from: f64,
    x: f64,
    peak: f64,
    accelerate: f64,
    cruise: f64,
    decelerate: f64,
}

impl Profile {
    /// The fastest profile over a segment of top speed and speed-change limit `(top,
    /// alpha)`, leaving a blend of `tau_x` seconds at speed `x` and entering one of `tau_e`
    /// seconds at speed `e` (`None`: the blends leave too little of the segment).
    pub(super) fn new(
        (top, alpha): (f64, f64),
        (x, tau_x): (f64, f64),
        (e, tau_e): (f64, f64),
    ) -> Option<Self> {
        let from = 0.5 * x * tau_x;
        let length = 1.0 - from - 0.5 * e * tau_e;
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
        Some(Self {
            from,
            x,
            peak,
            accelerate,
            cruise,
            decelerate,
        })
    }

    /// The time from the end of the blend before to the start of the blend after.
    pub(super) fn duration(&self) -> f64 {
        self.accelerate + self.cruise + self.decelerate
    }
}

impl Polyline<'_> {
    /// The number of segments.
    pub(super) fn segments(&self) -> usize {
        self.directions.len()
    }

    /// Corner `k`'s speeds in and out at `corner` (at rest at the path's ends).
    pub(super) fn corner_speeds(&self, k: usize, corner: Corner) -> (f64, f64) {
        let m = self.segments();
        if k == 0 || k == m {
            return (0.0, 0.0);
        }
        (
            corner.enter * self.speed[k - 1].0,
            corner.leave * self.speed[k].0,
        )
    }

    /// The blend duration at corner `k` with speeds `(e, x)`.
    pub(super) fn blend(&self, k: usize, (e, x): (f64, f64)) -> f64 {
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

    /// Segment `i`'s profile between corners `ci` and `cj` (`None`: infeasible).
    pub(super) fn profile(&self, i: usize, ci: Corner, cj: Corner) -> Option<Profile> {
        let (_, x) = self.corner_speeds(i, ci);
        let (e, _) = self.corner_speeds(i + 1, cj);
        Profile::new(
            self.speed[i],
            (x, self.blend(i, self.corner_speeds(i, ci))),
            (e, self.blend(i + 1, self.corner_speeds(i + 1, cj))),
        )
    }
}

/// The blend at corner `k` passed at `corner`: its first knot (time 0) and its duration.
fn blend_entry(line: &Polyline<'_>, k: usize, corner: Corner) -> (Sample, f64) {
    let n = line.limits.names().len();
    let m = line.segments();
    let (e, x) = line.corner_speeds(k, corner);
    let tau = line.blend(k, (e, x));
    let along = |i: usize, s: f64| -> Vec<f64> {
        if i < m {
            line.directions[i].iter().map(|d| s * d).collect()
        } else {
            vec![0.0; n]
        }
    };
    let vin = if k > 0 { along(k - 1, e) } else { vec![0.0; n] };
    let vout = along(k, x);
    let position = if k > 0 {
        let (w, d) = (line.points[k - 1], &line.directions[k - 1]);
        let f = 1.0 - 0.5 * e * tau;
        (0..n).map(|j| w[j] + f * d[j]).collect()
    } else {
        line.points[0].to_vec()
    };
    let acceleration = if tau > 0.0 {
        (0..n).map(|j| (vout[j] - vin[j]) / tau).collect()
    } else {
        vec![0.0; n]
    };
    let entry = Sample {
        time: 0.0,
        position,
        velocity: vin,
        acceleration,
    };
    (entry, tau)
}

/// The knots of the polyline with corners `c` (feasible).
fn knots(line: &Polyline<'_>, c: &[Corner]) -> Vec<Sample> {
    let n = line.limits.names().len();
    let m = line.segments();
    let mut out = Vec::new();
    let mut t = 0.0;
    let zero = vec![0.0; n];
    let along =
        |i: usize, s: f64| -> Vec<f64> { line.directions[i].iter().map(|d| s * d).collect() };
    let point = |i: usize, f: f64| -> Vec<f64> {
        let (w, d) = (line.points[i], &line.directions[i]);
        (0..n).map(|j| w[j] + f * d[j]).collect()
    };
    for k in 0..=m {
        let (mut entry, tau) = blend_entry(line, k, c[k]);
        // A phase too short to advance the clock is left out (its motion is below rounding).
        if t + tau > t {
            entry.time = t;
            out.push(entry);
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
    out
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
        let stops = vec![Corner::STOP; line.segments() + 1];
        Ok(timed(&line, &stops))
    }

    /// The motion along `path` with parabolic blends at its corners (module docs of
    /// `blend_timing.rs`), the corners' speeds those that take least time (a search over grids
    /// of them, `corner_search.rs`), each blend certified collision-free by `certifier`. A
    /// blend it cannot certify is shrunk (its speeds scaled down by 0.7 until certified, then
    /// bisected up to the largest scale certified), its corner capped a little below and the corners
    /// searched again; a corner refused twelve times becomes a stop. Returns the trajectory
    /// with what became of the corners; never slower than
    /// [`stop_at_corners`](Self::stop_at_corners) (stopping everywhere is among the candidates).
    ///
    /// Every configuration is on a segment of `path` or on a certified blend; the limits hold
    /// exactly. See [`Trajectory`]'s docs for the guarantee.
    ///
    /// A blend cuts inside its corner: where `path` wraps a corner tightly around an obstacle
    /// (as simplified paths do, grazing it at the checker's margin) the blend is shrunk and the
    /// motion slows there. A path simplified on the problem [padded](crate::ArmProblem::with_padding)
    /// by a little room (`mit-star plan --blend-room`), timed with a certifier of the problem
    /// as given, leaves its blends that room.
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
        caps[0] = 0.0;
        caps[m] = 0.0;
        let mut refusals = vec![0_u32; m + 1];
        let mut report = BlendReport::default();
        let mut verdicts = std::collections::HashMap::new();
        let mut certified = |k: usize, corner: Corner| -> bool {
            let key = (k, corner.enter.to_bits(), corner.leave.to_bits());
            *verdicts.entry(key).or_insert_with(|| {
                let (entry, tau) = blend_entry(&line, k, corner);
                if tau <= 0.0 {
                    return true;
                }
                report.certifications += 1;
                certifier.certify_blend(&entry, tau)
            })
        };
        let corners = loop {
            let corners = best_corners(&line, &caps);
            let refused: Vec<usize> = (1..m)
                .filter(|&k| corners[k] != Corner::STOP && !certified(k, corners[k]))
                .collect();
            if refused.is_empty() {
                break corners;
            }
            for k in refused {
                refusals[k] += 1;
                caps[k] = if refusals[k] > SHRINKS {
                    0.0
                } else {
                    let scale = largest_certified(|f| certified(k, corners[k].scaled(f)));
                    BACK_OFF * scale * corners[k].size()
                };
            }
        };
        for k in 1..m {
            match (corners[k] == Corner::STOP, refusals[k]) {
                (true, _) => report.stopped += 1,
                (false, 0) => report.blended += 1,
                (false, _) => report.shrunk += 1,
            }
        }
        Ok((timed(&line, &corners), report))
    }
}

/// The largest scale in `(0, 1)` for which `certified` holds, as found by shrinking by
/// [`SHRINK`] (down to 10⁻⁴) and then bisecting [`BISECTIONS`] times; 0 if none is.
fn largest_certified(mut certified: impl FnMut(f64) -> bool) -> f64 {
    let (mut good, mut bad) = (0.0, 1.0);
    let mut scale = SHRINK;
    while scale > 1e-4 {
        if certified(scale) {
            good = scale;
            break;
        }
        bad = scale;
        scale *= SHRINK;
    }
    if good > 0.0 {
        for _ in 0..BISECTIONS {
            let middle = 0.5 * (good + bad);
            if certified(middle) {
                good = middle;
            } else {
                bad = middle;
            }
        }
    }
    good
}

/// The polyline of a checked `path`.
pub(super) fn polyline<'a, P: AsRef<[f64]>>(
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

/// The trajectory of the polyline with corners `corners` (feasible).
pub(super) fn timed(line: &Polyline<'_>, corners: &[Corner]) -> Trajectory {
    Trajectory::from_knots(line.limits.names().to_vec(), knots(line, corners))
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
        let corners = best_corners(&line, &[0.0, 1.0, 0.0]);
        assert_eq!((corners[1].enter, corners[1].leave), (1.0, 1.0));
        let t = timed(&line, &corners);
        assert!((t.duration() - 7.0).abs() < 1e-9, "{}", t.duration());
    }

    /// A deterministic stream of numbers in `[0, 1)` (a 64-bit linear congruential
    /// generator's top bits).
    fn stream(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1_u64 << 53) as f64
        }
    }

    #[test]
    fn blended_limits_hold_between_knots_and_ends_are_at_rest() {
        use mit_star_spaces::StateSpace as _;
        // Random zigzags of three joints, certified in free space: at random instants (not
        // only knots) every velocity and acceleration is within its limit, the velocity is
        // the derivative of the position, and the motion starts and ends at rest at the ends.
        let panda = crate::ArmProblem::panda().unwrap();
        let certifier = BlendCertifier::new(&panda, &crate::Scene::default());
        let limits = MotionLimits::new(
            panda.joint_names().to_vec(),
            vec![2.0, 1.5, 2.5, 2.0, 2.5, 2.5, 2.5],
            vec![3.0, 2.0, 4.0, 3.0, 5.0, 5.0, 5.0],
        )
        .unwrap();
        let mut next = stream(7);
        for _ in 0..20 {
            let points = 2 + (next() * 6.0) as usize;
            let path: Vec<Vec<f64>> = (0..points)
                .map(|_| {
                    let (lower, upper) = (
                        panda.joint_space().lower().to_vec(),
                        panda.joint_space().upper().to_vec(),
                    );
                    (0..7)
                        .map(|j| lower[j] + (upper[j] - lower[j]) * (0.2 + 0.6 * next()))
                        .collect()
                })
                .collect();
            let (t, report) = Trajectory::blended(&path, &limits, &certifier).unwrap();
            let stopping = Trajectory::stop_at_corners(&path, &limits).unwrap();
            assert!(t.duration() <= stopping.duration() * (1.0 + 1e-12));
            assert_eq!(
                report.blended + report.shrunk + report.stopped,
                points - 2,
                "{report:?}"
            );
            assert!(t.within(&limits, 1e-9));
            let grow = 1.0 + 1e-9;
            for _ in 0..500 {
                let at = next() * t.duration();
                let (s, later) = (t.evaluate(at), t.evaluate(at + 1e-7));
                for j in 0..7 {
                    assert!(s.velocity[j].abs() <= limits.velocity()[j] * grow);
                    assert!(s.acceleration[j].abs() <= limits.acceleration()[j] * grow);
                    let slope = (later.position[j] - s.position[j]) / (later.time - s.time);
                    assert!(
                        (slope - s.velocity[j]).abs() < 1e-5 + 1e-6 * s.acceleration[j].abs() * 1e2
                    );
                }
            }
            let (first, last) = (t.evaluate(0.0), t.evaluate(t.duration()));
            assert_eq!(first.position, path[0]);
            assert_eq!(&last.position, path.last().unwrap());
            assert!(
                first
                    .velocity
                    .iter()
                    .chain(&last.velocity)
                    .all(|v| *v == 0.0)
            );
        }
    }

    #[test]
    fn the_largest_certified_scale_is_found_from_below() {
        for limit in [0.9, 0.5, 0.3, 0.01] {
            let found = largest_certified(|f| f <= limit);
            assert!(found <= limit && found > 0.0, "{limit}: {found}");
            // Within a sixteenth of the last shrink's step below the limit.
            assert!(
                limit - found <= limit * (1.0 / SHRINK - 1.0) / 16.0 + 1e-12,
                "{limit}: {found}"
            );
        }
        assert_eq!(largest_certified(|_| false), 0.0);
    }
}
