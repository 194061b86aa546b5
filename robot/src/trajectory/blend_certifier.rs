//! [`BlendCertifier`]: proves a parabolic blend collision-free by certifying a chord polyline
//! of it with every sphere grown by more than the blend can stray from its chords.

use mit_star_spaces::{Never, StateSpace};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};

use crate::{ArmChecker, LeverArms, Padding, RobotModel, Sample, Scene};

/// Certifies blends (motions at constant acceleration) for a robot in a scene.
///
/// # How
/// A blend `q(t) = q₀ + v₀ t + a t² / 2`, `t ∈ [0, τ]`, is cut into `m` chords of equal time
/// `h = τ / m`. Between the ends of a chord the parabola leaves the chord by at most
/// `|a_j| h² / 8` in coordinate `j` (at the same fraction of the chord), so every point of
/// link `k`'s spheres is within `e_k = Σ_j λ_kj |a_j| h² / 8` of where it is on the chord
/// ([`LeverArms`] `λ`). `m` is the least count with `max_k e_k ≤ δ`. Each chord is then
/// certified ([`StateValidity::certify_motion`]: every configuration of it, not only grid
/// points) by an [`ArmChecker`] of the robot whose every sphere is grown by `δ`: clear at
/// every chord configuration with spheres grown by `δ` (and the checker's margin), the
/// robot's own spheres are clear (by that margin) at every configuration of the blend —
/// against the scene and between the link pairs it checks.
///
/// Three growths are tried ([`GROWTHS`](Self::GROWTHS)): 1 mm (few chords), then 0.1 mm
/// (about three times as many) and 20 µm (seven times), for blends passing within a
/// millimetre of something — as blends of simplified paths often do, whose corners wrap
/// around obstacles.
#[derive(Debug, Clone)]
pub struct BlendCertifier {
    /// Per growth `δ`: the checker of the grown robot.
    checkers: Vec<(f64, ArmChecker)>,
    levers: LeverArms,
    space: mit_star_spaces::JointSpace,
    /// The link indices with spheres.
    links: Vec<usize>,
}

impl BlendCertifier {
    /// The growths tried, in metres.
    pub const GROWTHS: [f64; 3] = [1e-3, 1e-4, 2e-5];

    /// The most chords a blend is cut into before it is refused.
    pub const MAX_CHORDS: usize = 100_000;

    /// The certifier of `robot` (its self-collision pairs as they stand) in `scene`.
    pub fn new(robot: &RobotModel, scene: &Scene) -> Self {
        Self::padded(robot, scene, Padding::ZERO)
    }

    /// The certifier of blends that keep every sphere `padding` from the scene, as a
    /// [padded checker](ArmChecker::padded)'s certified edges do: each chord's checker is
    /// padded too.
    pub fn padded(robot: &RobotModel, scene: &Scene, padding: Padding) -> Self {
        let checkers = Self::GROWTHS
            .iter()
            .map(|&g| {
                let grown = robot.with_grown_spheres(g);
                (g, ArmChecker::padded(&grown, scene, padding))
            })
            .collect();
        let links = (0..robot.links().len())
            .filter(|&l| !robot.link_sphere_range(l).is_empty())
            .collect();
        Self {
            checkers,
            levers: LeverArms::new(robot),
            space: robot.joint_space().clone(),
            links,
        }
    }

    /// Whether the motion from `entry` (its position, velocity and constant acceleration)
    /// for `duration` seconds is certified collision-free (type docs).
    pub fn certify_blend(&self, entry: &Sample, duration: f64) -> bool {
        let n = self.space.dimension();
        if entry.position.len() != n || entry.velocity.len() != n || entry.acceleration.len() != n {
            return false;
        }
        let a = &entry.acceleration;
        let speed: Vec<f64> = (0..n)
            .map(|j| {
                entry.velocity[j]
                    .abs()
                    .max((entry.velocity[j] + a[j] * duration).abs())
            })
            .collect();
        let bend: Vec<f64> = a.iter().map(|x| x.abs()).collect();
        let at = |t: f64, q: &mut [f64]| {
            for (j, x) in q.iter_mut().enumerate() {
                *x = entry.position[j] + entry.velocity[j] * t + 0.5 * a[j] * t * t;
            }
        };
        self.certify_curve(&at, duration, (&bend, &speed))
    }

    /// Whether the motion `at(t)`, `t ∈ [0, duration]`, is certified collision-free, given
    /// bounds of each coordinate's second derivative (`bend`) and speed (`speed`) over the
    /// motion: as for a blend (type docs), a chord leaves the curve by at most
    /// `bend_j h² / 8` in coordinate `j`.
    pub fn certify_curve(
        &self,
        at: &dyn Fn(f64, &mut [f64]),
        duration: f64,
        (bend, speed): (&[f64], &[f64]),
    ) -> bool {
        let n = self.space.dimension();
        if bend.len() != n || speed.len() != n || !(duration > 0.0 && duration.is_finite()) {
            return false;
        }
        let strain = self
            .links
            .iter()
            .map(|&l| {
                (0..n)
                    .map(|j| self.levers.lever(l, j) * bend[j])
                    .sum::<f64>()
            })
            .fold(0.0, f64::max);
        // Chords short enough that no coordinate turns half a turn along one (the checker
        // takes a wrapping joint the short way round).
        let fastest = speed.iter().copied().fold(0.0, f64::max);
        let (mut from, mut to) = (vec![0.0; n], vec![0.0; n]);
        'growth: for (growth, checker) in &self.checkers {
            let chords = (duration * (strain / (8.0 * growth)).sqrt())
                .max(fastest * duration / 3.0)
                .ceil()
                .max(1.0);
            if chords.is_nan() || chords > Self::MAX_CHORDS as f64 {
                continue;
            }
            let chords = chords as usize;
            at(0.0, &mut from);
            for i in 1..=chords {
                at(duration * i as f64 / chords as f64, &mut to);
                if !from.iter().chain(&to).all(|x| x.is_finite()) {
                    return false;
                }
                let mut progress = MotionProgress::default();
                let status = checker.certify_motion(&self.space, &from, &to, &mut progress, &Never);
                if status != Some(EdgeStatus::Valid) {
                    continue 'growth;
                }
                std::mem::swap(&mut from, &mut to);
            }
            return true;
        }
        false
    }
}
