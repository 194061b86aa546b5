//! `ik_bench`: inverse kinematics on random reachable poses of every shipped arm (and a
//! held-out arm given by its spherised URDF).
//!
//! ```text
//! cargo run --release -p mit-star-robot --example ik_bench -- [--n 10000] [--seed 1] \
//!     [--only panda] [--held-out URDF LINK] [--unchecked] [--out ik.json] \
//!     [--restarts R] [--iterations I] [--damping D] [--max-step S] [--grasp]
//! ```
//!
//! The held-out arm of the measurements is the KUKA LBR iiwa 7 of pybullet's data, not shipped
//! here; its meshes covered with spheres by our own tool:
//!
//! ```text
//! pip download pybullet --no-deps -d dl && cd dl && unzip -q pybullet-*.whl 'pybullet_data/kuka_iiwa/*'
//! mit-star spherise --max-spheres 300 -o pybullet_data/kuka_iiwa/iiwa_spherized.urdf \
//!     pybullet_data/kuka_iiwa/model.urdf
//! ... --held-out dl/pybullet_data/kuka_iiwa/iiwa_spherized.urdf lbr_iiwa_link_7
//! ```
//!
//! Per robot: `N` targets, each the pose of the solver's frame at a random configuration the
//! checker (empty scene: self-collision and limits) accepts; IK from another random
//! configuration with the default settings, the same checker (none with `--unchecked`), a
//! one-second deadline. Prints a
//! markdown table: success rate, median and 95th percentile time per solution (successful
//! solves), mean attempts, and the largest position and orientation error of the returned
//! solutions, recomputed by the full `f64` forward kinematics (`Kinematics::link_poses_f64`,
//! not the solver's chain walk); solutions outside the limits or refused by the checker are
//! counted. `--grasp` makes each target a grasp: a ball of 5 mm about the position and a cone
//! of 0.1 rad about the frame's z axis (the errors are then measured to these sets, and the
//! JSON's targets are the centres). `--out` writes the sampled configurations, the targets and the solutions as JSON for
//! `benches/peers/pinocchio/check_ik.py`, which recomputes the errors with Pinocchio.

use std::fmt::Write as _;
use std::time::{Duration, Instant};

use glam::DAffine3;
use mit_star_robot::{
    ArmChecker, IkSolver, Kinematics, OrientationTolerance, PoseTarget, PositionTolerance,
    RobotModel, Scene, ShippedRobot,
};
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{Deadline, SeededRng, StateSpace};
use mit_star_validity::StateValidity;

/// A robot to test: name, model, frame, URDF path (for the JSON).
struct Arm {
    name: String,
    model: RobotModel,
    link: String,
    urdf: String,
}

fn shipped(name: &str, group: Option<&str>, link: &str) -> Arm {
    let robot = ShippedRobot::find(name).expect("a shipped robot");
    Arm {
        name: match group {
            Some(g) => format!("{name} ({g})"),
            None => name.to_owned(),
        },
        model: robot
            .model_of_group(false, group)
            .expect("the shipped model"),
        link: link.to_owned(),
        urdf: format!(
            "{}/data/{name}/{name}_spherized.urdf",
            env!("CARGO_MANIFEST_DIR")
        ),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .map(|i| args.get(i + 1).expect("a value after the flag").clone())
    };
    let n: usize = value("--n").map_or(10_000, |v| v.parse().expect("--n: a count"));
    let seed: u64 = value("--seed").map_or(1, |v| v.parse().expect("--seed: an integer"));
    let only = value("--only");
    let unchecked = args.iter().any(|a| a == "--unchecked");
    let number = |flag: &str| value(flag).map(|v| v.parse::<f64>().expect("a number"));
    let settings = Settings {
        restarts: number("--restarts").map_or(IkSolver::RESTARTS, |v| v as usize),
        iterations: number("--iterations").map_or(IkSolver::ITERATIONS, |v| v as usize),
        damping: number("--damping").unwrap_or(IkSolver::DAMPING),
        max_step: number("--max-step").unwrap_or(IkSolver::MAX_STEP),
        grasp: args.iter().any(|a| a == "--grasp"),
    };
    let mut arms = vec![
        shipped("panda", None, "panda_hand"),
        shipped("ur5", None, "ee_link"),
        shipped("fetch", Some("arm"), "gripper_link"),
        shipped("baxter", Some("right_arm"), "right_gripper"),
    ];
    if let Some(i) = args.iter().position(|a| a == "--held-out") {
        let (path, link) = (&args[i + 1], &args[i + 2]);
        let model = RobotModel::from_urdf_file(path.as_ref())
            .expect("the held-out URDF")
            .without_model_pairs();
        let name = model.name().to_owned();
        arms.push(Arm {
            name,
            model,
            link: link.clone(),
            urdf: std::fs::canonicalize(path)
                .expect("the held-out URDF")
                .display()
                .to_string(),
        });
    }
    arms.retain(|a| only.as_deref().is_none_or(|o| a.name.starts_with(o)));
    println!(
        "{n} targets per robot, seed {seed}, {settings:?}, accuracy {:?}",
        IkSolver::ACCURACY
    );
    println!(
        "| robot | DoF | success | median µs | p95 µs | mean attempts | mean iterations | max position error (m) | max orientation error (rad) | outside limits | invalid |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    let mut json = String::from("{\"robots\": [");
    for (k, arm) in arms.iter().enumerate() {
        let row = run(arm, (n, seed, unchecked), &settings, &mut json, k > 0);
        println!("{row}");
    }
    json.push_str("]}\n");
    if let Some(out) = value("--out") {
        std::fs::write(&out, json).expect("writing --out");
        eprintln!("wrote {out}");
    }
}

/// The solver settings (the defaults unless `--restarts`, `--iterations`, `--damping`,
/// `--max-step` say otherwise).
#[derive(Debug)]
struct Settings {
    restarts: usize,
    iterations: usize,
    damping: f64,
    max_step: f64,
    /// Grasp-like targets: a 5 mm ball and a 0.1 rad cone about the frame's z axis.
    grasp: bool,
}

impl Settings {
    fn apply(&self, solver: IkSolver) -> Result<IkSolver, mit_star_robot::IkError> {
        solver
            .restarts(self.restarts)
            .iterations(self.iterations)?
            .damping(self.damping)?
            .max_step(self.max_step)
    }
}

/// Solves `n` targets for `arm`; appends its JSON record; returns its table row.
fn run(
    arm: &Arm,
    (n, seed, unchecked): (usize, u64, bool),
    settings: &Settings,
    json: &mut String,
    comma: bool,
) -> String {
    let model = &arm.model;
    let space = model.joint_space();
    let dimension = model.joint_names().len();
    let checker = ArmChecker::new(model, &Scene::new(Vec::new()));
    let mut solver = settings
        .apply(IkSolver::new(model, &arm.link).expect("the frame"))
        .expect("valid settings")
        .seed(seed);
    let fk = Kinematics::new(model);
    let frame = model.link_index(&arm.link).expect("the frame");
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let mut rng = SeededRng::seed_from_u64(seed ^ 0x9e37_79b9);
    let (mut q, mut start) = (vec![0.0; dimension], vec![0.0; dimension]);
    let mut times = Vec::with_capacity(n);
    let (mut attempts, mut iterations, mut outside, mut invalid) = (0, 0, 0, 0);
    let (mut stopped, mut rejected) = (0, 0);
    let (mut max_p, mut max_o) = (0.0_f64, 0.0_f64);
    let _ = write!(
        json,
        "{}{{\"name\": {:?}, \"urdf\": {:?}, \"link\": {:?}, \"joints\": {:?}, \"held\": [{}], \"cases\": [",
        if comma { ", " } else { "" },
        arm.name,
        arm.urdf,
        arm.link,
        model.joint_names(),
        model
            .held_joints()
            .iter()
            .map(|(name, v)| format!("[{name:?}, {v}]"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for case in 0..n {
        loop {
            space.sample_uniform(&mut rng, &mut q);
            if checker.is_valid(&q) {
                break;
            }
        }
        space.sample_uniform(&mut rng, &mut start);
        let pose = solver.frame_pose(&q).expect("a configuration");
        let mut target = PoseTarget::from_pose(&pose).expect("a pose");
        if settings.grasp {
            target = target
                .with_position_tolerance(PositionTolerance::Ball { radius: 0.005 })
                .and_then(|t| {
                    t.with_orientation_tolerance(OrientationTolerance::Cone {
                        axis: glam::DVec3::Z,
                        half_angle: 0.1,
                    })
                })
                .expect("valid tolerances");
        }
        let deadline = Deadline::after(Duration::from_secs(1));
        let began = Instant::now();
        let validity: &dyn StateValidity = if unchecked {
            &mit_star_validity::AllValid
        } else {
            &checker
        };
        let result = solver.solve(&target, &start, validity, &deadline);
        let elapsed = began.elapsed();
        let (p, o) = (target.position(), target.orientation());
        let _ = write!(
            json,
            "{}{{\"sampled\": {q:?}, \"position\": [{}, {}, {}], \"quaternion\": [{}, {}, {}, {}], \"solution\": ",
            if case > 0 { ", " } else { "" },
            p.x,
            p.y,
            p.z,
            o.x,
            o.y,
            o.z,
            o.w
        );
        match result {
            Ok(solution) => {
                times.push(elapsed.as_secs_f64() * 1e6);
                attempts += solution.attempts;
                iterations += solution.iterations;
                let s = &solution.configuration;
                fk.link_poses_f64(s, &mut links);
                let (ep, eo) = target.errors(&links[frame]);
                max_p = max_p.max(ep);
                max_o = max_o.max(eo);
                if !space.contains(s) {
                    outside += 1;
                }
                if !checker.is_valid(s) {
                    invalid += 1;
                }
                let _ = write!(json, "{s:?}}}");
            }
            Err(e) => {
                match e {
                    mit_star_robot::IkError::Stopped { .. } => stopped += 1,
                    mit_star_robot::IkError::Unreachable { rejected: r, .. } => rejected += r,
                    _ => {}
                }
                json.push_str("null}");
            }
        }
    }
    json.push_str("]}");
    times.sort_by(f64::total_cmp);
    let quantile = |f: f64| {
        times
            .get(((times.len() as f64 - 1.0) * f).round() as usize)
            .copied()
            .unwrap_or(f64::NAN)
    };
    let solved = times.len();
    eprintln!(
        "{}: {} failures: {stopped} stopped by the deadline, {rejected} converged attempts refused (invalid or not distinct) among the others",
        arm.name,
        n - solved
    );
    format!(
        "| {} | {} | {:.2} % ({solved}/{n}) | {:.1} | {:.1} | {:.2} | {:.1} | {:.1e} | {:.1e} | {outside} | {invalid} |",
        arm.name,
        dimension,
        100.0 * solved as f64 / n as f64,
        quantile(0.5),
        quantile(0.95),
        attempts as f64 / solved.max(1) as f64,
        iterations as f64 / solved.max(1) as f64,
        max_p,
        max_o,
    )
}
