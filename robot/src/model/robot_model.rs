//! [`RobotModel`]: a kinematic tree with spheres as collision geometry, read from URDF.

use std::collections::{HashMap, HashSet};
use std::ops::Range;
use std::path::Path;

use glam::{DAffine3, DMat3, DQuat, DVec3};
use mit_star_spaces::{Joint, JointSpace};

use crate::model::joint_limits::{checked_limits, checked_mimic, keep_mimic_limits};
use crate::model::link_visual::{LinkVisual, read_visuals};
use crate::model::model_joint::ModelJoint;
use crate::{ModelError, ModelWarning};

/// How the joint above a link moves it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Motion {
    /// Rigidly attached to its parent.
    Fixed,
    /// Rotates about `axis` (a unit vector in the joint frame) by coordinate `coordinate`.
    Revolute {
        /// The unit axis.
        axis: DVec3,
        /// Index of the joint value in a configuration.
        coordinate: usize,
    },
    /// Slides along `axis` by coordinate `coordinate`.
    Prismatic {
        /// The unit axis.
        axis: DVec3,
        /// Index of the joint value in a configuration.
        coordinate: usize,
    },
}

/// One link in tree order: its parent (an earlier link) and the joint between them.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkFrame {
    /// The link's name.
    pub name: String,
    /// Index of the parent link (`None` for the root, which is link 0).
    pub parent: Option<usize>,
    /// The joint's origin in the parent's frame (URDF `<origin xyz rpy>`).
    pub origin: DAffine3,
    /// How the joint moves the link.
    pub motion: Motion,
}

/// One collision sphere, in its link's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkSphere {
    /// Index of the link it rides on.
    pub link: usize,
    /// Centre in the link's frame.
    pub center: DVec3,
    /// Radius.
    pub radius: f64,
}

/// A robot arm whose collision geometry is spheres: links in tree order (every link after its
/// parent), the actuated joints as a [`JointSpace`], the spheres grouped by link, and the link
/// pairs checked for self-collision.
///
/// Actuated joints (revolute, continuous, prismatic) are the configuration's coordinates in
/// depth-first tree order from the root (for the Panda: `panda_joint1` … `panda_joint7`);
/// fixed joints ride along. Mimic joints follow their leader; a planning group
/// ([`with_group_str`](Self::with_group_str)) keeps only its joints as coordinates and holds
/// the others ([`held_joints`](Self::held_joints)). Continuous coordinates wrap; prismatic
/// ones weigh `1 / `[`revolute_reach`](Self::revolute_reach) in the metric. Without an SRDF every pair of links with spheres is checked for
/// self-collision, adjacent links included: apply the robot's SRDF
/// ([`with_srdf_str`](Self::with_srdf_str)) as MoveIt does.
///
/// ```
/// let urdf = include_str!("../../data/panda/panda_spherized.urdf");
/// let srdf = include_str!("../../data/panda/panda.srdf");
/// let panda = mit_star_robot::RobotModel::from_urdf_str(urdf)?.with_srdf_str(srdf)?;
/// assert_eq!(panda.joint_names().len(), 7);
/// assert_eq!(panda.spheres().len(), 59);
/// # Ok::<(), mit_star_robot::ModelError>(())
/// ```
#[derive(Debug, Clone)]
pub struct RobotModel {
    pub(super) name: String,
    pub(super) links: Vec<LinkFrame>,
    pub(super) space: JointSpace,
    pub(super) joint_names: Vec<String>,
    /// Every revolute, continuous and prismatic joint, in tree order.
    pub(super) joints: Vec<ModelJoint>,
    /// Per link, the name of the joint above it (`None` for the root).
    pub(super) link_joints: Vec<Option<String>>,
    spheres: Vec<LinkSphere>,
    visuals: Vec<LinkVisual>,
    ranges: Vec<Range<usize>>,
    bounds: Vec<Option<(DVec3, f64)>>,
    pub(super) pairs: Vec<(usize, usize)>,
    pub(super) strict: bool,
    pub(super) warnings: Vec<ModelWarning>,
    /// The RRT range set for it (`rrt_range.rs`), if any.
    pub(super) rrt_range: Option<f64>,
}

impl RobotModel {
    /// Reads a URDF file.
    ///
    /// # Errors
    /// [`ModelError::Io`] if it cannot be read, else as [`from_urdf_str`](Self::from_urdf_str).
    pub fn from_urdf_file(path: &Path) -> Result<Self, ModelError> {
        let text = ModelError::read_text(path, "URDF")?;
        Self::parse(&text, &path.display().to_string())
    }

    /// Reads a URDF document.
    ///
    /// # Errors
    /// [`ModelError::TooLarge`], [`ModelError::TooDeep`] and [`ModelError::SeveralRoots`] for
    /// a document refused before parsing, [`ModelError::Urdf`] for malformed XML,
    /// [`ModelError::DuplicateName`] for two joints
    /// (or links) of one name, and the variants naming a link or joint for non-sphere
    /// collision geometry, unsupported joints, bad axes, limits or numbers (origins and radii
    /// beyond 10⁶ m included, and in `<visual>` elements: origins, sizes, mesh scales, colours
    /// outside `[0, 1]`), joint limits or mimic factors beyond their bounds
    /// ([`ModelError::LimitsTooWide`], [`ModelError::BadMimic`]), mimic joints whose limits
    /// cannot be kept ([`ModelError::MimicLimits`]), and links that do not form one tree.
    ///
    /// A mimic joint's own limits are kept: its leader's range shrinks to the values that
    /// keep every follower within its limits (a [`ModelWarning::MimicRange`] says so).
    pub fn from_urdf_str(text: &str) -> Result<Self, ModelError> {
        Self::parse(text, "URDF text")
    }

    fn parse(text: &str, origin: &str) -> Result<Self, ModelError> {
        crate::model::xml_guard::check_shape(text, origin)?;
        let urdf = urdf_rs::read_from_string(text).map_err(|e| ModelError::Urdf {
            origin: origin.to_owned(),
            message: e.to_string(),
        })?;
        for (what, name) in [
            ("link", repeated(urdf.links.iter().map(|l| l.name.as_str()))),
            (
                "joint",
                repeated(urdf.joints.iter().map(|j| j.name.as_str())),
            ),
        ] {
            if let Some(name) = name {
                return Err(ModelError::DuplicateName {
                    origin: origin.to_owned(),
                    what,
                    name: name.to_owned(),
                });
            }
        }
        let names: HashSet<&str> = urdf.links.iter().map(|l| l.name.as_str()).collect();
        let mut children: HashMap<&str, Vec<&urdf_rs::Joint>> = HashMap::new();
        let mut has_parent: HashSet<&str> = HashSet::new();
        for joint in &urdf.joints {
            for link in [&joint.parent.link, &joint.child.link] {
                if !names.contains(link.as_str()) {
                    return Err(ModelError::UnknownJointLink {
                        joint: joint.name.clone(),
                        link: link.clone(),
                    });
                }
            }
            if !has_parent.insert(joint.child.link.as_str()) {
                return Err(ModelError::NotATree {
                    why: format!("link `{}` has two parent joints", joint.child.link),
                });
            }
            children
                .entry(joint.parent.link.as_str())
                .or_default()
                .push(joint);
        }
        let roots: Vec<&str> = urdf
            .links
            .iter()
            .map(|l| l.name.as_str())
            .filter(|n| !has_parent.contains(n))
            .collect();
        let root = match roots.as_slice() {
            [root] => *root,
            [] => {
                return Err(ModelError::NotATree {
                    why: "every link has a parent (a cycle)".into(),
                });
            }
            many => {
                return Err(ModelError::NotATree {
                    why: format!("{} roots: {}", many.len(), many.join(", ")),
                });
            }
        };
        // Depth-first from the root, children in document order.
        let mut links = Vec::with_capacity(urdf.links.len());
        let mut link_joints = Vec::with_capacity(urdf.links.len());
        let mut joints = Vec::new();
        let mut stack: Vec<(Option<usize>, &str, Option<&urdf_rs::Joint>)> =
            vec![(None, root, None)];
        while let Some((parent, name, joint)) = stack.pop() {
            let index = links.len();
            let origin = match joint {
                None => DAffine3::IDENTITY,
                Some(j) => joint_frame(j, index, &mut joints)?,
            };
            link_joints.push(joint.map(|j| j.name.clone()));
            links.push(LinkFrame {
                name: name.to_owned(),
                parent,
                origin,
                motion: Motion::Fixed,
            });
            for j in children.get(name).into_iter().flatten().rev() {
                stack.push((Some(index), j.child.link.as_str(), Some(j)));
            }
        }
        if links.len() != urdf.links.len() {
            return Err(ModelError::NotATree {
                why: "some links are not reachable from the root (a cycle)".into(),
            });
        }
        if joints.iter().all(|j| j.mimic.is_some()) {
            return Err(ModelError::NoJoints);
        }
        let mut warnings = Vec::new();
        keep_mimic_limits(&mut joints, &mut warnings)?;
        let by_name: HashMap<&str, &urdf_rs::Link> =
            urdf.links.iter().map(|l| (l.name.as_str(), l)).collect();
        let (mut spheres, mut ranges, mut bounds) = (Vec::new(), Vec::new(), Vec::new());
        for (index, frame) in links.iter().enumerate() {
            let first = spheres.len();
            for collision in &by_name[frame.name.as_str()].collision {
                let radius = match collision.geometry {
                    urdf_rs::Geometry::Sphere { radius } => radius,
                    ref other => {
                        return Err(ModelError::UnsupportedGeometry {
                            link: frame.name.clone(),
                            kind: geometry_kind(other),
                        });
                    }
                };
                if !(radius > 0.0 && radius <= MAX_LENGTH) {
                    return Err(bad(&frame.name, "sphere radius (in (0, 1e6] m)", radius));
                }
                let pose = pose(&collision.origin, &frame.name)?;
                spheres.push(LinkSphere {
                    link: index,
                    center: pose.translation,
                    radius,
                });
            }
            ranges.push(first..spheres.len());
            bounds.push(bounding_sphere(&spheres[first..]));
        }
        let with_spheres: Vec<usize> = (0..links.len()).filter(|&l| bounds[l].is_some()).collect();
        let mut pairs = Vec::new();
        for (k, &i) in with_spheres.iter().enumerate() {
            for &j in &with_spheres[k + 1..] {
                pairs.push((i, j));
            }
        }
        let visuals = read_visuals(&urdf, &links)?;
        let mut model = Self {
            name: urdf.name,
            links,
            // Placeholders until `rebuild` derives them from the joints.
            space: JointSpace::new(vec![Joint::continuous("placeholder")])?,
            joint_names: Vec::new(),
            joints,
            link_joints,
            spheres,
            visuals,
            ranges,
            bounds,
            pairs,
            strict: false,
            warnings,
            rrt_range: None,
        };
        model.rebuild()?;
        Ok(model)
    }

    /// The robot's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The links in tree order (every link after its parent; the root first).
    pub fn links(&self) -> &[LinkFrame] {
        &self.links
    }

    /// The link names in tree order.
    pub fn link_names(&self) -> impl Iterator<Item = &str> {
        self.links.iter().map(|l| l.name.as_str())
    }

    /// The index of the link called `name`.
    pub fn link_index(&self, name: &str) -> Option<usize> {
        self.links.iter().position(|l| l.name == name)
    }

    /// The configuration space: the actuated joints with their limits.
    pub fn joint_space(&self) -> &JointSpace {
        &self.space
    }

    /// The actuated joints' names, in coordinate order.
    pub fn joint_names(&self) -> &[String] {
        &self.joint_names
    }

    /// Every collision sphere, grouped by link in tree order.
    pub fn spheres(&self) -> &[LinkSphere] {
        &self.spheres
    }

    /// Every visual element (URDF `<visual>`: what a viewer draws), in tree order of their
    /// links, with colours resolved; links kept only as frames (no spheres) keep theirs.
    /// [`VisualMeshes::load`](crate::VisualMeshes::load) turns them into triangles.
    pub fn visuals(&self) -> &[LinkVisual] {
        &self.visuals
    }

    /// The spheres of `link`, as a range of [`spheres`](Self::spheres).
    pub fn link_sphere_range(&self, link: usize) -> Range<usize> {
        self.ranges.get(link).cloned().unwrap_or(0..0)
    }

    /// Per link: a sphere (centre in the link frame, radius) enclosing all of its spheres, or
    /// `None` for a link without spheres. The centre is the mean of the sphere centres and the
    /// radius the largest `|c_i − centre| + r_i`: not minimal, but tight for the elongated
    /// clusters of spherised links, and exact for one sphere.
    pub fn link_bounding_spheres(&self) -> &[Option<(DVec3, f64)>] {
        &self.bounds
    }

    /// Grows every sphere and link bounding sphere by `by` metres.
    pub(super) fn grow_spheres(&mut self, by: f64) {
        for sphere in &mut self.spheres {
            sphere.radius += by;
        }
        for (_, radius) in self.bounds.iter_mut().flatten() {
            *radius += by;
        }
    }

    /// The link pairs checked for self-collision: both links have spheres, `i < j`, and
    /// neither the SRDF nor an allowed-collision entry disabled the pair.
    pub fn self_collision_pairs(&self) -> &[(usize, usize)] {
        &self.pairs
    }
}

/// The origin of a URDF joint moving link `link`; pushes the joint onto `joints` if it moves.
fn joint_frame(
    joint: &urdf_rs::Joint,
    link: usize,
    joints: &mut Vec<ModelJoint>,
) -> Result<DAffine3, ModelError> {
    use urdf_rs::JointType as T;
    let origin = pose(&joint.origin, &joint.name)?;
    let what = match joint.joint_type {
        // A fixed joint does not move, whatever it claims to mimic.
        T::Fixed => return Ok(origin),
        T::Revolute | T::Continuous | T::Prismatic => None,
        T::Floating => Some("a floating joint"),
        T::Planar => Some("a planar joint"),
        T::Spherical => Some("a spherical joint"),
    };
    if let Some(what) = what {
        return Err(ModelError::UnsupportedJoint {
            joint: joint.name.clone(),
            what,
        });
    }
    let raw = DVec3::from_array(joint.axis.xyz.0);
    let axis = raw.try_normalize().ok_or(ModelError::BadAxis {
        joint: joint.name.clone(),
        axis: joint.axis.xyz.0,
    })?;
    let mimic = match &joint.mimic {
        None => None,
        Some(m) => {
            let multiplier = m.multiplier.unwrap_or(1.0);
            let offset = m.offset.unwrap_or(0.0);
            checked_mimic(&joint.name, multiplier, offset)?;
            Some((m.joint.clone(), multiplier, offset))
        }
    };
    let (lower, upper) = (joint.limit.lower, joint.limit.upper);
    let prismatic = matches!(joint.joint_type, T::Prismatic);
    let spec = match (joint.joint_type.clone(), &mimic) {
        (_, Some(_)) => None,
        (T::Revolute | T::Prismatic, None) => {
            let (lower, upper) = checked_limits(&joint.name, prismatic, lower, upper)?;
            Some(if prismatic {
                Joint::prismatic(joint.name.clone(), lower, upper)
            } else {
                Joint::revolute(joint.name.clone(), lower, upper)
            })
        }
        _ => Some(Joint::continuous(joint.name.clone())),
    };
    // A mimic joint's own limits shrink its leader's range (`keep_mimic_limits`); without a
    // `<limit>` (read as `[0, 0]`) or continuous, it has none.
    let limits = match (joint.joint_type.clone(), &mimic) {
        (T::Revolute | T::Prismatic, Some(_)) if (lower, upper) != (0.0, 0.0) => {
            Some(checked_limits(&joint.name, prismatic, lower, upper)?)
        }
        _ => None,
    };
    let mut joint = ModelJoint {
        name: joint.name.clone(),
        link,
        origin,
        axis,
        prismatic,
        spec,
        mimic,
        limits,
        planned: true,
        value: 0.0,
        velocity: Some(joint.limit.velocity).filter(|v| *v != 0.0 && *v != f64::INFINITY),
    };
    joint.value = joint.default_value();
    joints.push(joint);
    Ok(origin)
}

/// A URDF pose: translation `xyz`, rotation `Rz(yaw)·Ry(pitch)·Rx(roll)` from `rpy`.
pub(super) fn pose(p: &urdf_rs::Pose, element: &str) -> Result<DAffine3, ModelError> {
    if let Some(&v) = p
        .xyz
        .0
        .iter()
        .find(|v| !(-MAX_LENGTH..=MAX_LENGTH).contains(*v))
    {
        return Err(bad(element, "origin xyz (finite, within ±1e6 m)", v));
    }
    if let Some(&v) = p.rpy.0.iter().find(|v| !v.is_finite()) {
        return Err(bad(element, "origin rpy", v));
    }
    Ok(DAffine3::from_mat3_translation(
        rpy_matrix(p.rpy.0),
        DVec3::from_array(p.xyz.0),
    ))
}

/// The largest magnitude of an origin coordinate or a sphere radius, in metres (as for scenes:
/// [`Scene::MAX_LENGTH`](crate::Scene::MAX_LENGTH)).
const MAX_LENGTH: f64 = crate::Scene::MAX_LENGTH;

/// The URDF rotation of roll, pitch, yaw: `Rz(yaw)·Ry(pitch)·Rx(roll)`.
pub fn rpy_matrix([roll, pitch, yaw]: [f64; 3]) -> DMat3 {
    DMat3::from_quat(
        DQuat::from_rotation_z(yaw) * DQuat::from_rotation_y(pitch) * DQuat::from_rotation_x(roll),
    )
}

/// The first name that occurs twice.
fn repeated<'a>(names: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let mut seen = HashSet::new();
    names.into_iter().find(|n| !seen.insert(*n))
}

fn bad(element: &str, what: &'static str, value: f64) -> ModelError {
    ModelError::BadNumber {
        element: element.to_owned(),
        what,
        value,
    }
}

fn geometry_kind(g: &urdf_rs::Geometry) -> &'static str {
    match g {
        urdf_rs::Geometry::Box { .. } => "box",
        urdf_rs::Geometry::Cylinder { .. } => "cylinder",
        urdf_rs::Geometry::Capsule { .. } => "capsule",
        urdf_rs::Geometry::Sphere { .. } => "sphere",
        urdf_rs::Geometry::Mesh { .. } => "mesh",
    }
}

/// The enclosing sphere of [`RobotModel::link_bounding_spheres`].
fn bounding_sphere(spheres: &[LinkSphere]) -> Option<(DVec3, f64)> {
    if spheres.is_empty() {
        return None;
    }
    let center = spheres.iter().map(|s| s.center).sum::<DVec3>() / spheres.len() as f64;
    let radius = spheres
        .iter()
        .map(|s| s.center.distance(center) + s.radius)
        .fold(0.0, f64::max);
    Some((center, radius))
}
