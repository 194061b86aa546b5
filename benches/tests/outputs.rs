//! End-to-end checks of a results folder: the OMPL log read back by the grammar, the Planner
//! Arena database queried (also after appending a second experiment), raw runs, plots, and the
//! independent Python reader when `python3` is available.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use mit_star_benches::{
    BenchmarkLog, ExecutionOptions, Executor, Experiment, ExperimentResults, Figures,
    INSTANCE_SEED_STRIDE, LogValue, PathValidation, PlannerArenaDatabase, ResultsFolder, RunStatus,
};

const TINY: &str = r#"
name = "tiny"
runs = 2
seed = 5
planners = ["mit-star", { configuration = "eit-star", name = "EIT* (batch 50)", parameters = { batch_size = 50 } }]
[[problems]]
name = "dividing-walls"
dimensions = [2]
time = 0.02
[[problems]]
name = "random-rectangles"
dimensions = [2]
time = 0.02
instance_seeds = [3]
"#;

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("outputs-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn run_tiny() -> ExperimentResults {
    let experiment = Experiment::from_toml_str(TINY, "tiny", None).unwrap();
    let instances = experiment.instances().unwrap();
    let options = ExecutionOptions {
        threads: 2,
        ..ExecutionOptions::default()
    };
    Executor::new(options).run(&experiment, instances).unwrap()
}

/// The tiny experiment, run once, written to a results folder.
fn tiny() -> &'static (ExperimentResults, PathBuf) {
    static TINY_RESULTS: OnceLock<(ExperimentResults, PathBuf)> = OnceLock::new();
    TINY_RESULTS.get_or_init(|| {
        let results = run_tiny();
        let dir = scratch("tiny");
        let mut folder = ResultsFolder::prepare(&dir).unwrap();
        folder.write(&results, Figures::ScenesAndProblems).unwrap();
        (results, dir)
    })
}

#[test]
fn every_run_is_recorded_with_its_seed() {
    let (results, _) = tiny();
    assert_eq!(results.run_count(), 2 * 2 * 2);
    assert_eq!(results.concurrency, 2);
    assert!(!results.interrupted);
    // Run i on the k-th instance: the base seed 5, plus k · INSTANCE_SEED_STRIDE, plus i.
    assert_eq!(results.runs.len(), 2);
    for (k, runs) in results.runs.iter().enumerate() {
        let seeds: Vec<(String, u64)> = runs.iter().map(|r| (r.planner.clone(), r.seed)).collect();
        let first = 5 + k as u64 * INSTANCE_SEED_STRIDE;
        assert_eq!(
            seeds,
            [
                ("MIT*".to_owned(), first),
                ("MIT*".to_owned(), first + 1),
                ("EIT* (batch 50)".to_owned(), first),
                ("EIT* (batch 50)".to_owned(), first + 1)
            ]
        );
    }
    for r in results.all_runs() {
        assert_ne!(r.status, RunStatus::InvalidPath, "{r:?}");
        if r.is_success() {
            assert!(r.validation.as_ref().unwrap().valid);
            assert!(r.trace.windows(2).all(|w| w[1].cost < w[0].cost));
            assert!(r.initial_time.unwrap() <= r.run_time);
        }
    }
}

#[test]
fn seeds_and_order_do_not_depend_on_the_thread_count() {
    let experiment = Experiment::from_toml_str(TINY, "tiny", None).unwrap();
    let one = Executor::new(ExecutionOptions {
        threads: 1,
        ..ExecutionOptions::default()
    })
    .run(&experiment, experiment.instances().unwrap())
    .unwrap();
    let (two, _) = tiny();
    assert_eq!(one.concurrency, 1);
    let key = |r: &ExperimentResults| -> Vec<(String, String, usize, u64)> {
        r.all_runs()
            .map(|x| (x.instance.clone(), x.planner.clone(), x.run, x.seed))
            .collect()
    };
    assert_eq!(key(&one), key(two));
}

#[test]
fn the_log_follows_the_grammar_and_holds_every_run() {
    let (results, dir) = tiny();
    for (index, instance) in results.instances.iter().enumerate() {
        let path = dir.join("logs").join(format!("{}.log", instance.id));
        let text = std::fs::read_to_string(&path).unwrap();
        // The first lines, literally.
        let mut lines = text.lines();
        assert_eq!(
            lines.next(),
            Some(format!("OMPL version mit-star-{}", env!("CARGO_PKG_VERSION")).as_str())
        );
        assert_eq!(
            lines.next(),
            Some(format!("Experiment {}", instance.label).as_str())
        );
        assert_eq!(lines.next(), Some("3 experiment properties"));
        assert!(text.contains("\n1 enum types\nstatus|Unknown status|Invalid start|"));
        assert!(text.contains("\n5 is the random seed\n0.02 seconds per run\n"));
        assert!(text.contains("concurrent runs: 2"));
        let log = BenchmarkLog::parse(&text).unwrap();
        assert_eq!(log, BenchmarkLog::from_results(results, index));
        assert_eq!(log.runs_per_planner, Some(2));
        assert_eq!(log.planners.len(), 2);
        let concurrency = log
            .properties
            .iter()
            .find(|p| p.name == "concurrent_runs")
            .unwrap();
        assert_eq!(concurrency.value, LogValue::Integer(2));
        for planner in &log.planners {
            let runs = results.runs_of(index, &planner.name);
            assert_eq!(planner.runs.len(), runs.len());
            assert_eq!(planner.progress.len(), runs.len());
            let column = |name: &str| {
                planner
                    .run_properties
                    .iter()
                    .position(|p| p.name == name)
                    .unwrap()
            };
            for (row, (record, progress)) in
                planner.runs.iter().zip(runs.iter().zip(&planner.progress))
            {
                assert_eq!(row.len(), planner.run_properties.len());
                assert_eq!(
                    row[column("solved")],
                    LogValue::Integer(i64::from(record.is_success()))
                );
                assert_eq!(row[column("seed")], LogValue::Integer(record.seed as i64));
                match record.final_cost {
                    Some(c) if record.is_success() => {
                        assert_eq!(row[column("final cost")], LogValue::Real(c));
                    }
                    _ => assert_eq!(row[column("final cost")], LogValue::Null),
                }
                assert_eq!(progress.len(), record.statistics_trace().len());
            }
            assert!(
                planner
                    .common
                    .iter()
                    .any(|(k, v)| k == "seed" && v == "5+i")
            );
        }
        let eit = &log.planners[1];
        assert!(
            eit.common
                .iter()
                .any(|(k, v)| k == "batch_size" && v == "50")
        );
        // Each planner lists its own parameters, as OMPL's logs do: none of RRT-Connect's or
        // AORRTC's for EIT*, and none of the estimated informed set's (MIT*'s).
        let foreign = |k: &str| k == "range" || k.starts_with("rrt_") || k.starts_with("aorrtc_");
        assert!(
            eit.common.iter().all(|(k, _)| !foreign(k)),
            "{:?}",
            eit.common
        );
        assert!(eit.common.iter().all(|(k, _)| !k.starts_with("eis_")));
        let mit = &log.planners[0];
        assert!(mit.common.iter().any(|(k, _)| k == "eis_expansion_rule"));
    }
}

fn query_i64(db: &PlannerArenaDatabase, sql: &str) -> i64 {
    db.connection().query_row(sql, [], |r| r.get(0)).unwrap()
}

#[test]
fn the_database_has_planner_arenas_schema_and_appends() {
    let (results, dir) = tiny();
    let copy = scratch("append");
    std::fs::create_dir_all(&copy).unwrap();
    std::fs::copy(dir.join("benchmark.db"), copy.join("benchmark.db")).unwrap();
    let db = PlannerArenaDatabase::open(&copy.join("benchmark.db")).unwrap();
    assert_eq!(db.count("experiments").unwrap(), 2);
    assert_eq!(db.count("runs").unwrap(), results.run_count() as i64);
    assert_eq!(db.count("plannerConfigs").unwrap(), 2);
    assert_eq!(db.count("enums").unwrap(), 10);
    let traces: usize = results.all_runs().map(|r| r.statistics_trace().len()).sum();
    assert_eq!(db.count("progress").unwrap(), traces as i64);
    assert_eq!(
        query_i64(
            &db,
            "SELECT value FROM enums WHERE name = 'status' AND description = 'Exact solution'"
        ),
        6
    );
    // One row per run, with its experiment and planner.
    assert_eq!(
        query_i64(
            &db,
            "SELECT count(DISTINCT experimentid || '-' || plannerid || '-' || run_index) FROM runs"
        ),
        results.run_count() as i64
    );
    let columns: Vec<String> = {
        let mut s = db
            .connection()
            .prepare("PRAGMA table_info(experiments)")
            .unwrap();
        s.query_map([], |r| r.get::<_, String>(1))
            .unwrap()
            .map(Result::unwrap)
            .collect()
    };
    assert_eq!(
        columns,
        [
            "id",
            "name",
            "totaltime",
            "timelimit",
            "memorylimit",
            "runcount",
            "version",
            "hostname",
            "cpuinfo",
            "date",
            "seed",
            "setup",
            "concurrent_runs",
            "dimension",
            "instance"
        ]
    );
    assert_eq!(
        query_i64(&db, "SELECT max(concurrent_runs) FROM experiments"),
        2
    );
    assert_eq!(
        query_i64(&db, "SELECT count(*) FROM experiments WHERE instance = 3"),
        1
    );
    let solved: i64 = results.all_runs().filter(|r| r.is_success()).count() as i64;
    assert_eq!(query_i64(&db, "SELECT sum(solved) FROM runs"), solved);
    let settings: String = db
        .connection()
        .query_row(
            "SELECT settings FROM plannerConfigs WHERE name = 'EIT* (batch 50)'",
            [],
            |r| r.get(0),
        )
        .unwrap();
    assert!(
        settings.starts_with("accelerated_checks = true\n;batch_growth = 0\n;batch_size = 50\n;"),
        "{settings:?}"
    );
    drop(db);

    // A results folder refuses to rebuild (and so lose) a database holding runs its raw
    // files do not have.
    let mut folder = ResultsFolder::prepare(&copy).unwrap();
    let refused = folder
        .write(results, Figures::None)
        .unwrap_err()
        .to_string();
    assert!(refused.contains("holds 8 runs"), "{refused}");
    drop(folder);

    // Append the same experiment again: new ids, same planner configurations.
    let mut db = PlannerArenaDatabase::open(&copy.join("benchmark.db")).unwrap();
    for index in 0..results.instances.len() {
        db.insert(&BenchmarkLog::from_results(results, index))
            .unwrap();
    }
    let db = &db;
    assert_eq!(db.count("experiments").unwrap(), 4);
    assert_eq!(db.count("runs").unwrap(), 2 * results.run_count() as i64);
    assert_eq!(db.count("plannerConfigs").unwrap(), 2);
    assert_eq!(db.count("enums").unwrap(), 10);
    assert_eq!(query_i64(db, "SELECT max(id) FROM experiments"), 4);
    assert_eq!(
        query_i64(db, "SELECT count(DISTINCT experimentid) FROM runs"),
        4
    );
}

#[test]
fn raw_runs_plots_and_kpis_are_written() {
    let (results, dir) = tiny();
    let csv = std::fs::read_to_string(dir.join("runs.csv")).unwrap();
    let mut lines = csv.lines();
    let header = lines.next().unwrap();
    assert!(
        header.starts_with(
            "instance,problem,dimension,instance_seed,budget,concurrent_runs,planner,"
        )
    );
    assert!(header.contains(",peak_edges,sampler_checks,"));
    assert!(header.ends_with(",estimate_initial,estimate_final,trace"));
    assert_eq!(lines.count(), results.run_count());
    let jsonl = std::fs::read_to_string(dir.join("runs.jsonl")).unwrap();
    assert_eq!(jsonl.lines().count(), results.run_count());
    let first: serde_json::Value = serde_json::from_str(jsonl.lines().next().unwrap()).unwrap();
    assert_eq!(first["concurrent_runs"], 2);
    assert!(first["trace"].is_array() && first["counters"]["iterations"].is_u64());
    for instance in &results.instances {
        for ext in ["svg", "png"] {
            let path = dir.join("plots").join(format!("{}.{ext}", instance.id));
            let size = std::fs::metadata(&path).unwrap().len();
            assert!(size > 10_000, "{} is {size} bytes", path.display());
        }
        let svg = std::fs::read_to_string(dir.join("plots").join(format!("{}.svg", instance.id)))
            .unwrap();
        assert!(
            svg.contains("Median cost") && svg.contains("Success rate") && svg.contains("MIT*")
        );
    }
    let kpi = std::fs::read_to_string(dir.join("kpi.md")).unwrap();
    assert!(
        kpi.contains(
            "| problem | MIT* t_init | MIT* c_init | MIT* c_final | EIT* (batch 50) t_init"
        )
    );
    assert!(kpi.contains("t_init gain |"));
    assert!(kpi.contains("2 runs executing concurrently"));
    let rerun = Experiment::from_file(&dir.join("experiment.toml")).unwrap();
    assert_eq!(rerun, results.experiment);
}

#[test]
fn invalid_paths_are_flagged_in_every_output() {
    let (results, _) = tiny();
    let mut results = results.clone();
    // Whatever the run found, make it return a path through the walls.
    let problem = results.instances[0].problem.clone();
    let victim = &mut results.runs[0][0];
    victim.path = vec![problem.start().to_vec(), problem.goals()[0].clone()];
    victim.final_cost = Some(problem.straight_line_cost());
    let validation = problem.validate(&victim.path, problem.straight_line_cost());
    assert!(!validation.valid);
    victim.status = RunStatus::InvalidPath;
    victim.validation = Some(PathValidation {
        failure: Some("segment 2 → 3 collides (test)".into()),
        ..validation
    });
    let (planner, run) = (victim.planner.clone(), victim.run);
    let dir = scratch("invalid");
    let mut folder = ResultsFolder::prepare(&dir).unwrap();
    folder.write(&results, Figures::None).unwrap();
    let csv = std::fs::read_to_string(dir.join("runs.csv")).unwrap();
    assert!(csv.contains(",invalid-path,false,false,"), "{csv}");
    assert!(csv.contains("segment 2 → 3 collides (test)"));
    let kpi = std::fs::read_to_string(dir.join("kpi.md")).unwrap();
    assert!(kpi.contains("WARNING: 1 runs returned a path that failed"));
    assert!(kpi.contains("**1 INVALID**"));
    let log = BenchmarkLog::parse(
        &std::fs::read_to_string(
            dir.join("logs")
                .join(format!("{}.log", results.instances[0].id)),
        )
        .unwrap(),
    )
    .unwrap();
    let p = log.planners.iter().find(|p| p.name == planner).unwrap();
    let col = |name: &str| {
        p.run_properties
            .iter()
            .position(|q| q.name == name)
            .unwrap()
    };
    let row = &p.runs[run];
    assert_eq!(row[col("correct solution")], LogValue::Integer(0));
    assert_eq!(row[col("solved")], LogValue::Integer(0));
    assert_eq!(row[col("final cost")], LogValue::Null);
    let db = folder.database();
    assert_eq!(
        query_i64(db, "SELECT count(*) FROM runs WHERE correct_solution = 0"),
        1
    );
}

#[test]
fn the_python_reader_agrees_when_python_is_available() {
    let (_, dir) = tiny();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tools/check_ompl_log.py");
    let Ok(output) = Command::new("python3").arg(&script).arg(dir).output() else {
        eprintln!("python3 not found: skipping the independent reader");
        return;
    };
    assert!(
        output.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(String::from_utf8_lossy(&output.stdout).contains("2 logs agree"));
}
