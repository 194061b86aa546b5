//! Experiments from Python: [`run_experiment`] (a shipped experiment or an experiment file,
//! on worker threads, interruptible by Ctrl-C), [`read_results`] (a results folder written by
//! `mit-star bench`), and [`PyExperimentResults`], whose runs read as a pandas-friendly table.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::Duration;

use mit_star_benches::{
    ExecutionOptions, Executor, Experiment, ExperimentResults, KpiTable, ResultsFolder,
    ShippedExperiment, kpi_markdown,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;

use crate::error::{BindingError, BindingResult};
use crate::json_value::json_to_python;
use crate::parameters::overrides;

/// How often a running experiment checks for Ctrl-C.
const POLL: Duration = Duration::from_millis(20);

/// The shipped experiments (`smoke`, `ablation`, `paper-table`, …) as `(name, summary)`.
#[pyfunction]
pub(crate) fn experiments() -> Vec<(&'static str, &'static str)> {
    ShippedExperiment::all()
        .iter()
        .map(|e| (e.name, e.summary))
        .collect()
}

/// Runs an experiment — a shipped one by name (`mit_star.experiments()`) or an experiment
/// file (`*.toml`) — and returns its results.
///
/// `runs` and `seed` replace the experiment's; every other keyword is a planner parameter
/// applied to every planner (as `mit-star bench --set`). `threads` runs execute at once
/// (default 1: concurrent runs perturb each other's timings). With `output`, the results
/// folder `mit-star bench --output` writes is written there too (raw runs, OMPL logs, the
/// Planner Arena database, `kpi.md`, and with `plots=True` one figure per scene). Ctrl-C stops the
/// experiment and raises `KeyboardInterrupt`; finished runs are then lost unless `output` was
/// given.
#[pyfunction]
#[allow(clippy::needless_pass_by_value, clippy::too_many_arguments)] // PyO3's argument shape
#[pyo3(signature = (experiment, *, runs=None, seed=None, threads=1, output=None, plots=false, **params))]
pub(crate) fn run_experiment(
    py: Python<'_>,
    experiment: &str,
    runs: Option<usize>,
    seed: Option<u64>,
    threads: usize,
    output: Option<PathBuf>,
    plots: bool,
    params: Option<&Bound<'_, PyDict>>,
) -> BindingResult<PyExperimentResults> {
    let mut definition = if experiment.ends_with(".toml") || Path::new(experiment).is_file() {
        Experiment::from_file(Path::new(experiment))?
    } else {
        Experiment::shipped(experiment)?
    };
    definition = definition.with_overrides(&overrides(params)?)?;
    if let Some(runs) = runs {
        definition.runs = runs;
    }
    if let Some(seed) = seed {
        definition.seed = seed;
    }
    definition.validate(experiment)?;
    let mut folder = output.as_deref().map(ResultsFolder::prepare).transpose()?;
    let instances = definition.instances()?;
    let options = ExecutionOptions {
        threads,
        ..ExecutionOptions::default()
    };
    let interrupt = Arc::clone(&options.interrupt);
    let executor = Executor::new(options);
    let (results, signal) = py.detach(|| {
        std::thread::scope(|scope| {
            let worker = scope.spawn(|| executor.run(&definition, instances));
            let mut signal = None;
            while !worker.is_finished() {
                std::thread::sleep(POLL);
                if signal.is_none()
                    && let Err(error) = Python::attach(|py| py.check_signals())
                {
                    interrupt.store(true, Ordering::SeqCst);
                    signal = Some(error);
                }
            }
            let results = worker.join().unwrap_or_else(|_| {
                Err(mit_star_benches::HarnessError::Usage(
                    "the experiment's worker thread failed".into(),
                ))
            });
            (results, signal)
        })
    });
    let results = results?;
    if let Some(folder) = &mut folder {
        let figures = if plots {
            mit_star_benches::Figures::Scenes
        } else {
            mit_star_benches::Figures::None
        };
        folder.write(&results, figures)?;
    }
    if let Some(error) = signal {
        return Err(error.into());
    }
    Ok(PyExperimentResults { results })
}

/// The results recorded in a results folder written by `mit-star bench` or `run_experiment`.
#[pyfunction]
#[allow(clippy::needless_pass_by_value)] // PyO3's argument shape
pub(crate) fn read_results(folder: PathBuf) -> BindingResult<PyExperimentResults> {
    Ok(PyExperimentResults {
        results: ResultsFolder::read_results(&folder)?,
    })
}

/// The results of an experiment: every finished run, with the experiment and its instances.
///
/// `records()` gives one flat `dict` per run and `table()` the same as a `dict` of columns,
/// both ready for `pandas.DataFrame(...)`; `kpi_markdown()` is the paper's KPI table.
#[pyclass(module = "mit_star._native", name = "ExperimentResults", frozen)]
#[derive(Debug)]
pub struct PyExperimentResults {
    /// The results.
    results: ExperimentResults,
}

impl PyExperimentResults {
    /// Every run as a flat JSON object: the record's scalars, `valid`, `validation_failure`
    /// and `validation_seconds` (the independent check's own time) from its path validation,
    /// the counters' fields, the trace as `[seconds, cost]` pairs and
    /// (with `paths`) the path with, for an arm, its `joints` and `wrapping`.
    fn flat_records(&self, paths: bool) -> BindingResult<Vec<serde_json::Map<String, Value>>> {
        let mut rows = Vec::new();
        for record in self.results.all_runs() {
            let Value::Object(mut row) =
                serde_json::to_value(record).map_err(|e| BindingError::Value(e.to_string()))?
            else {
                continue;
            };
            if !paths {
                for key in ["path", "joints", "wrapping"] {
                    row.remove(key);
                }
            }
            if let Some(Value::Object(counters)) = row.remove("counters") {
                row.extend(counters);
            }
            let validation = row.remove("validation");
            let valid = validation.as_ref().and_then(|v| v.get("valid")).cloned();
            let failure = validation.as_ref().and_then(|v| v.get("failure")).cloned();
            let seconds = validation.as_ref().and_then(|v| v.get("seconds")).cloned();
            row.insert("valid".into(), valid.unwrap_or(Value::Null));
            row.insert("validation_failure".into(), failure.unwrap_or(Value::Null));
            row.insert("validation_seconds".into(), seconds.unwrap_or(Value::Null));
            if let Some(Value::Array(points)) = row.get_mut("trace") {
                for point in points.iter_mut() {
                    let (t, c) = (point.get("time").cloned(), point.get("cost").cloned());
                    *point = Value::Array(vec![t.unwrap_or(Value::Null), c.unwrap_or(Value::Null)]);
                }
            }
            rows.push(row);
        }
        Ok(rows)
    }
}

#[pymethods]
impl PyExperimentResults {
    /// One `dict` per finished run: `instance`, `planner`, `configuration`, `run`, `seed`,
    /// `budget`, `status`, `setup_time`, `run_time`, `initial_time`, `initial_cost`,
    /// `final_cost`, `valid`, `validation_seconds` (the independent check's time, apart from
    /// `run_time`), `error`, the counters (`iterations`, `samples`, …) and `trace`
    /// (`[seconds, cost]` pairs); with `paths=True` also `path` (a list of states) and, for
    /// an arm, `joints` (the joint each coordinate is, in order) and `wrapping` (`True` for a
    /// continuous joint: interpolate it the short way round).
    #[pyo3(signature = (*, paths=false))]
    fn records<'py>(&self, py: Python<'py>, paths: bool) -> BindingResult<Bound<'py, PyList>> {
        let list = PyList::empty(py);
        for row in self.flat_records(paths)? {
            list.append(json_to_python(py, &Value::Object(row))?)?;
        }
        Ok(list)
    }

    /// The runs as a `dict` of columns (the keys of `records()`, `None` where a run lacks one):
    /// `pandas.DataFrame(results.table())`.
    #[pyo3(signature = (*, paths=false))]
    fn table<'py>(&self, py: Python<'py>, paths: bool) -> BindingResult<Bound<'py, PyDict>> {
        let rows = self.flat_records(paths)?;
        let mut keys: Vec<String> = Vec::new();
        for row in &rows {
            for key in row.keys() {
                if !keys.contains(key) {
                    keys.push(key.clone());
                }
            }
        }
        let table = PyDict::new(py);
        for key in keys {
            let column: Vec<Value> = rows
                .iter()
                .map(|row| row.get(&key).cloned().unwrap_or(Value::Null))
                .collect();
            table.set_item(key, json_to_python(py, &Value::Array(column))?)?;
        }
        Ok(table)
    }

    /// The paper's KPI table (Table I) and the full KPIs, as Markdown.
    fn kpi_markdown(&self) -> String {
        kpi_markdown(&self.results, &KpiTable::from_results(&self.results))
    }

    /// The experiment's name.
    #[getter]
    fn name(&self) -> &str {
        &self.results.experiment.name
    }

    /// The planners' names, in report order.
    #[getter]
    fn planners(&self) -> Vec<String> {
        self.results
            .experiment
            .planners
            .iter()
            .map(|p| p.name().to_owned())
            .collect()
    }

    /// The problem instances' identifiers.
    #[getter]
    fn instances(&self) -> Vec<String> {
        self.results
            .instances
            .iter()
            .map(|i| i.id.clone())
            .collect()
    }

    /// How many runs finished.
    #[getter]
    fn run_count(&self) -> usize {
        self.results.run_count()
    }

    /// Seconds the whole experiment took.
    #[getter]
    fn total_time(&self) -> f64 {
        self.results.total_time
    }

    /// `True` if the experiment was interrupted.
    #[getter]
    fn interrupted(&self) -> bool {
        self.results.interrupted
    }

    fn __repr__(&self) -> String {
        format!(
            "ExperimentResults({:?}, runs={}, planners={:?})",
            self.results.experiment.name,
            self.results.run_count(),
            self.planners()
        )
    }
}
