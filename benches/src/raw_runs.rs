//! Raw runs: `runs.csv` (one row per run) and `runs.jsonl` (one JSON object per run, with its
//! trace and path).

use std::io::Write as _;
use std::path::Path;

use crate::{ExperimentResults, HarnessError, RunRecord};

/// The fixed CSV columns before the counters (the trace column comes last).
pub const CSV_COLUMNS: [&str; 23] = [
    "instance",
    "problem",
    "dimension",
    "instance_seed",
    "budget",
    "concurrent_runs",
    "planner",
    "configuration",
    "run",
    "seed",
    "status",
    "success",
    "valid_path",
    "setup_time",
    "run_time",
    "initial_time",
    "initial_cost",
    "final_cost",
    "improvements",
    "path_states",
    "validation_checks",
    "validation_failure",
    "error",
];

fn optional(v: Option<f64>) -> String {
    v.filter(|x| x.is_finite())
        .map_or_else(String::new, |x| x.to_string())
}

/// Writes `runs.csv`: one row per finished run, the columns of [`CSV_COLUMNS`], then one
/// column per work counter (snake case), then `trace` (`time:cost` pairs separated by spaces,
/// seconds since the run started). Empty cells mean "none" (no solution, no error).
///
/// # Errors
/// [`HarnessError::Io`] or [`HarnessError::Serialise`] if the file cannot be written.
pub fn write_runs_csv(path: &Path, results: &ExperimentResults) -> Result<(), HarnessError> {
    let fail = |message: String| HarnessError::Serialise {
        path: path.to_path_buf(),
        message,
    };
    let mut w = csv::Writer::from_path(path).map_err(|e| fail(e.to_string()))?;
    let mut header: Vec<String> = CSV_COLUMNS.iter().map(|s| (*s).to_owned()).collect();
    header.extend(
        RunRecord::counter_names()
            .iter()
            .map(|n| n.replace(' ', "_")),
    );
    header.push("trace".into());
    w.write_record(&header).map_err(|e| fail(e.to_string()))?;
    for (index, runs) in results.runs.iter().enumerate() {
        let instance = &results.instances[index];
        for r in runs {
            let mut row = vec![
                instance.id.clone(),
                instance.label.clone(),
                instance.dimension.to_string(),
                instance.instance.to_string(),
                instance.budget.to_string(),
                results.concurrency.to_string(),
                r.planner.clone(),
                r.configuration.name().to_owned(),
                r.run.to_string(),
                r.seed.to_string(),
                r.status.name().to_owned(),
                r.is_success().to_string(),
                r.validation
                    .as_ref()
                    .map_or_else(String::new, |v| v.valid.to_string()),
                r.setup_time.to_string(),
                r.run_time.to_string(),
                optional(r.initial_time),
                optional(r.initial_cost),
                optional(r.final_cost),
                r.trace.len().to_string(),
                r.path.len().to_string(),
                r.validation
                    .as_ref()
                    .map_or_else(String::new, |v| v.states_checked.to_string()),
                r.validation
                    .as_ref()
                    .and_then(|v| v.failure.clone())
                    .unwrap_or_default(),
                r.error.clone().unwrap_or_default(),
            ];
            row.extend(r.counter_values().iter().map(|(_, c)| c.to_string()));
            row.push(
                r.trace
                    .iter()
                    .map(|p| format!("{}:{}", p.time, p.cost))
                    .collect::<Vec<_>>()
                    .join(" "),
            );
            w.write_record(&row).map_err(|e| fail(e.to_string()))?;
        }
    }
    w.flush().map_err(|e| fail(e.to_string()))
}

/// Writes `runs.jsonl`: one JSON object per finished run — every field of [`RunRecord`]
/// (trace, path, validation, counters) plus `problem`, `dimension`, `instance_seed` and
/// `concurrent_runs`.
///
/// # Errors
/// [`HarnessError::Io`] or [`HarnessError::Serialise`] if the file cannot be written.
pub fn write_runs_jsonl(path: &Path, results: &ExperimentResults) -> Result<(), HarnessError> {
    let io = |source| HarnessError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::create(path).map_err(io)?;
    let mut out = std::io::BufWriter::new(file);
    for (index, runs) in results.runs.iter().enumerate() {
        let instance = &results.instances[index];
        for r in runs {
            let mut value = serde_json::to_value(r).map_err(|e| HarnessError::Serialise {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?;
            if let Some(object) = value.as_object_mut() {
                object.insert("problem".into(), instance.label.clone().into());
                object.insert("dimension".into(), instance.dimension.into());
                object.insert("instance_seed".into(), instance.instance.into());
                object.insert("concurrent_runs".into(), results.concurrency.into());
            }
            writeln!(out, "{value}").map_err(io)?;
        }
    }
    out.flush().map_err(io)
}
