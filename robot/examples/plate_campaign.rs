//! `plate_campaign`: can a thin obstacle slip through the arm checker? Adversarial problems for
//! the Panda, each a plate 1–5 mm thick across the straight motion between its start and goal,
//! planned at every kind of resolution the tool accepts; every returned path is audited
//! independently and continuously in `f64` ([`mit_star_robot::MotionAudit`]).
//!
//! ```text
//! cargo run --release -p mit-star-robot --example plate_campaign               # 1 000 problems
//! cargo run --release -p mit-star-robot --example plate_campaign -- 200 7      # 200 problems, seed 7
//! ```
//!
//! Each problem: a random start and goal of the Panda at least 1 rad apart; a configuration
//! on the motion between them; one of its spheres, chosen at random; a plate 1–5 mm thick and
//! 4–30 cm wide centred on that sphere's centre, facing the way the sphere moves, so the straight
//! motion crosses it (ends touching the plate are drawn again). Each problem is planned by MIT*
//! (0.1 s, anytime) and RRT-Connect (to its first solution, at most 0.5 s) at every resolution
//! of the list below (the default 1/16 rad per unit, and 0.01, 0.05, 0.1, 0.2, 0.5, 0.999 of
//! the maximum extent), with certification on (the default). Then, as the control
//! that shows the audit has teeth, RRT-Connect plans the same problem with certification off
//! (`allowing_uncertified_motion`) at resolution 0.5 of the maximum extent.
//!
//! Prints the counts per resolution and planner; exits with code 1 if any certified path
//! failed the audit.

use std::collections::BTreeMap;

use glam::{DAffine3, DQuat, DVec3};
use mit_star::{
    Configuration, FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner,
};
use mit_star_robot::{ArmProblem, AuditVerdict, Kinematics, MotionAudit, Obstacle, Scene, Shape};
use mit_star_spaces::rand::{RngExt, SeedableRng};
use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::StateValidity;

const RESOLUTIONS: [Option<f64>; 7] = [
    None,
    Some(0.01),
    Some(0.05),
    Some(0.1),
    Some(0.2),
    Some(0.5),
    Some(0.999),
];

#[derive(Default)]
struct Tally {
    runs: u64,
    solved: u64,
    clear: u64,
    collides: u64,
    undecided: u64,
}

fn main() {
    let mut args = std::env::args().skip(1);
    let count: usize = args
        .next()
        .map_or(1000, |a| a.parse().expect("a problem count"));
    let seed: u64 = args.next().map_or(0, |a| a.parse().expect("a seed"));
    let robot = ArmProblem::panda().expect("the shipped Panda loads");
    let fk = Kinematics::new(&robot);
    let space = robot.joint_space().clone();
    let mut rng = SeededRng::seed_from_u64(seed);
    let mut tallies: BTreeMap<(String, &str), Tally> = BTreeMap::new();
    let mut failures = Vec::new();
    let mut thickness = (f64::INFINITY, 0.0_f64);
    let (mut links, mut centers) = (
        vec![DAffine3::IDENTITY; fk.link_count()],
        vec![(DVec3::ZERO, 0.0); fk.sphere_count()],
    );
    let mut made = 0;
    while made < count {
        // Ends: random, collision-free in the empty scene, at least 1 rad apart.
        let mut draw = || -> Vec<f64> {
            (0..7)
                .map(|j| rng.random_range(space.lower()[j]..space.upper()[j]))
                .collect()
        };
        let (start, goal) = (draw(), draw());
        if mit_star_spaces::euclidean_distance(&start, &goal) < 1.0 {
            continue;
        }
        let t = rng.random_range(0.2..0.8);
        let mut middle = vec![0.0; 7];
        space.interpolate(&start, &goal, t, &mut middle);
        let mut ahead = vec![0.0; 7];
        space.interpolate(&start, &goal, t + 1e-4, &mut ahead);
        fk.sphere_centers_f64(&ahead, &mut links, &mut centers);
        let later: Vec<DVec3> = centers.iter().map(|c| c.0).collect();
        fk.sphere_centers_f64(&middle, &mut links, &mut centers);
        let s = rng.random_range(0..centers.len());
        let (center, _) = centers[s];
        let velocity = later[s] - center;
        if velocity.length() < 1e-9 {
            continue;
        }
        let half_thickness = rng.random_range(0.0005..0.0025);
        let half_width = rng.random_range(0.02..0.15);
        // The plate's thin side (local y) along the sphere's motion.
        let facing = DQuat::from_rotation_arc(DVec3::Y, velocity.normalize());
        let plate = Obstacle::new(
            Shape::Cuboid {
                half_extents: DVec3::new(half_width, half_thickness, half_width),
            },
            center,
            facing,
        );
        let name = format!("plate{made:04}");
        let Ok(problem) = ArmProblem::new(
            name.clone(),
            robot.clone(),
            Scene::new(vec![plate]),
            start.clone(),
            goal.clone(),
        ) else {
            continue;
        };
        if !problem.ends_are_valid() {
            continue;
        }
        let audit = MotionAudit::new(problem.robot(), problem.scene());
        if !matches!(
            audit.audit(&start, &goal, 2_000_000),
            AuditVerdict::Collides { .. }
        ) {
            continue; // the plate must block the straight motion
        }
        thickness = (
            thickness.0.min(2.0 * half_thickness),
            thickness.1.max(2.0 * half_thickness),
        );
        let at = |resolution: Option<f64>, allow: bool| {
            match resolution {
                Some(r) => problem
                    .clone()
                    .with_resolution(r)
                    .expect("accepted resolutions"),
                None => problem.clone(),
            }
            .allowing_uncertified_motion(allow)
        };
        let label = |resolution: Option<f64>| {
            resolution.map_or_else(
                || format!("1/{} rad", mit_star_robot::CHECKS_PER_UNIT),
                |r| r.to_string(),
            )
        };
        let mut runs: Vec<(&str, String, ArmProblem, u32)> = Vec::new();
        for resolution in RESOLUTIONS {
            for planner in ["MIT*", "RRT-Connect"] {
                runs.push((planner, label(resolution), at(resolution, false), 4));
            }
        }
        let control = Some(0.5);
        runs.push((
            "RRT-Connect uncertified (control)",
            label(control),
            at(control, true),
            1,
        ));
        for (planner_name, label, p, certification) in runs {
            let configuration = if planner_name == "MIT*" {
                Configuration::MitStar
            } else {
                Configuration::RrtConnect
            };
            let parameters = Parameters {
                seed: made as u64,
                certification: Some(certification),
                range: (configuration == Configuration::RrtConnect).then_some(1.0),
                ..Parameters::default()
            };
            let mut planner = build_planner(configuration, &p, &parameters).expect("builds");
            let outcome = if configuration == Configuration::MitStar {
                planner.solve(&TimeLimit::seconds(0.1))
            } else {
                planner.solve(&FirstSolution.or(TimeLimit::seconds(0.5)))
            }
            .expect("plans");
            let tally = tallies.entry((label.clone(), planner_name)).or_default();
            tally.runs += 1;
            let Some(solution) = outcome.solution() else {
                continue;
            };
            tally.solved += 1;
            let path: Vec<&[f64]> = solution.path.iter().collect();
            match first_failure(&audit, &path) {
                None => tally.clear += 1,
                Some((undecided, why)) => {
                    if undecided {
                        tally.undecided += 1;
                    } else {
                        tally.collides += 1;
                    }
                    if certification > 1 {
                        failures.push(format!("{name} {planner_name} at {label}: {why}"));
                    }
                }
            }
        }
        made += 1;
        if made % 100 == 0 {
            eprintln!("{made} problems");
        }
    }
    println!(
        "{count} plate problems (seed {seed}), plates {:.1}–{:.1} mm thick, each blocking the straight motion",
        thickness.0 * 1e3,
        thickness.1 * 1e3
    );
    println!(
        "| resolution | planner | runs | solved | audit: clear | audit: collides | undecided |"
    );
    println!("|---|---|---|---|---|---|---|");
    for ((label, planner), t) in &tallies {
        println!(
            "| {label} | {planner} | {} | {} | {} | {} | {} |",
            t.runs, t.solved, t.clear, t.collides, t.undecided
        );
    }
    if failures.is_empty() {
        println!("every certified path passed the continuous audit");
    } else {
        println!("{} certified paths FAILED the audit:", failures.len());
        for f in &failures {
            println!("  {f}");
        }
        std::process::exit(1);
    }
}

/// Why the audit does not clear `path`, if it does not: `(undecided, why)` for its first
/// invalid state, colliding motion, or motion the budget left undecided.
fn first_failure(audit: &MotionAudit, path: &[&[f64]]) -> Option<(bool, String)> {
    if let Some(i) = path.iter().position(|state| !audit.is_valid(state)) {
        return Some((false, format!("state {i} is invalid")));
    }
    path.windows(2)
        .find_map(|pair| match audit.audit(pair[0], pair[1], 2_000_000) {
            AuditVerdict::Clear { .. } => None,
            AuditVerdict::Collides { contact, .. } => Some((false, contact)),
            AuditVerdict::Undecided { .. } => Some((true, "undecided".into())),
        })
}
