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
use std::sync::atomic::AtomicBool;

use mit_star_benches::{HarnessError, PlannerSpec, ProblemInstance, RunJob};

#[path = "support/cloud_runs.rs"]
mod cloud_runs;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(planner), Some(out)) = (args.first(), args.get(1)) else {
        eprintln!("usage: cloud_loop PLANNER OUT [--set KEY=VALUE]… < RUNS");
        std::process::exit(2);
    };
    let spec = cloud_runs::planner_spec(planner, &args[2..]);
    let out = PathBuf::from(out);
    std::fs::create_dir_all(&out).expect("the output folder");
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("standard input");
        let mut words = line.split_whitespace();
        let Some(name) = words.next() else { continue };
        let (json, err) = match cloud_runs::problem_with_cloud("cloud_loop", words)
            .and_then(|(instance, lines)| Ok((run_one(&instance, &spec)?, lines)))
        {
            Ok((json, lines)) => (json, lines.join("\n")),
            Err(e) => (String::new(), format!("error: {e}")),
        };
        write(&out, name, "json", &json);
        write(&out, name, "err", &err);
    }
}

/// Plans one problem; the record as JSON.
fn run_one(instance: &ProblemInstance, spec: &PlannerSpec) -> Result<String, HarnessError> {
    let job = RunJob {
        instance: 0,
        planner: 0,
        run: 0,
        seed: 0,
        first_solution: true,
    };
    let record = job
        .execute(instance, spec, &AtomicBool::new(false))
        .expect("not interrupted");
    serde_json::to_string(&record).map_err(|e| HarnessError::Serialise {
        path: "record".into(),
        message: e.to_string(),
    })
}

fn write(dir: &Path, name: &str, extension: &str, text: &str) {
    std::fs::write(dir.join(format!("{name}.{extension}")), text).expect("an output file");
}
