//! [`MotionAudit`]: an arm motion checked continuously in `f64`, independently of the planner's
//! checker — the re-check the experiment harness applies to every returned arm path.

use mit_star_spaces::{JointKind, StateSpace, wrap_angle};
use mit_star_validity::StateValidity;

use crate::checking::audit_broad_phase::{AuditBroadPhase, Clearances, PairRates, Tests};
use crate::{Motion, Padding, ParryChecker, RobotModel, Scene};

/// Closer than this (metres) counts as contact: the audit does not chase a gap that small.
pub const AUDIT_CONTACT: f64 = 1e-9;

/// What an audit found on one motion.
#[derive(Debug, Clone, PartialEq)]
pub enum AuditVerdict {
    /// Every configuration of the motion is collision-free.
    Clear {
        /// Configurations whose distances were computed.
        configurations: u64,
        /// The smallest gap (metres) the audit kept: between a robot sphere and an obstacle
        /// less the [padding](MotionAudit::padded), or between the spheres of a checked
        /// self-collision pair.
        clearance: f64,
        /// The smallest distance (metres) seen between a robot sphere and an obstacle, the
        /// padding not subtracted (`f64::INFINITY` in a scene without obstacles): at least the
        /// padding.
        obstacle_clearance: f64,
    },
    /// A configuration of the motion is in collision (or closer than [`AUDIT_CONTACT`]), or a
    /// robot sphere is within the padding of an obstacle.
    Collides {
        /// Where along the motion, in `[0, 1]`.
        t: f64,
        /// The configuration.
        configuration: Vec<f64>,
        /// What touches what, in words.
        contact: String,
    },
    /// The configuration budget ran out before the motion was decided.
    Undecided {
        /// How far the motion was certified, in `[0, 1]`.
        t: f64,
        /// Configurations computed.
        configurations: u64,
    },
}

/// An independent, continuous check of arm motions by **conservative advancement** in `f64`:
/// at a configuration it computes, with parry's distance queries, how far every robot sphere
/// is from the nearest obstacle (for a point cloud: from every point's ball, in `f64`, by brute
/// force) and from the spheres it must not meet; no sphere can close
/// that gap before the motion has gone `gap / speed`, where `speed` bounds how fast the sphere
/// moves along the motion; so the audit jumps that far and measures again. Every
/// configuration between two measured ones is thereby proven collision-free — no grid, and no
/// resolution to choose.
///
/// It shares nothing with the planner's checking but the robot's forward kinematics in
/// `f64`: not the `f32` lanes, not the margin, not the certification's lever-arm table, not
/// its subdivision. Its speed bound is its own, per sphere centre: a revolute joint turning by
/// `dθ` moves a point by at most `dθ` times its distance from the joint's origin, bounded by
/// summing the joint-origin offsets from that joint down to the sphere's link and the centre's
/// offset in its link (rotations keep lengths); a prismatic joint moves it by `|axis|·dq` and
/// adds its longest travel to the reach of the joints above it. A self-collision pair's gap
/// closes no faster than the sum of its two spheres' bounds over the joints that move one link
/// and not the other: the joints above both carry the two rigidly.
///
/// The motion is the joint space's straight line: coordinates interpolated linearly,
/// continuous joints the short way round.
///
/// ```
/// use mit_star_robot::{AuditVerdict, MotionAudit};
/// let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/box_panda");
/// let problem = mit_star_robot::ArmProblem::panda_mbm(folder.as_ref(), 1)?;
/// let audit = MotionAudit::new(problem.robot(), problem.scene());
/// let start = mit_star_problems::PlanningProblem::start(&problem).to_vec();
/// let verdict = audit.audit(&start, &start, 1_000);
/// assert!(matches!(verdict, AuditVerdict::Clear { .. }));
/// # Ok::<(), mit_star_robot::ArmError>(())
/// ```
#[derive(Debug, Clone)]
pub struct MotionAudit {
    checker: ParryChecker,
    space: mit_star_spaces::JointSpace,
    dimension: usize,
    /// `speeds[s · dimension + j]`: how fast sphere `s`'s centre moves per unit of `q_j`.
    speeds: Vec<f64>,
    /// Per sphere: its link's name (for messages).
    sphere_links: Vec<String>,
    /// Per checked pair of links, in the checker's order: what bounds how fast its spheres
    /// close in.
    pair_links: Vec<PairLinks>,
    /// Its own broad phase: per-link bounding spheres before sphere-by-sphere distances.
    broad: AuditBroadPhase,
    /// Kept from the scene's obstacles (metres).
    padding: f64,
}

/// A checked pair of links, as the audit bounds how fast their spheres close in.
#[derive(Debug, Clone)]
struct PairLinks {
    /// The first sphere and the sphere count of link `a` and of link `b`
    /// ([`RobotModel::link_sphere_range`]).
    spheres: ((usize, usize), (usize, usize)),
    /// Its entries in the checker's [sphere pairs](ParryChecker::sphere_pairs): every sphere
    /// of `a` with every sphere of `b`.
    entries: std::ops::Range<usize>,
    /// Per coordinate: `true` if it drives a joint above one link and not the other (joints
    /// above both carry the two rigidly and cannot close their gap).
    between: Vec<bool>,
}

impl MotionAudit {
    /// The audit of motions of `robot` (its self-collision pairs as they stand) in `scene`.
    pub fn new(robot: &RobotModel, scene: &Scene) -> Self {
        Self::padded(robot, scene, Padding::ZERO)
    }

    /// The audit of motions that must keep every robot sphere `padding` from every obstacle
    /// and point cloud (the robot's own pairs are not padded): a configuration where a sphere
    /// comes within the padding (plus [`AUDIT_CONTACT`]) of an obstacle counts as a contact.
    /// Each sphere is measured grown by the padding, in `f64`, as [`ParryChecker::padded`]
    /// measures it; nothing is shared with the planners' padded checker.
    pub fn padded(robot: &RobotModel, scene: &Scene, padding: Padding) -> Self {
        let links = robot.links();
        let space = robot.joint_space().clone();
        let dimension = space.dimension();
        let travel = |c: usize| space.lower()[c].abs().max(space.upper()[c].abs());
        let mut speeds = vec![0.0; robot.spheres().len() * dimension];
        for (s, sphere) in robot.spheres().iter().enumerate() {
            let row = &mut speeds[s * dimension..(s + 1) * dimension];
            // A bound on the distance from the current frame's origin to the centre.
            let mut reach = sphere.center.length();
            let mut at = Some(sphere.link);
            while let Some(link) = at {
                let frame = &links[link];
                match frame.motion {
                    Motion::Fixed => {}
                    Motion::Revolute { coordinate, .. } => row[coordinate] += reach,
                    Motion::Prismatic { axis, coordinate } => {
                        row[coordinate] += axis.length();
                        reach += axis.length() * travel(coordinate);
                    }
                }
                reach += frame.origin.translation.length();
                at = frame.parent;
            }
            // Rounded up, so that the bound holds for the computed values as well.
            for speed in row {
                *speed *= 1.0 + 1e-9;
            }
        }
        let sphere_links = robot
            .spheres()
            .iter()
            .map(|s| links[s.link].name.clone())
            .collect();
        // The moving joints above `link`, as (coordinate, joint's link), from the link up.
        let above = |link: usize| {
            let mut out = Vec::new();
            let mut at = Some(link);
            while let Some(l) = at {
                if let Motion::Revolute { coordinate, .. } | Motion::Prismatic { coordinate, .. } =
                    links[l].motion
                {
                    out.push((coordinate, l));
                }
                at = links[l].parent;
            }
            out
        };
        // A coordinate moves two links relative to each other if it drives a joint above one
        // and not the other. Joints above both (their common ancestors') carry the two
        // rigidly; a coordinate that also drives a mimic joint below one of them counts.
        let between = |a: usize, b: usize| -> Vec<bool> {
            let (over_a, over_b) = (above(a), above(b));
            let mut out = vec![false; dimension];
            for (joints, others) in [(&over_a, &over_b), (&over_b, &over_a)] {
                for joint in joints.iter().filter(|j| !others.contains(j)) {
                    out[joint.0] = true;
                }
            }
            out
        };
        let checker = ParryChecker::padded(robot, scene, padding);
        let mut next = 0;
        let pair_links: Vec<PairLinks> = robot
            .self_collision_pairs()
            .iter()
            .map(|&(a, b)| {
                let (ra, rb) = (robot.link_sphere_range(a), robot.link_sphere_range(b));
                let entries = next..next + ra.len() * rb.len();
                next = entries.end;
                PairLinks {
                    spheres: ((ra.start, ra.len()), (rb.start, rb.len())),
                    entries,
                    between: between(a, b),
                }
            })
            .collect();
        // The checker lists the pairs' spheres in the same order, a link pair at a time.
        debug_assert_eq!(next, checker.sphere_pairs().len());
        let broad = AuditBroadPhase::new(robot, scene, &checker);
        Self {
            broad,
            padding: padding.metres(),
            checker,
            space,
            dimension,
            speeds,
            sphere_links,
            pair_links,
        }
    }

    /// The padding it keeps from the scene.
    pub fn padding(&self) -> Padding {
        self.checker.padding()
    }

    /// The reference checker the audit measures with (for the states of a path).
    pub fn checker(&self) -> &ParryChecker {
        &self.checker
    }

    /// The joint space whose straight lines it audits (its metric measures a path's length:
    /// weighted, the short way round for continuous joints).
    pub fn space(&self) -> &mit_star_spaces::JointSpace {
        &self.space
    }

    /// Audits the straight motion `a → b`, computing at most `budget` configurations.
    ///
    /// Arguments: two configurations of the robot's dimension, within its joint limits (the
    /// audit checks distances, not limits: check the ends with
    /// [`checker`](Self::checker)`().is_valid`; between ends within limits the motion stays
    /// within them).
    ///
    /// Returns [`AuditVerdict::Clear`] if every configuration of the motion is collision-free,
    /// [`AuditVerdict::Collides`] with the first configuration found closer than
    /// [`AUDIT_CONTACT`], or [`AuditVerdict::Undecided`] if the budget ran out (a motion that
    /// grazes an obstacle for a long way). Ends of the wrong dimension or not finite collide
    /// at `t = 0`.
    ///
    /// Complexity: per configuration, one `f64` forward-kinematics pass, one distance query
    /// per link (bounded by one sphere) and obstacle and per checked link pair, and
    /// sphere-by-sphere queries only for the link–obstacle and link–link pairs whose bound
    /// could lower the advance or the clearance (the audit's own broad phase; its verdicts
    /// are [`audit_exhaustive`](Self::audit_exhaustive)'s); the number of configurations
    /// grows with the motion's length over its clearance.
    pub fn audit(&self, a: &[f64], b: &[f64], budget: u64) -> AuditVerdict {
        self.run(a, b, budget, true).0
    }

    /// The same audit without its broad phase: every sphere against every obstacle and
    /// every checked sphere pair at every configuration. Slower on large sphere models; the
    /// reference [`audit`](Self::audit)'s verdicts are tested against.
    pub fn audit_exhaustive(&self, a: &[f64], b: &[f64], budget: u64) -> AuditVerdict {
        self.run(a, b, budget, false).0
    }

    /// As [`audit`](Self::audit) (`broad`) or [`audit_exhaustive`](Self::audit_exhaustive),
    /// with the number of sphere distances and bound distances computed: `(exact, bounds)`.
    pub fn audit_counting(
        &self,
        a: &[f64],
        b: &[f64],
        budget: u64,
        broad: bool,
    ) -> (AuditVerdict, (u64, u64)) {
        let (verdict, tests) = self.run(a, b, budget, broad);
        (verdict, (tests.exact, tests.bounds))
    }

    fn run(&self, a: &[f64], b: &[f64], budget: u64, broad: bool) -> (AuditVerdict, Tests) {
        let mut tests = Tests::default();
        let verdict = self.run_counting(a, b, budget, broad, &mut tests);
        (verdict, tests)
    }

    fn run_counting(
        &self,
        a: &[f64],
        b: &[f64],
        budget: u64,
        broad: bool,
        tests: &mut Tests,
    ) -> AuditVerdict {
        let d = self.dimension;
        let collides = |t: f64, configuration: Vec<f64>, contact: String| AuditVerdict::Collides {
            t,
            configuration,
            contact,
        };
        if a.len() != d || b.len() != d || !a.iter().chain(b).all(|x| x.is_finite()) {
            return collides(0.0, a.to_vec(), "an end is not a configuration".into());
        }
        // Joint displacements along the motion (the short way round for continuous joints).
        let delta: Vec<f64> = (0..d)
            .map(|j| match self.space.joints()[j].kind {
                JointKind::Continuous => wrap_angle(b[j] - a[j]),
                _ => b[j] - a[j],
            })
            .collect();
        let speed: Vec<f64> = self
            .speeds
            .chunks_exact(d)
            .map(|row| row.iter().zip(&delta).map(|(v, x)| v * x.abs()).sum())
            .collect();
        let pairs = self.checker.sphere_pairs();
        // Per sphere pair, how fast its gap can close: only the joints between the two links
        // move them relative to each other, each sphere at most as fast as those joints move
        // its centre.
        // Per checked pair of links, per sphere of either link (a sphere pair closes at the
        // sum of its two spheres' rates).
        let rates: Vec<PairRates> = self
            .pair_links
            .iter()
            .map(|pair| {
                let relative = |s: usize| -> f64 {
                    let row = &self.speeds[s * d..(s + 1) * d];
                    // From +0.0: a pair no joint moves apart closes at +0 and its gap's
                    // advance is +∞ (an empty `sum` of `f64` is -0.0).
                    (0..d)
                        .filter(|&c| pair.between[c])
                        .fold(0.0, |sum, c| sum + row[c] * delta[c].abs())
                };
                let ((first_a, count_a), (first_b, count_b)) = pair.spheres;
                (
                    (first_a..first_a + count_a).map(relative).collect(),
                    (first_b..first_b + count_b).map(relative).collect(),
                )
            })
            .collect();
        let mut scratch = broad.then(|| self.broad.scratch(&speed, &rates));
        // Allocated at the first exhaustive measurement only.
        let (mut obstacle_gaps, mut pair_gaps) = (Vec::new(), Vec::new());
        let mut q = a.to_vec();
        let (mut t, mut configurations) = (0.0_f64, 0_u64);
        let mut clearances = Clearances::default();
        // A sphere whose gap (grown by the padding) is this small meets the obstacle, or, with
        // a padding, comes within it.
        let meets = if self.padding > 0.0 {
            format!(
                "comes within the padding ({}) of an obstacle",
                self.checker.padding()
            )
        } else {
            "meets an obstacle".to_owned()
        };
        loop {
            if configurations >= budget {
                return AuditVerdict::Undecided { t, configurations };
            }
            self.space.interpolate(a, b, t, &mut q);
            configurations += 1;
            // The longest advance no sphere can use to close its gap.
            let mut advance = f64::INFINITY;
            if let Some(scratch) = scratch.as_mut() {
                let bounds = (&speed[..], &rates[..]);
                let (found, now) = (&mut clearances, &mut advance);
                if !self.broad.measure(&q, bounds, scratch, now, found, tests) {
                    if let Some(verdict) = self.step(&mut t, advance, configurations, clearances) {
                        return verdict;
                    }
                    continue;
                }
                // A contact: measured exhaustively below, for its name.
                advance = f64::INFINITY;
            }
            obstacle_gaps.resize(speed.len(), 0.0);
            pair_gaps.resize(pairs.len(), 0.0);
            self.checker.gaps(&q, &mut obstacle_gaps, &mut pair_gaps);
            tests.exact += (obstacle_gaps.len() * self.broad_obstacles() + pair_gaps.len()) as u64;
            for (s, (&gap, &v)) in obstacle_gaps.iter().zip(&speed).enumerate() {
                if gap <= AUDIT_CONTACT {
                    let contact = format!("a sphere of `{}` {meets}", self.sphere_links[s]);
                    return collides(t, q, contact);
                }
                clearances.scene = clearances.scene.min(gap);
                advance = advance.min(gap / v);
            }
            for (pair, (rate_a, rate_b)) in self.pair_links.iter().zip(&rates) {
                let ((first_a, _), (first_b, _)) = pair.spheres;
                for k in pair.entries.clone() {
                    let (gap, (i, j)) = (pair_gaps[k], pairs[k]);
                    if gap <= AUDIT_CONTACT {
                        let contact = format!(
                            "a sphere of `{}` meets a sphere of `{}`",
                            self.sphere_links[i], self.sphere_links[j]
                        );
                        return collides(t, q, contact);
                    }
                    clearances.own = clearances.own.min(gap);
                    advance = advance.min(gap / (rate_a[i - first_a] + rate_b[j - first_b]));
                }
            }
            if let Some(verdict) = self.step(&mut t, advance, configurations, clearances) {
                return verdict;
            }
        }
    }

    /// Advances `t` by `advance` (to the end at most, which is measured too); the verdict
    /// once the end was measured.
    fn step(
        &self,
        t: &mut f64,
        advance: f64,
        configurations: u64,
        clearances: Clearances,
    ) -> Option<AuditVerdict> {
        if *t >= 1.0 {
            return Some(AuditVerdict::Clear {
                configurations,
                clearance: clearances.scene.min(clearances.own),
                obstacle_clearance: clearances.scene + self.padding,
            });
        }
        *t = if *t + advance >= 1.0 {
            1.0
        } else {
            *t + advance
        };
        None
    }

    /// How many obstacles each sphere is measured against.
    fn broad_obstacles(&self) -> usize {
        self.broad.obstacle_count()
    }
}

impl StateValidity for MotionAudit {
    fn is_valid(&self, q: &[f64]) -> bool {
        self.checker.is_valid(q)
    }
}
