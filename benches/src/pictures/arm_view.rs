//! [`ArmView`]: an arm problem as a 3-D view — the robot's links with their spheres, the
//! scene's solids and clouds, motions as link poses per frame, the search through the hand.

use glam::{DAffine3, DQuat, DVec3};
use mit_star::Snapshot;
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, Kinematics, Motion, Obstacle, Shape};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use mit_star_view::{
    CloudView, LinkView, MotionView, RobotView, SceneView, SearchOverlay, ShapeView, SolidView,
    ViewDocument, ViewKind,
};

use crate::pictures::view_frames::ViewFrames;

/// Builds the view of plans on one arm problem.
pub(crate) struct ArmView<'a> {
    arm: &'a ArmProblem,
    kinematics: Kinematics,
    hand: usize,
}

impl<'a> ArmView<'a> {
    /// The view of `arm`; the hand's trace follows link `hand` (a pose goal's link), else the
    /// link with the most moving joints above it.
    pub(crate) fn new(arm: &'a ArmProblem, hand: Option<&str>) -> Self {
        let robot = arm.robot();
        let hand = hand
            .and_then(|name| robot.link_index(name))
            .unwrap_or_else(|| tool_link(robot));
        Self {
            arm,
            kinematics: Kinematics::new(robot),
            hand,
        }
    }

    /// The arm's joint space.
    pub(crate) fn space(&self) -> &mit_star_spaces::JointSpace {
        self.arm.space()
    }

    /// The robot.
    pub(crate) fn robot(&self) -> &mit_star_robot::RobotModel {
        self.arm.robot()
    }

    /// A page with the robot and the scene, and no motion yet.
    pub(crate) fn document(&self, title: impl Into<String>) -> ViewDocument {
        let mut document = ViewDocument::new(ViewKind::Arm, title);
        document.robot = Some(self.robot_view());
        document.scene = scene_view(self.arm.scene());
        document
    }

    fn robot_view(&self) -> RobotView {
        let robot = self.arm.robot();
        let mut links: Vec<LinkView> = robot
            .links()
            .iter()
            .map(|link| LinkView {
                name: link.name.clone(),
                spheres: Vec::new(),
                meshes: Vec::new(),
            })
            .collect();
        for sphere in robot.spheres() {
            let c = sphere.center.as_vec3();
            links[sphere.link]
                .spheres
                .extend([c.x, c.y, c.z, sphere.radius as f32]);
        }
        RobotView {
            name: robot.name().to_owned(),
            links,
            hand: self.hand,
        }
    }

    /// The motion through `frames`, labelled `label`: each frame's link poses, and the frames
    /// the problem's checker refuses marked.
    pub(crate) fn motion(&self, label: impl Into<String>, frames: &ViewFrames) -> MotionView {
        let validity = self.arm.validity();
        let colliding = frames.colliding(|q| validity.is_valid(q));
        self.motion_marked(label, frames, colliding)
    }

    /// The motion through `frames` with the frames `colliding` marked.
    pub(crate) fn motion_marked(
        &self,
        label: impl Into<String>,
        frames: &ViewFrames,
        colliding: Vec<usize>,
    ) -> MotionView {
        let links = self.kinematics.link_count();
        let mut poses = Vec::with_capacity(frames.states.len() * links * 7);
        let mut joints = Vec::with_capacity(frames.states.len() * self.kinematics.dimension());
        let mut scratch = vec![DAffine3::IDENTITY; links];
        for q in &frames.states {
            self.kinematics.link_poses_f64(q, &mut scratch);
            for pose in &scratch {
                push_pose(pose, &mut poses);
            }
            joints.extend(q.iter().map(|&v| v as f32));
        }
        MotionView {
            label: label.into(),
            joint_names: self.arm.robot().joint_names().to_vec(),
            frames: frames.states.len(),
            joints,
            poses,
            times: frames.times.clone(),
            waypoints: frames.waypoints.clone(),
            colliding,
            mover_positions: Vec::new(),
        }
    }

    /// The motion along `path`, interpolated by length.
    pub(crate) fn path_motion(&self, label: impl Into<String>, path: &[Vec<f64>]) -> MotionView {
        self.motion(label, &ViewFrames::along_path(self.arm.space(), path))
    }

    /// The forward tree of `snapshot` drawn through the hand's position, coloured by
    /// cost-to-come in joint space.
    pub(crate) fn search(&self, snapshot: &Snapshot) -> SearchOverlay {
        let mut scratch = vec![DAffine3::IDENTITY; self.kinematics.link_count()];
        let hand = |q: &[f64], scratch: &mut [DAffine3]| {
            self.kinematics.link_poses_f64(q, scratch);
            scratch[self.hand].translation
        };
        let positions: Vec<DVec3> = (0..snapshot.states.len())
            .map(|i| hand(&snapshot.states[i], &mut scratch))
            .collect();
        let space = self.arm.space();
        let costs = crate::pictures::search_view::costs_to_come(snapshot, |a, b| {
            space.distance(&snapshot.states[a], &snapshot.states[b])
        });
        crate::pictures::search_view::overlay(snapshot, &positions, &costs, None)
    }
}

/// The colour of a mesh whose URDF material gives none.
const MESH_GREY: [f32; 3] = [0.72, 0.74, 0.78];

/// Adds `robot`'s visual meshes (files found by `resolver`) to the robot of `document`; a
/// mesh that cannot be loaded leaves its link drawn as spheres, with a note naming it.
pub(crate) fn add_meshes(
    document: &mut ViewDocument,
    robot: &mit_star_robot::RobotModel,
    resolver: &mit_star_robot::MeshResolver,
) {
    let Some(drawn) = document.robot.as_mut() else {
        return;
    };
    let loaded = mit_star_robot::VisualMeshes::load(robot, resolver);
    for mesh in loaded.meshes {
        if let Some(link) = drawn.links.get_mut(mesh.link) {
            link.meshes.push(mit_star_view::MeshView {
                positions: mesh.positions,
                indices: mesh.indices,
                colour: mesh.colour.map_or(MESH_GREY, |[r, g, b, _]| [r, g, b]),
            });
        }
    }
    if loaded.failures.is_empty() {
        return;
    }
    let shown: Vec<String> = loaded
        .failures
        .iter()
        .take(4)
        .map(ToString::to_string)
        .collect();
    let more = loaded.failures.len() - shown.len();
    document.notes.push(format!(
        "{} visual mesh(es) could not be loaded, their links are drawn as spheres: {}{}",
        loaded.failures.len(),
        shown.join("; "),
        if more > 0 {
            format!("; and {more} more")
        } else {
            String::new()
        }
    ));
}

/// The link with the most moving joints above it, the deepest such, preferring a link without
/// spheres (a tool frame such as the Panda's `panda_grasptarget`): where an arm's tool is.
fn tool_link(robot: &mit_star_robot::RobotModel) -> usize {
    let links = robot.links();
    let mut moving = vec![0usize; links.len()];
    let mut depth = vec![0usize; links.len()];
    for (i, link) in links.iter().enumerate() {
        if let Some(p) = link.parent {
            moving[i] = moving[p] + usize::from(!matches!(link.motion, Motion::Fixed));
            depth[i] = depth[p] + 1;
        }
    }
    let key = |i: usize| (moving[i], depth[i], robot.link_sphere_range(i).is_empty());
    (0..links.len()).rev().max_by_key(|&i| key(i)).unwrap_or(0)
}

/// `pose` as `x, y, z, qx, qy, qz, qw`.
fn push_pose(pose: &DAffine3, out: &mut Vec<f32>) {
    let t = pose.translation;
    let q = DQuat::from_mat3(&pose.matrix3).normalize();
    out.extend([t.x, t.y, t.z, q.x, q.y, q.z, q.w].map(|v| v as f32));
}

/// The scene's solids and clouds.
pub(crate) fn scene_view(scene: &mit_star_robot::Scene) -> SceneView {
    let names = scene.ids();
    let solids = scene
        .obstacles()
        .iter()
        .enumerate()
        .map(|(i, o)| solid_view(names.get(i).map_or("", String::as_str), o))
        .collect();
    let clouds = scene
        .clouds()
        .iter()
        .map(|c| CloudView {
            name: c.name().to_owned(),
            points: c
                .cloud()
                .points()
                .iter()
                .flat_map(|p| [p.x, p.y, p.z])
                .collect(),
            radius: c.cloud().radius() as f32,
        })
        .collect();
    SceneView {
        solids,
        clouds,
        movers: Vec::new(),
        bounds: None,
    }
}

fn solid_view(name: &str, obstacle: &Obstacle) -> SolidView {
    let pose = obstacle.pose();
    let t = pose.translation;
    let q = DQuat::from_mat3(&pose.matrix3).normalize();
    let shape = match obstacle.shape() {
        Shape::Cuboid { half_extents } => ShapeView::Cuboid {
            half_extents: half_extents.as_vec3().to_array(),
        },
        Shape::Sphere { radius } => ShapeView::Sphere {
            radius: radius as f32,
        },
        Shape::Cylinder {
            half_height,
            radius,
        } => ShapeView::Cylinder {
            radius: radius as f32,
            half_height: half_height as f32,
        },
    };
    SolidView {
        name: name.to_owned(),
        shape,
        position: t.as_vec3().to_array(),
        rotation: [q.x, q.y, q.z, q.w].map(|v| v as f32),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problem() -> ArmProblem {
        let wall = Obstacle::new(
            Shape::Cuboid {
                half_extents: DVec3::new(0.05, 0.3, 0.3),
            },
            DVec3::new(0.5, 0.0, 0.4),
            DQuat::IDENTITY,
        );
        problem_among(vec![wall])
    }

    fn problem_among(obstacles: Vec<Obstacle>) -> ArmProblem {
        let urdf = include_str!("../../../robot/data/panda/panda_spherized.urdf");
        let srdf = include_str!("../../../robot/data/panda/panda.srdf");
        let robot = mit_star_robot::RobotModel::from_urdf_str(urdf)
            .unwrap()
            .with_srdf_str(srdf)
            .unwrap();
        let start = vec![0.0, -0.5, 0.0, -2.0, 0.0, 1.6, 0.8];
        let goal = vec![1.0, -0.3, 0.0, -2.0, 0.0, 1.8, 0.8];
        ArmProblem::new(
            "wall",
            robot,
            mit_star_robot::Scene::new(obstacles),
            start,
            goal,
        )
        .unwrap()
    }

    #[test]
    fn a_path_becomes_link_poses_per_frame() {
        let arm = problem();
        let view = ArmView::new(&arm, None);
        let path = vec![arm.start().to_vec(), arm.goals()[0].clone()];
        let motion = view.path_motion("plan", &path);
        let links = arm.robot().links().len();
        assert_eq!(motion.poses.len(), motion.frames * links * 7);
        assert_eq!(motion.joints.len(), motion.frames * 7);
        assert_eq!(motion.waypoints, vec![0, motion.frames - 1]);
        // The last frame's hand is where forward kinematics puts it at the goal.
        let mut poses = vec![DAffine3::IDENTITY; links];
        Kinematics::new(arm.robot()).link_poses_f64(&arm.goals()[0], &mut poses);
        let hand = view.hand;
        let at = (motion.frames - 1) * links * 7 + hand * 7;
        let expected = poses[hand].translation.as_vec3();
        assert!((motion.poses[at] - expected.x).abs() < 1e-5);
        assert!((motion.poses[at + 2] - expected.z).abs() < 1e-5);
        assert_eq!(arm.robot().links()[hand].name, "panda_grasptarget");
        let document = view.document("wall");
        assert_eq!(document.scene.solids.len(), 1);
        let spheres: usize = document
            .robot
            .unwrap()
            .links
            .iter()
            .map(|l| l.spheres.len() / 4)
            .sum();
        assert_eq!(spheres, arm.robot().spheres().len());
    }

    #[test]
    fn frames_in_collision_are_marked() {
        // A ball where the hand is at the motion's end.
        let free = problem_among(Vec::new());
        let through = vec![0.0, 0.6, 0.0, -0.4, 0.0, 1.0, 0.8];
        let mut poses = vec![DAffine3::IDENTITY; free.robot().links().len()];
        Kinematics::new(free.robot()).link_poses_f64(&through, &mut poses);
        let hand = poses[ArmView::new(&free, None).hand].translation;
        let ball = Obstacle::new(Shape::Sphere { radius: 0.05 }, hand, DQuat::IDENTITY);
        let arm = problem_among(vec![ball]);
        let view = ArmView::new(&arm, None);
        let motion = view.path_motion("bad", &[arm.start().to_vec(), through]);
        assert!(!motion.colliding.is_empty());
        assert_eq!(motion.colliding.last(), Some(&(motion.frames - 1)));
    }
}
