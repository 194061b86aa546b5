//! A collision padding keeps every configuration of a returned path at least the padding from
//! every obstacle, as measured by the independent `f64` checks: the padded checker never calls
//! valid a configuration the reference measures closer than the padding, its certified edges
//! keep the padding all along (audited), planned and simplified paths on MotionBenchMaker
//! problems keep it, and an end within the padding is refused by name.

use std::path::{Path, PathBuf};
use std::time::Duration;

use glam::{DQuat, DVec3};
use mit_star::{FirstSolution, Parameters, PathSimplifier, Planner, TerminationExt, TimeLimit};
use mit_star_robot::{
    ArmChecker, ArmError, ArmProblem, AuditVerdict, Kinematics, MotionAudit, Obstacle, Padding,
    ParryChecker, Scene, Shape, ShippedRobot,
};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};
use proptest::prelude::*;

use crate::arm_cases::{HOME, edge, obstacle, panda};

/// The smallest distance, in `f64` (the reference checker, unpadded), from a robot sphere at
/// `q` to an obstacle of `scene`.
fn scene_gap(scene: &Scene, q: &[f64]) -> f64 {
    let robot = panda();
    let reference = ParryChecker::new(&robot, scene);
    let mut gaps = vec![0.0; robot.spheres().len()];
    let mut pairs = vec![0.0; reference.sphere_pairs().len()];
    reference.gaps(q, &mut gaps, &mut pairs);
    gaps.into_iter().fold(f64::INFINITY, f64::min)
}

/// A ball of radius `size` placed `gap` metres (along `direction`) from sphere `sphere` of the
/// Panda at `q`.
fn ball_near(q: &[f64], sphere: usize, direction: DVec3, gap: f64, size: f64) -> Obstacle {
    let robot = panda();
    let fk = Kinematics::new(&robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(q, &mut links, &mut centers);
    let (c, r) = centers[sphere % centers.len()];
    Obstacle::new(
        Shape::Sphere { radius: size },
        c + direction.normalize() * (r + gap + size),
        DQuat::IDENTITY,
    )
}

fn direction() -> impl Strategy<Value = DVec3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("a direction", |(x, y, z)| x * x + y * y + z * z > 0.01)
        .prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn configuration() -> impl Strategy<Value = Vec<f64>> {
    edge().prop_map(|(a, _)| a)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A ball placed about the padding away from a sphere: the padded checker calls the
    /// configuration valid only if the reference measures every sphere at least the padding
    /// from it; padding changes nothing between the robot's own links.
    #[test]
    fn the_padded_checker_never_accepts_a_configuration_within_the_padding(
        q in configuration(),
        sphere in 0usize..64,
        towards in direction(),
        padding in prop_oneof![Just(0.005), Just(0.01), Just(0.02)],
        share in 0.0..2.0f64,
        size in 0.005..0.2f64,
    ) {
        let robot = panda();
        let padding = Padding::new(padding).unwrap();
        let ball = ball_near(&q, sphere, towards, share * padding.metres(), size);
        let scene = Scene::new(vec![ball]);
        let checker = ArmChecker::padded(&robot, &scene, padding);
        let gap = scene_gap(&scene, &q);
        if checker.is_valid(&q) {
            prop_assert!(gap >= padding.metres(), "valid at {gap} m with a padding of {padding}");
        }
        let mut batch = [true; 3];
        checker.are_valid(&[q.clone(), q.clone(), q.clone()].concat(), 7, &mut batch);
        prop_assert!(batch.iter().all(|&v| v == checker.is_valid(&q)));
        // With nothing in the scene, the padded checker is the unpadded one.
        let empty = Scene::new(Vec::new());
        prop_assert_eq!(
            ArmChecker::padded(&robot, &empty, padding).is_valid(&q),
            ArmChecker::new(&robot, &empty).is_valid(&q)
        );
        // The reference checker pads alike: it refuses what is within the padding.
        let reference = ParryChecker::padded(&robot, &scene, padding);
        if gap < padding.metres() {
            prop_assert!(!reference.is_valid(&q));
        }
    }

    /// Every edge the padded checker certifies keeps the padding at every configuration: the
    /// padded audit finds it clear, and the unpadded audit's smallest obstacle distance is at
    /// least the padding.
    #[test]
    fn certified_padded_edges_keep_the_padding_all_along(
        (a, b) in edge(),
        obstacles in prop::collection::vec(obstacle(), 1..4),
        padding in prop_oneof![Just(0.005), Just(0.02)],
    ) {
        let robot = panda();
        let padding = Padding::new(padding).unwrap();
        let scene = Scene::new(obstacles);
        let checker = ArmChecker::padded(&robot, &scene, padding);
        let space = robot.joint_space();
        prop_assume!(checker.is_valid(&a) && checker.is_valid(&b));
        let mut progress = MotionProgress::new(0.0, 0.0);
        let status = checker.certify_motion(space, &a, &b, &mut progress, &mit_star_spaces::Never);
        if status == Some(EdgeStatus::Valid) {
            let audit = MotionAudit::padded(&robot, &scene, padding);
            let verdict = audit.audit(&a, &b, 2_000_000);
            prop_assert!(matches!(verdict, AuditVerdict::Clear { .. }), "{:?}", verdict);
            match MotionAudit::new(&robot, &scene).audit(&a, &b, 2_000_000) {
                AuditVerdict::Clear { obstacle_clearance, .. } => {
                    prop_assert!(obstacle_clearance >= padding.metres(), "{obstacle_clearance}");
                }
                other => prop_assert!(false, "{:?}", other),
            }
        }
    }
}

fn folder(scene: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/mbm")
        .join(scene)
}

/// Plans problem `index` of `scene` for `robot` with `padding`, simplifies the path, and checks
/// every edge of both with the unpadded `f64` audit: clear, with every sphere at least the
/// padding from every obstacle. Returns the smallest obstacle distance, or the error of an end
/// within the padding.
fn padded_plan(robot: &str, scene: &str, index: usize, padding: f64) -> Result<f64, ArmError> {
    let model = ShippedRobot::find(robot).unwrap().model(false).unwrap();
    let padding = Padding::new(padding).unwrap();
    let problem = ArmProblem::mbm(model, &folder(scene), index)?.with_padding(padding);
    problem.check_ends()?;
    let parameters = Parameters {
        seed: 3,
        ..Parameters::default()
    };
    let mut planner = mit_star::RrtConnect::for_problem(&problem, &parameters).unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(20.0)))
        .unwrap();
    let path: Vec<Vec<f64>> = outcome
        .solution()
        .unwrap_or_else(|| panic!("{robot} {scene} #{index}: no path"))
        .path
        .iter()
        .map(<[f64]>::to_vec)
        .collect();
    let simplified = PathSimplifier::new()
        .seed(7)
        .simplify(
            &problem,
            &path,
            &mit_star_spaces::Deadline::after(Duration::from_secs(2)),
        )
        .unwrap()
        .path;
    let audit = MotionAudit::new(problem.robot(), problem.scene());
    let mut nearest = f64::INFINITY;
    for w in path.windows(2).chain(simplified.windows(2)) {
        match audit.audit(&w[0], &w[1], 2_000_000) {
            AuditVerdict::Clear {
                obstacle_clearance, ..
            } => nearest = nearest.min(obstacle_clearance),
            other => panic!("{robot} {scene} #{index}: an edge is not clear: {other:?}"),
        }
    }
    assert!(
        nearest >= padding.metres(),
        "{robot} {scene} #{index}: {nearest} m from an obstacle, padding {padding}"
    );
    Ok(nearest)
}

#[test]
fn planned_and_simplified_paths_keep_a_centimetre_from_every_obstacle() {
    let mut planned = 0;
    for (robot, scene, index) in [
        ("panda", "bookshelf_small_panda", 1),
        ("panda", "bookshelf_tall_panda", 1),
        ("panda", "cage_panda", 1),
        ("panda", "box_panda", 1),
        ("panda", "table_pick_panda", 1),
        ("ur5", "box_ur5", 1),
        ("ur5", "box_ur5", 2),
        ("fetch", "box_fetch", 1),
    ] {
        match padded_plan(robot, scene, index, 0.01) {
            Ok(nearest) => {
                eprintln!("{robot} {scene} #{index}: {:.2} mm", nearest * 1e3);
                planned += 1;
            }
            // MotionBenchMaker's ends are grasps: some sit closer than a centimetre to the
            // object, and are refused by name.
            Err(e @ ArmError::EndWithinPadding { .. }) => {
                assert!(e.to_string().contains("padding (10 mm)"), "{e}");
                eprintln!("{robot} {scene} #{index}: {e}");
            }
            Err(e) => panic!("{robot} {scene} #{index}: {e}"),
        }
    }
    assert!(planned >= 4, "only {planned} problems planned");
}

#[test]
fn an_end_within_the_padding_is_refused_by_name() {
    let robot = panda();
    // A ball 5 mm from a sphere of the hand at the start: clear, but within 1 cm.
    let hand = robot
        .links()
        .iter()
        .position(|l| l.name == "panda_hand")
        .unwrap();
    let sphere = robot.link_sphere_range(hand).start;
    let ball = ball_near(&HOME, sphere, DVec3::Z, 0.005, 0.02);
    let mut goal = HOME;
    goal[0] = 1.0;
    let problem = ArmProblem::new(
        "near",
        robot,
        Scene::new(vec![ball]),
        HOME.to_vec(),
        goal.to_vec(),
    )
    .unwrap();
    assert!(problem.check_ends().is_ok());
    let padded = problem.clone().with_padding(Padding::new(0.01).unwrap());
    assert_eq!(padded.padding().metres(), 0.01);
    let e = padded.check_ends().unwrap_err();
    assert!(
        matches!(&e, ArmError::EndWithinPadding { what: "start", .. }),
        "{e}"
    );
    let text = e.to_string();
    assert!(
        text.contains("within the collision padding (10 mm)") && text.contains("obstacle0"),
        "{text}"
    );
    // Within the margin it is a collision, padding or not.
    let touching = ball_near(&HOME, sphere, DVec3::Z, -0.001, 0.02);
    let e = problem
        .with_scene(Scene::new(vec![touching]))
        .with_padding(Padding::new(0.01).unwrap())
        .check_ends()
        .unwrap_err();
    assert!(matches!(e, ArmError::EndInCollision { .. }), "{e}");
    // The diagnosis says which contacts are only the padding's.
    let padded_diagnosis = padded.diagnose(&HOME);
    assert!(padded_diagnosis.only_padding(), "{padded_diagnosis}");
    assert!(
        padded_diagnosis
            .to_string()
            .contains("within the padding (10 mm)"),
        "{padded_diagnosis}"
    );
}
