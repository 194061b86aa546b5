//! [`ExperimentResults`]: every finished run of an experiment, with how and where it ran.

use crate::{Experiment, MachineInfo, ProblemInstance, RunRecord, RunStatus};

/// The outcome of executing an [`Experiment`]: the runs of every problem instance, and what
/// the outputs must record about the execution (start date, total time, how many runs
/// executed concurrently, whether it was interrupted, the machine).
#[derive(Debug, Clone)]
pub struct ExperimentResults {
    /// The experiment.
    pub experiment: Experiment,
    /// Its problem instances.
    pub instances: Vec<ProblemInstance>,
    /// The finished runs of each instance (same order as `instances`), ordered by planner
    /// (experiment order) and run index.
    pub runs: Vec<Vec<RunRecord>>,
    /// When the experiment started (ISO 8601, UTC).
    pub started_at: String,
    /// Seconds the whole experiment took.
    pub total_time: f64,
    /// How many runs executed at the same time (worker threads): concurrency changes timings.
    pub concurrency: usize,
    /// `true` if the experiment was interrupted (Ctrl-C): only finished runs are kept.
    pub interrupted: bool,
    /// The machine.
    pub machine: MachineInfo,
}

impl ExperimentResults {
    /// The finished runs of planner `planner` (by name) on instance `instance` (by index).
    pub fn runs_of(&self, instance: usize, planner: &str) -> Vec<&RunRecord> {
        self.runs
            .get(instance)
            .map(|runs| runs.iter().filter(|r| r.planner == planner).collect())
            .unwrap_or_default()
    }

    /// Every run whose returned path failed the independent validation.
    pub fn invalid_runs(&self) -> Vec<&RunRecord> {
        self.all_runs()
            .filter(|r| r.status == RunStatus::InvalidPath)
            .collect()
    }

    /// Every run whose planner reported an error.
    pub fn failed_runs(&self) -> Vec<&RunRecord> {
        self.all_runs()
            .filter(|r| r.status == RunStatus::Error)
            .collect()
    }

    /// Every finished run, instance after instance.
    pub fn all_runs(&self) -> impl Iterator<Item = &RunRecord> {
        self.runs.iter().flatten()
    }

    /// Number of finished runs.
    pub fn run_count(&self) -> usize {
        self.runs.iter().map(Vec::len).sum()
    }
}
