//! [`ParryChecker`]: the reference collision checker, in `f64` with parry's shape queries.

use std::sync::Arc;

use glam::{DAffine3, DQuat, DVec3};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use parry3d_f64::math::Pose;
use parry3d_f64::query::{distance, intersection_test};
use parry3d_f64::shape::{Ball, Cuboid, Cylinder, SharedShape};

use crate::checking::audit_clouds::AuditClouds;
use crate::checking::scratch_cell::ScratchCell;
use crate::{Kinematics, Padding, RobotModel, Scene, Shape};

/// Per-clone scratch: link poses, and sphere centres with radii.
type Placed = (Vec<DAffine3>, Vec<(DVec3, f64)>);

#[derive(Debug)]
struct Shared {
    fk: Kinematics,
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// Obstacles as parry shapes with their poses.
    obstacles: Vec<(Pose, SharedShape)>,
    /// The scene's point clouds, every point in `f64`.
    clouds: Arc<AuditClouds>,
    /// Per link: its spheres' indices (empty for a link without spheres).
    link_spheres: Vec<std::ops::Range<usize>>,
    pairs: Vec<(usize, usize)>,
    /// The self-collision pairs as pairs of sphere indices.
    sphere_pairs: Vec<(usize, usize)>,
    /// Kept from the scene (not between links): spheres are grown by it against obstacles
    /// and clouds.
    padding: Padding,
}

/// The reference checker: the same model and scene as [`ArmChecker`](crate::ArmChecker), but
/// every sphere placed in `f64` and every test a parry query (balls against cuboids,
/// cylinders and balls) or, for point clouds, a distance to every point in `f64`, with no
/// broad phase and no early culling — slow and independent.
///
/// It is what the property tests compare the fast checker with, and what the experiment
/// harness re-checks returned arm paths with.
/// [`is_valid_with_margin`](Self::is_valid_with_margin) grows (or, negative, shrinks) every
/// robot sphere, which states the tolerance of a comparison on touching contacts.
///
/// ```
/// use mit_star_validity::StateValidity;
/// let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/box_panda");
/// let problem = mit_star_robot::ArmProblem::panda_mbm(folder.as_ref(), 1)?;
/// let reference = mit_star_robot::ParryChecker::new(problem.robot(), problem.scene());
/// let start = mit_star_problems::PlanningProblem::start(&problem).to_vec();
/// assert!(reference.is_valid(&start));
/// # Ok::<(), mit_star_robot::ArmError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ParryChecker {
    shared: Arc<Shared>,
    scratch: ScratchCell<Placed>,
}

impl ParryChecker {
    /// The obstacles of `scene` as parry shapes with their poses, in the scene's order
    /// (MoveIt's cylinders run along z, parry's along y: they are turned onto z).
    pub fn obstacle_shapes(scene: &Scene) -> Vec<(Pose, SharedShape)> {
        scene
            .obstacles()
            .iter()
            .map(|o| {
                let pose = o.pose();
                let rotation = DQuat::from_mat3(&pose.matrix3);
                let (shape, local) = match o.shape() {
                    Shape::Cuboid { half_extents } => {
                        (SharedShape::new(Cuboid::new(half_extents)), DQuat::IDENTITY)
                    }
                    Shape::Cylinder {
                        half_height,
                        radius,
                    } => (
                        SharedShape::new(Cylinder::new(half_height, radius)),
                        DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2),
                    ),
                    Shape::Sphere { radius } => {
                        (SharedShape::new(Ball::new(radius)), DQuat::IDENTITY)
                    }
                };
                (Pose::from_parts(pose.translation, rotation * local), shape)
            })
            .collect()
    }

    /// The reference checker of `robot` (its self-collision pairs as they stand) in `scene`.
    pub fn new(robot: &RobotModel, scene: &Scene) -> Self {
        Self::padded(robot, scene, Padding::ZERO)
    }

    /// The reference checker of `robot` in `scene` with every sphere grown by `padding`
    /// against the scene's obstacles and clouds (not against the robot's other links), as
    /// [`ArmChecker::padded`](crate::ArmChecker::padded) pads.
    pub fn padded(robot: &RobotModel, scene: &Scene, padding: Padding) -> Self {
        let fk = Kinematics::new(robot);
        let obstacles = Self::obstacle_shapes(scene);
        let space = robot.joint_space();
        let link_spheres = (0..robot.links().len())
            .map(|l| robot.link_sphere_range(l))
            .collect();
        let pairs = robot.self_collision_pairs().to_vec();
        let sphere_pairs = pairs
            .iter()
            .flat_map(|&(a, b)| {
                let theirs = robot.link_sphere_range(b);
                robot
                    .link_sphere_range(a)
                    .flat_map(move |i| theirs.clone().map(move |j| (i, j)))
            })
            .collect();
        let scratch = (
            vec![DAffine3::IDENTITY; fk.link_count()],
            vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
        );
        Self {
            shared: Arc::new(Shared {
                fk,
                lower: space.lower().to_vec(),
                upper: space.upper().to_vec(),
                obstacles,
                clouds: Arc::new(AuditClouds::of(scene)),
                link_spheres,
                pairs,
                sphere_pairs,
                padding,
            }),
            scratch: ScratchCell::new(scratch),
        }
    }

    /// Validity with every robot sphere's radius changed by `margin` (metres; a sphere whose
    /// radius would not stay positive is a point), and by the padding too against the scene.
    /// `margin = 0` is [`is_valid`](StateValidity::is_valid).
    pub fn is_valid_with_margin(&self, q: &[f64], margin: f64) -> bool {
        let s = &*self.shared;
        if q.len() != s.lower.len()
            || q.iter()
                .zip(s.lower.iter().zip(&s.upper))
                .any(|(x, (lo, hi))| !(lo <= x && x <= hi))
        {
            return false;
        }
        let mut guard = self.scratch.lock();
        let (links, centers) = &mut *guard;
        s.fk.sphere_centers_f64(q, links, centers);
        let ball =
            |&(c, r): &(DVec3, f64)| (Pose::from_translation(c), Ball::new((r + margin).max(0.0)));
        let meets = |p1: &Pose,
                     g1: &dyn parry3d_f64::shape::Shape,
                     p2: &Pose,
                     g2: &dyn parry3d_f64::shape::Shape| {
            // Balls, cuboids and cylinders are all supported by the default dispatcher.
            intersection_test(p1, g1, p2, g2).is_ok_and(|i| i.intersecting)
        };
        let padding = s.padding.metres();
        for &(c, r) in centers.iter() {
            let (p, b) = ball(&(c, r + padding));
            if s.obstacles
                .iter()
                .any(|(op, shape)| meets(&p, &b, op, shape.as_ref()))
                || s.clouds.touches(c, b.radius)
            {
                return false;
            }
        }
        for &(a, b) in &s.pairs {
            for i in s.link_spheres[a].clone() {
                let (pi, bi) = ball(&centers[i]);
                for j in s.link_spheres[b].clone() {
                    let (pj, bj) = ball(&centers[j]);
                    if meets(&pi, &bi, &pj, &bj) {
                        return false;
                    }
                }
            }
        }
        true
    }
}

impl ParryChecker {
    /// The scene's point clouds as this checker measures them.
    pub(crate) fn clouds(&self) -> &Arc<AuditClouds> {
        &self.shared.clouds
    }

    /// The padding kept from the scene ([`Padding::ZERO`] unless built [padded](Self::padded)).
    pub fn padding(&self) -> Padding {
        self.shared.padding
    }

    /// The self-collision pairs as pairs of indices into [`RobotModel::spheres`]: every
    /// sphere of one link of a checked pair with every sphere of the other.
    pub fn sphere_pairs(&self) -> &[(usize, usize)] {
        &self.shared.sphere_pairs
    }

    /// Separation distances at `q`, in `f64` with parry's distance queries:
    /// `obstacle_gaps[s]` is the distance from robot sphere `s` ([`RobotModel::spheres`]),
    /// grown by the [padding](Self::padding), to the nearest obstacle (`f64::INFINITY` in an
    /// empty scene, 0 if they touch or overlap),
    /// and `pair_gaps[k]` the gap between the two spheres of the `k`-th
    /// [sphere pair](Self::sphere_pairs) (negative if they overlap). Joint limits are not
    /// looked at.
    ///
    /// # Panics
    /// If `q` is shorter than the robot's dimension or an output is shorter than the sphere
    /// or pair count (a caller's bug).
    pub fn gaps(&self, q: &[f64], obstacle_gaps: &mut [f64], pair_gaps: &mut [f64]) {
        let s = &*self.shared;
        let mut guard = self.scratch.lock();
        let (links, centers) = &mut *guard;
        s.fk.sphere_centers_f64(q, links, centers);
        for (gap, &(c, r)) in obstacle_gaps.iter_mut().zip(centers.iter()) {
            let r = r + s.padding.metres();
            let (pose, ball) = (Pose::from_translation(c), Ball::new(r));
            *gap = s
                .obstacles
                .iter()
                .map(|(op, shape)| {
                    // Balls, cuboids and cylinders are all supported: an error cannot occur,
                    // and would read as contact.
                    distance(&pose, &ball, op, shape.as_ref()).map_or(0.0, |d| d.distance)
                })
                .fold(f64::INFINITY, f64::min)
                .min(s.clouds.nearest_gap(c, r));
        }
        for (gap, &(i, j)) in pair_gaps.iter_mut().zip(&s.sphere_pairs) {
            let ((ci, ri), (cj, rj)) = (centers[i], centers[j]);
            *gap = ci.distance(cj) - ri - rj;
        }
    }
}

impl StateValidity for ParryChecker {
    fn is_valid(&self, q: &[f64]) -> bool {
        self.is_valid_with_margin(q, 0.0)
    }
}
