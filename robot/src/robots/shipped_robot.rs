//! [`ShippedRobot`]: the robot models compiled into this crate, and their problem sets.

use crate::{ModelError, RobotModel};

/// A robot model shipped with this crate (`robot/data/<name>/`): its spherised URDF and SRDF,
/// compiled in, and where its MotionBenchMaker problems are.
///
/// ```
/// let ur5 = robot::ShippedRobot::find("ur5").expect("shipped");
/// let model = ur5.model(false)?;
/// assert_eq!(model.joint_names().len(), 6);
/// assert!(robot::ShippedRobot::names().contains("fetch"));
/// # Ok::<(), robot::ModelError>(())
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
}

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
