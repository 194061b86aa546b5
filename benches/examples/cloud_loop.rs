//! `cloud_loop`: `mit-star plan`'s runs among point clouds, many problems in one process, as
//! VAMP's benchmark loop plans them (benches/peers/vamp/side_by_side_clouds.sh).
//!
//! ```text
//! cargo build --release -p mit-star-benches --example cloud_loop
//! echo "table_pick_0001 --problem mbm:target/table_pick_panda --instance 1 \
//!   --scene-as-cloud 10000 --crop-reach --min-distance 0.02" \
//!   | target/release/examples/cloud_loop rrt-connect OUT --set range=1.0
//! ```
//!
//! Each line of standard input is a run: a name, then `plan`'s problem options (the problem,
//! its instance, the cloud options; no spaces inside an option's value). Each run plans with
//! the planner named first (seed 0, 1 s, to its first solution, `--set` overrides after the
//! folder) and writes `OUT/NAME.json`, the record `plan --json` prints, and `OUT/NAME.err`,
//! the `cloud:` lines `plan` prints on stderr (each filter step's and the tree's time) or why
//! the run was refused (a start or goal touching the cloud). A fresh process per problem,
//! as `plan` is, pays for cold caches and first-touched memory on every solve (about 30 µs
//! of RRT-Connect's first solution among the primitives of table_pick, 33 µs in `bench`'s
//! loop against 62 µs in `plan`); here only the first problem does.

use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use clap::Parser;
use mit_star_benches::commands::ProblemArgs;
use mit_star_benches::{
    HarnessError, InstanceProblem, ParameterOverrides, PlannerSpec, RunJob, parse_configuration,
};

/// One run's problem options, as `plan` takes them.
#[derive(Debug, Parser)]
struct Run {
    #[command(flatten)]
    problem: ProblemArgs,
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(planner), Some(out)) = (args.first(), args.get(1)) else {
        eprintln!("usage: cloud_loop PLANNER OUT [--set KEY=VALUE]… < RUNS");
        std::process::exit(2);
    };
    let mut overrides = ParameterOverrides::default();
    for pair in args[2..].chunks(2) {
        match pair {
            [flag, value] if flag == "--set" => overrides.push_assignment(value).expect("--set"),
            _ => panic!("expected --set KEY=VALUE, got {pair:?}"),
        }
    }
    let configuration = parse_configuration(planner).expect("a planner");
    let spec = PlannerSpec::new(configuration, None, &overrides).expect("parameters");
    let out = PathBuf::from(out);
    std::fs::create_dir_all(&out).expect("the output folder");
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("standard input");
        let mut words = line.split_whitespace();
        let Some(name) = words.next() else { continue };
        let options = std::iter::once("cloud_loop").chain(words);
        let (json, err) = match Run::try_parse_from(options) {
            Ok(run) => match run_one(run.problem, &spec) {
                Ok((json, lines)) => (json, lines.join("\n")),
                Err(e) => (String::new(), format!("error: {e}")),
            },
            Err(e) => (String::new(), format!("error: {e}")),
        };
        write(&out, name, "json", &json);
        write(&out, name, "err", &err);
    }
}

/// Plans one problem; the record as JSON and the cloud's lines.
fn run_one(
    mut problem: ProblemArgs,
    spec: &PlannerSpec,
) -> Result<(String, Vec<String>), HarnessError> {
    let clouds = std::mem::take(&mut problem.clouds);
    let mut instance = problem.build(1.0)?;
    let mut lines = Vec::new();
    if clouds.any() {
        let arm = instance
            .problem
            .as_arm()
            .ok_or_else(|| HarnessError::Usage("clouds need an arm problem".into()))?;
        let label = format!("#{}", instance.instance);
        let (with_cloud, summary) = clouds.apply(arm, instance.instance, &label)?;
        lines.extend(summary.steps.iter().map(|s| format!("cloud: {s}")));
        with_cloud.check_ends().map_err(HarnessError::ArmEnd)?;
        instance.problem = InstanceProblem::Arm(Arc::new(with_cloud));
    }
    let job = RunJob {
        instance: 0,
        planner: 0,
        run: 0,
        seed: 0,
        first_solution: true,
    };
    let record = job
        .execute(&instance, spec, &AtomicBool::new(false))
        .expect("not interrupted");
    let json = serde_json::to_string(&record).map_err(|e| HarnessError::Serialise {
        path: "record".into(),
        message: e.to_string(),
    })?;
    Ok((json, lines))
}

fn write(dir: &Path, name: &str, extension: &str, text: &str) {
    std::fs::write(dir.join(format!("{name}.{extension}")), text).expect("an output file");
}
