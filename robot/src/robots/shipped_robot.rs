//! [`ShippedRobot`]: the robot models compiled into this crate, and their problem sets.

use std::path::{Path, PathBuf};

use crate::{MeshResolver, ModelError, RobotModel};

/// A robot model shipped with this crate (`robot/data/<name>/`): its spherised URDF and SRDF,
/// compiled in, and where its MotionBenchMaker problems are.
///
/// ```
/// let ur5 = mit_star_robot::ShippedRobot::find("ur5").expect("shipped");
/// let model = ur5.model(false)?;
/// assert_eq!(model.joint_names().len(), 6);
/// assert!(mit_star_robot::ShippedRobot::names().contains("fetch"));
/// # Ok::<(), mit_star_robot::ModelError>(())
/// ```
#[derive(Debug)]
pub struct ShippedRobot {
    /// The name `--robot` takes (`panda`, `ur5`, `fetch`, `baxter`).
    pub name: &'static str,
    /// One line on what it is.
    pub description: &'static str,
    /// The problem set's tarball, as an absolute path into this crate's `data` folder.
    pub problems: &'static str,
    /// Where `tar xjf PROBLEMS -C target/` puts a scene folder, `{scene}` standing for the
    /// scene (`target/problems/{scene}_ur5`).
    pub unpacked: &'static str,
    /// A scene of its problem set (`box`; Baxter's `bookshelf_tall_both_arms_easy`).
    pub scene: &'static str,
    /// The RRT extension range its problems default to (RRT-Connect, AORRTC, Informed RRT*;
    /// `--set range=` overrides it), in radians, chosen by measurement on its problem set
    /// (`docs/guide/src/your-own-robot.md`, "RRT's range").
    pub range: f64,
    urdf: &'static str,
    srdf: &'static str,
    /// Its data folder, as an absolute path into this crate's source.
    data: &'static str,
    /// Visual mesh names of its URDF drawn with another, smaller file of the same link
    /// (`robot/data/<name>/meshes/README.md` says which and why; the UR5's
    /// `visual/README.md`).
    mesh_aliases: &'static [(&'static str, &'static str)],
}

/// The Panda's visual meshes are 9 MB: its collision meshes (0.4 MB) are drawn instead.
const PANDA_ALIASES: [(&str, &str); 8] = [
    ("meshes/visual/link1.obj", "meshes/collision/link1.obj"),
    ("meshes/visual/link2.obj", "meshes/collision/link2.obj"),
    ("meshes/visual/link3.obj", "meshes/collision/link3.obj"),
    ("meshes/visual/link4.obj", "meshes/collision/link4.obj"),
    ("meshes/visual/link5.obj", "meshes/collision/link5.obj"),
    ("meshes/visual/link6.obj", "meshes/collision/link6.obj"),
    ("meshes/visual/hand.obj", "meshes/collision/hand.obj"),
    ("meshes/visual/finger.obj", "meshes/collision/finger.obj"),
];

/// The UR5 arm's COLLADA visual meshes are 6 MB: its collision STLs (0.3 MB, shipped for
/// `spherise`) are drawn instead. The gripper's meshes live in `visual/` (out of
/// `spherise`'s reach, which keeps VAMP's spheres for the gripper), its base's coarse mesh
/// standing for the fine one.
const UR5_ALIASES: [(&str, &str); 13] = [
    (
        "package://meshes/ur5/visual/base.dae",
        "meshes/ur5/collision/base.stl",
    ),
    (
        "package://meshes/ur5/visual/shoulder.dae",
        "meshes/ur5/collision/shoulder.stl",
    ),
    (
        "package://meshes/ur5/visual/upperarm.dae",
        "meshes/ur5/collision/upperarm.stl",
    ),
    (
        "package://meshes/ur5/visual/forearm.dae",
        "meshes/ur5/collision/forearm.stl",
    ),
    (
        "package://meshes/ur5/visual/wrist1.dae",
        "meshes/ur5/collision/wrist1.stl",
    ),
    (
        "package://meshes/ur5/visual/wrist2.dae",
        "meshes/ur5/collision/wrist2.stl",
    ),
    (
        "package://meshes/ur5/visual/wrist3.dae",
        "meshes/ur5/collision/wrist3.stl",
    ),
    (
        "package://meshes/robotiq/robotiq_85_base_link_fine.STL",
        "visual/robotiq/robotiq_85_base_link_coarse.STL",
    ),
    (
        "package://meshes/robotiq_fts300.stl",
        "visual/robotiq_fts300.stl",
    ),
    (
        "meshes/robotiq/inner_finger_fine.STL",
        "visual/robotiq/inner_finger_fine.STL",
    ),
    (
        "meshes/robotiq/inner_knuckle_fine.STL",
        "visual/robotiq/inner_knuckle_fine.STL",
    ),
    (
        "meshes/robotiq/outer_finger_fine.STL",
        "visual/robotiq/outer_finger_fine.STL",
    ),
    (
        "meshes/robotiq/outer_knuckle_fine.STL",
        "visual/robotiq/outer_knuckle_fine.STL",
    ),
];

/// Baxter's COLLADA visual meshes are over 20 MB: Rethink's simplified STLs of the same
/// links (the arms and head, but `W1`, whose simplified mesh lacks the COLLADA file's node
/// rotation), its collision meshes (torso, pedestal) and the gripper's STL are drawn
/// instead.
const BAXTER_ALIASES: [(&str, &str); 11] = [
    ("meshes/head/H0.DAE", "meshes/head/H0_simple.STL"),
    ("meshes/head/H1.DAE", "meshes/head/H1_simple.STL"),
    (
        "meshes/upper_shoulder/S0.DAE",
        "meshes/upper_shoulder/S0_simple.STL",
    ),
    (
        "meshes/lower_shoulder/S1.DAE",
        "meshes/lower_shoulder/S1_simple.STL",
    ),
    (
        "meshes/upper_elbow/E0.DAE",
        "meshes/upper_elbow/E0_simple.STL",
    ),
    (
        "meshes/lower_elbow/E1.DAE",
        "meshes/lower_elbow/E1_simple.STL",
    ),
    (
        "meshes/upper_forearm/W0.DAE",
        "meshes/upper_forearm/W0_simple.STL",
    ),
    ("meshes/wrist/W2.DAE", "meshes/wrist/W2_simple.STL"),
    (
        "meshes/torso/base_link.DAE",
        "meshes/torso/base_link_collision.STL",
    ),
    (
        "meshes/base/PEDESTAL.DAE",
        "meshes/base/pedestal_link_collision.STL",
    ),
    (
        "meshes/electric_gripper/electric_gripper_base.DAE",
        "meshes/electric_gripper/electric_gripper_base.STL",
    ),
];

/// The shipped robots, the default ([`ShippedRobot::DEFAULT`]) first.
const SHIPPED: [ShippedRobot; 4] = [
    ShippedRobot {
        name: "panda",
        description: "Franka Panda arm and hand (VAMP's spheres)",
        problems: concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/data/panda/mbm_problems.tar.bz2"
        ),
        unpacked: "target/{scene}_panda",
        scene: "box",
        range: 1.0,
        urdf: include_str!("../../data/panda/panda_spherized.urdf"),
        srdf: include_str!("../../data/panda/panda.srdf"),
        data: concat!(env!("CARGO_MANIFEST_DIR"), "/data/panda"),
        mesh_aliases: &PANDA_ALIASES,
    },
    ShippedRobot {
        name: "ur5",
        description: "Universal Robots UR5 with Robotiq gripper (VAMP's spheres)",
        problems: concat!(env!("CARGO_MANIFEST_DIR"), "/data/ur5/problems.tar.bz2"),
        unpacked: "target/problems/{scene}_ur5",
        scene: "box",
        range: 1.0,
        urdf: include_str!("../../data/ur5/ur5_spherized.urdf"),
        srdf: include_str!("../../data/ur5/ur5.srdf"),
        data: concat!(env!("CARGO_MANIFEST_DIR"), "/data/ur5"),
        mesh_aliases: &UR5_ALIASES,
    },
    ShippedRobot {
        name: "fetch",
        description: "Fetch torso and arm, base fixed (VAMP's spheres)",
        problems: concat!(env!("CARGO_MANIFEST_DIR"), "/data/fetch/problems.tar.bz2"),
        unpacked: "target/problems/{scene}_fetch",
        scene: "box",
        range: 1.25,
        urdf: include_str!("../../data/fetch/fetch_spherized.urdf"),
        srdf: include_str!("../../data/fetch/fetch.srdf"),
        data: concat!(env!("CARGO_MANIFEST_DIR"), "/data/fetch"),
        mesh_aliases: &[],
    },
    ShippedRobot {
        name: "baxter",
        description: "Rethink Baxter, both arms, torso fixed (VAMP's spheres)",
        problems: concat!(env!("CARGO_MANIFEST_DIR"), "/data/baxter/problems.tar.bz2"),
        unpacked: "target/problems/{scene}_baxter",
        scene: "bookshelf_tall_both_arms_easy",
        range: 0.5,
        urdf: include_str!("../../data/baxter/baxter_spherized.urdf"),
        srdf: include_str!("../../data/baxter/baxter.srdf"),
        data: concat!(env!("CARGO_MANIFEST_DIR"), "/data/baxter"),
        mesh_aliases: &BAXTER_ALIASES,
    },
];

impl ShippedRobot {
    /// The robot planned for when none is named.
    pub const DEFAULT: &'static str = "panda";

    /// Every shipped robot, the default first.
    pub fn all() -> &'static [ShippedRobot] {
        &SHIPPED
    }

    /// The robot planned for when none is named ([`DEFAULT`](Self::DEFAULT)).
    pub fn default_robot() -> &'static ShippedRobot {
        &SHIPPED[0]
    }

    /// The shipped robot called `name` (exactly).
    pub fn find(name: &str) -> Option<&'static ShippedRobot> {
        SHIPPED.iter().find(|r| r.name == name)
    }

    /// The shipped robots' names, comma separated.
    pub fn names() -> String {
        SHIPPED
            .iter()
            .map(|r| r.name)
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Its data folder in this crate's source (`robot/data/<name>`), where its mesh files
    /// are; it may be missing when the program was moved away from the source.
    pub fn data_folder(&self) -> &'static Path {
        Path::new(self.data)
    }

    /// The [`MeshResolver`] for its URDF's visual meshes: relative and `package://` names
    /// under [`data_folder`](Self::data_folder), with the aliases its
    /// `meshes/README.md` (the UR5's `visual/README.md`) lists. Without the folder every mesh is reported missing by
    /// [`VisualMeshes::load`](crate::VisualMeshes::load); the model itself is compiled in and
    /// works anywhere.
    pub fn mesh_resolver(&self) -> MeshResolver {
        let folder = PathBuf::from(self.data);
        self.mesh_aliases.iter().fold(
            MeshResolver::new(Some(folder.clone()), vec![folder]),
            |resolver, &(name, instead)| resolver.with_alias(name, instead),
        )
    }

    /// The planning groups its SRDF defines, in file order (`--group NAME`).
    pub fn groups(&self) -> Vec<String> {
        RobotModel::srdf_groups(self.srdf).unwrap_or_default()
    }

    /// The model: the URDF with its SRDF applied, [strict](RobotModel::strict) or lenient
    /// about SRDF entries naming links the sphere model lacks, then
    /// [without the pairs the sphere model rules out](RobotModel::without_model_pairs)
    /// (none for the Panda, whose SRDF already disables them: tested).
    ///
    /// # Errors
    /// Only in strict mode, [`ModelError::UnknownLink`] for such an entry (the shipped files
    /// are tested to load).
    pub fn model(&self, strict: bool) -> Result<RobotModel, ModelError> {
        self.model_of_group(strict, None)
    }

    /// As [`model`](Self::model), planning only the SRDF group `group` if one is named
    /// ([`RobotModel::with_group_str`]); the pairs the sphere model rules out are found with
    /// the other joints held.
    ///
    /// # Errors
    /// As [`model`](Self::model), and as [`RobotModel::with_group_str`] for the group.
    pub fn model_of_group(
        &self,
        strict: bool,
        group: Option<&str>,
    ) -> Result<RobotModel, ModelError> {
        let origin = format!("robot/data/{0}/{0}.srdf", self.name);
        let mut model = RobotModel::from_urdf_str(self.urdf)?
            .strict(strict)
            .with_srdf_named(self.srdf, &origin)?;
        if let Some(group) = group {
            model = model.with_group_named(self.srdf, &origin, group)?;
        }
        Ok(model.without_model_pairs().with_rrt_range(self.range))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_robot_loads_leniently_and_has_its_problems() {
        for robot in ShippedRobot::all() {
            let model = robot.model(false).unwrap();
            assert!(!model.spheres().is_empty(), "{}", robot.name);
            assert!(
                std::path::Path::new(robot.problems).is_file(),
                "{}",
                robot.problems
            );
        }
        assert_eq!(ShippedRobot::default_robot().name, ShippedRobot::DEFAULT);
        let panda = ShippedRobot::find("panda").unwrap().model(true).unwrap();
        assert!(panda.warnings().is_empty());
        // The Panda's SRDF already disables every pair its spheres rule out.
        let bare = RobotModel::from_urdf_str(SHIPPED[0].urdf)
            .and_then(|m| m.with_srdf_str(SHIPPED[0].srdf))
            .unwrap();
        assert_eq!(bare.self_collision_pairs(), panda.self_collision_pairs());
        assert_eq!(ShippedRobot::names(), "panda, ur5, fetch, baxter");
    }

    #[test]
    fn every_mesh_alias_is_named_by_its_urdf_and_stands_for_a_shipped_file() {
        for robot in ShippedRobot::all() {
            let named: Vec<String> = robot
                .model(false)
                .unwrap()
                .visuals()
                .iter()
                .filter_map(|v| match &v.geometry {
                    crate::VisualGeometry::Mesh { filename, .. } => Some(filename.clone()),
                    _ => None,
                })
                .collect();
            let resolver = robot.mesh_resolver();
            for &(name, instead) in robot.mesh_aliases {
                assert!(named.iter().any(|n| n == name), "{}: {name}", robot.name);
                assert_eq!(resolver.alias_of(name), instead);
                assert!(robot.data_folder().join(instead).is_file(), "{instead}");
            }
        }
    }

    #[test]
    fn the_ur5_pair_its_spheres_always_collide_in_is_not_checked() {
        let ur5 = ShippedRobot::find("ur5").unwrap().model(true).unwrap();
        let [warning @ crate::ModelWarning::DisabledPairs { pairs, .. }] = ur5.warnings() else {
            panic!("{:?}", ur5.warnings())
        };
        assert_eq!(pairs, &[("wrist_2_link".into(), "fts_robotside".into())]);
        assert!(warning.to_string().contains("wrist_2_link/fts_robotside"));
        assert!(
            ur5.colliding_link_pairs(&ur5.default_configuration())
                .is_empty()
        );
    }

    #[test]
    fn the_fetch_srdf_names_links_its_spheres_lack() {
        let fetch = ShippedRobot::find("fetch").unwrap();
        assert_eq!(fetch.model(false).unwrap().joint_names().len(), 8);
        assert!(!fetch.model(false).unwrap().warnings().is_empty());
        let e = fetch.model(true).unwrap_err();
        assert!(matches!(e, ModelError::UnknownLink { .. }), "{e}");
        assert!(
            e.to_string().starts_with("robot/data/fetch/fetch.srdf: "),
            "{e}"
        );
    }
}
