//! [`ArmChecker`]: is an arm configuration collision-free in its scene and with itself.

use std::cell::RefCell;
use std::ops::Range;
use std::sync::Arc;

use glam::{Affine3A, Vec3A};
use spaces::StateSpace;
use validity::StateValidity;

use crate::{Kinematics, Obstacle, RobotModel, Scene};

/// What the checks share between clones: the kinematics, the scene and the pair lists.
#[derive(Debug)]
struct Shared {
    fk: Kinematics,
    lower: Vec<f64>,
    upper: Vec<f64>,
    obstacles: Vec<Obstacle>,
    /// Links with spheres, in tree order: link, its sphere range, local bounding sphere.
    links: Vec<(usize, Range<usize>, Vec3A, f32)>,
    /// Local sphere centres and radii.
    spheres: Vec<(Vec3A, f32)>,
    /// Self-collision pairs as indices into `links`.
    pairs: Vec<(usize, usize)>,
}

/// Per-clone scratch: link poses and sphere centres, reused by every check.
#[derive(Debug, Clone)]
struct Scratch {
    poses: Vec<Affine3A>,
    centers: Vec<Vec3A>,
    /// Per entry of `Shared::links`: its world bounding-sphere centre, and whether its sphere
    /// centres are placed for the current configuration.
    bounds: Vec<Vec3A>,
    placed: Vec<bool>,
}

/// The collision checker of an arm in a scene: a configuration is valid if it is within the
/// joint limits, no sphere of the robot meets an obstacle, and no two spheres of a
/// self-collision pair of links meet.
///
/// Forward kinematics places the links ([`Kinematics`], `f32`); each link with spheres is
/// first tested as one bounding sphere against each obstacle's bounding sphere and the
/// obstacle itself (broad phase), and its small spheres only if that hits; self-collision
/// pairs likewise test the two links' bounding spheres first. The first contact ends the
/// check. Sphere centres are placed only for links that reach the narrow phase.
///
/// Clones share the model and scene (an [`Arc`]) and own their scratch buffers, so a check
/// never allocates. A checker is `Send` but not `Sync`: one per planner.
#[derive(Debug, Clone)]
pub struct ArmChecker {
    shared: Arc<Shared>,
    scratch: RefCell<Scratch>,
}

impl ArmChecker {
    /// The checker of `robot` (its self-collision pairs as they stand) in `scene`.
    pub fn new(robot: &RobotModel, scene: &Scene) -> Self {
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
        let pairs = robot
            .self_collision_pairs()
            .iter()
            .filter_map(|&(a, b)| Some((slot(a)?, slot(b)?)))
            .collect();
        let spheres = robot
            .spheres()
            .iter()
            .map(|s| (s.center.as_vec3a(), s.radius as f32))
            .collect();
        let scratch = Scratch {
            poses: vec![Affine3A::IDENTITY; fk.link_count()],
            centers: vec![Vec3A::ZERO; fk.sphere_count()],
            bounds: vec![Vec3A::ZERO; links.len()],
            placed: vec![false; links.len()],
        };
        let space = robot.joint_space();
        Self {
            shared: Arc::new(Shared {
                fk,
                lower: space.lower().to_vec(),
                upper: space.upper().to_vec(),
                obstacles: scene.obstacles().to_vec(),
                links,
                spheres,
                pairs,
            }),
            scratch: RefCell::new(scratch),
        }
    }

    /// The forward kinematics it uses.
    pub fn kinematics(&self) -> &Kinematics {
        &self.shared.fk
    }
}

impl StateValidity for ArmChecker {
    fn is_valid(&self, q: &[f64]) -> bool {
        let s = &*self.shared;
        if q.len() != s.lower.len()
            || q.iter()
                .zip(s.lower.iter().zip(&s.upper))
                .any(|(x, (lo, hi))| !(lo <= x && x <= hi))
        {
            return false;
        }
        let mut guard = self.scratch.borrow_mut();
        let Scratch {
            poses,
            centers,
            bounds,
            placed,
        } = &mut *guard;
        s.fk.link_poses(q, poses);
        placed.fill(false);
        // Scene: each link's bounding sphere, then its spheres.
        for (k, (link, range, center, radius)) in s.links.iter().enumerate() {
            let pose = &poses[*link];
            bounds[k] = pose.transform_point3a(*center);
            for obstacle in &s.obstacles {
                if !obstacle.collides_sphere(bounds[k], *radius) {
                    continue;
                }
                if !placed[k] {
                    place(pose, &s.spheres[range.clone()], &mut centers[range.clone()]);
                    placed[k] = true;
                }
                let hit = range
                    .clone()
                    .any(|i| obstacle.collides_sphere(centers[i], s.spheres[i].1));
                if hit {
                    return false;
                }
            }
        }
        // Self: bounding spheres of the two links, then sphere pairs.
        for &(a, b) in &s.pairs {
            let (la, lb) = (&s.links[a], &s.links[b]);
            let reach = la.3 + lb.3;
            if bounds[a].distance_squared(bounds[b]) > reach * reach {
                continue;
            }
            for (k, l) in [(a, la), (b, lb)] {
                if !placed[k] {
                    place(
                        &poses[l.0],
                        &s.spheres[l.1.clone()],
                        &mut centers[l.1.clone()],
                    );
                    placed[k] = true;
                }
            }
            for i in la.1.clone() {
                for j in lb.1.clone() {
                    let r = s.spheres[i].1 + s.spheres[j].1;
                    if centers[i].distance_squared(centers[j]) <= r * r {
                        return false;
                    }
                }
            }
        }
        true
    }
}

/// Places local sphere centres by a link pose.
#[inline]
fn place(pose: &Affine3A, spheres: &[(Vec3A, f32)], out: &mut [Vec3A]) {
    for (o, (c, _)) in out.iter_mut().zip(spheres) {
        *o = pose.transform_point3a(*c);
    }
}
