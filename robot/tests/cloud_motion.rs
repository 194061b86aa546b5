//! Point clouds as obstacles of the Panda: the checker's states against the `f64` reference,
//! certified edges among a random cloud audited by the independent `f64` audit (every point,
//! continuous), the diagnosis naming the cloud and the point, and a plan among a cloud.

use glam::{DVec3, Vec3};
use mit_star::{FirstSolution, Parameters, Planner, RrtConnect, TerminationExt, TimeLimit};
use mit_star_robot::{
    ArmChecker, ArmProblem, AuditVerdict, CloudObstacle, MotionAudit, ParryChecker, PointCloud,
    RobotModel, Scene, StateDiagnosis,
};
use mit_star_spaces::{Never, SeededRng, StateSpace};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};
use proptest::prelude::*;

use crate::arm_cases::{Graze, HOME, edge, graze, panda};

/// The surfaces of `boxes` boxes in front of the Panda, sampled at about `density` points a
/// box (a camera's view of a cluttered table, from a seed).
fn box_cloud(boxes: usize, density: usize, seed: u64) -> Vec<Vec3> {
    let mut rng = <SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(seed);
    let mut unit = || mit_star_spaces::rand::RngExt::random_range(&mut rng, -1.0_f32..1.0);
    let mut points = Vec::new();
    for _ in 0..boxes {
        let centre = Vec3::new(0.5 + 0.2 * unit(), 0.5 * unit(), 0.35 + 0.35 * unit());
        let half = Vec3::new(
            0.02 + 0.1 * unit().abs(),
            0.02 + 0.1 * unit().abs(),
            0.02 + 0.1 * unit().abs(),
        );
        for _ in 0..density {
            // A point on a random face.
            let mut p = Vec3::new(unit(), unit(), unit());
            let axis = (unit().abs() * 2.999) as usize;
            p[axis] = p[axis].signum();
            points.push(centre + p * half);
        }
    }
    points
}

/// `sheets` square sheets of points 0.5 m wide, `spacing` apart, at random places and
/// turns in the Panda's reach (walls a camera sees), from a seed.
fn sheet_cloud(sheets: usize, spacing: f32, seed: u64) -> Vec<Vec3> {
    let mut rng = <SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(seed);
    let mut unit = || mit_star_spaces::rand::RngExt::random_range(&mut rng, -1.0_f32..1.0);
    let mut points = Vec::new();
    let steps = (0.5 / spacing) as i32;
    for _ in 0..sheets {
        let centre = Vec3::new(0.4 + 0.25 * unit(), 0.4 * unit(), 0.45 + 0.3 * unit());
        let normal = Vec3::new(unit(), unit(), unit()).normalize_or(Vec3::X);
        let u = normal.any_orthonormal_vector();
        let v = normal.cross(u);
        for i in 0..=steps {
            for j in 0..=steps {
                let (a, b) = (i as f32 * spacing - 0.25, j as f32 * spacing - 0.25);
                points.push(centre + a * u + b * v);
            }
        }
    }
    points
}

fn cloud_scene(points: Vec<Vec3>) -> Scene {
    let cloud = PointCloud::new(points).unwrap();
    Scene::new(vec![]).with_cloud(CloudObstacle::new("camera", cloud))
}

fn certify(checker: &ArmChecker, robot: &RobotModel, a: &[f64], b: &[f64]) -> EdgeStatus {
    let mut progress = MotionProgress::default();
    checker
        .certify_motion(robot.joint_space(), a, b, &mut progress, &Never)
        .unwrap()
}

fn random_state(robot: &RobotModel, rng: &mut SeededRng) -> Vec<f64> {
    let mut q = vec![0.0; 7];
    robot.joint_space().sample_uniform(rng, &mut q);
    q
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// Single states and batches: the checker's verdict is the reference's wherever the
    /// reference is decided by more than 0.1 mm either way, and never valid where the
    /// reference finds a contact.
    #[test]
    fn states_among_a_cloud_agree_with_the_reference(
        boxes in 1..5_usize,
        density in 50..800_usize,
        seed in any::<u64>(),
    ) {
        let robot = panda();
        let scene = cloud_scene(box_cloud(boxes, density, seed));
        let checker = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        let mut rng = <SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(seed);
        let states: Vec<f64> = (0..64).flat_map(|_| random_state(&robot, &mut rng)).collect();
        let mut batched = vec![false; 64];
        checker.are_valid(&states, 7, &mut batched);
        let mut invalid = 0;
        for (q, &together) in states.chunks(7).zip(&batched) {
            let fast = checker.is_valid(q);
            prop_assert_eq!(fast, together);
            if fast {
                prop_assert!(reference.is_valid(q), "{:?}", q);
            }
            if reference.is_valid_with_margin(q, 1e-4) == reference.is_valid_with_margin(q, -1e-4) {
                prop_assert_eq!(fast, reference.is_valid(q), "{:?}", q);
            }
            invalid += usize::from(!fast);
        }
        let first = checker.first_invalid(&states, 7);
        prop_assert_eq!(first, batched.iter().position(|v| !v));
        prop_assert!(invalid < 64);
    }

    /// A checker among a cloud with affordances (for the Panda's largest sphere) decides
    /// every state as one among the same cloud without: one at a time (one lane, answered
    /// by the affordances), in batches (the tree) and the first invalid of a batch.
    #[test]
    fn affordances_change_no_state_decision(
        boxes in 1..5_usize,
        density in 50..800_usize,
        seed in any::<u64>(),
    ) {
        let robot = panda();
        let points = box_cloud(boxes, density, seed);
        let plain = ArmChecker::new(&robot, &cloud_scene(points.clone()));
        let cloud = PointCloud::new(points).unwrap();
        let afforded = Scene::new(vec![])
            .with_cloud(CloudObstacle::new("camera", cloud).with_affordances(0.0801));
        prop_assert!(afforded.clouds()[0].affordances().is_some());
        let fast = ArmChecker::new(&robot, &afforded);
        let mut rng = <SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(seed);
        let states: Vec<f64> = (0..48).flat_map(|_| random_state(&robot, &mut rng)).collect();
        let (mut a, mut b) = (vec![false; 48], vec![false; 48]);
        plain.are_valid(&states, 7, &mut a);
        fast.are_valid(&states, 7, &mut b);
        prop_assert_eq!(&a, &b);
        for (q, &expected) in states.chunks(7).zip(&a) {
            prop_assert_eq!(fast.is_valid(q), expected, "{:?}", q);
        }
        prop_assert_eq!(fast.first_invalid(&states, 7), plain.first_invalid(&states, 7));
    }

    /// Certified edges among a random cloud (planner-free): the independent audit (`f64`,
    /// every point, continuous) finds no configuration of them within a point's radius of a
    /// point, and measures every sphere clear of every point's ball by half the checker's
    /// margin or more.
    #[test]
    fn certified_edges_among_a_cloud_pass_the_audit(
        sheets in 1..4_usize,
        spacing in 0.005..0.03_f32,
        seed in any::<u64>(),
    ) {
        let found = certify_and_audit(sheets, spacing, seed);
        prop_assert_eq!(&found.failure, &None);
        prop_assert!(found.undecided <= found.certified / 2 + 1, "{:?}", found);
    }
}

proptest! {
    // About four draws are set aside for each case run (a sphere barely moving, the nearest
    // point bulged over by another sphere, an end in collision): room for many more cases.
    #![proptest_config(ProptestConfig { max_global_rejects: 1 << 14, ..ProptestConfig::with_cases(64) })]

    /// Grazes among a cloud, where the bound from each point's rate of approach matters: a
    /// patch of points, `spacing` apart in the plane across a sphere's motion at a point of a
    /// random edge, its nearest point's ball `depth` beyond the sphere (negative: into it).
    /// Certified ⇒ the audit finds every sphere clear of every point's ball by half the
    /// margin or more (half the cases graze within 0.1 mm of contact); a ball reaching 0.2 mm
    /// into the path is never certified.
    #[test]
    fn grazing_points_are_judged_exactly(
        (a, b) in edge(),
        at in 0.15..0.85_f64,
        depth in prop_oneof![-1e-3..4e-3_f64, 0.0..1e-4_f64],
        pick in 0..1000_usize,
        turn in 0.0..std::f64::consts::TAU,
        spacing in 0.002..0.02_f64,
    ) {
        let robot = panda();
        let graze = graze(&robot, (&a, &b), at, pick, turn);
        prop_assume!(graze.is_some());
        let Graze { centres, index, across } = graze.unwrap();
        let (c, r) = centres[index];
        // The patch: a disc of 3 cm in the plane tangent to the sphere (grown by `depth` and
        // the points' radius) across the motion; its centre is its point nearest the sphere.
        let nearest = c + across * (r + PointCloud::DEFAULT_RADIUS + depth);
        let v = across.any_orthonormal_vector();
        let w = across.cross(v);
        let steps = (0.03 / spacing) as i32;
        let mut points = Vec::new();
        for j in -steps..=steps {
            for k in -steps..=steps {
                let offset = v * (f64::from(j) * spacing) + w * (f64::from(k) * spacing);
                let p = nearest + offset;
                // Only where the grazing sphere is the nearest to the point at `at` (others of
                // the link bulge towards the plane elsewhere).
                let own = p.distance(c) - r;
                let nearest_sphere = centres
                    .iter()
                    .enumerate()
                    .all(|(s, &(centre, radius))| s == index || p.distance(centre) - radius > own);
                if offset.length() <= 0.03 && nearest_sphere {
                    points.push(p.as_vec3());
                }
            }
        }
        // The disc's centre, the point nearest the sphere, is kept.
        prop_assume!(points.contains(&nearest.as_vec3()));
        let scene = cloud_scene(points);
        let checker = ArmChecker::new(&robot, &scene);
        prop_assume!(checker.is_valid(&a) && checker.is_valid(&b));
        if certify(&checker, &robot, &a, &b) == EdgeStatus::Valid {
            prop_assert!(depth > -2e-4, "a point {depth} m into the path was certified");
            match MotionAudit::new(&robot, &scene).audit(&a, &b, 200_000) {
                AuditVerdict::Clear { clearance, .. } => prop_assert!(
                    clearance >= 0.5 * checker.margin(),
                    "certified edge clear by {clearance}"
                ),
                AuditVerdict::Collides { contact, t, .. } => {
                    prop_assert!(false, "certified edge collides at {t}: {contact}");
                }
                AuditVerdict::Undecided { .. } => {}
            }
        }
    }
}

/// What [`certify_and_audit`] found.
#[derive(Debug, Default)]
struct Audited {
    certified: usize,
    refused: usize,
    undecided: usize,
    failure: Option<String>,
}

/// Sixteen random edges of at most 1.5 rad among `sheets` sheets of points: each with valid
/// ends certified, and each certified one audited.
fn certify_and_audit(sheets: usize, spacing: f32, seed: u64) -> Audited {
    let robot = panda();
    let scene = cloud_scene(sheet_cloud(sheets, spacing, seed));
    let checker = ArmChecker::new(&robot, &scene);
    let audit = MotionAudit::new(&robot, &scene);
    let mut rng = <SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(seed ^ 5);
    let mut found = Audited::default();
    for _ in 0..16 {
        let a = random_state(&robot, &mut rng);
        let mut b = random_state(&robot, &mut rng);
        // Edges of at most 1.5 rad, as planners' extensions are.
        let length = mit_star_spaces::euclidean_distance(&a, &b);
        if length > 1.5 {
            for (x, y) in b.iter_mut().zip(&a) {
                *x = y + (*x - y) * 1.5 / length;
            }
        }
        if !(checker.is_valid(&a) && checker.is_valid(&b)) {
            continue;
        }
        match certify(&checker, &robot, &a, &b) {
            EdgeStatus::Valid => {
                found.certified += 1;
                match audit.audit(&a, &b, 200_000) {
                    AuditVerdict::Clear { clearance, .. } => {
                        if clearance < 0.5 * checker.margin() {
                            found.failure = Some(format!("certified edge clear by {clearance}"));
                        }
                    }
                    AuditVerdict::Collides { contact, t, .. } => {
                        found.failure = Some(format!("certified edge collides at {t}: {contact}"));
                    }
                    AuditVerdict::Undecided { .. } => found.undecided += 1,
                }
            }
            EdgeStatus::Invalid => found.refused += 1,
            EdgeStatus::Unknown => found.failure = Some("unknown without a stop".into()),
        }
    }
    found
}

/// The random edges are a real test: over a few seeds, some are certified and some refused
/// (sheets in their way).
#[test]
fn random_edges_among_sheets_are_both_certified_and_refused() {
    let (mut certified, mut refused) = (0, 0);
    for seed in 0..12 {
        let found = certify_and_audit(3, 0.01, seed);
        assert_eq!(found.failure, None, "seed {seed}");
        certified += found.certified;
        refused += found.refused;
    }
    assert!(
        certified > 20 && refused > 2,
        "{certified} certified, {refused} refused"
    );
}

/// A cloud point on the hand's sphere at `HOME`: the diagnosis names the link, the cloud and
/// the point; far away, the cloud is only the nearest obstacle.
#[test]
fn the_diagnosis_names_the_cloud_and_the_point() {
    let robot = panda();
    let fk = mit_star_robot::Kinematics::new(&robot);
    let mut poses = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(&HOME, &mut poses, &mut centres);
    let hand = robot
        .links()
        .iter()
        .position(|l| l.name == "panda_hand")
        .unwrap();
    let at = centres[robot.link_sphere_range(hand).start].0.as_vec3();
    let mut points = box_cloud(1, 50, 1)
        .into_iter()
        .map(|p| p + Vec3::new(2.0, 0.0, 0.0))
        .collect::<Vec<_>>();
    points.insert(17, at);
    let scene = cloud_scene(points.clone());
    let checker = ArmChecker::new(&robot, &scene);
    assert!(!checker.is_valid(&HOME));
    let d = StateDiagnosis::of(&robot, &scene, &checker, &HOME);
    assert!(!d.valid, "{d}");
    assert!(
        d.scene
            .iter()
            .any(|c| c.link == "panda_hand" && c.other == "camera point 17"),
        "{d}"
    );
    assert!(d.to_string().contains("camera point 17"), "{d}");
    points.remove(17);
    let scene = cloud_scene(points);
    let checker = ArmChecker::new(&robot, &scene);
    let d = StateDiagnosis::of(&robot, &scene, &checker, &HOME);
    assert!(d.valid && d.scene.is_empty(), "{d}");
    assert!(d.nearest.unwrap().other.starts_with("camera point "));
}

/// RRT-Connect plans among a cloud of a cluttered table (primitives and a cloud together),
/// and every edge of its path passes the independent audit.
#[test]
fn a_plan_among_a_cloud_passes_the_audit() {
    let robot = panda();
    let table = mit_star_robot::Obstacle::new(
        mit_star_robot::Shape::Cuboid {
            half_extents: DVec3::new(0.3, 0.6, 0.02),
        },
        DVec3::new(0.6, 0.0, -0.03),
        glam::DQuat::IDENTITY,
    );
    // A wall of points between the start and the goal.
    let wall: Vec<Vec3> = (0..40)
        .flat_map(|i| {
            (0..30).map(move |j| Vec3::new(0.5, -0.05 + 0.01 * i as f32, 0.02 * j as f32))
        })
        .collect();
    let scene = Scene::new(vec![table])
        .with_cloud(CloudObstacle::new("wall", PointCloud::new(wall).unwrap()));
    let start = vec![-0.8, 0.3, 0.0, -1.8, 0.0, 2.0, 0.785];
    let goal = vec![0.8, 0.3, 0.0, -1.8, 0.0, 2.0, 0.785];
    let problem = ArmProblem::new("wall", robot.clone(), scene.clone(), start, goal).unwrap();
    assert!(problem.ends_are_valid());
    let parameters = Parameters {
        seed: 3,
        ..Parameters::default()
    };
    let mut planner = RrtConnect::for_problem(&problem, &parameters).unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(60.0)))
        .unwrap();
    let solution = outcome.solution().expect("solved among the cloud");
    let audit = MotionAudit::new(&robot, &scene);
    let path: Vec<Vec<f64>> = solution.path.iter().map(<[f64]>::to_vec).collect();
    assert!(path.len() >= 2);
    for pair in path.windows(2) {
        let verdict = audit.audit(&pair[0], &pair[1], 1_000_000);
        assert!(matches!(verdict, AuditVerdict::Clear { .. }), "{verdict:?}");
    }
}
