//! `anytime_arm`: how fast planners find a first path on the Panda and how short their paths
//! get over time — our side of the anytime comparison with VAMP's planners.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example anytime_arm -- target 20 aorrtc,mit-star 1.0
//! ```
//!
//! Runs each named configuration once (seed = the problem's index, one thread) on the first
//! `N` problems of each of the five MotionBenchMaker scenes for `SECONDS`, and prints per
//! scene and planner: problems solved, the median time to the first solution, the median cost
//! (joint-space path length) of the best path at 10 ms, 100 ms and 1 s (a run without a path by
//! then counts as infinitely long), the median straight-line lower bound, and how many final
//! paths fail a continuous audit in `f64` (parry). Extra `key=value` arguments set parameters
//! (`simplify_solutions=true`, `simplify_smoothing=false`, `warm_start=true`,
//! `aorrtc_simplify=false`, `polish_when_idle=false`, `rrt_balance=false`, `rrt_halton=true`,
//! `range=2` (RRT-Connect's and AORRTC's; 1 by default, as VAMP's scripts), `batch_size=200`,
//! `rewire_factor=1.5`, `near_terminals=0.3`, `connection=k-nearest`, …; `aorrtc_moves=perturb|relax|relax-then-perturb`
//! for AORRTC's smoothing moves, `relax` by default; `scenes=cage,box` for some scenes only;
//! `seed=K` adds `K` to every run's seed, for repeats with other random draws; `robot=ur5` or
//! `robot=fetch` for another shipped robot's problems, read from `FOLDER/<scene>_<robot>` as
//! `robot/data/<robot>/problems.tar.bz2` unpacks them under `problems/`); `csv=FILE` also
//! writes one line per run (`scene,index,planner,first_ms,cost_10ms,cost_100ms,cost_1s`) for
//! `benches/peers/vamp/anytime_table.py` (and, over several seeds, `seed_spread.py`).

use std::io::Write;

use mit_star::{Aorrtc, Configuration, Parameters, SmoothingMoves, TimeLimit, build_planner};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, AuditVerdict, MotionAudit};
use mit_star_spaces::StateSpace;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
#[path = "support/parameter_switches.rs"]
mod parameter_switches;
use mbm_scenes::{SCENES, median, problems_of};
use parameter_switches::set_parameter;

/// The times at which the best cost is read, in seconds.
const MOMENTS: [f64; 3] = [0.01, 0.1, 1.0];

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target".into());
    let count: usize = args
        .next()
        .map_or(20, |a| a.parse().expect("a problem count"));
    let names = args.next().unwrap_or_else(|| "aorrtc,mit-star".into());
    let seconds: f64 = args.next().map_or(1.0, |a| a.parse().expect("seconds"));
    let mut base = Parameters::default();
    let mut csv = None;
    let mut seed_offset: u64 = 0;
    let mut aorrtc_moves = None;
    let mut scenes: Vec<String> = SCENES
        .iter()
        .map(|s| s.trim_end_matches("_panda").to_owned())
        .collect();
    let mut robot = (
        "panda".to_owned(),
        ArmProblem::panda().expect("the shipped Panda loads"),
    );
    for setting in args {
        let (key, value) = setting.split_once('=').expect("key=value");
        if key == "seed" {
            seed_offset = value.parse().expect("a seed offset");
            continue;
        }
        if key == "scenes" {
            scenes = value.split(',').map(str::to_owned).collect();
            continue;
        }
        if key == "robot" {
            robot = mbm_scenes::shipped_robot(value);
            continue;
        }
        if key == "aorrtc_moves" {
            aorrtc_moves = Some(match value {
                "perturb" => SmoothingMoves::Perturb,
                "relax" => SmoothingMoves::Relax,
                "relax-then-perturb" => SmoothingMoves::RelaxThenPerturb,
                other => panic!("unknown smoothing moves {other}"),
            });
            continue;
        }
        if key == "csv" {
            let mut file = std::fs::File::create(value).expect("a writable CSV file");
            writeln!(
                file,
                "scene,index,planner,first_ms,cost_10ms,cost_100ms,cost_1s"
            )
            .unwrap();
            csv = Some(file);
            continue;
        }
        assert!(
            set_parameter(&mut base, key, value),
            "unknown parameter {key}"
        );
    }
    let configurations: Vec<Configuration> = names
        .split(',')
        .map(|n| n.parse().expect("a planner configuration"))
        .collect();
    println!(
        "| scene | planner | solved | median t_first (ms) | cost at 10 ms | at 100 ms | at 1 s | straight line | failed audits |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut pooled = vec![Vec::new(); configurations.len() * MOMENTS.len()];
    for scene in &scenes {
        let loaded = problems_of(&robot.1, &folder, &format!("{scene}_{}", robot.0), count);
        for (p, &configuration) in configurations.iter().enumerate() {
            let (mut first, mut line) = (Vec::new(), Vec::new());
            let mut at = vec![Vec::new(); MOMENTS.len()];
            let (mut solved, mut failed) = (0, 0);
            for (index, problem) in &loaded {
                let parameters = Parameters {
                    seed: *index as u64 + seed_offset,
                    // VAMP's range, for RRT-Connect wherever it runs (a warm start's too),
                    // unless `range=` sets another.
                    range: base.range.or((matches!(
                        configuration,
                        Configuration::RrtConnect | Configuration::Aorrtc
                    ) || base.warm_start)
                        .then_some(1.0)),
                    ..base.clone()
                };
                let mut planner = match (configuration, aorrtc_moves) {
                    (Configuration::Aorrtc, Some(moves)) => {
                        let mut aorrtc = Aorrtc::for_problem(problem, &parameters).expect("builds");
                        let smoothing = Aorrtc::<
                            mit_star_spaces::JointSpace,
                            mit_star_robot::ArmChecker,
                        >::smooths_solutions(&parameters);
                        let simplifier = Aorrtc::<
                            mit_star_spaces::JointSpace,
                            mit_star_robot::ArmChecker,
                        >::default_simplifier(
                            parameters.seed, smoothing
                        );
                        aorrtc.set_simplifier(simplifier.smoothing_moves(moves));
                        Box::new(aorrtc)
                    }
                    _ => build_planner(configuration, problem, &parameters).expect("builds"),
                };
                let outcome = planner.solve(&TimeLimit::seconds(seconds)).expect("plans");
                let trace = planner.trace();
                first.push(trace.initial().map_or(f64::INFINITY, |p| p.time * 1e3));
                if let Some(file) = csv.as_mut() {
                    let costs = MOMENTS.map(|m| trace.cost_at(m).to_string()).join(",");
                    let planner = configuration.name();
                    writeln!(
                        file,
                        "{scene},{index},{planner},{},{costs}",
                        first[first.len() - 1]
                    )
                    .expect("the CSV file takes a line");
                }
                for (m, &moment) in MOMENTS.iter().enumerate() {
                    at[m].push(trace.cost_at(moment));
                    pooled[p * MOMENTS.len() + m].push(trace.cost_at(moment));
                }
                let space = problem.space();
                line.push(space.distance(problem.start(), &problem.goals()[0]));
                let Some(solution) = outcome.solution() else {
                    continue;
                };
                solved += 1;
                let audit = MotionAudit::new(problem.robot(), problem.scene());
                let path = &solution.path;
                if path.iter().zip(path.iter().skip(1)).any(|(a, b)| {
                    !matches!(audit.audit(a, b, 1_000_000), AuditVerdict::Clear { .. })
                }) {
                    failed += 1;
                }
            }
            let [a, b, c] = [0, 1, 2].map(|m| median(&mut at[m]));
            println!(
                "| {} | {} | {solved}/{} | {:.2} | {a:.2} | {b:.2} | {c:.2} | {:.2} | {failed} |",
                scene,
                configuration.label(),
                loaded.len(),
                median(&mut first),
                median(&mut line),
            );
        }
    }
    for (p, configuration) in configurations.iter().enumerate() {
        let [a, b, c] = [0, 1, 2].map(|m| median(&mut pooled[p * MOMENTS.len() + m]));
        println!(
            "| all | {} | | | {a:.2} | {b:.2} | {c:.2} | | |",
            configuration.label()
        );
    }
}
