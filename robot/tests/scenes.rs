//! MotionBenchMaker scenes and requests: the shipped samples load, and malformed files are
//! typed errors naming the file and the field.

use std::path::{Path, PathBuf};

use problems::PlanningProblem;
use robot::{ArmError, ArmProblem, MbmProblem, ParryChecker, Scene, SceneError, Shape};
use spaces::StateSpace;
use validity::StateValidity;

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
            // VAMP's default: 32 checks per unit of joint-space distance.
            let extent = problem.space().maximum_extent();
            assert!((problem.resolution() * extent * 32.0 - 1.0).abs() < 1e-12);
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

/// `(YAML, field named in the error)` for every kind of malformed scene.
const BROKEN_SCENES: [(&str, &str); 10] = [
    (
        "world: {collision_objects: [{id: a, primitives: [{type: cone, dimensions: [1, 1]}], primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]}]}",
        "world.collision_objects[0].primitives[0].type",
    ),
    (
        "world: {collision_objects: [{id: a, primitives: [{type: box, dimensions: [1, 1]}], primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]}]}",
        "world.collision_objects[0].primitives[0].dimensions",
    ),
    (
        "world: {collision_objects: [{id: a, primitives: [{type: sphere, dimensions: [-1]}], primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]}]}",
        "world.collision_objects[0].primitives[0].dimensions",
    ),
    (
        "world: {collision_objects: [{id: a, primitives: [{type: sphere, dimensions: [1]}], primitive_poses: []}]}",
        "world.collision_objects[0]",
    ),
    (
        "world: {collision_objects: [{id: a, primitives: [{type: sphere, dimensions: [1]}], primitive_poses: [{position: [0, 0], orientation: [0, 0, 0, 1]}]}]}",
        "world.collision_objects[0].primitive_poses[0]",
    ),
    (
        "world: {collision_objects: [{id: a, primitives: [{type: sphere, dimensions: [1]}], primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 0]}]}]}",
        "world.collision_objects[0].primitive_poses[0]",
    ),
    (
        "world: {collision_objects: [{id: a, pose: {position: [.nan, 0, 0], orientation: [0, 0, 0, 1]}, primitives: [], primitive_poses: []}]}",
        "world.collision_objects[0].pose",
    ),
    (
        "allowed_collision_matrix: {entry_names: [a, b], entry_values: [[false, true], [false, false]]}",
        "allowed_collision_matrix.entry_values[0][1]",
    ),
    (
        "allowed_collision_matrix: {entry_names: [a, b], entry_values: [[false, true]]}",
        "allowed_collision_matrix.entry_values",
    ),
    (
        "allowed_collision_matrix: {entry_names: [a, b], entry_values: [[false, true], [true]]}",
        "allowed_collision_matrix.entry_values[1]",
    ),
];

#[test]
fn malformed_scenes_name_the_file_and_the_field() {
    for (yaml, expected) in BROKEN_SCENES {
        let error = Scene::from_yaml_str(yaml, "broken.yaml").unwrap_err();
        match &error {
            SceneError::Field { origin, field, .. } => {
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
