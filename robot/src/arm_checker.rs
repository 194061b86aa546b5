//! [`ArmChecker`]: is an arm configuration collision-free in its scene and with itself.

use std::ops::Range;
use std::sync::Arc;

use glam::{Affine3A, Vec3A};
use spaces::StateSpace;
use validity::StateValidity;

use wide::f32x8;

use crate::lanes::{LANES, LaneKinematics, Point8, Pose8};
use crate::scratch_cell::ScratchCell;
use crate::{Kinematics, Obstacle, RobotModel, Scene};

/// What the checks share between clones: the kinematics, the scene and the pair lists.
#[derive(Debug)]
struct Shared {
    fk: Kinematics,
    lanes: LaneKinematics,
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
    /// The same, eight configurations at a time, and the joint values by coordinate.
    poses8: Vec<Pose8>,
    centers8: Vec<Point8>,
    bounds8: Vec<Point8>,
    q8: Vec<f32x8>,
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
/// **Batches** ([`StateValidity::first_invalid`], [`batch_width`](StateValidity::batch_width)
/// 8): eight configurations are checked at once in `f32x8` lanes — forward kinematics,
/// broad and narrow phases, self-collision — with the same arithmetic as the scalar check.
/// A lane drops out of the work once a lane before it is known invalid, and the batch ends
/// when no lane before the first invalid one is left to decide, so the answer is exactly the
/// first invalid configuration.
///
/// Clones share the model and scene (an [`Arc`]) and own their scratch buffers, so a check
/// never allocates. The scratch sits behind a mutex so that problems holding a checker
/// can be shared between threads; each planner owns its own clone, so the lock is never
/// contended (an uncontended lock costs a few nanoseconds against a check of about a
/// microsecond).
#[derive(Debug, Clone)]
pub struct ArmChecker {
    shared: Arc<Shared>,
    scratch: ScratchCell<Scratch>,
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
            poses8: vec![Pose8::IDENTITY; fk.link_count()],
            centers8: vec![[f32x8::ZERO; 3]; fk.sphere_count()],
            bounds8: vec![[f32x8::ZERO; 3]; links.len()],
            q8: vec![f32x8::ZERO; fk.dimension()],
        };
        let space = robot.joint_space();
        Self {
            shared: Arc::new(Shared {
                lanes: LaneKinematics::new(&fk),
                fk,
                lower: space.lower().to_vec(),
                upper: space.upper().to_vec(),
                obstacles: scene.obstacles().to_vec(),
                links,
                spheres,
                pairs,
            }),
            scratch: ScratchCell::new(scratch),
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
        let mut guard = self.scratch.lock();
        let Scratch {
            poses,
            centers,
            bounds,
            placed,
            ..
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
            // Each sphere of the first link against the second's bounding sphere, then its
            // spheres.
            for i in la.1.clone() {
                let near = s.spheres[i].1 + lb.3;
                if centers[i].distance_squared(bounds[b]) > near * near {
                    continue;
                }
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

    #[inline]
    fn batch_width(&self) -> usize {
        LANES
    }

    fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        let dimension = dimension.max(1);
        for (c, chunk) in states.chunks(LANES * dimension).enumerate() {
            let invalid = self.invalid_lanes(chunk, dimension);
            if invalid != 0 {
                return Some(c * LANES + invalid.trailing_zeros() as usize);
            }
        }
        None
    }
}

impl ArmChecker {
    /// Bit `l` set if configuration `l` of `chunk` (at most [`LANES`] configurations of
    /// `dimension` values) is invalid, exact for every lane up to the first invalid one.
    fn invalid_lanes(&self, chunk: &[f64], dimension: usize) -> u32 {
        let s = &*self.shared;
        let count = chunk.len() / dimension;
        let live: u32 = (1 << count) - 1;
        if dimension != s.lower.len() {
            return live;
        }
        let mut guard = self.scratch.lock();
        let Scratch {
            poses8,
            centers8,
            bounds8,
            placed,
            q8,
            ..
        } = &mut *guard;
        let mut invalid = 0u32;
        for (l, q) in chunk.chunks_exact(dimension).enumerate() {
            let out = q
                .iter()
                .zip(s.lower.iter().zip(&s.upper))
                .any(|(x, (lo, hi))| !(lo <= x && x <= hi));
            invalid |= u32::from(out) << l;
        }
        // Lanes still to decide: those before the first invalid one.
        let undecided = |invalid: u32| {
            if invalid == 0 {
                live
            } else {
                live & ((1 << invalid.trailing_zeros()) - 1)
            }
        };
        let mut active = undecided(invalid);
        if active == 0 {
            return invalid;
        }
        // Joint values by coordinate; padding lanes repeat configuration 0.
        for (c, v) in q8.iter_mut().enumerate() {
            *v = f32x8::new(std::array::from_fn(|l| {
                chunk[if l < count { l } else { 0 } * dimension + c] as f32
            }));
        }
        s.lanes.link_poses(q8, poses8);
        placed.fill(false);
        let place8 = |pose: &Pose8, range: &Range<usize>, centers: &mut [Point8]| {
            for i in range.clone() {
                centers[i] = pose.point(s.spheres[i].0);
            }
        };
        for (k, (link, range, center, radius)) in s.links.iter().enumerate() {
            let pose = &poses8[*link];
            bounds8[k] = pose.point(*center);
            for obstacle in &s.obstacles {
                if obstacle.collides_spheres8(&bounds8[k], f32x8::splat(*radius)) & active == 0 {
                    continue;
                }
                if !placed[k] {
                    place8(pose, range, centers8);
                    placed[k] = true;
                }
                for i in range.clone() {
                    let hit =
                        obstacle.collides_spheres8(&centers8[i], f32x8::splat(s.spheres[i].1));
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
        for &(a, b) in &s.pairs {
            let (la, lb) = (&s.links[a], &s.links[b]);
            let reach = f32x8::splat(la.3 + lb.3);
            if distance_squared(&bounds8[a], &bounds8[b])
                .simd_le(reach * reach)
                .to_bitmask()
                & active
                == 0
            {
                continue;
            }
            for (k, l) in [(a, la), (b, lb)] {
                if !placed[k] {
                    place8(&poses8[l.0], &l.1, centers8);
                    placed[k] = true;
                }
            }
            for i in la.1.clone() {
                let near = f32x8::splat(s.spheres[i].1 + lb.3);
                if distance_squared(&centers8[i], &bounds8[b])
                    .simd_le(near * near)
                    .to_bitmask()
                    & active
                    == 0
                {
                    continue;
                }
                for j in lb.1.clone() {
                    let r = f32x8::splat(s.spheres[i].1 + s.spheres[j].1);
                    let hit = distance_squared(&centers8[i], &centers8[j])
                        .simd_le(r * r)
                        .to_bitmask();
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
}

#[inline]
fn distance_squared(a: &Point8, b: &Point8) -> f32x8 {
    let (x, y, z) = (a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    x * x + y * y + z * z
}

/// Places local sphere centres by a link pose.
#[inline]
fn place(pose: &Affine3A, spheres: &[(Vec3A, f32)], out: &mut [Vec3A]) {
    for (o, (c, _)) in out.iter_mut().zip(spheres) {
        *o = pose.transform_point3a(*c);
    }
}
