//! MotionBenchMaker scenes and requests: the shipped samples load, and malformed files are
//! typed errors naming the file and the field.

use std::path::{Path, PathBuf};

use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmError, ArmProblem, MbmProblem, ParryChecker, Scene, SceneError, Shape};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;

const SCENES: [&str; 5] = [
    "bookshelf_small_panda",
    "bookshelf_tall_panda",
    "box_panda",
    "cage_panda",
    "table_pick_panda",
];

fn data(scene: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/mbm")
        .join(scene)
}

#[test]
fn every_sample_problem_loads_with_valid_ends_under_both_checkers() {
    for scene in SCENES {
        assert_eq!(
            MbmProblem::indices(&data(scene)).unwrap(),
            [1, 2],
            "{scene}"
        );
        for index in [1, 2] {
            let problem = ArmProblem::panda_mbm(&data(scene), index).unwrap();
            assert_eq!(problem.name(), format!("{scene}/{index:04}"));
            assert_eq!(problem.start().len(), 7);
            assert_eq!(problem.goals().len(), 1);
            assert!(!problem.scene().obstacles().is_empty());
            // The default: `CHECKS_PER_UNIT` checks per unit of joint-space distance.
            let extent = problem.space().maximum_extent();
            let per_unit = mit_star_robot::CHECKS_PER_UNIT;
            assert!((problem.resolution() * extent * per_unit - 1.0).abs() < 1e-12);
            let reference = ParryChecker::new(problem.robot(), problem.scene());
            for q in [problem.start(), &problem.goals()[0][..]] {
                assert_eq!(
                    problem.validity().is_valid(q),
                    reference.is_valid(q),
                    "{scene}/{index}"
                );
            }
            assert!(problem.ends_are_valid(), "{scene}/{index}");
        }
    }
}

#[test]
fn primitives_and_poses_are_read_as_moveit_writes_them() {
    let scene = Scene::from_yaml_str(
        "world:
  collision_objects:
    - id: shelf
      pose: {position: [1, 0, 0], orientation: [0, 0, 0.7071067811865476, 0.7071067811865476]}
      primitives:
        - {type: box, dimensions: [0.2, 0.4, 0.6]}
        - {type: cylinder, dimensions: [0.5, 0.1]}
        - {type: sphere, dimensions: [0.25]}
      primitive_poses:
        - {position: [0.5, 0, 0], orientation: [0, 0, 0, 1]}
        - {position: [0, 0, 1], orientation: [0, 0, 0, 2]}
        - {position: [0, 0, 2], orientation: [0, 0, 0, 1]}
allowed_collision_matrix:
  entry_names: [a, b, c]
  entry_values: [[false, true, false], [true, false, false], [false, false, false]]
",
        "inline.yaml",
    )
    .unwrap();
    assert_eq!(scene.ids(), ["shelf", "shelf", "shelf"]);
    assert_eq!(scene.allowed_pairs(), [("a".to_owned(), "b".to_owned())]);
    let [b, c, s] = scene.obstacles() else {
        panic!("three obstacles")
    };
    // The object pose turns the primitive's offset (0.5, 0, 0) onto +y.
    let t = b.pose().translation;
    assert!(
        (t - glam::DVec3::new(1.0, 0.5, 0.0)).length() < 1e-12,
        "{t}"
    );
    assert_eq!(
        b.shape(),
        Shape::Cuboid {
            half_extents: glam::DVec3::new(0.1, 0.2, 0.3)
        }
    );
    assert_eq!(
        c.shape(),
        Shape::Cylinder {
            half_height: 0.25,
            radius: 0.1
        }
    );
    assert_eq!(s.shape(), Shape::Sphere { radius: 0.25 });
    // The quaternion (0, 0, 0, 2) is normalised, not rejected.
    assert!((c.pose().matrix3.determinant() - 1.0).abs() < 1e-12);
}

/// A scene of one object `a` with one primitive and its pose.
fn one(primitive: &str, pose: &str) -> String {
    format!(
        "world: {{collision_objects: [{{id: a, primitives: [{primitive}], primitive_poses: [{pose}]}}]}}"
    )
}

const SPHERE: &str = "{type: sphere, dimensions: [1]}";
const AT_ORIGIN: &str = "{position: [0, 0, 0], orientation: [0, 0, 0, 1]}";

/// `(YAML, field named in the error)` for every kind of malformed scene.
fn broken_scenes() -> Vec<(String, &'static str)> {
    let acm = |matrix: &str| format!("world: {{}}\nallowed_collision_matrix: {matrix}");
    vec![
        (
            one("{type: cone, dimensions: [1, 1]}", AT_ORIGIN),
            "world.collision_objects[0].primitives[0].type",
        ),
        (
            one("{type: box, dimensions: [1, 1]}", AT_ORIGIN),
            "world.collision_objects[0].primitives[0].dimensions",
        ),
        (
            one("{type: sphere, dimensions: [-1]}", AT_ORIGIN),
            "world.collision_objects[0].primitives[0].dimensions[0]",
        ),
        (
            "world: {collision_objects: [{id: a, primitives: [{type: sphere, dimensions: [1]}], primitive_poses: []}]}".into(),
            "world.collision_objects[0]",
        ),
        (
            one(SPHERE, "{position: [0, 0], orientation: [0, 0, 0, 1]}"),
            "world.collision_objects[0].primitive_poses[0].position",
        ),
        (
            one(SPHERE, "{position: [0, 0, 0], orientation: [0, 0, 0, 0]}"),
            "world.collision_objects[0].primitive_poses[0].orientation",
        ),
        (
            "world: {collision_objects: [{id: a, pose: {position: [.nan, 0, 0], orientation: [0, 0, 0, 1]}, primitives: [], primitive_poses: []}]}".into(),
            "world.collision_objects[0].pose.position[0]",
        ),
        (
            acm("{entry_names: [a, b], entry_values: [[false, true], [false, false]]}"),
            "allowed_collision_matrix.entry_values[0][1]",
        ),
        (
            acm("{entry_names: [a, b], entry_values: [[false, true]]}"),
            "allowed_collision_matrix.entry_values",
        ),
        (
            acm("{entry_names: [a, b], entry_values: [[false, true], [true]]}"),
            "allowed_collision_matrix.entry_values[1]",
        ),
    ]
}

#[test]
fn malformed_scenes_name_the_file_and_the_field() {
    for (yaml, expected) in broken_scenes() {
        let error = Scene::from_yaml_str(&yaml, "broken.yaml").unwrap_err();
        match &error {
            SceneError::Field { origin, field, .. } | SceneError::Number { origin, field, .. } => {
                assert_eq!(origin, "broken.yaml");
                assert_eq!(field, expected, "{yaml}");
            }
            other => panic!("{yaml}: {other}"),
        }
        assert!(error.to_string().starts_with("broken.yaml: "), "{error}");
    }
    let error = Scene::from_yaml_str("world: [not, a, map", "bad.yaml").unwrap_err();
    assert!(matches!(error, SceneError::Yaml { .. }), "{error}");
    assert!(error.to_string().starts_with("bad.yaml"), "{error}");
}

/// A fresh folder under the target directory holding the given files.
fn folder(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

#[test]
fn broken_problem_folders_and_requests_are_typed_errors() {
    let scene = std::fs::read_to_string(data("box_panda").join("scene0001.yaml")).unwrap();
    let request = std::fs::read_to_string(data("box_panda").join("request0001.yaml")).unwrap();

    let empty = folder("empty", &[]);
    let error = MbmProblem::indices(&empty).unwrap_err();
    assert!(matches!(error, SceneError::Folder { .. }), "{error}");
    let missing = MbmProblem::indices("/nonexistent/scene_panda".as_ref()).unwrap_err();
    assert!(
        missing.to_string().contains("/nonexistent/scene_panda"),
        "{missing}"
    );

    let half = folder("half", &[("scene0001.yaml", &scene)]);
    let error = ArmProblem::panda_mbm(&half, 1).unwrap_err();
    assert!(error.to_string().contains("request0001.yaml"), "{error}");

    let no_joint = request.replace("joint_name: panda_joint5", "joint_name: panda_joint9");
    let dir = folder(
        "no_joint",
        &[("scene0001.yaml", &scene), ("request0001.yaml", &no_joint)],
    );
    let error = ArmProblem::panda_mbm(&dir, 1).unwrap_err();
    assert!(
        matches!(&error, ArmError::Scene(SceneError::MissingJoint { joint, .. }) if joint == "panda_joint5"),
        "{error}"
    );
    assert!(error.to_string().contains("request0001.yaml"), "{error}");

    let outside = request.replace("position: 1.7628", "position: 2.5");
    let dir = folder(
        "outside",
        &[("scene0001.yaml", &scene), ("request0001.yaml", &outside)],
    );
    let error = ArmProblem::panda_mbm(&dir, 1).unwrap_err();
    assert!(
        matches!(&error, ArmError::Query { what: "goal", .. }),
        "{error}"
    );

    let bad_scene = scene.replacen("type: box", "type: mesh", 1);
    let dir = folder(
        "bad_scene",
        &[
            ("scene0001.yaml", &bad_scene),
            ("request0001.yaml", &request),
        ],
    );
    let error = ArmProblem::panda_mbm(&dir, 1).unwrap_err();
    let text = error.to_string();
    assert!(
        text.contains("scene0001.yaml") && text.contains(".type"),
        "{text}"
    );
}

/// The error of a scene that must be refused, with the field it names.
fn refused(yaml: &str) -> (SceneError, String) {
    let error = Scene::from_yaml_str(yaml, "hostile.yaml").unwrap_err();
    let field = error
        .field()
        .unwrap_or_else(|| panic!("{error}"))
        .to_owned();
    assert!(error.to_string().starts_with("hostile.yaml: "), "{error}");
    (error, field)
}

#[test]
fn finite_but_absurd_numbers_are_refused_naming_the_field_the_value_and_the_bound() {
    // A sphere of radius 1e30 at 1e30: the size is reported first, then the position.
    let (error, field) = refused(&one(
        "{type: sphere, dimensions: [1e30]}",
        "{position: [1e30, 0, 0], orientation: [0, 0, 0, 1]}",
    ));
    assert_eq!(
        field,
        "world.collision_objects[0].primitives[0].dimensions[0]"
    );
    assert!(
        matches!(error, SceneError::Number { value, .. } if value == 1e30),
        "{error}"
    );
    assert!(
        error
            .to_string()
            .contains("1e30 is not a size in (0, 1e6] m"),
        "{error}"
    );
    let (error, field) = refused(&one(
        SPHERE,
        "{position: [0, 0, 1e30], orientation: [0, 0, 0, 1]}",
    ));
    assert_eq!(
        field,
        "world.collision_objects[0].primitive_poses[0].position[2]"
    );
    assert!(
        error
            .to_string()
            .contains("1e30 is not a coordinate within ±1e6 m"),
        "{error}"
    );
    // Poses of 1e308 (their composition would overflow to infinity), in the object's pose.
    let (error, field) = refused(
        "world: {collision_objects: [{id: a, pose: {position: [1e308, 1e308, 0], orientation: [0, 0, 0, 1]}, primitives: [{type: box, dimensions: [1, 1, 1]}], primitive_poses: [{position: [1e308, 0, 0], orientation: [0, 0, 0, 1]}]}]}",
    );
    assert_eq!(field, "world.collision_objects[0].pose.position[0]");
    assert!(
        error.to_string().contains("1e308 is not a coordinate"),
        "{error}"
    );
    // Just inside and just outside the bound (the messages say 1e6 m).
    assert_eq!(Scene::MAX_LENGTH, 1e6);
    let edge = format!(
        "{{position: [{}, 0, 0], orientation: [0, 0, 0, 1]}}",
        Scene::MAX_LENGTH
    );
    assert_eq!(
        Scene::from_yaml_str(&one(SPHERE, &edge), "e.yaml")
            .unwrap()
            .obstacles()
            .len(),
        1
    );
    refused(&one(
        SPHERE,
        "{position: [-1000000.001, 0, 0], orientation: [0, 0, 0, 1]}",
    ));
    refused(&one("{type: box, dimensions: [1, 2e6, 1]}", AT_ORIGIN));
    refused(&one("{type: cylinder, dimensions: [1, .inf]}", AT_ORIGIN));
    // Quaternion components must be finite; a norm that overflows is refused.
    let (error, field) = refused(&one(
        SPHERE,
        "{position: [0, 0, 0], orientation: [0, 0, -.inf, 1]}",
    ));
    assert_eq!(
        field,
        "world.collision_objects[0].primitive_poses[0].orientation[2]"
    );
    assert!(
        error
            .to_string()
            .contains("-inf is not a finite quaternion component"),
        "{error}"
    );
    let (_, field) = refused(&one(
        SPHERE,
        "{position: [0, 0, 0], orientation: [1.7e308, 1.7e308, 0, 0]}",
    ));
    assert_eq!(
        field,
        "world.collision_objects[0].primitive_poses[0].orientation"
    );
}

#[test]
fn a_huge_quaternion_is_normalised_without_overflow() {
    // Its norm squared overflows: normalised naively it is NaN.
    let scene = Scene::from_yaml_str(
        &one(
            SPHERE,
            "{position: [0, 0, 0], orientation: [0, 0, 1e200, 1e200]}",
        ),
        "q.yaml",
    )
    .unwrap();
    let rotation = scene.obstacles()[0].pose().matrix3;
    let expected = glam::DMat3::from_rotation_z(std::f64::consts::FRAC_PI_2);
    assert!(rotation.abs_diff_eq(expected, 1e-12), "{rotation}");
    // One whose norm squared underflows but whose norm is above the floor is normalised too.
    let scene = Scene::from_yaml_str(
        &one(
            SPHERE,
            "{position: [0, 0, 0], orientation: [0, 0, 3e-9, 3e-9]}",
        ),
        "q.yaml",
    )
    .unwrap();
    assert!(
        scene.obstacles()[0]
            .pose()
            .matrix3
            .abs_diff_eq(expected, 1e-12)
    );
    // Below the floor it is the zero quaternion: no rotation.
    let (error, _) = refused(&one(
        SPHERE,
        "{position: [0, 0, 0], orientation: [0, 0, 3e-160, 3e-160]}",
    ));
    assert!(
        error
            .to_string()
            .contains("norm 4.2426406871192854e-160 is below 1e-9"),
        "{error}"
    );
}

#[test]
fn empty_worlds_are_empty_scenes_and_files_without_a_world_are_refused() {
    // As MoveIt: a world without objects is an empty scene, and so is an explicit null.
    for yaml in [
        "world: {collision_objects: []}",
        "world: {}",
        "world: null",
        "world: ~",
        "world:\nname: empty",
    ] {
        let scene = Scene::from_yaml_str(yaml, "empty.yaml").unwrap_or_else(|e| panic!("{e}"));
        assert!(
            scene.obstacles().is_empty() && scene.ids().is_empty(),
            "{yaml}"
        );
    }
    // No `world` at all: not a planning scene (an empty file, a request, a typo).
    for yaml in [
        "",
        "# nothing\n",
        "{}",
        "name: scene",
        "wrold: {collision_objects: []}",
        "allowed_collision_matrix: {entry_names: [], entry_values: []}",
    ] {
        let error = Scene::from_yaml_str(yaml, "none.yaml").unwrap_err();
        assert_eq!(error.field(), Some("world"), "{yaml:?}: {error}");
        assert!(
            error.to_string().contains("not a MoveIt planning scene"),
            "{error}"
        );
    }
}

#[test]
fn ambiguous_scenes_are_refused() {
    let (error, field) = refused(&format!(
        "world: {{collision_objects: [{0}, {1}, {0}]}}",
        "{id: shelf, primitives: [{type: sphere, dimensions: [1]}], primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]}",
        "{id: table, primitives: [], primitive_poses: []}",
    ));
    assert_eq!(field, "world.collision_objects[2].id");
    assert!(
        error
            .to_string()
            .contains("`shelf` is also the id of world.collision_objects[0]"),
        "{error}"
    );
    // Shapes the scene cannot represent are refused, not dropped.
    let (_, field) = refused(
        "world: {collision_objects: [{id: m, meshes: [{triangles: [], vertices: []}], mesh_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]}]}",
    );
    assert_eq!(field, "world.collision_objects[0].meshes");
    let (_, field) =
        refused("world: {collision_objects: [{id: p, planes: [{coef: [0, 0, 1, 0]}]}]}");
    assert_eq!(field, "world.collision_objects[0].planes");
    let (error, field) = refused(
        "world: {}\nallowed_collision_matrix: {entry_names: [a, b, a], entry_values: [[false, true, false], [true, false, true], [false, true, false]]}",
    );
    assert_eq!(field, "allowed_collision_matrix.entry_names[2]");
    assert!(
        error.to_string().contains("`a` is also entry_names[0]"),
        "{error}"
    );
}

#[test]
fn a_joint_named_twice_in_a_request_is_refused_naming_it() {
    let scene = std::fs::read_to_string(data("box_panda").join("scene0001.yaml")).unwrap();
    let request = std::fs::read_to_string(data("box_panda").join("request0001.yaml")).unwrap();
    // The goal gives panda_joint3 twice (with different values).
    let twice = request.replace("joint_name: panda_joint5", "joint_name: panda_joint3");
    let dir = folder(
        "goal_twice",
        &[("scene0001.yaml", &scene), ("request0001.yaml", &twice)],
    );
    let error = MbmProblem::load(&dir, 1).unwrap_err();
    assert!(
        matches!(&error, SceneError::DuplicateJoint { joint, what, .. }
            if joint == "panda_joint3" && *what == "goal_constraints[0].joint_constraints"),
        "{error}"
    );
    assert!(error.to_string().contains("request0001.yaml"), "{error}");
    // The start state names panda_joint1 twice.
    let twice = request.replace(
        "name: [panda_joint1, panda_joint2,",
        "name: [panda_joint1, panda_joint1,",
    );
    assert_ne!(twice, request);
    let dir = folder(
        "start_twice",
        &[("scene0001.yaml", &scene), ("request0001.yaml", &twice)],
    );
    let error = ArmProblem::panda_mbm(&dir, 1).unwrap_err();
    assert!(
        matches!(&error, ArmError::Scene(SceneError::DuplicateJoint { joint, what, .. })
            if joint == "panda_joint1" && *what == "start_state.joint_state.name"),
        "{error}"
    );
}

#[test]
fn a_scene_of_fifty_thousand_primitives_loads() {
    // Above the YAML parser's default budget of 250 000 nodes, which once refused it with
    // "budget breached: Nodes { nodes: 250001 }".
    let primitives = vec![SPHERE; 50_000].join(", ");
    let poses = vec![AT_ORIGIN; 50_000].join(", ");
    let yaml = one(&primitives, &poses);
    let scene = Scene::from_yaml_str(&yaml, "large.yaml").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(scene.obstacles().len(), 50_000);
}
