//! `arm_profile`: where an arm planner's time goes, per MotionBenchMaker scene.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example arm_profile -- target 100 rrt-connect 3
//! ```
//!
//! Plans the named configuration (`rrt-connect` and `aorrtc` with range 1 unless `range=` is
//! given, `mit-star`, `eit-star`, …) to its first solution on the first `N` problems of each
//! of the five scenes under `FOLDER`, `SEEDS` seeds each, one thread (then parameters as
//! `name=value`, as `anytime_arm` takes them: `rrt_balance=false`, `lazy_certification=false`,
//! `connection=k-nearest`, …), and prints per scene the median time to the first solution (the
//! `solve` call's, construction excluded: AORRTC's includes the shortcuts it makes to its first
//! path before returning) with the medians of the planner's counters: configurations tested
//! (sampler and edges, certification included), edge grid points, edges certified,
//! nearest-neighbour queries, iterations and states added (samples kept). Then the cost of one
//! configuration check on the scenes' first problems: scalar, batched a batch of the checker's
//! lanes at a time (eight, or sixteen with AVX-512; resuming after each invalid one), batched
//! asking only whether any of the batch is invalid,
//! and batched over valid configurations only. Run it under `perf record` for
//! the shares of kinematics, sphere tests, nearest neighbours and bookkeeping
//! (`robot=ur5` or `robot=fetch` plans that shipped robot's problems of the seven scenes, read
//! from `FOLDER/<scene>_<robot>`; `ARM_PROFILE_SCENES=box,cage` keeps those scenes; `ARM_PROFILE_NO_CHECKS=1` skips the
//! per-configuration table; `ARM_PROFILE_AUDIT=1` audits every path with parry between runs,
//! as `bench --audit-every-run` does; `ARM_PROFILE_TIME=30` gives each solve 30 s instead of 1 s,
//! so that under valgrind no solve is cut short by its deadline; `ARM_PROFILE_CSV=FILE` writes
//! each solve's scene, problem, seed, time in µs, whether it solved and its counters, for
//! `benches/tools/arm_profile_table.py` and `benches/peers/vamp/summarize_loops.py`) (the
//! arm-planning reference page, "Where an arm solve's time goes").

use std::hint::black_box;
use std::io::Write;
use std::time::Instant;

use mit_star::{
    Configuration, FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner,
};
use mit_star_problems::PlanningProblem;
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::{SCENES, SEVEN_SCENES, median, problems_of};
#[path = "support/parameter_switches.rs"]
mod parameter_switches;
use parameter_switches::set_parameter;

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target".into());
    let count: usize = args
        .next()
        .map_or(100, |a| a.parse().expect("a problem count"));
    let name = args.next().unwrap_or_else(|| "rrt-connect".into());
    let seeds: u64 = args.next().map_or(3, |a| a.parse().expect("a seed count"));
    // Seconds per solve (1 by default; longer under valgrind, so that no solve is cut short and
    // two builds' instruction counts compare the same decisions).
    let budget: f64 = std::env::var("ARM_PROFILE_TIME")
        .map_or(1.0, |t| t.parse().expect("ARM_PROFILE_TIME in seconds"));
    // Then parameters as `name=value` (`rrt_balance=false`, `lazy_certification=false`,
    // `sparse_initial_steps=4`, `connection=k-nearest`, …).
    let mut base = Parameters::default();
    let mut robot = (
        "panda".to_owned(),
        mit_star_robot::ArmProblem::panda().expect("the shipped Panda loads"),
    );
    let mut scenes: Vec<String> = SCENES.iter().map(|s| (*s).to_owned()).collect();
    for setting in args {
        let (name, value) = setting.split_once('=').expect("name=value");
        if name == "robot" {
            robot = mbm_scenes::shipped_robot(value);
            scenes = SEVEN_SCENES
                .iter()
                .map(|s| format!("{s}_{value}"))
                .collect();
            continue;
        }
        assert!(
            set_parameter(&mut base, name, value),
            "unknown parameter {name}"
        );
    }
    let configuration = name
        .parse::<Configuration>()
        .expect("a planner configuration");
    println!(
        "| scene | problems | median t_first (µs) | configurations | grid points | certified edges | NN queries | iterations | states | µs / configuration |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    // One line per solve, for a comparison run by run (`benches/tools/arm_profile_table.py`,
    // `benches/peers/vamp/summarize_loops.py`).
    let mut csv = std::env::var_os("ARM_PROFILE_CSV").map(|path| {
        let mut file = std::io::BufWriter::new(std::fs::File::create(path).expect("a CSV file"));
        writeln!(
            file,
            "scene,index,seed,solve_us,solved,configurations,iterations,neighbour_queries,states"
        )
        .expect("writes the CSV");
        file
    });
    let mut pooled = Vec::new();
    let mut setups = Vec::new();
    let mut first_problems = Vec::new();
    let only = std::env::var("ARM_PROFILE_SCENES").unwrap_or_default();
    let suffix = format!("_{}", robot.0);
    for scene in &scenes {
        let scene = scene.as_str();
        if !only.is_empty() && !only.split(',').any(|s| scene.starts_with(s)) {
            continue;
        }
        let problems = problems_of(&robot.1, &folder, scene, count);
        if let Some((_, first)) = problems.first() {
            first_problems.push((scene, first.clone()));
        }
        let mut rows: [Vec<f64>; 7] = Default::default();
        for seed in 0..seeds {
            for (i, (index, problem)) in problems.iter().enumerate() {
                let parameters = Parameters {
                    seed: seed * 1000 + i as u64,
                    // VAMP's range for RRT-Connect wherever it runs (AORRTC's first search, a
                    // warm start), as `anytime_arm` and the `panda-mbm` experiment give it,
                    // unless `range=` sets another.
                    range: base.range.or((matches!(
                        configuration,
                        Configuration::RrtConnect | Configuration::Aorrtc
                    ) || base.warm_start)
                        .then_some(1.0)),
                    ..base.clone()
                };
                let built = Instant::now();
                let mut planner =
                    build_planner(configuration, problem, &parameters).expect("builds");
                setups.push(built.elapsed().as_secs_f64() * 1e6);
                let run = Instant::now();
                let outcome = planner.solve(&FirstSolution.or(TimeLimit::seconds(budget)));
                let t = run.elapsed().as_secs_f64() * 1e6;
                let c = planner.counters();
                if let Some(file) = csv.as_mut() {
                    let solved = outcome.as_ref().is_ok_and(|o| o.solution().is_some());
                    let name = scene.trim_end_matches(&suffix);
                    writeln!(
                        file,
                        "{name},{index},{},{t:.3},{},{},{},{},{}",
                        parameters.seed,
                        u8::from(solved),
                        c.validity_checks,
                        c.iterations,
                        c.neighbour_queries,
                        c.samples
                    )
                    .expect("writes the CSV");
                }
                // As the benchmark harness does between runs: audit the path with parry.
                if std::env::var_os("ARM_PROFILE_AUDIT").is_some()
                    && let Some(solution) = outcome.ok().and_then(|o| o.solution().cloned())
                {
                    let audit = mit_star_robot::MotionAudit::new(problem.robot(), problem.scene());
                    let path: Vec<&[f64]> = solution.path.iter().collect();
                    for w in path.windows(2) {
                        let _ = audit.audit(w[0], w[1], 2_000_000);
                    }
                }
                for (row, v) in rows.iter_mut().zip([
                    t,
                    c.validity_checks as f64,
                    c.points_tested as f64,
                    c.certifications as f64,
                    c.neighbour_queries as f64,
                    c.iterations as f64,
                    c.samples as f64,
                ]) {
                    row.push(v);
                }
                pooled.push(t);
            }
        }
        let per = rows[0].iter().sum::<f64>() / rows[1].iter().sum::<f64>().max(1.0);
        let n = problems.len();
        let [t, checks, points, certified, queries, iterations, states] =
            rows.map(|mut r| median(&mut r));
        println!(
            "| {} | {n} | {t:.0} | {checks:.0} | {points:.0} | {certified:.0} | {queries:.0} | {iterations:.0} | {states:.0} | {per:.3} |",
            scene.trim_end_matches(&suffix)
        );
    }
    println!(
        "\npooled median t_first: {:.0} µs over {} runs; median construction {:.1} µs",
        median(&mut pooled),
        pooled.len(),
        median(&mut setups)
    );
    if std::env::var_os("ARM_PROFILE_NO_CHECKS").is_some() {
        return;
    }
    println!(
        "\n| scene | scalar ns / configuration | batched ns / configuration | share valid | batched, any invalid | batched, valid ones |"
    );
    println!("|---|---|---|---|---|---|");
    for (scene, problem) in first_problems {
        let space = problem.space();
        let checker = problem.validity();
        let width = checker.batch_width();
        let d = space.dimension();
        let mut rng = 0x9e37_79b9_7f4a_7c15_u64;
        let mut states = vec![0.0; 4096 * d];
        let (lower, upper) = (space.lower().to_vec(), space.upper().to_vec());
        for (k, x) in states.iter_mut().enumerate() {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            let u = (rng >> 11) as f64 / (1u64 << 53) as f64;
            let j = k % d;
            *x = lower[j] + u * (upper[j] - lower[j]);
        }
        let started = Instant::now();
        let mut valid = 0;
        for _ in 0..5 {
            valid = states.chunks(d).filter(|q| checker.is_valid(q)).count();
        }
        let scalar = started.elapsed().as_secs_f64() * 1e9 / (5.0 * 4096.0);
        let started = Instant::now();
        for _ in 0..5 {
            let mut at = 0;
            while at < 4096 {
                let rest = &states[at * d..];
                at += checker
                    .first_invalid(black_box(&rest[..rest.len().min(width * d)]), d)
                    .map_or(width, |i| i + 1);
            }
        }
        let batched = started.elapsed().as_secs_f64() * 1e9 / (5.0 * 4096.0);
        // A batch per call, asking only whether any is invalid (an edge check's question).
        let started = Instant::now();
        for _ in 0..5 {
            black_box(
                states
                    .chunks(width * d)
                    .filter(|batch| checker.any_invalid(black_box(batch), d).is_some())
                    .count(),
            );
        }
        let any = started.elapsed().as_secs_f64() * 1e9 / (5.0 * 4096.0);
        // Valid configurations only, a batch per call: nothing ends a batch early.
        let valid_states: Vec<f64> = states
            .chunks(d)
            .filter(|q| checker.is_valid(q))
            .flatten()
            .copied()
            .collect();
        let count = valid_states.len() / d / width * width;
        let started = Instant::now();
        for _ in 0..5 {
            for batch in valid_states[..count * d].chunks(width * d) {
                assert!(checker.first_invalid(batch, d).is_none());
            }
        }
        let all_valid = started.elapsed().as_secs_f64() * 1e9 / (5.0 * count as f64);
        println!(
            "| {} | {scalar:.0} | {batched:.0} | {:.2} | {any:.0} | {all_valid:.0} |",
            scene.trim_end_matches(&suffix),
            valid as f64 / 4096.0
        );
    }
}
