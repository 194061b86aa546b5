//! [`AuditBroadPhase`]: the [`MotionAudit`](crate::MotionAudit)'s own broad phase. Per
//! configuration it bounds each link's spheres by one sphere, measures those bounds against
//! the obstacles and against each other, and measures sphere by sphere only the link–obstacle
//! and link–link pairs whose bound could still lower the audit's advance or its clearance
//! (for a link pair, each sphere of one link against the other's bound first).
//! The advance, the clearance and the contacts it finds are exactly the exhaustive
//! measurement's (the same `f64` operations on the pairs it measures; the others are proven
//! not to matter), so the audit's verdicts do not change — only its cost, which no longer
//! grows as spheres × obstacles and sphere × sphere per configuration.

use std::ops::Range;

use glam::{DAffine3, DVec3};
use parry3d_f64::math::Pose;
use parry3d_f64::query::distance;
use parry3d_f64::shape::{Ball, SharedShape};

use std::sync::Arc;

use crate::checking::audit_clouds::AuditClouds;
use crate::checking::motion_audit::AUDIT_CONTACT;
use crate::{Kinematics, ParryChecker, RobotModel, Scene};

/// Per checked link pair, how fast each sphere of its first link and of its second closes
/// in along a motion (a sphere pair at the sum of its two spheres' rates).
pub(super) type PairRates = (Vec<f64>, Vec<f64>);

/// A lower bound of a distance is lowered by this much (metres, plus as much per metre of
/// the bound's size) before it is trusted, to cover the rounding of bounds and poses.
const SLACK: f64 = 1e-9;

/// A link with spheres, bounded by one sphere.
#[derive(Debug, Clone)]
struct BoundedLink {
    link: usize,
    spheres: Range<usize>,
    /// The bound's centre in the link's frame.
    center: DVec3,
    /// Its radius, rounded up.
    radius: f64,
}

/// The audit's broad phase (see the module's documentation).
#[derive(Debug, Clone)]
pub(super) struct AuditBroadPhase {
    fk: Kinematics,
    obstacles: Vec<(Pose, SharedShape)>,
    /// The point clouds (the reference checker's), after the obstacles in the candidates'
    /// numbering.
    clouds: Arc<AuditClouds>,
    links: Vec<BoundedLink>,
    /// Per checked link pair, in the checker's order: its two links (indices into `links`)
    /// and its entries in `sphere_pairs`.
    pairs: Vec<(usize, usize, Range<usize>)>,
    sphere_pairs: Vec<(usize, usize)>,
    /// The padding (metres) every sphere and bound is grown by against the obstacles.
    padding: f64,
}

/// The smallest gaps a motion's measurements found so far, in metres: from a robot sphere,
/// grown by the padding, to an obstacle (`scene`), and between the spheres of a checked pair
/// (`own`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Clearances {
    pub(super) scene: f64,
    pub(super) own: f64,
}

impl Default for Clearances {
    fn default() -> Self {
        Self {
            scene: f64::INFINITY,
            own: f64::INFINITY,
        }
    }
}

/// What one audit's measurements reuse from one configuration to the next.
#[derive(Debug)]
pub(super) struct BroadScratch {
    poses: Vec<DAffine3>,
    centers: Vec<(DVec3, f64)>,
    /// Per bounded link: its bound's world centre.
    bounds: Vec<DVec3>,
    /// Per bounded link: the fastest of its spheres along this motion.
    link_speed: Vec<f64>,
    /// Per link pair: the fastest closing of its sphere pairs along this motion.
    pair_speed: Vec<f64>,
    /// Bound distances and what they bound: link `i` and obstacle `o` as
    /// `i · obstacles + o`, link pair `p` as `links · obstacles + p`.
    candidates: Vec<(f64, usize)>,
}

/// How many sphere tests a measurement made (for the tests and the cost report).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(super) struct Tests {
    /// Sphere–obstacle and sphere–sphere distances computed.
    pub(super) exact: u64,
    /// Bound distances computed.
    pub(super) bounds: u64,
}

impl AuditBroadPhase {
    /// The broad phase of `robot` (its checked pairs as they stand) in `scene`; `checker` is
    /// the audit's reference checker, whose sphere-pair order it follows.
    pub(super) fn new(robot: &RobotModel, scene: &Scene, checker: &ParryChecker) -> Self {
        let spheres = robot.spheres();
        let links: Vec<BoundedLink> = (0..robot.links().len())
            .filter_map(|link| {
                let range = robot.link_sphere_range(link);
                if range.is_empty() {
                    return None;
                }
                // The mean of the centres, and the farthest sphere's reach from it.
                let members = &spheres[range.clone()];
                let center = members.iter().map(|s| s.center).sum::<DVec3>() / members.len() as f64;
                let radius = members
                    .iter()
                    .map(|s| s.center.distance(center) + s.radius)
                    .fold(0.0, f64::max);
                Some(BoundedLink {
                    link,
                    spheres: range,
                    center,
                    radius: radius * (1.0 + 1e-12) + SLACK,
                })
            })
            .collect();
        let bounded = |link: usize| links.iter().position(|l| l.link == link);
        let mut next = 0;
        let pairs = robot
            .self_collision_pairs()
            .iter()
            .filter_map(|&(a, b)| {
                let count = robot.link_sphere_range(a).len() * robot.link_sphere_range(b).len();
                let entries = next..next + count;
                next = entries.end;
                Some((bounded(a)?, bounded(b)?, entries))
            })
            .collect();
        Self {
            fk: Kinematics::new(robot),
            obstacles: ParryChecker::obstacle_shapes(scene),
            clouds: checker.clouds().clone(),
            links,
            pairs,
            sphere_pairs: checker.sphere_pairs().to_vec(),
            padding: checker.padding().metres(),
        }
    }

    /// How many obstacles the scene has (its point clouds count one each).
    pub(super) fn obstacle_count(&self) -> usize {
        self.obstacles.len() + self.clouds.len()
    }

    /// The gap between the ball (`center`, `radius`), grown by the padding, and obstacle `o`
    /// (primitives first, then clouds), 0 if they touch or overlap.
    fn gap(&self, o: usize, center: DVec3, radius: f64) -> f64 {
        let radius = radius + self.padding;
        match self.obstacles.get(o) {
            Some((op, shape)) => {
                let (pose, ball) = (Pose::from_translation(center), Ball::new(radius));
                distance(&pose, &ball, op, shape.as_ref()).map_or(0.0, |d| d.distance)
            }
            None => self.clouds.gap(o - self.obstacles.len(), center, radius),
        }
    }

    /// The scratch of one motion whose spheres move at most `speed` (per sphere) and whose
    /// checked link pairs' spheres close in at most at `rates` (per pair, per sphere of its
    /// first link and of its second: a sphere pair closes at the sum).
    pub(super) fn scratch(&self, speed: &[f64], rates: &[PairRates]) -> BroadScratch {
        let fastest = |values: &[f64]| values.iter().copied().fold(0.0, f64::max);
        BroadScratch {
            poses: vec![DAffine3::IDENTITY; self.fk.link_count()],
            centers: vec![(DVec3::ZERO, 0.0); self.fk.sphere_count()],
            bounds: vec![DVec3::ZERO; self.links.len()],
            link_speed: self
                .links
                .iter()
                .map(|l| fastest(&speed[l.spheres.clone()]))
                .collect(),
            pair_speed: rates.iter().map(|(a, b)| fastest(a) + fastest(b)).collect(),
            candidates: Vec::with_capacity(
                self.links.len() * self.obstacle_count() + self.pairs.len(),
            ),
        }
    }

    /// Measures configuration `q`: lowers `advance` to the longest advance no sphere can use
    /// to close its gap (each sphere's gap over its `speed`, each sphere pair's over the sum
    /// of its spheres' `rates`) and `clearances` to the smallest gaps, as the exhaustive
    /// measurement would.
    /// Returns `true` as soon as a gap is at most [`AUDIT_CONTACT`] (the values are then
    /// partial: measure exhaustively for the contact's name).
    pub(super) fn measure(
        &self,
        q: &[f64],
        (speed, rates): (&[f64], &[PairRates]),
        scratch: &mut BroadScratch,
        advance: &mut f64,
        clearances: &mut Clearances,
        tests: &mut Tests,
    ) -> bool {
        let s = scratch;
        self.fk.sphere_centers_f64(q, &mut s.poses, &mut s.centers);
        for (bound, link) in s.bounds.iter_mut().zip(&self.links) {
            *bound = s.poses[link.link].transform_point3(link.center);
        }
        let slack = |lower: f64, size: f64| lower - SLACK * (1.0 + size);
        let n = self.obstacle_count();
        s.candidates.clear();
        for (i, link) in self.links.iter().enumerate() {
            for o in 0..n {
                let d = self.gap(o, s.bounds[i], link.radius);
                let size = s.bounds[i].length() + link.radius;
                s.candidates.push((slack(d, size), i * n + o));
            }
        }
        for (p, &(a, b, _)) in self.pairs.iter().enumerate() {
            let (la, lb) = (&self.links[a], &self.links[b]);
            let d = s.bounds[a].distance(s.bounds[b]) - la.radius - lb.radius;
            let size = s.bounds[a].length() + s.bounds[b].length() + la.radius + lb.radius;
            s.candidates
                .push((slack(d, size), self.links.len() * n + p));
        }
        tests.bounds += s.candidates.len() as u64;
        s.candidates.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        for &(lower, c) in &s.candidates {
            let obstacle = c < self.links.len() * n;
            let fastest = if obstacle {
                s.link_speed[c / n]
            } else {
                s.pair_speed[c - self.links.len() * n]
            };
            // Every gap it bounds is at least `lower`: none can lower the clearance, nor the
            // advance (each over a speed at most `fastest`). A contact is at most
            // AUDIT_CONTACT < clearance, so it cannot hide here either.
            let clearance = if obstacle {
                clearances.scene
            } else {
                clearances.own
            };
            if lower >= clearance && lower / fastest >= *advance {
                continue;
            }
            if obstacle {
                let link = &self.links[c / n];
                for k in link.spheres.clone() {
                    let (center, radius) = s.centers[k];
                    let gap = self.gap(c % n, center, radius);
                    tests.exact += 1;
                    if gap <= AUDIT_CONTACT {
                        return true;
                    }
                    clearances.scene = clearances.scene.min(gap);
                    *advance = advance.min(gap / speed[k]);
                }
            } else {
                // A sphere of `a` against the bound of `b` first: a row of sphere pairs.
                let p = c - self.links.len() * n;
                let ((a, b, entries), (rate_a, rate_b)) = (&self.pairs[p], &rates[p]);
                let (bound, radius) = (s.bounds[*b], self.links[*b].radius);
                let columns = self.links[*b].spheres.len();
                for (row, i) in self.links[*a].spheres.clone().enumerate() {
                    let (ci, ri) = s.centers[i];
                    let size = ci.length() + bound.length() + radius + ri;
                    let lower = slack(ci.distance(bound) - ri - radius, size);
                    tests.bounds += 1;
                    if lower >= clearances.own && lower / fastest >= *advance {
                        continue;
                    }
                    let first = entries.start + row * columns;
                    for (column, k) in (first..first + columns).enumerate() {
                        let (i, j) = self.sphere_pairs[k];
                        let ((ci, ri), (cj, rj)) = (s.centers[i], s.centers[j]);
                        let gap = ci.distance(cj) - ri - rj;
                        tests.exact += 1;
                        if gap <= AUDIT_CONTACT {
                            return true;
                        }
                        clearances.own = clearances.own.min(gap);
                        *advance = advance.min(gap / (rate_a[row] + rate_b[column]));
                    }
                }
            }
        }
        false
    }
}
