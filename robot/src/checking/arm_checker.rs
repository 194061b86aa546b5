//! [`ArmChecker`]: is an arm configuration collision-free in its scene and with itself.

use std::ops::Range;
use std::sync::Arc;

use glam::Vec3A;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{EdgeStatus, MotionProgress, Preparation, Segment, StateValidity};

use wide::f64x4;

use crate::checking::arm_certification::CertifyScratch;
use crate::checking::clearance::LinkMotion;
use crate::checking::lanes::{LANES, LaneF32, LaneKinematics, LanePoint, LanePose};
use crate::checking::local_sweep::LocalSweep;
use crate::checking::obstacle_grid::{Candidates, GRID_THRESHOLD, ObstacleGrid, widest};
use crate::checking::reachable_obstacles::reachable_obstacles;
use crate::checking::scratch_cell::ScratchCell;
use crate::checking::spare_scratch;
use crate::{CloudObstacle, Kinematics, LeverArms, Obstacle, Padding, RobotModel, Scene};

/// What the checks share between clones: the kinematics, the scene, the pair lists and the
/// bounds certification uses.
#[derive(Debug)]
pub(crate) struct Shared {
    pub(crate) fk: Kinematics,
    pub(crate) lanes: LaneKinematics,
    pub(crate) lower: Vec<f64>,
    pub(crate) upper: Vec<f64>,
    /// Per coordinate: the joint wraps around (continuous), so motions go the short way.
    pub(crate) wraps: Vec<bool>,
    /// Per entry of `links`: the obstacles it can reach in some configuration
    /// (`reachable_obstacles.rs`), the only ones its tests look at.
    pub(crate) reachable: Vec<Vec<Obstacle>>,
    /// Per entry of `links`: a grid over its reachable obstacles where they are many
    /// (`obstacle_grid.rs`), so that its tests look only at those near its lanes.
    pub(crate) grids: Vec<Option<ObstacleGrid>>,
    /// The scene's point clouds.
    pub(crate) clouds: Vec<Arc<CloudObstacle>>,
    /// Per entry of `links`: the clouds (indices into `clouds`) with a point it can reach in
    /// some configuration.
    pub(crate) reachable_clouds: Vec<Vec<usize>>,
    /// Links with spheres, in tree order: link, its sphere range, local bounding sphere.
    pub(crate) links: Vec<(usize, Range<usize>, Vec3A, f32)>,
    /// Local sphere centres and radii.
    pub(crate) spheres: Vec<(Vec3A, f32)>,
    /// Per sphere: how far its ball reaches from its link's bounding-sphere centre, plus two
    /// margins (rounded up). A sphere is no nearer an obstacle than that centre less this
    /// (less its radius), so when the centre is further than this and the test's growth, the
    /// sphere's test cannot find a contact and is skipped. The two margins cover the `f32`
    /// rounding of the two points' placement and distances, so the skip never changes an
    /// answer.
    pub(crate) reaches: Vec<f32>,
    /// Self-collision pairs as indices into `links`.
    pub(crate) pairs: Vec<(usize, usize)>,
    /// How much every sphere is grown in every test, covering the `f32` rounding of the
    /// kinematics and of the contact tests (see [`ArmChecker::margin`]).
    pub(crate) margin: f64,
    /// The user's padding: spheres are grown by it, beyond the margin, in every test against
    /// the scene (not between links).
    pub(crate) padding: Padding,
    /// The margin and the padding per entry of `links`, in every lane (rounded up): the growth
    /// of a plain check against the scene.
    plain: Vec<LaneF32>,
    /// The margin in every lane: the growth of each sphere of a self-collision pair.
    pair_grow: LaneF32,
    /// Per entry of `links`, per coordinate: the link's lever arm ([`LeverArms`]).
    pub(crate) levers: Vec<f64>,
    /// Per entry of `pairs`, per coordinate: how fast the pair's links can move relative to
    /// each other ([`LocalSweep::relative_levers`]).
    pub(crate) pair_levers: Vec<f64>,
    /// The configuration-dependent sweep bound certification uses.
    pub(crate) local: LocalSweep,
    /// The sizes of a clone's scratch.
    scratch_shape: ScratchShape,
}

/// Which invalid configuration of a batch a check must find.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Wanted {
    /// The first one: every lane before it is decided.
    First,
    /// Any one: the check ends at the first contact in any lane.
    Any,
    /// Every one: each lane is decided.
    All,
}

/// Per-clone scratch, reused by every check. The default holds no buffer: it is what a dropped
/// checker leaves in place of the one it hands on, and no check ever runs on it.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    pub(crate) lanes: LaneScratch,
    pub(crate) certify: CertifyScratch,
    /// The sizes it was made for.
    shape: ScratchShape,
}

/// The sizes of a checker's [`Scratch`], fixed by its robot and scene (all 0: no buffer).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct ScratchShape {
    /// Links of the kinematic tree.
    pub(crate) links: usize,
    /// Spheres of the robot.
    pub(crate) spheres: usize,
    /// Links with spheres (entries of `Shared::links`).
    pub(crate) entries: usize,
    /// Joints.
    pub(crate) dimension: usize,
    /// Obstacles the longest grid list holds.
    pub(crate) candidates: usize,
    /// Self-collision pairs.
    pub(crate) pairs: usize,
}

impl Scratch {
    /// New buffers of `shape`.
    pub(crate) fn new(shape: ScratchShape) -> Self {
        Self {
            lanes: LaneScratch::new(
                shape.links,
                shape.spheres,
                shape.entries,
                shape.dimension,
                shape.candidates,
            ),
            certify: CertifyScratch::new(shape.dimension, shape.entries, shape.pairs),
            shape,
        }
    }

    /// The sizes it was made for.
    pub(crate) fn shape(&self) -> ScratchShape {
        self.shape
    }

    /// Forgets what earlier checks left as hints or to resume (the link hit last, a stopped
    /// certification), as a new scratch has none: a check's work does not depend on the
    /// previous owner of a recycled scratch.
    pub(crate) fn reset(&mut self) {
        self.lanes.last_hit = usize::MAX;
        self.certify.forget_stop();
    }
}

/// The lane checks' buffers: link poses, sphere centres, link bounding-sphere centres
/// (and whether a link's sphere centres are placed for the current batch), joint values by
/// coordinate.
#[derive(Debug, Default)]
pub(crate) struct LaneScratch {
    pub(crate) lane_poses: Vec<LanePose>,
    pub(crate) lane_centers: Vec<LanePoint>,
    pub(crate) lane_bounds: Vec<LanePoint>,
    pub(crate) placed: Vec<bool>,
    pub(crate) lane_q: Vec<LaneF32>,
    /// The entry of `Shared::links` whose spheres met an obstacle in the last batch that ended
    /// at a contact (`usize::MAX`: none yet): a check that may stop at any contact tests it
    /// first, since consecutive batches (the points of one edge, the extensions of one
    /// search) tend to hit the same thing.
    pub(crate) last_hit: usize,
    /// The obstacles a link's grid returned (indices into its reachable list), with room for
    /// the longest list that has a grid: a query never allocates.
    pub(crate) candidates: Candidates,
    /// Per link entry, its motion at the batch's configurations once certification has
    /// computed it (reset per batch): obstacles and self-collision pairs share it.
    pub(crate) motions: Vec<Option<LinkMotion>>,
}

impl LaneScratch {
    /// Buffers for `links` links, `spheres` spheres, `entries` links with spheres and
    /// `dimension` joints, with room for `candidates` obstacles from a grid.
    fn new(
        links: usize,
        spheres: usize,
        entries: usize,
        dimension: usize,
        candidates: usize,
    ) -> Self {
        Self {
            lane_poses: vec![LanePose::IDENTITY; links],
            lane_centers: vec![[LaneF32::ZERO; 3]; spheres],
            lane_bounds: vec![[LaneF32::ZERO; 3]; entries],
            placed: vec![false; entries],
            lane_q: vec![LaneF32::ZERO; dimension],
            last_hit: usize::MAX,
            candidates: Candidates::with_capacity(candidates),
            motions: vec![None; entries],
        }
    }
}

/// Smallest growth of the spheres in every test, in metres: covers the `f32` rounding of the
/// kinematics and the contact tests near the origin, with an order of magnitude to spare
/// (`tests/one_sided.rs`: without a margin, configurations overlapping an obstacle by
/// nanometres pass the `f32` check).
const MARGIN_FLOOR: f64 = 2e-5;

/// Further growth per metre of the scene's extent (obstacles' distance from the base plus the
/// robot's reach): `f32` rounding grows with the magnitude of the coordinates.
const MARGIN_PER_METRE: f64 = 2e-6;

/// The collision checker of an arm in a scene: a configuration is valid if it is within the
/// joint limits, no sphere of the robot meets an obstacle, and no two spheres of a
/// self-collision pair of links meet — every sphere grown by a small [margin](Self::margin)
/// that covers the rounding of the `f32` arithmetic, so that a configuration this checker
/// calls valid is valid in exact arithmetic too (one-sided).
///
/// Forward kinematics places the links in `LaneF32` lanes, a batch of configurations at once
/// (eight, or sixteen where the CPU has AVX-512: `lane_f32.rs`), as VAMP lays out its checks;
/// one configuration uses one lane of the same code, so a single check and a batch share one
/// arithmetic; each link with spheres is first tested as one bounding sphere against each
/// primitive obstacle's bounding sphere and the obstacle itself (broad phase), and its small
/// spheres only if that hits (a point cloud is asked sphere by sphere: its tree's walks stop
/// at once in the lanes that are far); self-collision pairs likewise test the two links'
/// bounding spheres first.
/// Sphere centres are placed only for links that reach the narrow phase. A link is tested only
/// against the obstacles it can reach in some configuration (found once, when the checker is
/// built, from its lever arms). Edge checks prepare their segment
/// ([`StateValidity::prepare_segment`]): the lanes are filled from `a + (b − a)·t` directly,
/// bit for bit the interpolated configurations.
///
/// **Batches** ([`StateValidity::first_invalid`], [`batch_width`](StateValidity::batch_width) 8
/// or 16): a lane drops out of the work once a lane before it is known invalid, and the batch
/// ends when no lane before the first invalid one is left to decide, so the answer is exactly
/// the first invalid configuration — the one testing them one by one finds. A check that may
/// end at any contact ([`StateValidity::any_invalid`], the edge checks) tests first the link
/// that met an obstacle in the last batch that ended at a contact: the points of one edge and
/// the extensions of one search tend to hit the same thing (on RRT-Connect's Panda solves, 12 %
/// fewer instructions). The answer does not depend on the order.
///
/// **Certified motion** ([`StateValidity::certify_motion`]): every configuration of an edge
/// is proven collision-free, not only its grid points (see [`LeverArms`] for the bound and
/// `arm_certification.rs` for the walk).
///
/// **Padding** ([`padded`](Self::padded)): every sphere is grown by a user's [`Padding`] too
/// in every test against the scene (plain checks, batches and certification), not between
/// the robot's links, so a padded checker's certified edges keep the padding from every
/// obstacle at every configuration.
///
/// Clones share the model and scene (an [`Arc`]) and own their scratch buffers, so a check
/// never allocates. The scratch sits behind a mutex so that problems holding a checker
/// can be shared between threads; each planner owns its own clone, so the lock is never
/// contended (an uncontended lock costs a few nanoseconds against a check of about a
/// microsecond). A dropped checker leaves its buffers to the next clone of the same shape on
/// its thread, so a program that builds a planner per query (a benchmark, a robot's planning
/// loop) does not allocate and write them anew each time.
#[derive(Debug)]
pub struct ArmChecker {
    pub(crate) shared: Arc<Shared>,
    pub(crate) scratch: ScratchCell<Scratch>,
}

impl Clone for ArmChecker {
    /// Shares the model and scene; the scratch is one a checker of the same shape dropped on
    /// this thread (`spare_scratch.rs`), reset, or new buffers: a check writes every buffer
    /// before it reads it, so contents are never copied.
    fn clone(&self) -> Self {
        Self {
            shared: Arc::clone(&self.shared),
            scratch: ScratchCell::new(spare_scratch::take(self.shared.scratch_shape)),
        }
    }
}

impl Drop for ArmChecker {
    /// Leaves the scratch to the next clone on this thread (`spare_scratch.rs`).
    fn drop(&mut self) {
        spare_scratch::give(std::mem::take(self.scratch.get_mut()));
    }
}

impl ArmChecker {
    /// The checker of `robot` (its self-collision pairs as they stand) in `scene`, without
    /// padding.
    pub fn new(robot: &RobotModel, scene: &Scene) -> Self {
        Self::build(robot, scene, GRID_THRESHOLD, Padding::ZERO)
    }

    /// The checker of `robot` in `scene` keeping every sphere `padding` (beyond the
    /// [margin](Self::margin)) from every obstacle and point cloud: a configuration is valid
    /// only with every sphere grown by the margin and the padding clear of the scene (and, grown
    /// by the margin only, of the other links of its self-collision pairs), and a certified
    /// motion keeps that at every configuration.
    pub fn padded(robot: &RobotModel, scene: &Scene, padding: Padding) -> Self {
        Self::build(robot, scene, GRID_THRESHOLD, padding)
    }

    /// [`new`](Self::new) with a grid over a link's reachable obstacles from `threshold` of
    /// them on (`usize::MAX`: never; 0: always), for tests that compare the two paths: the
    /// answers are the same either way.
    #[doc(hidden)]
    pub fn with_grid_threshold(robot: &RobotModel, scene: &Scene, threshold: usize) -> Self {
        Self::build(robot, scene, threshold, Padding::ZERO)
    }

    /// [`with_grid_threshold`](Self::with_grid_threshold) with `padding`.
    fn build(robot: &RobotModel, scene: &Scene, threshold: usize, padding: Padding) -> Self {
        let fk = Kinematics::new(robot);
        let bounds = robot.link_bounding_spheres();
        let links: Vec<(usize, Range<usize>, Vec3A, f32)> = (0..robot.links().len())
            .filter_map(|l| {
                bounds[l].map(|(c, r)| {
                    // Rounded up: the f32 cull must never reject a real contact.
                    let r = (r * (1.0 + 1e-6) + 1e-6) as f32;
                    (l, robot.link_sphere_range(l), c.as_vec3a(), r)
                })
            })
            .collect();
        let slot = |link: usize| links.iter().position(|e| e.0 == link);
        let pairs: Vec<(usize, usize)> = robot
            .self_collision_pairs()
            .iter()
            .filter_map(|&(a, b)| Some((slot(a)?, slot(b)?)))
            .collect();
        let spheres: Vec<(Vec3A, f32)> = robot
            .spheres()
            .iter()
            .map(|s| (s.center.as_vec3a(), s.radius as f32))
            .collect();
        let space = robot.joint_space();
        let dimension = fk.dimension();
        let arms = LeverArms::new(robot);
        let levers: Vec<f64> = links
            .iter()
            .flat_map(|&(link, ..)| (0..dimension).map(move |j| (link, j)))
            .map(|(link, j)| arms.lever(link, j))
            .collect();
        let reach = (0..robot.links().len())
            .flat_map(|l| (0..dimension).map(move |j| (l, j)))
            .map(|(l, j)| arms.lever(l, j))
            .fold(0.0, f64::max);
        let far = scene
            .obstacles()
            .iter()
            .map(|o| {
                let (c, r) = o.bounding_sphere();
                f64::from(c.length() + r)
            })
            .chain(scene.clouds().iter().map(|c| {
                let (c, r) = c.bounding_sphere();
                f64::from(c.length() + r)
            }))
            .fold(0.0, f64::max);
        let margin = MARGIN_FLOOR + MARGIN_PER_METRE * (reach + far);
        let mut reaches = vec![0.0_f32; spheres.len()];
        for (_, range, center, _) in &links {
            for (out, sphere) in reaches[range.clone()]
                .iter_mut()
                .zip(&spheres[range.clone()])
            {
                let reach = f64::from((sphere.0 - *center).length()) + f64::from(sphere.1);
                *out = ((reach + 2.0 * margin) * (1.0 + 1e-6) + 1e-6) as f32;
            }
        }
        let (reachable, reachable_clouds) = reachable_obstacles(
            (robot, &fk, &arms),
            &links,
            (scene.obstacles(), scene.clouds()),
            padding.metres(),
        );
        let grids: Vec<Option<ObstacleGrid>> = reachable
            .iter()
            .zip(&links)
            .map(|(list, link)| {
                (list.len() >= threshold)
                    .then(|| ObstacleGrid::new(list, link.3))
                    .flatten()
            })
            .collect();
        let longest = grids.iter().flatten().map(ObstacleGrid::len).max();
        let scratch_shape = ScratchShape {
            links: fk.link_count(),
            spheres: fk.sphere_count(),
            entries: links.len(),
            dimension,
            candidates: longest.unwrap_or(0),
            pairs: pairs.len(),
        };
        let local = LocalSweep::new(robot, &links);
        let pair_levers = pairs
            .iter()
            .flat_map(|&pair| local.relative_levers(pair, &levers, dimension))
            .collect();
        let wraps = space
            .joints()
            .iter()
            .map(|j| matches!(j.kind, mit_star_spaces::JointKind::Continuous))
            .collect();
        Self {
            shared: Arc::new(Shared {
                lanes: LaneKinematics::new(&fk),
                fk,
                lower: space.lower().to_vec(),
                upper: space.upper().to_vec(),
                wraps,
                reachable,
                grids,
                clouds: scene.clouds().to_vec(),
                reachable_clouds,
                plain: vec![
                    LaneF32::splat(((margin + padding.metres()) * (1.0 + 1e-6)) as f32);
                    links.len()
                ],
                pair_grow: LaneF32::splat(margin as f32),
                links,
                spheres,
                reaches,
                pairs,
                margin,
                padding,
                levers,
                pair_levers,
                local,
                scratch_shape,
            }),
            scratch: ScratchCell::new(spare_scratch::take(scratch_shape)),
        }
    }

    /// The forward kinematics it uses.
    pub fn kinematics(&self) -> &Kinematics {
        &self.shared.fk
    }

    /// How much every sphere is grown in every test, in metres: enough to cover the rounding
    /// of the `f32` kinematics and contact tests, so that a configuration this checker calls
    /// valid has every sphere clear of the scene and of the other links in exact arithmetic.
    /// `2e-5 m` plus `2e-6` per metre of the scene's extent (about 25 µm for the Panda in a
    /// MotionBenchMaker scene).
    pub fn margin(&self) -> f64 {
        self.shared.margin
    }

    /// The [padding](Self::padded) kept from the scene's obstacles beyond the margin
    /// ([`Padding::ZERO`] unless built padded).
    pub fn padding(&self) -> Padding {
        self.shared.padding
    }
}

impl StateValidity for ArmChecker {
    fn is_valid(&self, q: &[f64]) -> bool {
        let s = &*self.shared;
        let mut guard = self.scratch.lock();
        invalid_lanes(
            s,
            &mut guard.lanes,
            (q, q.len().max(1)),
            &s.plain,
            Wanted::Any,
        ) == 0
    }

    #[inline]
    fn batch_width(&self) -> usize {
        LANES
    }

    /// Certified motion along the robot's joint space (straight in joint coordinates, the
    /// short way round for wrapping joints): see `arm_certification.rs` for the guarantee.
    /// `None` for a space of another dimension.
    fn certify_motion(
        &self,
        space: &dyn StateSpace,
        a: &[f64],
        b: &[f64],
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        self.certify(space, (a, b), progress, stop)
    }

    fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        self.invalid_in(states, dimension, Wanted::First)
    }

    /// Ends a batch at its first contact in any lane, without deciding the lanes before it.
    fn any_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        self.invalid_in(states, dimension, Wanted::Any)
    }

    /// A batch of configurations per pass (eight or sixteen), each lane decided (it leaves the
    /// work once found invalid).
    fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
        let dimension = dimension.max(1);
        let s = &*self.shared;
        let mut guard = self.scratch.lock();
        let chunks = states
            .chunks(LANES * dimension)
            .zip(valid.chunks_mut(LANES));
        for (chunk, answers) in chunks {
            let count = (chunk.len() / dimension).min(answers.len());
            let chunk = &chunk[..count * dimension];
            let invalid = invalid_lanes(
                s,
                &mut guard.lanes,
                (chunk, dimension),
                &s.plain,
                Wanted::All,
            );
            for (l, answer) in answers[..count].iter_mut().enumerate() {
                *answer = invalid & (1 << l) == 0;
            }
        }
    }

    /// Prepared when the segment has the robot's dimension and finite ends: its points then
    /// go into the lanes straight from `start + delta · t`, without interpolated states.
    fn prepare_segment(&self, segment: &mut Segment) -> Preparation {
        if segment.dimension() == self.shared.lower.len() && segment.is_finite() {
            Preparation::Prepared
        } else {
            Preparation::Unprepared
        }
    }

    fn first_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.invalid_on(segment, fractions, Wanted::First)
    }

    /// Ends a batch at its first contact in any lane, as [`any_invalid`](Self::any_invalid).
    fn any_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.invalid_on(segment, fractions, Wanted::Any)
    }
}

impl ArmChecker {
    /// An invalid configuration of `states` (the first, or any, as `wanted`), a batch of
    /// `LANES` at a time.
    fn invalid_in(&self, states: &[f64], dimension: usize, wanted: Wanted) -> Option<usize> {
        let dimension = dimension.max(1);
        let s = &*self.shared;
        let mut guard = self.scratch.lock();
        for (c, chunk) in states.chunks(LANES * dimension).enumerate() {
            let invalid = invalid_lanes(s, &mut guard.lanes, (chunk, dimension), &s.plain, wanted);
            if invalid != 0 {
                return Some(c * LANES + invalid.trailing_zeros() as usize);
            }
        }
        None
    }

    /// [`invalid_in`](Self::invalid_in) for the points at `fractions` of a prepared segment.
    fn invalid_on(&self, segment: &Segment, fractions: &[f64], wanted: Wanted) -> Option<usize> {
        let s = &*self.shared;
        let mut guard = self.scratch.lock();
        for (c, chunk) in fractions.chunks(LANES).enumerate() {
            let invalid = invalid_lanes_on(s, &mut guard.lanes, (segment, chunk), &s.plain, wanted);
            if invalid != 0 {
                return Some(c * LANES + invalid.trailing_zeros() as usize);
            }
        }
        None
    }
}

/// Bit `l` set if configuration `l` of `chunk` (at most [`LANES`] configurations of
/// `dimension` values) is invalid with every sphere of the link in entry `k` of
/// `Shared::links` grown by `grow[k]` (the same in every lane) against the scene, and by the
/// margin against the other link of a self-collision pair. [`Wanted::First`]: exact for
/// every lane up to the first invalid one. [`Wanted::Any`]: nonzero exactly when some lane is
/// invalid, and every bit set is an invalid lane. [`Wanted::All`]: exact for every lane. A
/// chunk of the wrong dimension is invalid in every lane.
pub(crate) fn invalid_lanes(
    s: &Shared,
    scratch: &mut LaneScratch,
    (chunk, dimension): (&[f64], usize),
    grow: &[LaneF32],
    wanted: Wanted,
) -> u32 {
    let count = (chunk.len() / dimension).min(LANES);
    let live: u32 = (1 << count) - 1;
    if dimension != s.lower.len() || chunk.len() != count * dimension || count == 0 {
        return live.max(1);
    }
    let invalid = outside_limits(s, chunk, dimension);
    if undecided(invalid, live, wanted) == 0 {
        return invalid;
    }
    fill_lanes(&mut scratch.lane_q, chunk, dimension);
    invalid_filled(s, scratch, (live, invalid), grow, wanted)
}

/// Bit `l` set if the point at `fractions[l]` of the prepared `segment` (`start + delta · t`,
/// as the space's interpolation computes it: the answer of [`invalid_lanes`] for the
/// interpolated configurations, bit for bit) is invalid; at most [`LANES`] fractions.
fn invalid_lanes_on(
    s: &Shared,
    scratch: &mut LaneScratch,
    (segment, fractions): (&Segment, &[f64]),
    grow: &[LaneF32],
    wanted: Wanted,
) -> u32 {
    let count = fractions.len().min(LANES);
    let live: u32 = (1 << count) - 1;
    if segment.dimension() != s.lower.len() || count == 0 {
        return live.max(1);
    }
    // Joint values by coordinate, straight from the segment, as the scalar interpolation
    // rounds them: the lanes hold the interpolated configurations bit for bit.
    let ends = (segment.start(), segment.delta());
    let invalid = fill_on_line(s, &mut scratch.lane_q, ends, fractions, |_| {
        Coordinate::AsIs
    });
    if undecided(invalid, live, wanted) == 0 {
        return invalid;
    }
    invalid_filled(s, scratch, (live, invalid), grow, wanted)
}

/// What [`fill_on_line`] does with a coordinate `start + delta · t`.
#[derive(Clone, Copy)]
pub(crate) enum Coordinate {
    /// Kept as it is.
    AsIs,
    /// Kept between two values (the edge's ends, which rounding could leave by an ulp).
    Between(f64, f64),
    /// Wrapped into `[-π, π)` (a wrapping joint).
    Wrapped,
}

/// Writes into `lane_q`, by coordinate, the configurations `start + delta · t` at the first
/// [`LANES`] fractions `t` of `fractions` (padding lanes repeat the first), coordinate `j` as
/// `coordinate(j)` says, and returns the lanes outside the joint limits. Four lanes at a time
/// in `f64x4`: `start + delta · t` rounds as the scalar interpolation does (no fused
/// multiply-add).
pub(crate) fn fill_on_line(
    s: &Shared,
    lane_q: &mut [LaneF32],
    (start, delta): (&[f64], &[f64]),
    fractions: &[f64],
    coordinate: impl Fn(usize) -> Coordinate,
) -> u32 {
    let count = fractions.len().min(LANES);
    let mut ts = [fractions[0]; LANES];
    ts[..count].copy_from_slice(&fractions[..count]);
    let fours: [f64x4; LANES / 4] = std::array::from_fn(|h| {
        f64x4::from([ts[4 * h], ts[4 * h + 1], ts[4 * h + 2], ts[4 * h + 3]])
    });
    let mut inside = u32::MAX;
    for (j, q) in lane_q.iter_mut().enumerate() {
        let (x0, d) = (f64x4::splat(start[j]), f64x4::splat(delta[j]));
        let (lo, hi) = (f64x4::splat(s.lower[j]), f64x4::splat(s.upper[j]));
        let mut values = [0.0_f32; LANES];
        let kind = coordinate(j);
        for (h, t) in fours.iter().enumerate() {
            let x = x0 + d * *t;
            let x = match kind {
                Coordinate::AsIs => x,
                Coordinate::Between(low, high) => x.max(f64x4::splat(low)).min(f64x4::splat(high)),
                Coordinate::Wrapped => f64x4::from(x.to_array().map(mit_star_spaces::wrap_angle)),
            };
            // Lanes `4h … 4h + 3`: cleared where outside the limits, the others kept.
            let within = (x.simd_ge(lo) & x.simd_le(hi)).to_bitmask();
            inside &= !(0xf << (4 * h)) | (within << (4 * h));
            for (v, x) in values[4 * h..4 * h + 4].iter_mut().zip(x.to_array()) {
                *v = x as f32;
            }
        }
        *q = LaneF32::new(values);
    }
    let live: u32 = (1 << count) - 1;
    !inside & live
}

/// Lanes still to decide: those before the first invalid one (none once one is found, if any
/// will do; every lane not yet found invalid, if all are wanted).
#[inline]
fn undecided(invalid: u32, live: u32, wanted: Wanted) -> u32 {
    match wanted {
        _ if invalid == 0 => live,
        Wanted::All => live & !invalid,
        Wanted::Any => 0,
        Wanted::First => live & ((1 << invalid.trailing_zeros()) - 1),
    }
}

/// The sphere tests of [`invalid_lanes`] on joint values already in `scratch.lane_q`: `live` the
/// lanes in use, `invalid` those already known invalid (outside the joint limits).
fn invalid_filled(
    s: &Shared,
    scratch: &mut LaneScratch,
    (live, mut invalid): (u32, u32),
    grow: &[LaneF32],
    wanted: Wanted,
) -> u32 {
    let LaneScratch {
        lane_poses,
        lane_centers,
        lane_bounds,
        placed,
        lane_q,
        last_hit,
        candidates,
        ..
    } = scratch;
    let undecided = |invalid: u32| undecided(invalid, live, wanted);
    let mut active = undecided(invalid);
    placed.fill(false);
    // Links are placed as the tests reach them (in tree order), so that a batch found invalid
    // early skips the rest of the walk. `posed`: links placed so far (in tree order).
    let mut posed = 0;
    // A closure over the pose and range this loop already holds, not `place_link`: its
    // lookups cost the plain checks 5–8 % (criterion `arm_check`).
    let place_lanes = |pose: &LanePose, range: &Range<usize>, centers: &mut [LanePoint]| {
        for (c, sphere) in centers[range.clone()]
            .iter_mut()
            .zip(&s.spheres[range.clone()])
        {
            *c = pose.point(sphere.0);
        }
    };
    // When any contact will do, the link that met an obstacle last time goes first.
    let first = (wanted == Wanted::Any && *last_hit < s.links.len()).then_some(*last_hit);
    let order = first
        .into_iter()
        .chain((0..s.links.len()).filter(|&k| Some(k) != first));
    for k in order {
        let (link, range, center, radius) = &s.links[k];
        if *link >= posed {
            s.lanes.link_poses_in(lane_q, lane_poses, posed..*link + 1);
            posed = *link + 1;
        }
        let pose = &lane_poses[*link];
        let bounding = pose.point(*center);
        lane_bounds[k] = bounding;
        let grown = grow[k];
        let bound = LaneF32::splat(*radius) + grown;
        let spheres = s.spheres[range.clone()]
            .iter()
            .zip(&s.reaches[range.clone()]);
        // Among many obstacles, only those the grid finds near the lanes still undecided: the
        // others are beyond `bound` of every such lane (`obstacle_grid.rs`), and the test
        // below would skip them.
        let list = &s.reachable[k];
        let near = s.grids[k].as_ref().is_some_and(|grid| {
            grid.candidates(&bounding, active, widest(bound), &mut candidates.0)
        });
        // The same tests over the grid's candidates or (no grid: the linear scan as it always
        // was) the whole list.
        macro_rules! test_each {
            ($obstacles:expr) => {
                for obstacle in $obstacles {
                    let Some((hit, excess)) = obstacle.contacts_lanes(&bounding, bound) else {
                        continue;
                    };
                    if hit & active == 0 {
                        continue;
                    }
                    if !placed[k] {
                        place_lanes(pose, range, lane_centers);
                        placed[k] = true;
                    }
                    for (c, (sphere, &reach)) in
                        lane_centers[range.clone()].iter().zip(spheres.clone())
                    {
                        // The bounding centre too far for this sphere to touch, in every lane that
                        // counts.
                        let reach = LaneF32::splat(reach) + grown;
                        if excess.simd_le(reach * reach).to_bitmask() & active == 0 {
                            continue;
                        }
                        let radius = LaneF32::splat(sphere.1) + grown;
                        let hit = obstacle.collides_spheres_lanes(c, radius);
                        if hit & active != 0 {
                            invalid |= hit & active;
                            active = undecided(invalid);
                            if active == 0 {
                                *last_hit = k;
                                return invalid;
                            }
                        }
                    }
                }
            };
        }
        if near {
            test_each!(candidates.0.iter().map(|&i| &list[i as usize]));
        } else {
            test_each!(list);
        }
        // Point clouds: each sphere a query of the cloud for the lanes still undecided. No
        // query of the link's bounding sphere first, as among primitives: its walk reaches
        // every point near any lane's bound, and the spheres' walks, which stop at once where
        // a lane is far, cost less than it saved (measured without it, RRT-Connect among
        // clouds: no scene slower, cage and bookshelf_thin a sixth faster).
        for &cloud in &s.reachable_clouds[k] {
            let cloud = &s.clouds[cloud];
            if active == 0 {
                break;
            }
            if !placed[k] {
                place_lanes(pose, range, lane_centers);
                placed[k] = true;
            }
            for (c, sphere) in lane_centers[range.clone()]
                .iter()
                .zip(&s.spheres[range.clone()])
            {
                if active == 0 {
                    break;
                }
                let hit = cloud.touches_lanes(c, LaneF32::splat(sphere.1) + grown, active);
                if hit != 0 {
                    invalid |= hit;
                    active = undecided(invalid);
                    if active == 0 {
                        *last_hit = k;
                        return invalid;
                    }
                }
            }
        }
    }
    for &(a, b) in &s.pairs {
        let (la, lb) = (&s.links[a], &s.links[b]);
        let grown = s.pair_grow + s.pair_grow;
        let reach = LaneF32::splat(la.3 + lb.3) + grown;
        let bound_b = lane_bounds[b];
        if distance_squared(&lane_bounds[a], &bound_b)
            .simd_le(reach * reach)
            .to_bitmask()
            & active
            == 0
        {
            continue;
        }
        for (k, l) in [(a, la), (b, lb)] {
            if !placed[k] {
                place_lanes(&lane_poses[l.0], &l.1, lane_centers);
                placed[k] = true;
            }
        }
        let (spheres_a, spheres_b) = (&s.spheres[la.1.clone()], &s.spheres[lb.1.clone()]);
        let (centers_a, centers_b) = (&lane_centers[la.1.clone()], &lane_centers[lb.1.clone()]);
        // Each sphere of the first link against the second's bounding sphere, then its
        // spheres.
        for (ca, sa) in centers_a.iter().zip(spheres_a) {
            let near = LaneF32::splat(sa.1 + lb.3) + grown;
            if distance_squared(ca, &bound_b)
                .simd_le(near * near)
                .to_bitmask()
                & active
                == 0
            {
                continue;
            }
            for (cb, sb) in centers_b.iter().zip(spheres_b) {
                let r = LaneF32::splat(sa.1 + sb.1) + grown;
                let hit = distance_squared(ca, cb).simd_le(r * r).to_bitmask();
                if hit & active != 0 {
                    invalid |= hit & active;
                    active = undecided(invalid);
                    if active == 0 {
                        return invalid;
                    }
                }
            }
        }
    }
    invalid
}

/// Places the sphere centres of link entry `k` (of `Shared::links`) in every lane from its
/// pose in `poses`, unless `placed[k]` says this batch already has them (certification's
/// placements).
#[inline]
pub(crate) fn place_link(
    s: &Shared,
    k: usize,
    poses: &[LanePose],
    centers: &mut [LanePoint],
    placed: &mut [bool],
) {
    if placed[k] {
        return;
    }
    let (link, range, ..) = &s.links[k];
    let pose = &poses[*link];
    for (c, sphere) in centers[range.clone()]
        .iter_mut()
        .zip(&s.spheres[range.clone()])
    {
        *c = pose.point(sphere.0);
    }
    placed[k] = true;
}

/// Per lane, the squared distance between the two points.
#[inline]
pub(crate) fn distance_squared(a: &LanePoint, b: &LanePoint) -> LaneF32 {
    let (x, y, z) = (a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    x * x + y * y + z * z
}

/// Bit `l` set if configuration `l` of `chunk` (`dimension` values each) is outside the joint
/// limits (or not a number).
pub(crate) fn outside_limits(s: &Shared, chunk: &[f64], dimension: usize) -> u32 {
    let mut outside = 0u32;
    for (l, q) in chunk.chunks_exact(dimension).take(LANES).enumerate() {
        let out = q
            .iter()
            .zip(s.lower.iter().zip(&s.upper))
            .any(|(x, (lo, hi))| !(lo <= x && x <= hi));
        outside |= u32::from(out) << l;
    }
    outside
}

/// Writes the joint values of `chunk`'s configurations (at most [`LANES`], `dimension` values
/// each) into `lane_q` by coordinate; padding lanes repeat configuration 0.
pub(crate) fn fill_lanes(lane_q: &mut [LaneF32], chunk: &[f64], dimension: usize) {
    let count = (chunk.len() / dimension).min(LANES);
    for (c, v) in lane_q.iter_mut().enumerate() {
        *v = LaneF32::new(std::array::from_fn(|l| {
            chunk[if l < count { l } else { 0 } * dimension + c] as f32
        }));
    }
}
