//! [`RunRecord`] and [`RunStatus`]: everything measured in one run of one planner.

use mit_star::{COUNT_NAMES, COUNT_NAMES_LEN, Configuration, Counters, REAL_NAMES, TracePoint};
use serde::{Deserialize, Serialize};

use crate::path_validation::PathValidation;

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum RunStatus {
    /// A solution was found and passed the independent validation.
    Solved,
    /// No solution within the budget.
    Unsolved,
    /// The planner returned a path that failed the independent validation: counted as a
    /// failure everywhere, and flagged.
    InvalidPath,
    /// The planner refused the query or could not be built.
    Error,
}

impl RunStatus {
    /// The status's name (`solved`, `unsolved`, `invalid-path`, `error`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Solved => "solved",
            Self::Unsolved => "unsolved",
            Self::InvalidPath => "invalid-path",
            Self::Error => "error",
        }
    }

    /// The value of OMPL's `status` enum: what the planner reported (`Exact solution` = 6,
    /// also for an invalid path, which the `correct solution` and `solved` properties flag;
    /// `Timeout` = 4; `Crash` = 7 for errors).
    pub fn ompl_status(self) -> i64 {
        match self {
            Self::Solved | Self::InvalidPath => 6,
            Self::Unsolved => 4,
            Self::Error => 7,
        }
    }
}

/// One run of one planner on one problem instance.
///
/// Times are seconds since the run started, before the planner was built (construction counts
/// against the budget): `initial_time` and every trace point include `setup_time`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunRecord {
    /// The problem instance's id.
    pub instance: String,
    /// The planner's name.
    pub planner: String,
    /// The planner's configuration.
    pub configuration: Configuration,
    /// The run index `i` (0-based).
    pub run: usize,
    /// The planner's seed (`base seed + k · 100 000 + i` on the `k`-th instance).
    pub seed: u64,
    /// The budget in seconds.
    pub budget: f64,
    /// How the run ended.
    pub status: RunStatus,
    /// Seconds to build the planner.
    pub setup_time: f64,
    /// Seconds the run took (construction and planning; about the budget unless the planner
    /// proved its solution optimal early).
    pub run_time: f64,
    /// Seconds to the first solution.
    pub initial_time: Option<f64>,
    /// Cost of the first solution.
    pub initial_cost: Option<f64>,
    /// Cost of the returned solution.
    pub final_cost: Option<f64>,
    /// Every improvement `(seconds since the run started, cost)`.
    pub trace: Vec<TracePoint>,
    /// The returned path (empty without a solution).
    pub path: Vec<Vec<f64>>,
    /// The joint each coordinate of the path's states is, in coordinate order (arm problems
    /// with a path; empty otherwise, and in records written before joints were recorded).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub joints: Vec<String>,
    /// Per coordinate, `true` for a continuous joint: its value wraps at `±π`, and a motion
    /// between two states takes the short way round (empty as [`joints`](Self::joints)).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub wrapping: Vec<bool>,
    /// The independent validation of the returned path.
    pub validation: Option<PathValidation>,
    /// The planner's work counters.
    pub counters: Counters,
    /// The error, for [`RunStatus::Error`].
    pub error: Option<String>,
}

impl RunRecord {
    /// The run's identity in a results folder: instance id, planner name, run index.
    pub fn key(&self) -> crate::RunKey {
        (self.instance.clone(), self.planner.clone(), self.run)
    }

    /// `true` if the run found a solution that passed validation.
    pub fn is_success(&self) -> bool {
        self.status == RunStatus::Solved
    }

    /// The trace statistics use: the run's trace if it succeeded, empty otherwise (a failed
    /// run counts as `+∞` at every time).
    pub fn statistics_trace(&self) -> &[TracePoint] {
        if self.is_success() { &self.trace } else { &[] }
    }

    /// Time to the first solution, `+∞` unless the run succeeded.
    pub fn initial_time_or_inf(&self) -> f64 {
        self.success_value(self.initial_time)
    }

    /// Cost of the first solution, `+∞` unless the run succeeded.
    pub fn initial_cost_or_inf(&self) -> f64 {
        self.success_value(self.initial_cost)
    }

    /// Final cost, `+∞` unless the run succeeded.
    pub fn final_cost_or_inf(&self) -> f64 {
        self.success_value(self.final_cost)
    }

    fn success_value(&self, value: Option<f64>) -> f64 {
        match value {
            Some(v) if self.is_success() => v,
            _ => f64::INFINITY,
        }
    }

    /// The work counters as `(name, value)`, in a fixed order ([`mit_star::COUNT_NAMES`]):
    /// the one list every output (CSV, OMPL log, database, `plan`) takes them from.
    pub fn counter_values(&self) -> [(&'static str, u64); COUNTERS] {
        self.counters.counts()
    }

    /// The names of [`counter_values`](Self::counter_values), in order.
    pub fn counter_names() -> [&'static str; COUNTERS] {
        COUNT_NAMES
    }

    /// The real-valued counters (the estimated informed set's first and last cost, `None`
    /// when the planner never created one) as `(name, value)`, in a fixed order.
    pub fn real_counter_values(&self) -> [(&'static str, Option<f64>); 2] {
        self.counters.reals()
    }

    /// The names of [`real_counter_values`](Self::real_counter_values), in order.
    pub fn real_counter_names() -> [&'static str; 2] {
        REAL_NAMES
    }
}

/// How many integer counters a run records.
pub(crate) const COUNTERS: usize = COUNT_NAMES_LEN;

#[cfg(test)]
impl RunRecord {
    /// A solved-looking run of MIT* for tests, with `status`.
    pub(crate) fn example(status: RunStatus) -> RunRecord {
        RunRecord {
            instance: "i".into(),
            planner: "MIT*".into(),
            configuration: Configuration::MitStar,
            run: 0,
            seed: 0,
            budget: 1.0,
            status,
            setup_time: 0.0,
            run_time: 1.0,
            initial_time: Some(0.1),
            initial_cost: Some(2.0),
            final_cost: Some(1.5),
            trace: vec![TracePoint {
                time: 0.1,
                cost: 2.0,
            }],
            path: Vec::new(),
            joints: Vec::new(),
            wrapping: Vec::new(),
            validation: None,
            counters: Counters::default(),
            error: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(status: RunStatus) -> RunRecord {
        RunRecord::example(status)
    }

    #[test]
    fn only_validated_solutions_count() {
        let ok = record(RunStatus::Solved);
        assert!(ok.is_success());
        assert_eq!(
            (ok.initial_time_or_inf(), ok.final_cost_or_inf()),
            (0.1, 1.5)
        );
        assert_eq!(ok.statistics_trace().len(), 1);
        let bad = record(RunStatus::InvalidPath);
        assert!(!bad.is_success());
        assert_eq!(bad.initial_cost_or_inf(), f64::INFINITY);
        assert!(bad.statistics_trace().is_empty());
        assert_eq!(RunStatus::InvalidPath.ompl_status(), 6);
        assert_eq!(RunStatus::Unsolved.ompl_status(), 4);
        assert_eq!(RunStatus::Error.name(), "error");
        let names: Vec<&str> = ok.counter_values().iter().map(|c| c.0).collect();
        assert!(names.contains(&"vertices") && names.contains(&"sparse_checks_by_length_4"));
    }
}
