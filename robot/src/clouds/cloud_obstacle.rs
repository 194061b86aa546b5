//! [`CloudObstacle`]: a named point cloud with its structure, as a scene holds it.

use glam::{Vec3, Vec3A};

use crate::lane_f32::{LANES, LaneF32};
use crate::{AffordanceTree, PointCloud, PointTree};

/// A point cloud as a scene's obstacle: its name (for diagnoses and audits), the validated
/// points and their radius, and the [`PointTree`] the checker queries, built once here; with
/// [`with_affordances`](Self::with_affordances), an [`AffordanceTree`] too, which answers the
/// contact queries of spheres up to a radius several times faster (the tree answers the
/// others, and the distance bounds).
///
/// A ball of the robot (centre `c`, radius `r`) **collides** with the cloud when it shares a
/// point with some point's ball: `|c − p| ≤ r + ρ`, `ρ` the points' radius (touching counts,
/// as for the primitives).
///
/// ```
/// use glam::Vec3;
/// use mit_star_robot::{CloudObstacle, PointCloud, Scene};
/// let cloud = PointCloud::new(vec![Vec3::new(0.5, 0.0, 0.3), Vec3::new(0.5, 0.02, 0.3)])?;
/// let obstacle = CloudObstacle::new("camera", cloud);
/// assert!(obstacle.touches_sphere(Vec3::new(0.45, 0.0, 0.3), 0.048));
/// assert!(!obstacle.touches_sphere(Vec3::new(0.45, 0.0, 0.3), 0.04));
/// let lower = obstacle.distance_lower_bound(Vec3::new(0.4, 0.0, 0.3), f32::INFINITY);
/// assert!(lower <= 0.1 - 0.0025 && lower > 0.0974);
/// let scene = Scene::new(vec![]).with_cloud(obstacle);
/// assert_eq!(scene.clouds().len(), 1);
/// # Ok::<(), mit_star_robot::CloudError>(())
/// ```
#[derive(Debug, Clone)]
pub struct CloudObstacle {
    name: String,
    cloud: PointCloud,
    tree: PointTree,
    /// The contact structure for spheres up to a radius, if built.
    affordances: Option<AffordanceTree>,
    /// The points' radius in `f32`, rounded up.
    radius: f32,
    /// A sphere enclosing every point's ball: centre and radius (rounded up).
    bound: (Vec3A, f32),
}

impl PartialEq for CloudObstacle {
    /// The same name, points and radius (the tree follows from them).
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name && self.cloud == other.cloud
    }
}

impl CloudObstacle {
    /// The obstacle `name` made of `cloud`, its [`PointTree`] built here (`O(n log n)`: about
    /// a millisecond for ten thousand points).
    pub fn new(name: impl Into<String>, cloud: PointCloud) -> Self {
        let tree = PointTree::new(cloud.points());
        Self::with_tree(name.into(), cloud, tree)
    }

    /// As [`new`](Self::new), polling `stop` while the tree is built: `None` if it said to
    /// stop.
    pub fn new_polled(
        name: impl Into<String>,
        cloud: PointCloud,
        stop: &dyn mit_star_spaces::Stop,
    ) -> Option<Self> {
        let tree = PointTree::new_polled(cloud.points(), stop)?;
        Some(Self::with_tree(name.into(), cloud, tree))
    }

    fn with_tree(name: String, cloud: PointCloud, tree: PointTree) -> Self {
        let radius = (cloud.radius() * (1.0 + 1e-6)) as f32;
        let (min, max) = tree.bounds();
        let center = 0.5 * (min + max);
        let half = f64::from((max - min).length()) * 0.5 + cloud.radius();
        let bound = (center.into(), (half * (1.0 + 1e-6) + 1e-6) as f32);
        Self {
            name,
            cloud,
            tree,
            affordances: None,
            radius,
            bound,
        }
    }

    /// The same obstacle with an [`AffordanceTree`] for spheres of radius up to
    /// `max_radius` (the points' radius is added here): contact queries of such spheres are
    /// answered by it, the same answers faster; larger spheres and the distance bounds are
    /// answered by the [`PointTree`]. Without it if its lists would outgrow its memory budget
    /// (dense clouds of millions of points; see [`AffordanceTree`]) or if `max_radius` is not
    /// a finite non-negative number. Building takes `O(n log n)` plus the lists: about a
    /// millisecond for ten thousand points 2 cm apart among the Panda's spheres.
    ///
    /// An arm problem's largest sphere (padding included) is
    /// [`ArmProblem::cloud_contact_radius`](crate::ArmProblem::cloud_contact_radius).
    #[must_use]
    pub fn with_affordances(mut self, max_radius: f32) -> Self {
        self.affordances = (max_radius.is_finite() && max_radius >= 0.0)
            .then(|| {
                AffordanceTree::new_polled(
                    &self.tree,
                    max_radius + self.radius,
                    &mit_star_spaces::Never,
                )
            })
            .flatten();
        self
    }

    /// The contact structure, if [built](Self::with_affordances) (and within its budget).
    pub fn affordances(&self) -> Option<&AffordanceTree> {
        self.affordances.as_ref()
    }

    /// The name it goes by in diagnoses and audits.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The points and their radius.
    pub fn cloud(&self) -> &PointCloud {
        &self.cloud
    }

    /// The tree: distance bounds, and the contacts the affordances do not answer.
    pub fn tree(&self) -> &PointTree {
        &self.tree
    }

    /// Centre and radius of a sphere enclosing every point's ball.
    pub fn bounding_sphere(&self) -> (Vec3A, f32) {
        self.bound
    }

    /// `true` if the ball of `radius` at `center` meets some point's ball (`f32`).
    pub fn touches_sphere(&self, center: Vec3, radius: f32) -> bool {
        let reach = radius + self.radius;
        self.affordances
            .as_ref()
            .and_then(|a| a.any_within(center, reach))
            .unwrap_or_else(|| self.tree.any_within(center, reach))
    }

    /// [`touches_sphere`](Self::touches_sphere) for many balls at once, a batch of the
    /// checker's lanes (eight or sixteen) per walk of the tree, or, with affordances and at
    /// most four balls in a batch, each ball's own query: `out[i]` for `centers[i]`,
    /// `radii[i]` (as many as the shortest of the three). The answers are the single
    /// queries' answers.
    pub fn touches_spheres(&self, centers: &[Vec3], radii: &[f32], out: &mut [bool]) {
        let count = centers.len().min(radii.len()).min(out.len());
        for start in (0..count).step_by(LANES) {
            let end = (start + LANES).min(count);
            let (lanes, live) = lanes_of(&centers[start..end]);
            let r = LaneF32::new(std::array::from_fn(|l| radii[(start + l).min(end - 1)]));
            let hit = self.touches_lanes(&lanes, r, live);
            for (l, answer) in out[start..end].iter_mut().enumerate() {
                *answer = hit & (1 << l) != 0;
            }
        }
    }

    /// A lower bound of the distance from `point` to the nearest point's ball (negative
    /// inside one), or a value above `limit` if none is nearer than that: never above the
    /// true distance, and below it by at most a millionth of it when at most `limit`.
    pub fn distance_lower_bound(&self, point: Vec3, limit: f32) -> f32 {
        let r = self.radius;
        self.tree.distance_lower_bound(point, widened(limit, r) + r) - r
    }

    /// [`distance_lower_bound`](Self::distance_lower_bound) of many points, a batch of the
    /// checker's lanes per walk: `out[i]` for `points[i]`. The answers are the single
    /// queries' answers.
    pub fn distance_lower_bounds(&self, points: &[Vec3], limit: f32, out: &mut [f32]) {
        let count = points.len().min(out.len());
        for start in (0..count).step_by(LANES) {
            let end = (start + LANES).min(count);
            let (lanes, live) = lanes_of(&points[start..end]);
            let lower = self
                .distance_lower_bounds_lanes(&lanes, LaneF32::splat(limit), live)
                .to_array();
            out[start..end].copy_from_slice(&lower[..end - start]);
        }
    }

    /// Bit `l` set if lane `l` of `active` has its ball (centre, `radius[l]`) meeting some
    /// point's ball. The affordances answer when at most [`AFFORDED_LANES`] lanes are active (each lane a
    /// query of its own), the tree's one walk for all the lanes otherwise.
    #[inline]
    pub(crate) fn touches_lanes(&self, center: &[LaneF32; 3], radius: LaneF32, active: u32) -> u32 {
        let reach = radius + LaneF32::splat(self.radius);
        self.affordances
            .as_ref()
            .filter(|_| active.count_ones() <= AFFORDED_LANES)
            .and_then(|a| a.any_within_lanes(center, reach, active))
            .unwrap_or_else(|| self.tree.any_within_lanes(center, reach, active))
    }

    /// Per lane of `live`, [`distance_lower_bound`](Self::distance_lower_bound).
    #[inline]
    pub(crate) fn distance_lower_bounds_lanes(
        &self,
        point: &[LaneF32; 3],
        limit: LaneF32,
        live: u32,
    ) -> LaneF32 {
        let r = LaneF32::splat(self.radius);
        self.tree
            .lower_bounds_lanes(point, widened_lanes(limit, r) + r, live)
            - r
    }

    /// Calls `visit` for each point whose ball may lie within `limit` of the centre of a lane
    /// of `live` (`limit[l]` for lane `l`), with per lane a lower bound of the distance from
    /// the centre to the ball (as [`distance_lower_bound`](Self::distance_lower_bound)'s),
    /// the unit direction from the point to the centre as computed in `f32` (its error is
    /// the caller's to allow for), and the mask of the lanes of `live` within the limit;
    /// `visit` returns the limit for the rest of the walk, which may only shrink. Every
    /// point whose ball is nearer than the limit in a lane of `live` is visited.
    #[inline]
    pub(crate) fn visit_balls_lanes(
        &self,
        center: &[LaneF32; 3],
        limit: LaneF32,
        live: u32,
        mut visit: impl FnMut(LaneF32, [LaneF32; 3], LaneF32) -> LaneF32,
    ) {
        let r = LaneF32::splat(self.radius);
        let [x, y, z] = *center;
        self.tree.visit_within_lanes(
            center,
            widened_lanes(limit, r) + r,
            live,
            |p, d2, within| {
                let d = d2.sqrt();
                let inverse = LaneF32::ONE / d.max(LaneF32::splat(f32::MIN_POSITIVE));
                let direction = [
                    (x - LaneF32::splat(p.x)) * inverse,
                    (y - LaneF32::splat(p.y)) * inverse,
                    (z - LaneF32::splat(p.z)) * inverse,
                ];
                let ball = d * LaneF32::splat(crate::clouds::point_tree::LOWER) - r;
                widened_lanes(visit(ball, direction, within), r) + r
            },
        );
    }

    /// The point whose ball is nearest `point`, in `f64` by brute force over every point
    /// (diagnoses): its index in the cloud and the distance from `point` to its ball
    /// (negative inside).
    pub fn nearest_ball_f64(&self, point: glam::DVec3) -> (usize, f64) {
        let (index, d) = self
            .cloud
            .points()
            .iter()
            .enumerate()
            .map(|(i, p)| (i, p.as_dvec3().distance(point)))
            .fold(
                (0, f64::INFINITY),
                |best, x| if x.1 < best.1 { x } else { best },
            );
        (index, d - self.cloud.radius())
    }
}

/// Most active lanes the affordances answer one by one: beyond, the tree's single walk for
/// all the lanes costs less (`examples/cloud_query.rs`: a batch of sixteen nearby spheres
/// costs the tree 12–28 ns a sphere, the affordances 47–73).
const AFFORDED_LANES: u32 = 4;

/// How much wider than asked a distance walk looks (with as much again of the points'
/// radius), so that a cloud with nothing within the limit gets a bound above the limit
/// despite the bound's shrinking by a millionth: a caller comparing it with the limit then
/// knows the cloud is that far.
const WIDER: f32 = 1.0 + 1e-5;

/// `limit` widened by [`WIDER`] (the arithmetic of [`widened_lanes`], one lane).
#[inline]
fn widened(limit: f32, r: f32) -> f32 {
    limit * WIDER + r * (WIDER - 1.0)
}

/// [`widened`], a lane at a time.
#[inline]
fn widened_lanes(limit: LaneF32, r: LaneF32) -> LaneF32 {
    limit * LaneF32::splat(WIDER) + r * LaneF32::splat(WIDER - 1.0)
}

/// Up to [`LANES`] points as lanes (padding lanes repeat the first), and the lanes in use.
fn lanes_of(points: &[Vec3]) -> ([LaneF32; 3], u32) {
    let at = |l: usize| points[if l < points.len() { l } else { 0 }];
    let lanes = [
        LaneF32::new(std::array::from_fn(|l| at(l).x)),
        LaneF32::new(std::array::from_fn(|l| at(l).y)),
        LaneF32::new(std::array::from_fn(|l| at(l).z)),
    ];
    (lanes, (1_u32 << points.len()) - 1)
}
