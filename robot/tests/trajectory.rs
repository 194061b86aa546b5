//! Timed paths keep their limits and their certification: random polylines timed with and
//! without blends never exceed a velocity or acceleration limit (dense evaluation), start and
//! end at rest at the path's ends, stop on every waypoint when asked to; blended trajectories
//! of planned Panda paths pass the continuous check; bad inputs are refused by name.

use std::path::Path;
use std::time::Duration;

use mit_star::PathSimplifier;

use crate::arm_cases::first_mbm_path;
use mit_star_robot::{
    ArmChecker, ArmProblem, BlendCertifier, JointLimitsYaml, MotionLimits, PANDA_JOINT_LIMITS,
    Scene, Trajectory, TrajectoryError, TrajectoryFile, Violation, check_trajectory,
};
use mit_star_spaces::StateSpace;
use proptest::prelude::*;

/// The Panda's limits: the URDF's velocities, MoveIt's accelerations, scaled.
fn panda_limits(velocity: f64, acceleration: f64) -> MotionLimits {
    let yaml = JointLimitsYaml::parse(PANDA_JOINT_LIMITS, "panda").unwrap();
    MotionLimits::for_robot(&ArmProblem::panda().unwrap(), Some(&yaml), None)
        .unwrap()
        .scaled(velocity, acceleration)
        .unwrap()
}

/// Whether `trajectory` keeps `limits` (relative 1e-9) at `count` evenly spread times and
/// just either side of every knot, and starts and ends at rest at `path`'s ends.
fn keeps_limits(
    trajectory: &Trajectory,
    limits: &MotionLimits,
    path: &[Vec<f64>],
    count: usize,
) -> Result<(), TestCaseError> {
    let duration = trajectory.duration();
    prop_assert!(duration > 0.0 && duration.is_finite());
    let mut times: Vec<f64> = (0..=count)
        .map(|i| duration * i as f64 / count as f64)
        .collect();
    for k in trajectory.knots() {
        times.extend([k.time, k.time * (1.0 - 1e-12), k.time * (1.0 + 1e-12)]);
    }
    for t in times {
        let s = trajectory.evaluate(t);
        for j in 0..limits.names().len() {
            prop_assert!(
                s.velocity[j].abs() <= limits.velocity()[j] * (1.0 + 1e-9),
                "velocity {} at {t}",
                s.velocity[j]
            );
            prop_assert!(
                s.acceleration[j].abs() <= limits.acceleration()[j] * (1.0 + 1e-9),
                "acceleration {} at {t}",
                s.acceleration[j]
            );
        }
    }
    let (first, last) = (trajectory.evaluate(0.0), trajectory.evaluate(duration));
    prop_assert_eq!(&first.position, &path[0]);
    prop_assert_eq!(&last.position, &path[path.len() - 1]);
    prop_assert!(
        first
            .velocity
            .iter()
            .chain(&last.velocity)
            .all(|v| *v == 0.0)
    );
    Ok(())
}

/// Random polylines of the Panda within its joint limits: 2 to 7 waypoints.
fn polyline() -> impl Strategy<Value = Vec<Vec<f64>>> {
    let space = ArmProblem::panda().unwrap().joint_space().clone();
    let (lower, upper) = (space.lower().to_vec(), space.upper().to_vec());
    let point = (0..7).map(|j| lower[j]..upper[j]).collect::<Vec<_>>();
    prop::collection::vec(point, 2..7)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn stopping_keeps_the_limits_and_every_waypoint(
        path in polyline(),
        scale in (0.05..=1.0_f64, 0.05..=1.0_f64),
    ) {
        let limits = panda_limits(scale.0, scale.1);
        let trajectory = Trajectory::stop_at_corners(&path, &limits).unwrap();
        keeps_limits(&trajectory, &limits, &path, 2000)?;
        // Every waypoint is a knot at rest, in order.
        let mut knots = trajectory.knots().iter();
        for w in &path {
            prop_assert!(knots.any(|k| &k.position == w && k.velocity.iter().all(|v| *v == 0.0)), "waypoint {w:?} missed");
        }
        // The checker's rules hold at the knots (sampled straight lines are the segments).
        let file = TrajectoryFile::of(&trajectory, None).unwrap();
        for w in file.samples.windows(2) {
            prop_assert!(w[1].time > w[0].time);
        }
    }

    #[test]
    fn blending_keeps_the_limits_and_is_no_slower(
        path in polyline(),
        scale in (0.05..=1.0_f64, 0.05..=1.0_f64),
    ) {
        let limits = panda_limits(scale.0, scale.1);
        let robot = ArmProblem::panda().unwrap();
        let certifier = BlendCertifier::new(&robot, &Scene::default());
        let (blended, report) = Trajectory::blended(&path, &limits, &certifier).unwrap();
        keeps_limits(&blended, &limits, &path, 2000)?;
        let stopping = Trajectory::stop_at_corners(&path, &limits).unwrap();
        prop_assert!(blended.duration() <= stopping.duration());
        prop_assert_eq!(report.blended + report.shrunk + report.stopped, path.len() - 2);
    }
}

/// Blended trajectories of planned and simplified Panda paths: every blend certified, the
/// trajectory sampled every millisecond passes `check_trajectory` (limits, continuity, and
/// the continuous collision check between samples), and it is faster than stopping.
#[test]
fn blended_panda_trajectories_pass_the_check() {
    let mut blends = 0;
    for (scene, seed) in [
        ("cage_panda", 3),
        ("bookshelf_small_panda", 5),
        ("table_pick_panda", 7),
    ] {
        let (problem, path) = first_mbm_path(scene, seed);
        let simplified = PathSimplifier::new()
            .seed(seed)
            .simplify(
                &problem,
                &path,
                &mit_star_spaces::Deadline::after(Duration::from_secs(1)),
            )
            .unwrap();
        let path = mit_star_robot::merge_repeated_waypoints(&simplified.path);
        let limits = panda_limits(1.0, 1.0);
        let certifier = BlendCertifier::new(problem.robot(), problem.scene());
        let (trajectory, report) = Trajectory::blended(&path, &limits, &certifier).unwrap();
        blends += report.blended + report.shrunk;
        let file = TrajectoryFile::of(&trajectory, Some(1e-3)).unwrap();
        let checker = ArmChecker::new(problem.robot(), problem.scene());
        let check =
            check_trajectory(&file, problem.robot(), problem.scene(), &limits, &checker).unwrap();
        assert!(check.is_valid(), "{scene}: {:?}", check.violations);
        assert!(check.velocity_excess <= 1e-9 && check.acceleration_excess <= 1e-9);
        if path.len() > 2 {
            let stopping = Trajectory::stop_at_corners(&path, &limits).unwrap();
            assert!(trajectory.duration() < stopping.duration(), "{scene}");
        }
    }
    assert!(blends > 0, "no corner was blended");
}

/// A blend through an obstacle is refused: a small ball where the fingertip passes in the
/// middle of a corner's blend (timed in free space), beside the segments, makes the certifier
/// refuse that blend; the trajectory shrinks it (or stops) and passes the check.
#[test]
fn a_blend_through_an_obstacle_is_refused() {
    let robot = ArmProblem::panda().unwrap();
    let home = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
    let mut corner = home;
    corner[0] += 1.5;
    let mut end = corner;
    end[1] += 0.8;
    let path = [home.to_vec(), corner.to_vec(), end.to_vec()];
    let limits = panda_limits(1.0, 1.0);
    let free = BlendCertifier::new(&robot, &Scene::default());
    let (timed, report) = Trajectory::blended(&path, &limits, &free).unwrap();
    assert_eq!(report.blended, 1, "{report:?}");
    // The middle of the blend: the knot whose velocity turns from the first segment's
    // direction to the second's.
    let knots = timed.knots();
    let blend = knots
        .windows(2)
        .find(|w| w[0].velocity[0] != 0.0 && w[1].velocity[1] != 0.0 && w[0].acceleration[1] != 0.0)
        .expect("a blend");
    let middle = timed.evaluate(0.5 * (blend[0].time + blend[1].time));
    let fk = mit_star_robot::Kinematics::new(&robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(glam::DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(&middle.position, &mut links, &mut centers);
    // A 5 mm ball at the centre of one of the robot's spheres in the middle of the blend, or
    // as far again from where it is at the corner: the first (from the hand down) that
    // leaves both segments certified.
    let middles = centers.clone();
    fk.sphere_centers_f64(&corner, &mut links, &mut centers);
    let segments_clear = |scene: &Scene| {
        let checker = ArmChecker::new(&robot, scene);
        path.windows(2).all(|w| {
            let mut progress = mit_star_validity::MotionProgress::default();
            mit_star_validity::StateValidity::certify_motion(
                &checker,
                robot.joint_space(),
                &w[0],
                &w[1],
                &mut progress,
                &mit_star_spaces::Never,
            ) == Some(mit_star_validity::EdgeStatus::Valid)
        })
    };
    assert!(segments_clear(&Scene::default()), "segments in free space");
    let scene = middles
        .iter()
        .zip(&centers)
        .rev()
        .flat_map(|(&(mid, _), &(at_corner, _))| [mid, 2.0 * mid - at_corner])
        .map(|at| {
            Scene::new(vec![mit_star_robot::Obstacle::new(
                mit_star_robot::Shape::Sphere { radius: 0.005 },
                at,
                glam::DQuat::IDENTITY,
            )])
        })
        .find(|scene| segments_clear(scene))
        .expect("a ball beside the segments");
    let checker = ArmChecker::new(&robot, &scene);
    let blocked = BlendCertifier::new(&robot, &scene);
    let (trajectory, report) = Trajectory::blended(&path, &limits, &blocked).unwrap();
    assert_eq!(report.blended, 0, "{report:?}");
    assert_eq!(report.shrunk + report.stopped, 1);
    let file = TrajectoryFile::of(&trajectory, Some(1e-3)).unwrap();
    let check = check_trajectory(&file, &robot, &scene, &limits, &checker).unwrap();
    assert!(check.is_valid(), "{:?}", check.violations);
    // The free-space timing, through the ball, fails the same check.
    let file = TrajectoryFile::of(&timed, Some(1e-3)).unwrap();
    let check = check_trajectory(&file, &robot, &scene, &limits, &checker).unwrap();
    assert!(
        check
            .violations
            .iter()
            .any(|v| matches!(v, Violation::Collision { .. }))
    );
}

#[test]
fn bad_inputs_are_refused_by_name() {
    let limits = panda_limits(1.0, 1.0);
    let home = vec![0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
    assert_eq!(
        Trajectory::stop_at_corners(std::slice::from_ref(&home), &limits),
        Err(TrajectoryError::TooShort { points: 1 })
    );
    assert_eq!(
        Trajectory::stop_at_corners(&[home.clone(), home.clone()], &limits),
        Err(TrajectoryError::RepeatedWaypoint { index: 1 })
    );
    let mut nan = home.clone();
    nan[3] = f64::NAN;
    assert!(matches!(
        Trajectory::stop_at_corners(&[home, nan], &limits),
        Err(TrajectoryError::NotFinite { index: 1, joint, .. }) if joint == "panda_joint4"
    ));
    for scale in [0.0, -0.5, 1.01, f64::NAN] {
        assert!(matches!(
            limits.clone().scaled(1.0, scale),
            Err(TrajectoryError::BadScaling {
                what: "acceleration",
                ..
            })
        ));
    }
    let yaml = JointLimitsYaml::parse(
        "joint_limits:\n  elbow: {has_acceleration_limits: true, max_acceleration: 1}\n",
        "t",
    )
    .unwrap();
    assert_eq!(
        MotionLimits::for_robot(&ArmProblem::panda().unwrap(), Some(&yaml), None),
        Err(TrajectoryError::UnknownJoint {
            joint: "elbow".into()
        })
    );
    assert!(matches!(
        MotionLimits::for_robot(&ArmProblem::panda().unwrap(), None, None),
        Err(TrajectoryError::MissingLimit { joint, what: "acceleration", .. }) if joint == "panda_joint1"
    ));
    let yaml = JointLimitsYaml::parse(
        "joint_limits:\n  panda_joint6: {has_velocity_limits: true, max_velocity: 0}\n",
        "t",
    )
    .unwrap();
    assert!(matches!(
        MotionLimits::for_robot(&ArmProblem::panda().unwrap(), Some(&yaml), Some(2.0)),
        Err(TrajectoryError::BadLimit { joint, what: "velocity", .. }) if joint == "panda_joint6"
    ));
}

/// The check catches what is wrong with a file: times going backwards (an error), a velocity
/// beyond its limit and a jump in position (violations); the files round-trip.
#[test]
fn the_check_catches_tampering() {
    let problem = ArmProblem::panda_mbm(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm/table_pick_panda"),
        1,
    )
    .unwrap();
    let limits = panda_limits(1.0, 1.0);
    let home = vec![0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
    let mut away = home.clone();
    away[6] += 0.5;
    let trajectory = Trajectory::stop_at_corners(&[home, away], &limits).unwrap();
    let file = TrajectoryFile::of(&trajectory, Some(0.01)).unwrap();
    let dir = std::env::temp_dir().join(format!("trajectory-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for name in ["t.json", "t.csv"] {
        file.write(&dir.join(name)).unwrap();
        assert_eq!(TrajectoryFile::read(&dir.join(name)).unwrap(), file);
    }
    let checker = ArmChecker::new(problem.robot(), problem.scene());
    let check = |f: &TrajectoryFile| {
        check_trajectory(f, problem.robot(), problem.scene(), &limits, &checker)
    };
    assert!(check(&file).unwrap().is_valid());
    let mut backwards = file.clone();
    backwards.samples[5].time = backwards.samples[3].time;
    assert!(matches!(
        check(&backwards),
        Err(TrajectoryError::TimeNotIncreasing { index: 5, .. })
    ));
    let mut fast = file.clone();
    fast.samples[10].velocity[6] = 1.5 * limits.velocity()[6];
    let found = check(&fast).unwrap();
    assert!(found.violations.iter().any(|v| matches!(
        v,
        Violation::Limit {
            sample: 10,
            what: "velocity",
            ..
        }
    )));
    let mut jump = file;
    jump.samples[20].position[6] += 0.05;
    let found = check(&jump).unwrap();
    assert!(found.violations.iter().any(|v| matches!(
        v,
        Violation::Discontinuity {
            sample: 20,
            what: "position",
            ..
        }
    )));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A long path (300 waypoints of small random steps, as an unsimplified planner path or a
/// dense smoothing gives) is timed blended within the limits, no slower than stopping.
#[test]
fn a_long_path_is_timed_within_the_limits() {
    let robot = ArmProblem::panda().unwrap();
    let space = robot.joint_space();
    let mut at = vec![0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
    let mut path = vec![at.clone()];
    while path.len() < 300 {
        let i = path.len() as f64;
        for (j, q) in at.iter_mut().enumerate() {
            // Steps of up to 0.05 rad that turn irregularly (no two joints in phase).
            let step = 0.05 * (1.7 * i + 2.3 * j as f64).sin() * (0.37 * i * (j + 1) as f64).cos();
            *q = (*q + step).clamp(space.lower()[j], space.upper()[j]);
        }
        path.push(at.clone());
    }
    let path = mit_star_robot::merge_repeated_waypoints(&path);
    let limits = panda_limits(1.0, 1.0);
    let started = std::time::Instant::now();
    let certifier = BlendCertifier::new(&robot, &Scene::default());
    let (blended, _) = Trajectory::blended(&path, &limits, &certifier).unwrap();
    eprintln!("300 waypoints timed in {:?}", started.elapsed());
    let stopping = Trajectory::stop_at_corners(&path, &limits).unwrap();
    assert!(blended.duration() <= stopping.duration());
    let result = keeps_limits(&blended, &limits, &path, 20_000);
    assert!(result.is_ok(), "{result:?}");
}
