//! The shipped `panda-mbm` experiment end to end, on the two sample problems per scene shipped
//! in `robot/tests/data/mbm` (the full 500 live in a tarball extracted into `target/`): every
//! scene loads, every run ends solved or unsolved with no invalid path, the pooled per-scene
//! table is written, and arm problems ask planners for certification and the EIT* family for
//! samples near the terminals.

use std::path::Path;

use mit_star_benches::{
    ExecutionOptions, Executor, Experiment, Figures, ResultsFolder, RunStatus, ShippedExperiment,
};

/// The shipped experiment, pointed at the sample folders, two problems per scene, `budget` s.
fn sample_experiment(budget: f64) -> Experiment {
    let shipped = ShippedExperiment::find("panda-mbm").unwrap();
    assert!(shipped.data.is_some());
    let samples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/tests/data/mbm");
    let seeds = (1..=100)
        .map(|i: u32| i.to_string())
        .collect::<Vec<_>>()
        .join(", ");
    let text = shipped
        .text
        .replace("mbm:target/", &format!("mbm:{}/", samples.display()))
        .replace(&format!("[{seeds}]"), "[1, 2]")
        .replace("time = 1.0", &format!("time = {budget}"));
    Experiment::from_toml_str(&text, "panda-mbm", None).unwrap()
}

#[test]
fn the_arm_experiment_runs_every_scene_without_invalid_paths() {
    let experiment = sample_experiment(1.0);
    let instances = experiment.instances().unwrap();
    assert_eq!(instances.len(), 5 * 2);
    for instance in &instances {
        assert_eq!(instance.dimension, 7);
        assert_eq!(instance.budget, 1.0);
    }
    let options = ExecutionOptions {
        threads: 2,
        ..ExecutionOptions::default()
    };
    let results = Executor::new(options).run(&experiment, instances).unwrap();
    assert_eq!(results.run_count(), 5 * 12);
    let mut solved = 0;
    let mut drew_near_terminals = 0;
    for run in results.all_runs() {
        assert!(
            matches!(run.status, RunStatus::Solved | RunStatus::Unsolved),
            "{run:?}"
        );
        if run.status == RunStatus::Solved {
            solved += 1;
            let counters: Vec<(&str, u64)> = run.counter_values().to_vec();
            let certified = counters.iter().find(|(n, _)| *n == "certifications");
            assert!(certified.is_some_and(|&(_, c)| c > 0), "{counters:?}");
            // Arm problems ask the EIT* family for samples near the start and the goal.
            let near = counters
                .iter()
                .find(|(n, _)| *n == "sampler_near_terminals")
                .map(|&(_, c)| c);
            if run.planner == "RRT-Connect" || run.planner == "AORRTC" {
                assert!(near.is_none_or(|c| c == 0), "{run:?}");
            } else if near.is_some_and(|c| c > 0) {
                drew_near_terminals += 1;
            }
        }
    }
    // Most runs solve their problem in 1 s, even in an unoptimised test build (this checks that
    // planning happens; success rates are the benchmark's business).
    assert!(solved >= 30, "{solved} of 60 solved");
    // Every informed-trees run that samples at all draws some near the terminals (a problem
    // whose straight line is free is solved before the first batch).
    assert!(drew_near_terminals >= 20, "{drew_near_terminals} of 40");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("arm-experiment");
    let _ = std::fs::remove_dir_all(&dir);
    let mut folder = ResultsFolder::prepare(&dir).unwrap();
    folder.write(&results, Figures::None).unwrap();
    let kpi = std::fs::read_to_string(dir.join("kpi.md")).unwrap();
    assert!(kpi.contains("## Problems with several layouts"), "{kpi}");
    for scene in [
        "bookshelf_small",
        "bookshelf_tall",
        "box",
        "cage",
        "table_pick",
    ] {
        for planner in ["MIT*", "EIT*", "BIT*", "RRT-Connect", "AORRTC"] {
            let row = format!("| {scene}_panda R^7 (2 layouts) | {planner} | 2 |");
            assert!(kpi.contains(&row), "{row}\n{kpi}");
        }
    }
    // The logs record the values that ran: the arm's sparse spacing, certification and
    // near-terminal fraction, and MIT*'s suspension rule, not "the problem's".
    let log = std::fs::read_to_string(
        dir.join("logs")
            .join(format!("{}.log", results.instances[0].id)),
    )
    .unwrap();
    assert!(!log.contains("problem's"), "{log}");
    let mit = &log[log.find("MIT*").unwrap()..];
    for setting in [
        "sparse_initial_steps = 4\n",
        "sparse_min_steps = 2\n",
        "near_terminals = 0.15\n",
        "suspend_reverse_when_forward_empty = true\n",
    ] {
        assert!(mit.contains(setting), "{setting}{mit}");
    }
}
