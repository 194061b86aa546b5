//! Robot models from URDF: the Panda, a hand-written robot with forward kinematics worked out
//! by hand, and every malformed input as a typed error.

use glam::{Affine3A, DAffine3, DVec3, Vec3A};
use mit_star_robot::{Kinematics, ModelError, ModelWarning, RobotModel};
use mit_star_spaces::StateSpace;

const PANDA_URDF: &str = include_str!("../data/panda/panda_spherized.urdf");
const PANDA_SRDF: &str = include_str!("../data/panda/panda.srdf");
const TWO_LINK: &str = include_str!("data/two_link.urdf");

#[test]
fn the_panda_has_seven_limited_joints_fifty_nine_spheres_and_its_srdf_pairs_removed() {
    let bare = RobotModel::from_urdf_str(PANDA_URDF).unwrap();
    let panda = bare.clone().with_srdf_str(PANDA_SRDF).unwrap();
    let names: Vec<&str> = panda.joint_names().iter().map(String::as_str).collect();
    assert_eq!(
        names,
        [
            "panda_joint1",
            "panda_joint2",
            "panda_joint3",
            "panda_joint4",
            "panda_joint5",
            "panda_joint6",
            "panda_joint7"
        ]
    );
    let space = panda.joint_space();
    assert_eq!(space.dimension(), 7);
    // The URDF's <limit>, not the safety controller's soft limits.
    assert_eq!(space.lower()[2], -2.9671);
    assert_eq!(space.upper()[5], 3.8223);
    assert_eq!(panda.spheres().len(), 59);
    // Hand and fingers ride along as links of the tree.
    for link in ["panda_hand", "panda_leftfinger", "panda_rightfinger"] {
        let l = panda.link_index(link).unwrap();
        assert!(!panda.link_sphere_range(l).is_empty(), "{link} has spheres");
    }
    // Every link after its parent.
    for (i, l) in panda.links().iter().enumerate() {
        assert!(l.parent.is_none_or(|p| p < i));
    }
    let removed = bare.self_collision_pairs().len() - panda.self_collision_pairs().len();
    assert!(
        removed > 0 && removed <= 34,
        "{removed} pairs removed by the SRDF"
    );
    let pair = |a: &str, b: &str| {
        let (i, j) = (panda.link_index(a).unwrap(), panda.link_index(b).unwrap());
        panda.self_collision_pairs().contains(&(i.min(j), i.max(j)))
    };
    assert!(
        !pair("panda_link0", "panda_link1"),
        "adjacent links are disabled"
    );
    assert!(
        pair("panda_link1", "panda_hand"),
        "the hand can hit the shoulder"
    );
}

#[test]
fn a_hand_written_robot_loads_and_its_kinematics_match_the_hand_computation() {
    let robot = RobotModel::from_urdf_str(TWO_LINK).unwrap();
    assert_eq!(robot.name(), "two_link");
    assert_eq!(robot.joint_names(), ["shoulder", "extend"]);
    assert_eq!(robot.joint_space().lower(), [-3.0, 0.0]);
    assert_eq!(robot.joint_space().upper(), [3.0, 0.3]);
    assert_eq!(robot.spheres().len(), 5);
    // Four links with spheres, no SRDF: all six pairs are checked.
    assert_eq!(robot.self_collision_pairs().len(), 6);
    let fk = Kinematics::new(&robot);
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    let mut links32 = vec![Affine3A::IDENTITY; fk.link_count()];
    let mut centers32 = vec![Vec3A::ZERO; fk.sphere_count()];
    for (theta, d) in [(0.0, 0.0), (0.7, 0.1), (-2.5, 0.3), (3.0, 0.05)] {
        let q = [theta, d];
        fk.sphere_centers_f64(&q, &mut links, &mut centers);
        fk.sphere_centers(&q, &mut links32, &mut centers32);
        let (s, c) = f64::sin_cos(theta);
        // base; arm at 0.25 and 0.5 along the rotated x; the slider's origin is 0.5 along
        // x, turned a quarter about z, then moved d along its (doubled, normalised) x axis;
        // the tool sits 0.1 further along the slider's x.
        let expected = [
            (DVec3::ZERO, 0.05),
            (DVec3::new(0.25 * c, 0.25 * s, 0.1), 0.04),
            (DVec3::new(0.5 * c, 0.5 * s, 0.1), 0.04),
            (DVec3::new(0.5 * c - d * s, 0.5 * s + d * c, 0.1), 0.03),
            (
                DVec3::new(0.5 * c - (d + 0.1) * s, 0.5 * s + (d + 0.1) * c, 0.1),
                0.02,
            ),
        ];
        for (i, ((got, r), (want, rw))) in centers.iter().zip(expected).enumerate() {
            assert!(
                got.distance(want) < 1e-12,
                "sphere {i} at {q:?}: {got} vs {want}"
            );
            assert_eq!(*r, rw);
            assert!(centers32[i].as_dvec3().distance(want) < 1e-6);
        }
    }
}

#[test]
fn srdf_pairs_and_allowed_collisions_remove_pairs_and_name_unknown_links() {
    let robot = RobotModel::from_urdf_str(TWO_LINK).unwrap();
    let srdf = r#"<robot name="two_link"><disable_collisions link1="base" link2="arm" reason="Adjacent"/></robot>"#;
    let robot = robot.with_srdf_str(srdf).unwrap();
    assert_eq!(robot.self_collision_pairs().len(), 5);
    let robot = robot.allow_collisions([("tool", "slider")]).unwrap();
    assert_eq!(robot.self_collision_pairs().len(), 4);
    // Strict: an unknown link is an error naming it.
    let error = robot
        .clone()
        .strict(true)
        .allow_collisions([("tool", "gripper")])
        .unwrap_err();
    assert!(matches!(&error, ModelError::UnknownLink { link, .. } if link == "gripper"));
    assert!(error.to_string().contains("`gripper`"), "{error}");
    // Lenient (the default): the entry is skipped and a warning names the link, once.
    assert!(!robot.is_strict() && robot.warnings().is_empty());
    let lenient = robot
        .allow_collisions([("tool", "gripper"), ("gripper", "base"), ("arm", "tool")])
        .unwrap();
    assert_eq!(lenient.self_collision_pairs().len(), 3);
    let [warning @ ModelWarning::UnknownLinks { links, entries, .. }] = lenient.warnings() else {
        panic!("one warning: {:?}", lenient.warnings())
    };
    assert_eq!(
        (links.as_slice(), *entries),
        (&["gripper".to_owned()][..], 2)
    );
    let text = warning.to_string();
    assert!(
        text.contains("allowed-collision matrix")
            && text.contains("2 entries")
            && text.contains("gripper"),
        "{text}"
    );
    // An SRDF naming unknown links: a warning when lenient, an error when strict.
    let srdf = r#"<robot name="r"><disable_collisions link1="base" link2="camera"/>
        <disable_collisions link1="sensor" link2="camera"/></robot>"#;
    let model = RobotModel::from_urdf_str(TWO_LINK).unwrap();
    let lenient = model.clone().with_srdf_str(srdf).unwrap();
    assert!(
        matches!(&lenient.warnings()[0], ModelWarning::UnknownLinks { links, .. } if links == &["camera", "sensor"])
    );
    assert_eq!(lenient.self_collision_pairs(), model.self_collision_pairs());
    let error = model.strict(true).with_srdf_str(srdf).unwrap_err();
    assert!(matches!(&error, ModelError::UnknownLink { link, .. } if link == "camera"));
    let error = RobotModel::from_urdf_str(TWO_LINK)
        .unwrap()
        .with_srdf_str("<robot><disable_collisions link1=\"base\"/></robot>")
        .unwrap_err();
    assert!(matches!(error, ModelError::Srdf { .. }), "{error}");
}

/// The two-link robot with one substitution made.
fn edited(from: &str, to: &str) -> Result<RobotModel, ModelError> {
    assert!(TWO_LINK.contains(from), "{from}");
    RobotModel::from_urdf_str(&TWO_LINK.replacen(from, to, 1))
}

#[test]
fn malformed_urdfs_are_typed_errors_naming_the_culprit() {
    let error = edited("<sphere radius=\"0.03\"/>", "<box size=\"1 1 1\"/>").unwrap_err();
    assert!(
        matches!(&error, ModelError::UnsupportedGeometry { link, kind } if link == "slider" && *kind == "box"),
        "{error}"
    );
    let error = edited("type=\"prismatic\"", "type=\"floating\"").unwrap_err();
    assert!(
        matches!(&error, ModelError::UnsupportedJoint { joint, .. } if joint == "extend"),
        "{error}"
    );
    let error = edited("lower=\"0.0\" upper=\"0.3\"", "lower=\"0.3\" upper=\"0.0\"").unwrap_err();
    assert!(
        matches!(&error, ModelError::BadLimits { joint, .. } if joint == "extend"),
        "{error}"
    );
    let error = edited("<axis xyz=\"2 0 0\"/>", "<axis xyz=\"0 0 0\"/>").unwrap_err();
    assert!(
        matches!(&error, ModelError::BadAxis { joint, .. } if joint == "extend"),
        "{error}"
    );
    let error = edited("radius=\"0.02\"", "radius=\"-0.02\"").unwrap_err();
    assert!(
        matches!(&error, ModelError::BadNumber { element, .. } if element == "tool"),
        "{error}"
    );
    let error = edited("<parent link=\"slider\"/>", "<parent link=\"nowhere\"/>").unwrap_err();
    assert!(
        matches!(&error, ModelError::UnknownJointLink { link, .. } if link == "nowhere"),
        "{error}"
    );
    let error = edited(
        "<parent link=\"slider\"/><child link=\"tool\"/>",
        "<parent link=\"tool\"/><child link=\"tool\"/>",
    )
    .unwrap_err();
    assert!(matches!(error, ModelError::NotATree { .. }), "{error}");
    let error = edited(
        "<link name=\"tool\">",
        "<link name=\"extra\"/><link name=\"tool\">",
    )
    .unwrap_err();
    assert!(
        matches!(&error, ModelError::NotATree { why } if why.contains("extra")),
        "{error}"
    );
    let error = RobotModel::from_urdf_str("<robot name=\"x\"><link name=").unwrap_err();
    assert!(matches!(error, ModelError::Urdf { .. }), "{error}");
    let error =
        RobotModel::from_urdf_str("<robot name=\"still\"><link name=\"a\"/></robot>").unwrap_err();
    assert!(matches!(error, ModelError::NoJoints), "{error}");
    let error = RobotModel::from_urdf_file("/nonexistent/robot.urdf".as_ref()).unwrap_err();
    assert!(
        error.to_string().contains("/nonexistent/robot.urdf"),
        "{error}"
    );
}

#[test]
fn names_given_twice_are_refused_naming_them() {
    // A second joint called `shoulder` (it would otherwise load: one of them would win).
    let error = edited(
        "<joint name=\"mount\" type=\"fixed\">",
        "<joint name=\"shoulder\" type=\"fixed\">",
    )
    .unwrap_err();
    assert!(
        matches!(&error, ModelError::DuplicateName { what: "joint", name, .. } if name == "shoulder"),
        "{error}"
    );
    assert_eq!(
        error.to_string(),
        "URDF text: two joints are called `shoulder`"
    );
    let error = edited("<link name=\"tool\">", "<link name=\"arm\">").unwrap_err();
    assert!(
        matches!(&error, ModelError::DuplicateName { what: "link", name, .. } if name == "arm"),
        "{error}"
    );
}

#[test]
fn absurd_origins_and_radii_are_refused() {
    let error = edited(
        "<origin xyz=\"0.1 0 0\" rpy=\"0 0 0\"/>",
        "<origin xyz=\"1e308 0 0\" rpy=\"0 0 0\"/>",
    )
    .unwrap_err();
    assert!(
        matches!(&error, ModelError::BadNumber { element, value, .. } if element == "mount" && *value == 1e308),
        "{error}"
    );
    assert!(error.to_string().contains("1e6"), "{error}");
    let error = edited("radius=\"0.02\"", "radius=\"1e30\"").unwrap_err();
    assert!(
        matches!(&error, ModelError::BadNumber { element, .. } if element == "tool"),
        "{error}"
    );
}

#[test]
fn an_srdf_whose_root_is_not_robot_is_refused() {
    let robot = RobotModel::from_urdf_str(TWO_LINK).unwrap();
    let error = robot
        .clone()
        .with_srdf_str(r#"<launch><disable_collisions link1="base" link2="arm"/></launch>"#)
        .unwrap_err();
    assert!(matches!(error, ModelError::Srdf { .. }), "{error}");
    assert!(
        error.to_string().contains("<launch>, not <robot>"),
        "{error}"
    );
    // An SRDF file is named in the error.
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("not_robot.srdf");
    std::fs::write(&path, "<?xml version=\"1.0\"?>\n<srdf/>").unwrap();
    let error = robot.with_srdf_file(&path).unwrap_err().to_string();
    assert!(
        error.contains("not_robot.srdf") && error.contains("<srdf>, not <robot>"),
        "{error}"
    );
}
