//! [`ExperimentResults`]: every finished run of an experiment, with how and where it ran.

use crate::definition::experiment::Experiment;
use crate::definition::problem_instance::ProblemInstance;
use crate::execution::shard::Shard;
use crate::outcome::machine_info::MachineInfo;
use crate::outcome::run_record::{RunRecord, RunStatus};

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

    /// The runs the experiment schedules on these instances — every planner on every instance
    /// `experiment.runs` times — or the share of them `shard` owns (the schedule's positions
    /// `p ≡ K − 1 (mod N)`).
    ///
    /// ```
    /// use mit_star_benches::{Experiment, ExperimentResults, MachineInfo, Shard};
    /// let experiment = Experiment::from_toml_str(
    ///     "planners = [\"mit-star\", \"eit-star\"]\nruns = 5\n[[problems]]\n\
    ///      name = \"wall-gap\"\ndimensions = [2]\ntime = 0.05\n",
    ///     "doc",
    ///     None,
    /// )?;
    /// let instances = experiment.instances()?;
    /// let results = ExperimentResults {
    ///     runs: vec![Vec::new(); instances.len()],
    ///     experiment,
    ///     instances,
    ///     started_at: String::new(),
    ///     total_time: 0.0,
    ///     concurrency: 1,
    ///     interrupted: false,
    ///     machine: MachineInfo::detect(),
    /// };
    /// assert_eq!(results.planned_runs(None), 10);
    /// // Positions 0, 3, 6, 9 and 2, 5, 8 of the schedule.
    /// assert_eq!(results.planned_runs(Some("1/3".parse::<Shard>()?)), 4);
    /// assert_eq!(results.planned_runs(Some("3/3".parse::<Shard>()?)), 3);
    /// # Ok::<(), mit_star_benches::HarnessError>(())
    /// ```
    pub fn planned_runs(&self, shard: Option<Shard>) -> usize {
        let whole = self
            .instances
            .len()
            .saturating_mul(self.experiment.planners.len())
            .saturating_mul(self.experiment.runs);
        match shard {
            None => whole,
            Some(s) => (whole + s.count() - s.index()) / s.count(),
        }
    }
}
