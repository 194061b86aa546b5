//! [`BenchmarkLog`]: one problem instance's results in the form of an OMPL benchmark log, the
//! single source of what the `.log` file and the Planner Arena database hold.

use std::fmt::Write as _;

use crate::formats::ompl_log::log_value::{
    EnumType, ExperimentProperty, LogValue, Property, PropertyType,
};
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::run_record::RunRecord;

/// One planner's block of a log.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannerLog {
    /// The planner's name.
    pub name: String,
    /// Common properties: the configuration's parameters, `(name, value)`.
    pub common: Vec<(String, String)>,
    /// The run properties.
    pub run_properties: Vec<Property>,
    /// One row of values per run, in `run_properties` order.
    pub runs: Vec<Vec<LogValue>>,
    /// The progress properties (`time`, `best cost`).
    pub progress_properties: Vec<Property>,
    /// Per run, the progress samples (each one value per progress property).
    pub progress: Vec<Vec<Vec<LogValue>>>,
}

impl PlannerLog {
    /// `name = value` lines joined as OMPL's reader stores them in `plannerConfigs.settings`:
    /// each line with its line break, followed by `;`.
    pub fn settings(&self) -> String {
        self.common
            .iter()
            .map(|(k, v)| format!("{k} = {v}\n;"))
            .collect()
    }
}

/// The OMPL status enum's value descriptions, in value order.
pub const OMPL_STATUS: [&str; 10] = [
    "Unknown status",
    "Invalid start",
    "Invalid goal",
    "Unrecognized goal type",
    "Timeout",
    "Approximate solution",
    "Exact solution",
    "Crash",
    "Abort",
    "Infeasible",
];

/// One OMPL benchmark log: the results of every planner on one problem instance, in the
/// structure of OMPL's log grammar (spec `benchmarking.md`). [`to_text`](Self::to_text)
/// writes it; [`parse`](Self::parse) reads it back; the Planner Arena database is filled from
/// the same value, so both files always agree.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchmarkLog {
    /// The library name of the first line (`OMPL`).
    pub library: String,
    /// The version of the first line.
    pub version: String,
    /// The experiment's name (one word).
    pub experiment: String,
    /// Experiment properties.
    pub properties: Vec<ExperimentProperty>,
    /// The host's name.
    pub hostname: String,
    /// The start date.
    pub date: String,
    /// Setup description (free text, line-terminated lines).
    pub setup: String,
    /// CPU description (free text, line-terminated lines).
    pub cpu_info: Option<String>,
    /// The random seed.
    pub seed: u64,
    /// Seconds per run.
    pub time_limit: f64,
    /// MB per run (`-1`: no limit).
    pub memory_limit: f64,
    /// Runs per planner.
    pub runs_per_planner: Option<usize>,
    /// Seconds spent collecting the data.
    pub total_time: f64,
    /// Enum types.
    pub enums: Vec<EnumType>,
    /// The planners.
    pub planners: Vec<PlannerLog>,
}

impl BenchmarkLog {
    /// The log text, following OMPL's grammar: run values end with `"; "`, progress samples are
    /// `","`-terminated fields separated by `";"`, and every planner block ends with `.`.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{} version {}", self.library, self.version);
        let _ = writeln!(s, "Experiment {}", self.experiment);
        let _ = writeln!(s, "{} experiment properties", self.properties.len());
        for p in &self.properties {
            let _ = writeln!(
                s,
                "{} {} = {}",
                p.name,
                p.kind.word(),
                p.value.to_log_text()
            );
        }
        let _ = writeln!(s, "Running on {}", self.hostname);
        let _ = writeln!(s, "Starting at {}", self.date);
        block(&mut s, &self.setup);
        if let Some(cpu) = &self.cpu_info {
            block(&mut s, cpu);
        }
        let _ = writeln!(s, "{} is the random seed", self.seed);
        let _ = writeln!(s, "{} seconds per run", self.time_limit);
        let _ = writeln!(s, "{} MB per run", self.memory_limit);
        if let Some(runs) = self.runs_per_planner {
            let _ = writeln!(s, "{runs} runs per planner");
        }
        let _ = writeln!(s, "{} seconds spent to collect the data", self.total_time);
        let _ = writeln!(s, "{} enum types", self.enums.len());
        for e in &self.enums {
            let _ = writeln!(s, "{}|{}", e.name, e.values.join("|"));
        }
        let _ = writeln!(s, "{} planners", self.planners.len());
        for p in &self.planners {
            let _ = writeln!(s, "{}", p.name);
            let _ = writeln!(s, "{} common properties", p.common.len());
            for (k, v) in &p.common {
                let _ = writeln!(s, "{k} = {v}");
            }
            let _ = writeln!(s, "{} properties for each run", p.run_properties.len());
            for prop in &p.run_properties {
                let _ = writeln!(s, "{} {}", prop.name, prop.kind.word());
            }
            let _ = writeln!(s, "{} runs", p.runs.len());
            for run in &p.runs {
                for v in run {
                    let _ = write!(s, "{}; ", v.to_log_text());
                }
                s.push('\n');
            }
            if !p.progress_properties.is_empty() {
                let n = p.progress_properties.len();
                let _ = writeln!(s, "{n} progress properties for each run");
                for prop in &p.progress_properties {
                    let _ = writeln!(s, "{} {}", prop.name, prop.kind.word());
                }
                let _ = writeln!(s, "{} runs", p.progress.len());
                for run in &p.progress {
                    for sample in run {
                        for v in sample {
                            let _ = write!(s, "{},", v.to_log_text());
                        }
                        s.push(';');
                    }
                    s.push('\n');
                }
            }
            s.push_str(".\n");
        }
        s
    }

    /// The log of instance `index` of `results`; its header's run count is the number of runs
    /// recorded (per planner, the most any planner has), not the number planned.
    pub fn from_results(results: &ExperimentResults, index: usize) -> Self {
        Self::from_runs(results, index, &results.runs[index], results.total_time)
    }

    /// The log of instance `index` of `results` holding `runs` (runs of that instance, in
    /// place of `results.runs[index]`) and total time `total_time`: how a batch of finished runs
    /// is committed to the database without copying the experiment's results.
    pub(crate) fn from_runs(
        results: &ExperimentResults,
        index: usize,
        runs: &[RunRecord],
        total_time: f64,
    ) -> Self {
        let instance = &results.instances[index];
        let experiment = &results.experiment;
        let planners = experiment
            .planners
            .iter()
            .map(|spec| {
                let runs: Vec<&RunRecord> =
                    runs.iter().filter(|r| r.planner == spec.name()).collect();
                // The values that ran: defaults left to the problem or the planner decided
                // for this instance (a problem that refuses them ran nothing either).
                let parameters = spec.parameters_for_seed(experiment.seed);
                let parameters = instance
                    .problem
                    .effective_parameters(spec.configuration(), &parameters)
                    .unwrap_or(parameters);
                // The planner's own parameters, as OMPL lists each planner's properties.
                let mut common: Vec<(String, String)> = spec
                    .configuration()
                    .settings(&parameters)
                    .into_iter()
                    .map(|(k, v)| match k.as_str() {
                        "seed" => (k, format!("{}+i", experiment.seed)),
                        "resolution" => (k, instance.problem.resolution().to_string()),
                        _ => (k, v),
                    })
                    .collect();
                common.push(("configuration".into(), spec.configuration().name().into()));
                common.sort();
                PlannerLog {
                    name: spec.name().to_owned(),
                    common,
                    run_properties: run_properties(),
                    runs: runs.iter().map(|r| run_values(r)).collect(),
                    progress_properties: vec![
                        Property::new("time", PropertyType::Real),
                        Property::new("best cost", PropertyType::Real),
                    ],
                    progress: runs
                        .iter()
                        .map(|r| {
                            r.statistics_trace()
                                .iter()
                                .map(|p| vec![LogValue::real(p.time), LogValue::real(p.cost)])
                                .collect()
                        })
                        .collect(),
                }
            })
            .collect();
        let int = |name: &str, v: u64| ExperimentProperty {
            name: name.to_owned(),
            kind: PropertyType::Integer,
            value: LogValue::count(v),
        };
        Self {
            library: "OMPL".into(),
            version: format!("mit-star-{}", env!("CARGO_PKG_VERSION")),
            experiment: instance.label.clone(),
            properties: vec![
                int("dimension", instance.dimension as u64),
                int("instance", instance.instance),
                int("concurrent_runs", results.concurrency as u64),
            ],
            hostname: results.machine.hostname.clone(),
            date: results.started_at.clone(),
            setup: crate::formats::ompl_log::setup_description::setup_description(results, index),
            cpu_info: Some(format!("{}\n", results.machine.cpu)),
            seed: experiment.seed,
            time_limit: instance.budget,
            memory_limit: -1.0,
            // The recorded truth: an interrupted experiment has fewer runs than planned.
            runs_per_planner: Some(recorded_runs_per_planner(results, runs)),
            total_time,
            enums: vec![EnumType {
                name: "status".into(),
                values: OMPL_STATUS.iter().map(|s| (*s).to_owned()).collect(),
            }],
            planners,
        }
    }
}

/// Writes a `<<<| … |>>>` block; the text's lines end with a line break.
fn block(s: &mut String, text: &str) {
    s.push_str("<<<|\n");
    s.push_str(text);
    if !text.is_empty() && !text.ends_with('\n') {
        s.push('\n');
    }
    s.push_str("|>>>\n");
}

/// The run properties of every planner block, in order.
fn run_properties() -> Vec<Property> {
    use PropertyType::{Boolean, Enum, Integer, Real};
    let mut p = vec![
        Property::new("time", Real),
        Property::new("memory", Real),
        Property::new("status", Enum),
        Property::new("solved", Boolean),
        Property::new("approximate solution", Boolean),
        Property::new("solution length", Real),
        Property::new("solution segments", Integer),
        Property::new("correct solution", Boolean),
        Property::new("initial solution time", Real),
        Property::new("initial solution cost", Real),
        Property::new("final cost", Real),
        Property::new("run time", Real),
        Property::new("setup time", Real),
        Property::new("run index", Integer),
        Property::new("seed", Integer),
        Property::new("improvements", Integer),
        Property::new("validation checks", Integer),
    ];
    let names = RunRecord::counter_names();
    p.extend(names.iter().map(|n| Property::new(n, Integer)));
    let reals = RunRecord::real_counter_names();
    p.extend(reals.iter().map(|n| Property::new(n, Real)));
    p
}

/// One run's values, in [`run_properties`] order. Cost and time figures are `NULL` unless the
/// run succeeded (a path that failed validation is flagged by `correct solution = 0` and
/// `solved = 0`); `time` is the time to the first solution, or the budget without one.
fn run_values(r: &RunRecord) -> Vec<LogValue> {
    let ok = r.is_success();
    let when_ok = |v: Option<f64>| {
        if ok {
            LogValue::real_or_null(v)
        } else {
            LogValue::Null
        }
    };
    let mut v = vec![
        LogValue::real(if ok {
            r.initial_time_or_inf()
        } else {
            r.budget
        }),
        LogValue::Null,
        LogValue::Integer(r.status.ompl_status()),
        LogValue::boolean(ok),
        LogValue::boolean(false),
        when_ok(r.final_cost),
        if ok {
            LogValue::count(r.path.len().saturating_sub(1) as u64)
        } else {
            LogValue::Null
        },
        r.validation
            .as_ref()
            .map_or(LogValue::Null, |v| LogValue::boolean(v.valid)),
        when_ok(r.initial_time),
        when_ok(r.initial_cost),
        when_ok(r.final_cost),
        LogValue::real(r.run_time),
        LogValue::real(r.setup_time),
        LogValue::count(r.run as u64),
        LogValue::count(r.seed),
        LogValue::count(r.statistics_trace().len() as u64),
        r.validation
            .as_ref()
            .map_or(LogValue::Null, |v| LogValue::count(v.states_checked)),
    ];
    v.extend(r.counter_values().iter().map(|(_, c)| LogValue::count(*c)));
    v.extend(
        r.real_counter_values()
            .iter()
            .map(|(_, c)| LogValue::real_or_null(*c)),
    );
    v
}

/// Runs per planner of the experiment among `runs` (the most any planner has).
fn recorded_runs_per_planner(results: &ExperimentResults, runs: &[RunRecord]) -> usize {
    results
        .experiment
        .planners
        .iter()
        .map(|spec| runs.iter().filter(|r| r.planner == spec.name()).count())
        .max()
        .unwrap_or(0)
}
