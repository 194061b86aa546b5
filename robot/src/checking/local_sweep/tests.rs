//! Tests of [`LocalSweep`]'s bounds against the `f64` kinematics, sampled finely.

use glam::{DAffine3, DVec3};
use mit_star_spaces::StateSpace;

use super::*;
use crate::{ArmChecker, ArmProblem, Kinematics, Scene};

/// A small deterministic generator (no dependency for one test).
struct Lcg(u64);

impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A configuration drawn uniformly within the joint limits of `space`.
    fn configuration(&mut self, space: &mit_star_spaces::JointSpace) -> Vec<f64> {
        (0..space.dimension())
            .map(|j| space.lower()[j] + self.unit() * (space.upper()[j] - space.lower()[j]))
            .collect()
    }
}

/// Over random pieces of random Panda edges, no sphere centre moves (sampled finely, in
/// `f64`) further from where it is at the piece's middle than the growth beyond the margin.
#[test]
fn no_sphere_moves_further_than_the_local_bound() {
    let robot = ArmProblem::panda().unwrap();
    let checker = ArmChecker::new(&robot, &Scene::new(vec![]));
    let s = &*checker.shared;
    let space = robot.joint_space();
    let n = space.dimension();
    let fk = &s.fk;
    let (mut links, mut at_middle, mut at_t) = (
        vec![DAffine3::IDENTITY; fk.link_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
    );
    let mut poses = vec![LanePose::IDENTITY; fk.link_count()];
    let mut bounds = vec![[LaneF32::ZERO; 3]; s.links.len()];
    let mut speeds = vec![LaneF32::ZERO; s.links.len()];
    let mut terms = EdgeTerms::default();
    let mut rng = Lcg(7);
    let mut tightest = f64::INFINITY;
    for _ in 0..300 {
        let (a, b) = (rng.configuration(space), rng.configuration(space));
        let delta: Vec<f64> = a.iter().zip(&b).map(|(x, y)| y - x).collect();
        let h = 0.5 * rng.unit().powi(3);
        let m = h + rng.unit() * (1.0 - 2.0 * h);
        let q = |t: f64| -> Vec<f64> { a.iter().zip(&delta).map(|(x, d)| x + d * t).collect() };
        let middle = q(m);
        let lane_q: Vec<LaneF32> = middle.iter().map(|&x| LaneF32::splat(x as f32)).collect();
        s.lanes.link_poses(&lane_q, &mut poses);
        for (bound, (link, _, center, _)) in bounds.iter_mut().zip(&s.links) {
            *bound = poses[*link].point(*center);
        }
        s.local.edge_terms(&delta, &s.levers, &mut terms);
        let sweep: Vec<f64> = (0..s.links.len())
            .map(|k| (0..n).map(|j| s.levers[k * n + j] * delta[j].abs()).sum())
            .collect();
        for (k, speed) in speeds.iter_mut().enumerate() {
            *speed = s.local.speed_of(k, &poses, &bounds[k], (&delta, &terms)).0;
        }
        fk.sphere_centers_f64(&middle, &mut links, &mut at_middle);
        over_piece(fk, &q, (m, h, 64), (&mut links, &mut at_t), |_, at_t| {
            for (k, (_, range, ..)) in s.links.iter().enumerate() {
                let speed = f64::from(speeds[k].to_array()[0]);
                let allowed = (h * speed + h * h * terms.second(k)).min(h * sweep[k]);
                for i in range.clone() {
                    let moved = at_t[i].0.distance(at_middle[i].0);
                    assert!(
                        moved <= allowed + 1e-7,
                        "link entry {k}: {moved} > {allowed}"
                    );
                    tighter(&mut tightest, allowed, moved);
                }
            }
        });
    }
    // The bound is not vacuous: somewhere it is within a factor of 3 of the truth.
    assert!(tightest < 3.0, "{tightest}");
}

/// Places the sphere centres of `steps + 1` evenly spaced configurations `q(t)` of the piece
/// `[m − h, m + h]` in `at_t`, one after the other, and hands each with its `t` to `check`.
fn over_piece(
    fk: &Kinematics,
    q: &dyn Fn(f64) -> Vec<f64>,
    (m, h, steps): (f64, f64, u32),
    (links, at_t): (&mut [DAffine3], &mut [(DVec3, f64)]),
    mut check: impl FnMut(f64, &[(DVec3, f64)]),
) {
    for step in 0..=steps {
        let t = m - h + 2.0 * h * f64::from(step) / f64::from(steps);
        fk.sphere_centers_f64(&q(t), links, at_t);
        check(t, at_t);
    }
}

/// Keeps in `tightest` the smallest ratio of a bound to what it bounds, where that is more
/// than a millimetre: how close the bound comes to the truth.
fn tighter(tightest: &mut f64, allowed: f64, seen: f64) {
    if seen > 1e-3 {
        *tightest = tightest.min(allowed / seen);
    }
}

/// Over random pieces of random edges of the Panda and of the Fetch (whose torso is
/// prismatic), every sphere centre (sampled finely, in `f64`) stays within
/// `Acc · (t − m)² / 2` of where its velocity at the piece's middle (computed in the lanes,
/// as certification does) takes it, and that velocity is the centre's derivative.
#[test]
fn sphere_centres_leave_their_tangent_no_faster_than_the_acceleration_bound() {
    for name in ["panda", "fetch"] {
        let robot = crate::ShippedRobot::find(name)
            .unwrap()
            .model(false)
            .unwrap();
        leave_the_tangent_within_the_bound(&robot);
    }
}

fn leave_the_tangent_within_the_bound(robot: &RobotModel) {
    let checker = ArmChecker::new(robot, &Scene::new(vec![]));
    let s = &*checker.shared;
    let space = robot.joint_space();
    let fk = &s.fk;
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let (mut at_middle, mut at_t, mut ahead, mut behind) = (
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
    );
    let mut poses = vec![LanePose::IDENTITY; fk.link_count()];
    let mut bounds = vec![[LaneF32::ZERO; 3]; s.links.len()];
    let mut motions = vec![LaneMotion::ZERO; s.links.len()];
    let mut velocities = vec![DVec3::ZERO; fk.sphere_count()];
    let mut terms = EdgeTerms::default();
    let mut rng = Lcg(5);
    let mut tightest = f64::INFINITY;
    for _ in 0..300 {
        let (a, b) = (rng.configuration(space), rng.configuration(space));
        let delta: Vec<f64> = a.iter().zip(&b).map(|(x, y)| y - x).collect();
        let q = |t: f64| -> Vec<f64> { a.iter().zip(&delta).map(|(x, d)| x + d * t).collect() };
        let h = 0.5 * rng.unit().powi(2);
        let m = h + rng.unit() * (1.0 - 2.0 * h);
        let lane_q: Vec<LaneF32> = q(m).iter().map(|&x| LaneF32::splat(x as f32)).collect();
        s.lanes.link_poses(&lane_q, &mut poses);
        for (bound, (link, _, center, _)) in bounds.iter_mut().zip(&s.links) {
            *bound = poses[*link].point(*center);
        }
        s.local.edge_terms(&delta, &s.levers, &mut terms);
        for (k, motion) in motions.iter_mut().enumerate() {
            *motion = s.local.speed_of(k, &poses, &bounds[k], (&delta, &terms)).1;
        }
        fk.sphere_centers_f64(&q(m), &mut links, &mut at_middle);
        let e = 1e-6;
        fk.sphere_centers_f64(&q(m + e), &mut links, &mut ahead);
        fk.sphere_centers_f64(&q(m - e), &mut links, &mut behind);
        let lane = |p: &LanePoint| {
            DVec3::new(
                f64::from(p[0].to_array()[0]),
                f64::from(p[1].to_array()[0]),
                f64::from(p[2].to_array()[0]),
            )
        };
        // Each sphere centre's velocity at the middle, as certification computes it.
        for (k, (link, range, centre, _)) in s.links.iter().enumerate() {
            let (v, w) = (lane(&motions[k].velocity), lane(&motions[k].angular));
            let p = lane(&poses[*link].point(*centre));
            for i in range.clone() {
                velocities[i] = v + w.cross(at_middle[i].0 - p);
                let derivative = (ahead[i].0 - behind[i].0) / (2.0 * e);
                assert!(
                    (velocities[i] - derivative).length() < 1e-3 * (1.0 + derivative.length()),
                    "link entry {k}: {} against {derivative}",
                    velocities[i]
                );
            }
        }
        over_piece(fk, &q, (m, h, 32), (&mut links, &mut at_t), |t, at_t| {
            for (k, (_, range, ..)) in s.links.iter().enumerate() {
                let allowed = terms.acceleration(k) * (t - m) * (t - m) / 2.0;
                for i in range.clone() {
                    let off = (at_t[i].0 - at_middle[i].0 - velocities[i] * (t - m)).length();
                    assert!(
                        off <= allowed + 1e-4 * (t - m).abs() + 1e-9,
                        "{k}: {off} > {allowed}"
                    );
                    tighter(&mut tightest, allowed, off);
                }
            }
        });
    }
    // The bound is not vacuous: somewhere it is within a factor of 10 of the truth.
    assert!(tightest < 10.0, "{tightest}");
}

/// Over random Panda edges, the distance between a sphere of one link of a
/// self-collision pair and a sphere of the other changes (sampled finely, in `f64`) by no
/// more than the pair's relative lever-arm sweep times the fraction of the edge between.
#[test]
fn pairs_move_apart_no_faster_than_their_relative_levers() {
    let robot = ArmProblem::panda().unwrap();
    let checker = ArmChecker::new(&robot, &Scene::new(vec![]));
    let s = &*checker.shared;
    let space = robot.joint_space();
    let n = space.dimension();
    let fk = &s.fk;
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let (mut at_m, mut at_t) = (
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
    );
    let mut rng = Lcg(11);
    let mut tightest = f64::INFINITY;
    assert!(!s.pairs.is_empty());
    for _ in 0..100 {
        let (a, b) = (rng.configuration(space), rng.configuration(space));
        let q = |t: f64| -> Vec<f64> { a.iter().zip(&b).map(|(x, y)| x + (y - x) * t).collect() };
        let (m, t) = (rng.unit(), rng.unit());
        fk.sphere_centers_f64(&q(m), &mut links, &mut at_m);
        fk.sphere_centers_f64(&q(t), &mut links, &mut at_t);
        for (p, &(ka, kb)) in s.pairs.iter().enumerate() {
            let levers = &s.pair_levers[p * n..(p + 1) * n];
            let sweep: f64 = (0..n).map(|j| levers[j] * (b[j] - a[j]).abs()).sum();
            let allowed = sweep * (t - m).abs();
            for i in s.links[ka].1.clone() {
                for k in s.links[kb].1.clone() {
                    let before = at_m[i].0.distance(at_m[k].0);
                    let after = at_t[i].0.distance(at_t[k].0);
                    let changed = (after - before).abs();
                    assert!(changed <= allowed + 1e-9, "pair {p}: {changed} > {allowed}");
                    if changed > 1e-3 {
                        tightest = tightest.min(allowed / changed);
                    }
                }
            }
        }
    }
    assert!(tightest < 3.0, "{tightest}");
}
