//! Inverse kinematics on the shipped arms: forward kinematics of random valid configurations
//! solved back from other starts (the solution's pose recomputed by the full `f64` forward
//! kinematics, its limits and its validity checked), every tolerance kind respected by what
//! is returned, distinct goals from a [`PoseGoal`], and every bad input refused by name.

use std::f64::consts::PI;

use glam::{DAffine3, DQuat, DVec3};
use mit_star_robot::{
    ArmChecker, IkError, IkSolver, Kinematics, OrientationTolerance, PoseGoal, PoseTarget,
    PositionTolerance, RobotModel, Scene, ShippedRobot,
};
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::StateValidity;
use proptest::prelude::*;

fn panda() -> RobotModel {
    ShippedRobot::find("panda").unwrap().model(false).unwrap()
}

/// A random configuration `checker` accepts, drawn from `seed`.
fn valid_configuration(model: &RobotModel, checker: &ArmChecker, seed: u64) -> Vec<f64> {
    let mut rng = SeededRng::seed_from_u64(seed);
    let mut q = vec![0.0; model.joint_names().len()];
    loop {
        model.joint_space().sample_uniform(&mut rng, &mut q);
        if checker.is_valid(&q) {
            return q;
        }
    }
}

/// The world pose of `link` at `q`, by the full walk (not the solver's chain walk).
fn link_pose(model: &RobotModel, link: &str, q: &[f64]) -> DAffine3 {
    let fk = Kinematics::new(model);
    let mut poses = vec![DAffine3::IDENTITY; fk.link_count()];
    fk.link_poses_f64(q, &mut poses);
    poses[model.link_index(link).unwrap()]
}

/// The rotation angle between two orientations.
fn angle(a: &DAffine3, b: &DAffine3) -> f64 {
    let q = DQuat::from_mat3(&(a.matrix3 * b.matrix3.transpose()));
    2.0 * DVec3::new(q.x, q.y, q.z).length().atan2(q.w.abs())
}

/// Solves `target` for `link` from a random start drawn from `seed`, checking what every
/// solution must satisfy: within limits and valid by the checker.
fn solve(model: &RobotModel, link: &str, target: &PoseTarget, seed: u64) -> Vec<f64> {
    let checker = ArmChecker::new(model, &Scene::new(Vec::new()));
    // Enough restarts that the rare hard pose (a wrist near a singularity, a solution
    // region mostly in self-collision) does not make the test flaky.
    let mut solver = IkSolver::new(model, link).unwrap().seed(seed).restarts(500);
    let mut start = vec![0.0; model.joint_names().len()];
    let mut rng = SeededRng::seed_from_u64(seed.wrapping_add(17));
    model.joint_space().sample_uniform(&mut rng, &mut start);
    let solution = solver
        .solve(target, &start, &checker, &mit_star_spaces::Never)
        .unwrap_or_else(|e| panic!("{e}: {target:?}"));
    let q = solution.configuration;
    assert!(model.joint_space().contains(&q), "{q:?} outside the limits");
    assert!(checker.is_valid(&q), "{q:?} refused by the checker");
    q
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn panda_poses_are_solved_back_from_other_starts(seed in any::<u64>()) {
        let model = panda();
        let checker = ArmChecker::new(&model, &Scene::new(Vec::new()));
        let q = valid_configuration(&model, &checker, seed);
        let pose = link_pose(&model, "panda_hand", &q);
        let target = PoseTarget::from_pose(&pose).unwrap();
        let s = solve(&model, "panda_hand", &target, seed ^ 0x5555);
        let reached = link_pose(&model, "panda_hand", &s);
        prop_assert!((reached.translation - pose.translation).length() <= 1e-5);
        prop_assert!(angle(&reached, &pose) <= 1e-4);
    }

    #[test]
    fn a_tool_frame_is_placed_and_a_prismatic_torso_moves(seed in any::<u64>()) {
        // Fetch with its torso (a prismatic joint) planned, and a fingertip tool offset.
        let model = ShippedRobot::find("fetch").unwrap().model(false).unwrap();
        let checker = ArmChecker::new(&model, &Scene::new(Vec::new()));
        let tool = DAffine3::from_rotation_translation(
            DQuat::from_rotation_y(0.3),
            DVec3::new(0.15, 0.0, 0.02),
        );
        let q = valid_configuration(&model, &checker, seed);
        let pose = link_pose(&model, "gripper_link", &q) * tool;
        let target = PoseTarget::from_pose(&pose).unwrap();
        let mut solver = IkSolver::new(&model, "gripper_link")
            .unwrap()
            .tool(tool)
            .unwrap()
            .seed(seed)
            .restarts(500);
        let s = solver
            .solve(&target, &model.default_configuration(), &checker, &mit_star_spaces::Never)
            .unwrap()
            .configuration;
        let reached = link_pose(&model, "gripper_link", &s) * tool;
        prop_assert!((reached.translation - pose.translation).length() <= 1e-5);
        prop_assert!(angle(&reached, &pose) <= 1e-4);
        prop_assert!(checker.is_valid(&s) && model.joint_space().contains(&s));
    }

    #[test]
    fn tolerances_are_respected_by_the_solutions(
        seed in any::<u64>(),
        tilt in 0.0..0.3_f64,
        spin in -PI..PI,
        half_angle in 0.02..0.4_f64,
        offset in prop::array::uniform3(-1.0..1.0_f64),
        extents in prop::array::uniform3(0.0..0.05_f64),
    ) {
        let model = panda();
        let checker = ArmChecker::new(&model, &Scene::new(Vec::new()));
        let q = valid_configuration(&model, &checker, seed);
        let pose = link_pose(&model, "panda_hand", &q);
        let rotation = DQuat::from_mat3(&pose.matrix3);
        // The target's z axis tilted (by at most the half-angle) and spun from the pose's:
        // the pose itself is inside the cone.
        let tilt = tilt.min(half_angle);
        let turned = rotation * DQuat::from_rotation_x(tilt) * DQuat::from_rotation_z(spin);
        let h = DVec3::from_array(extents);
        // The target position moved inside the box (in the target's frame).
        let inside = turned * (DVec3::from_array(offset) * h);
        let target = PoseTarget::new(pose.translation - inside, turned).unwrap()
            .with_position_tolerance(PositionTolerance::Box { half_extents: h }).unwrap()
            .with_orientation_tolerance(OrientationTolerance::Cone { axis: DVec3::Z, half_angle }).unwrap();
        let s = solve(&model, "panda_hand", &target, seed ^ 0xaaaa);
        let reached = link_pose(&model, "panda_hand", &s);
        let local = turned.inverse() * (reached.translation - target.position());
        prop_assert!((local.abs() - h).max_element() <= 1e-5, "{local} outside {h}");
        let axis_angle = (reached.matrix3 * DVec3::Z).angle_between(turned * DVec3::Z);
        prop_assert!(axis_angle <= half_angle + 1e-4, "{axis_angle} > {half_angle}");

        // A ball and a free axis: the distance and the axis are respected, spin is free.
        // Large enough to hold the pose's own position.
        let radius = inside.length() + extents[0];
        let target = PoseTarget::new(pose.translation - inside, turned).unwrap()
            .with_position_tolerance(PositionTolerance::Ball { radius }).unwrap()
            .with_orientation_tolerance(OrientationTolerance::FreeAxis { axis: DVec3::Z }).unwrap();
        // The pose's own z axis, so that the pose is inside.
        let target = PoseTarget::new(target.position(), rotation * DQuat::from_rotation_z(spin))
            .unwrap()
            .with_position_tolerance(target.position_tolerance()).unwrap()
            .with_orientation_tolerance(target.orientation_tolerance()).unwrap();
        let s = solve(&model, "panda_hand", &target, seed ^ 0x3333);
        let reached = link_pose(&model, "panda_hand", &s);
        prop_assert!((reached.translation - target.position()).length() <= radius + 1e-5);
        let axis_angle = (reached.matrix3 * DVec3::Z).angle_between(pose.matrix3 * DVec3::Z);
        prop_assert!(axis_angle <= 1e-4, "{axis_angle}");
    }
}

#[test]
fn a_pose_goal_gives_distinct_valid_solutions_deterministically() {
    let model = panda();
    let checker = ArmChecker::new(&model, &Scene::new(Vec::new()));
    let q = valid_configuration(&model, &checker, 11);
    let target = PoseTarget::from_pose(&link_pose(&model, "panda_hand", &q)).unwrap();
    let solutions = |seed| {
        let solver = IkSolver::new(&model, "panda_hand")
            .unwrap()
            .distinct_distance(0.3)
            .unwrap()
            .seed(seed);
        let mut goal = PoseGoal::new(solver, target)
            .with_start(&model.default_configuration())
            .unwrap();
        for _ in 0..4 {
            assert!(
                goal.next_solution(&checker, &mit_star_spaces::Never)
                    .is_some(),
                "{:?}",
                goal.last_failure()
            );
        }
        goal.solutions().to_vec()
    };
    let found = solutions(5);
    for (i, a) in found.iter().enumerate() {
        assert!(checker.is_valid(a));
        let pose = link_pose(&model, "panda_hand", a);
        assert!((pose.translation - target.position()).length() <= 1e-5);
        for b in &found[..i] {
            assert!(model.joint_space().distance(a, b) >= 0.3);
        }
    }
    assert_eq!(found, solutions(5), "the same seed, the same solutions");
}

#[test]
fn bad_inputs_are_refused_by_name() {
    let model = panda();
    let e = IkSolver::new(&model, "panda_wrist").unwrap_err();
    assert!(
        matches!(&e, IkError::UnknownLink { link, .. } if link == "panda_wrist"),
        "{e}"
    );
    assert!(e.to_string().contains("panda_hand"), "{e}");
    let e = IkSolver::new(&model, "panda_link0").unwrap_err();
    assert!(matches!(e, IkError::ImmovableLink { .. }), "{e}");
    for bad in [f64::NAN, -1.0, 0.0, 2.0] {
        let e = IkSolver::new(&model, "panda_hand")
            .unwrap()
            .damping(bad)
            .unwrap_err();
        assert!(e.to_string().contains("damping"), "{e}");
    }
    assert!(
        IkSolver::new(&model, "panda_hand")
            .unwrap()
            .iterations(0)
            .is_err()
    );
    assert!(
        IkSolver::new(&model, "panda_hand")
            .unwrap()
            .max_step(f64::INFINITY)
            .is_err()
    );
    assert!(
        IkSolver::new(&model, "panda_hand")
            .unwrap()
            .distinct_distance(-0.1)
            .is_err()
    );
    assert!(
        IkSolver::new(&model, "panda_hand")
            .unwrap()
            .accuracy(1e-6, 0.0)
            .is_err()
    );
    let scaled = DAffine3::from_scale(DVec3::splat(2.0));
    let e = IkSolver::new(&model, "panda_hand")
        .unwrap()
        .tool(scaled)
        .unwrap_err();
    assert!(matches!(e, IkError::BadTool { .. }), "{e}");

    let e = PoseTarget::new(DVec3::ZERO, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).unwrap_err();
    assert!(matches!(e, IkError::BadQuaternion { .. }), "{e}");
    let e = PoseTarget::new(DVec3::ZERO, DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0)).unwrap_err();
    assert!(matches!(e, IkError::BadQuaternion { .. }), "{e}");
    let target = PoseTarget::new(DVec3::new(0.4, 0.0, 0.4), DQuat::from_rotation_x(PI)).unwrap();
    let e = target
        .with_position_tolerance(PositionTolerance::Ball { radius: f64::NAN })
        .unwrap_err();
    assert!(e.to_string().contains("ball radius"), "{e}");
    let e = target
        .with_orientation_tolerance(OrientationTolerance::Cone {
            axis: DVec3::Z,
            half_angle: 4.0,
        })
        .unwrap_err();
    assert!(e.to_string().contains("cone half-angle"), "{e}");

    let mut solver = IkSolver::new(&model, "panda_hand").unwrap().restarts(3);
    let never = mit_star_spaces::Never;
    let e = solver
        .solve(&target, &[0.0; 6], &mit_star_validity::AllValid, &never)
        .unwrap_err();
    assert_eq!(
        e,
        IkError::WrongLength {
            expected: 7,
            got: 6
        }
    );
    let mut start = model.default_configuration();
    start[2] = f64::NAN;
    let e = solver
        .solve(&target, &start, &mit_star_validity::AllValid, &never)
        .unwrap_err();
    assert!(
        matches!(e, IkError::NonFiniteCoordinate { index: 2, .. }),
        "{e}"
    );
    assert!(
        PoseGoal::new(solver.clone(), target)
            .with_start(&[0.0])
            .is_err()
    );

    // Ten metres away: unreachable, with the best error reached.
    let far = PoseTarget::new(DVec3::new(10.0, 0.0, 0.0), DQuat::IDENTITY).unwrap();
    let start = model.default_configuration();
    match solver.solve(&far, &start, &mit_star_validity::AllValid, &never) {
        Err(IkError::Unreachable {
            attempts: 4,
            position_error,
            ..
        }) => {
            assert!(position_error > 8.0, "{position_error}");
        }
        other => panic!("{other:?}"),
    }
    // A checker refusing everything: converged attempts are counted as refused.
    struct Nothing;
    impl StateValidity for Nothing {
        fn is_valid(&self, _: &[f64]) -> bool {
            false
        }
    }
    let reachable = PoseTarget::from_pose(&solver.frame_pose(&start).unwrap()).unwrap();
    match solver.solve(&reachable, &start, &Nothing, &never) {
        Err(IkError::Unreachable {
            rejected,
            position_error,
            ..
        }) => {
            assert!(rejected >= 1 && position_error < 1e-5);
        }
        other => panic!("{other:?}"),
    }
    // A stop that has fired: stopped, and a pose goal says why it gave up.
    let stop = || true;
    let e = solver
        .solve(&far, &start, &mit_star_validity::AllValid, &stop)
        .unwrap_err();
    assert!(matches!(e, IkError::Stopped { .. }), "{e}");
    let mut goal = PoseGoal::new(solver, far);
    assert!(
        goal.next_solution(&mit_star_validity::AllValid, &stop)
            .is_none()
    );
    assert!(matches!(goal.last_failure(), Some(IkError::Stopped { .. })));
    assert!(goal.solutions().is_empty());
}

/// A planar arm of three continuous joints (no limits: coordinates wrap into `[-π, π]`):
/// positions in the plane, orientation free, solved back from starts a half-turn away.
#[test]
fn continuous_joints_wrap() {
    let sphere = r#"<collision><geometry><sphere radius="0.01"/></geometry></collision>"#;
    let joint = |i: usize, x: f64| {
        format!(
            r#"<joint name="j{i}" type="continuous"><parent link="l{i}"/><child link="l{}"/><origin xyz="{x} 0 0"/><axis xyz="0 0 1"/></joint>"#,
            i + 1
        )
    };
    let urdf = format!(
        r#"<robot name="planar">{}{}{}{}</robot>"#,
        (0..4)
            .map(|i| format!(r#"<link name="l{i}">{sphere}</link>"#))
            .collect::<String>(),
        joint(0, 0.0),
        joint(1, 0.5),
        joint(2, 0.4),
    );
    let model = RobotModel::from_urdf_str(&urdf).unwrap();
    let fk_tool = DAffine3::from_translation(DVec3::new(0.3, 0.0, 0.0));
    let mut solver = IkSolver::new(&model, "l3")
        .unwrap()
        .tool(fk_tool)
        .unwrap()
        .seed(4);
    for (q, start) in [
        ([3.0, 0.4, -2.5], [-3.0, 0.4, 2.5]),
        ([-3.1, -1.0, 2.0], [3.1, 1.0, -2.0]),
    ] {
        let pose = solver.frame_pose(&q).unwrap();
        let target = PoseTarget::new(pose.translation, DQuat::IDENTITY)
            .unwrap()
            .with_orientation_tolerance(OrientationTolerance::Free)
            .unwrap();
        let s = solver
            .solve(
                &target,
                &start,
                &mit_star_validity::AllValid,
                &mit_star_spaces::Never,
            )
            .unwrap()
            .configuration;
        assert!(s.iter().all(|x| x.abs() <= PI), "{s:?}");
        let reached = solver.frame_pose(&s).unwrap().translation;
        assert!(
            (reached - pose.translation).length() <= 1e-5,
            "{reached} {pose:?}"
        );
    }
}
