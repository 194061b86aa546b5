//! Audits in batches ([`AuditBatch`]): a worker that solves short runs back to back and audits
//! them afterwards records what a worker auditing each run at once records, hands the sink no
//! unaudited run, and keeps every finished run when interrupted.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use mit_star_benches::{
    AuditBatch, ExecutionOptions, Executor, Experiment, ExperimentResults, RunRecord, RunStatus,
};

/// Short first-solution runs, three planners, deterministic given their seeds.
const SHORT_RUNS: &str = r#"
name = "short-runs"
runs = 6
seed = 11
first_solution = true
planners = ["mit-star", "eit-star", "rrt-connect"]
[[problems]]
name = "dividing-walls"
dimensions = [2, 4]
time = 5.0
"#;

fn experiment() -> Experiment {
    Experiment::from_toml_str(SHORT_RUNS, "short-runs", None).unwrap()
}

fn run(batch: AuditBatch, sink: Option<Arc<mit_star_benches::RecordSink>>) -> ExperimentResults {
    run_with(batch, sink, Arc::new(AtomicBool::new(false)))
}

fn run_with(
    batch: AuditBatch,
    sink: Option<Arc<mit_star_benches::RecordSink>>,
    interrupt: Arc<AtomicBool>,
) -> ExperimentResults {
    let experiment = experiment();
    let options = ExecutionOptions {
        threads: 1,
        audit_batch: batch,
        on_record: sink,
        interrupt,
        ..ExecutionOptions::default()
    };
    Executor::new(options)
        .run(&experiment, experiment.instances().unwrap())
        .unwrap()
}

/// What a run decided and what its audit found, without its timings.
fn decisions(record: &RunRecord) -> String {
    let validation = record.validation.as_ref().map(|v| {
        (
            v.valid,
            v.method,
            v.states_checked,
            v.segments_checked,
            v.length,
        )
    });
    format!(
        "{} {} {} {} {:?} {:?} {:?} {:?}",
        record.instance,
        record.planner,
        record.run,
        record.seed,
        record.status,
        record.final_cost,
        record.path,
        validation
    )
}

#[test]
fn batched_audits_record_what_audits_of_each_run_record() {
    let each = run(AuditBatch::EACH_RUN, None);
    let batched = run(AuditBatch::DEFAULT, None);
    assert_eq!(each.run_count(), 2 * 3 * 6);
    let each: Vec<String> = each.all_runs().map(decisions).collect();
    let batched: Vec<String> = batched.all_runs().map(decisions).collect();
    assert_eq!(each, batched);
}

#[test]
fn the_sink_never_sees_an_unaudited_path() {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let into = Arc::clone(&seen);
    let sink = move |_: usize, record: &RunRecord| into.lock().unwrap().push(record.clone());
    let results = run(
        AuditBatch {
            runs: 5,
            seconds: 10.0,
        },
        Some(Arc::new(sink)),
    );
    let seen = seen.lock().unwrap();
    assert_eq!(seen.len(), results.run_count());
    let solved = seen
        .iter()
        .filter(|r| r.status == RunStatus::Solved)
        .count();
    assert!(solved > 30, "{solved} of {} runs solved", seen.len());
    for record in seen.iter() {
        if !record.path.is_empty() {
            let validation = record.validation.as_ref().expect("audited");
            assert!(validation.valid, "{record:?}");
        }
    }
}

#[test]
fn an_interrupted_worker_records_the_runs_awaiting_their_audit() {
    // The interrupt is raised as the first audited run reaches the sink: the other runs of its
    // batch are finished, so they are audited and recorded too, and no new run starts.
    let interrupt = Arc::new(AtomicBool::new(false));
    let raise = Arc::clone(&interrupt);
    let count = Arc::new(AtomicUsize::new(0));
    let counted = Arc::clone(&count);
    let sink = move |_: usize, record: &RunRecord| {
        assert!(record.path.is_empty() || record.validation.is_some());
        counted.fetch_add(1, Ordering::SeqCst);
        raise.store(true, Ordering::SeqCst);
    };
    let batch = AuditBatch {
        runs: 4,
        seconds: 10.0,
    };
    let results = run_with(batch, Some(Arc::new(sink)), interrupt);
    assert!(results.interrupted);
    assert_eq!(count.load(Ordering::SeqCst), 4, "the first batch, whole");
    assert_eq!(results.run_count(), 4);
}
