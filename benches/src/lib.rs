//! The mit-star experiment harness and the `mit-star` command-line tool.
//!
//! One command runs the paper's experiments — planners × problems × dimensions × seeds — on
//! every core, and writes what motion-planning researchers read with their own tools: raw runs
//! (CSV, JSON lines), OMPL benchmark logs (`ompl_benchmark_statistics.py`), a Planner Arena
//! database, SVG/PNG figures and the KPI table of the paper's Table I. Statistics follow PDT:
//! medians of order statistics with nonparametric confidence intervals (unsolved runs count as
//! `+∞`), Clopper–Pearson intervals for success rates. Every returned path is re-validated
//! independently at full resolution.
//!
//! ```
//! use mit_star_benches::{ExecutionOptions, Executor, Experiment, KpiTable};
//!
//! // MIT* and EIT* on the 2-D dividing walls, 2 runs of 20 ms each.
//! let experiment = Experiment::from_toml_str(
//!     r#"
//!     runs = 2
//!     planners = ["mit-star", "eit-star"]
//!     [[problems]]
//!     name = "dividing-walls"
//!     dimensions = [2]
//!     time = 0.02
//!     "#,
//!     "doc",
//!     None,
//! )?;
//! let instances = experiment.instances()?;
//! let options = ExecutionOptions { threads: 2, ..ExecutionOptions::default() };
//! let results = Executor::new(options).run(&experiment, instances)?;
//! assert_eq!(results.run_count(), 4);
//! assert!(results.invalid_runs().is_empty());
//! let table = KpiTable::from_results(&results);
//! assert!(table.paper_markdown().contains("| dividing-walls R^2 |"));
//! # Ok::<(), mit_star_benches::HarnessError>(())
//! ```
//!
//! # Layout
//! | folder | what it holds |
//! |---|---|
//! | `definition/` | defining experiments: the experiment and its TOML file, shipped experiments, planner and problem specs, parameter overrides, problem sources, instances and their problems |
//! | `execution/` | running them: the run schedule, the executor, interrupts, the run journal, the results folder (lock, agreement), shards and their merge |
//! | `outcome/` | what was measured: run records, an experiment's results, the machine |
//! | `formats/` | the result formats, each writer beside its reader: `ompl_log/` (OMPL logs written and parsed), the Planner Arena database, raw runs (CSV, JSON lines), KPI tables and campaign comparisons |
//! | `pictures/` | figures of experiments, pictures of 2-D runs and of arm plans, their shared style |
//! | `statistics/` | medians and their confidence intervals, Clopper–Pearson, anytime series |
//! | `replanning/` | the paper's re-planning experiment on the Panda: moving-obstacle scenes, the trial loop, its judge, table and picture ([`replanning`]) |
//! | `commands/` | the `mit-star` command line, thin on top of the rest |
//! | `path_validation.rs`, `budget.rs`, `error.rs` | the independent path check; time budgets; [`HarnessError`] |
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`Experiment`], [`experiment_file`], [`ShippedExperiment`] | an experiment; its TOML file format; the embedded `paper-table`, `ablation`, `smoke` |
//! | [`PlannerSpec`], [`parse_configuration`], [`ParameterOverrides`] | a planner of an experiment; configuration names; `key = value` parameter changes |
//! | [`ProblemSpec`], [`ProblemSource`], [`ProblemInstance`] | a problem over dimensions and layouts; built-in or file; one concrete instance with its budget |
//! | [`MbmFolder`], [`RobotChoice`] | a MotionBenchMaker folder and the robot planned for (`--robot`, shipped or a folder) |
//! | [`PoseGoalSpec`], [`PoseGoalSource`], [`pose_goal_planner`] | a link's pose as an arm problem's goal (`plan --goal-pose`, `[problems.pose_goal]`); the goal region inverse kinematics makes of it; the planner towards it |
//! | [`RunJob`], [`Executor`], [`ExecutionOptions`], [`Interrupt`] | the shuffled, seeded schedule of runs; parallel execution with progress; SIGINT/SIGTERM |
//! | [`RunJournal`], [`results_from_records`] | every finished run appended to the raw files at once and committed to the database in batches; reading them back |
//! | [`RunRecord`], [`RunStatus`], [`PathValidation`], [`ValidationMethod`] | what one run measured; how it ended; the independent path check (exact for box worlds) |
//! | [`ExperimentResults`], [`MachineInfo`], [`iso_timestamp`] | every finished run, with how, when and where it ran |
//! | [`statistics`] | medians and their confidence intervals, Clopper–Pearson, anytime series |
//! | [`Scene`], [`SceneSummary`], [`SceneRow`] | the instances of one problem in one dimension; the summary by scene `bench` prints |
//! | [`KpiTable`], [`KpiRow`], [`t_init_gain`] | the paper's Table I and the full KPIs |
//! | [`BenchmarkLog`] (+ [`PlannerLog`], [`Property`], [`PropertyType`], [`LogValue`], [`EnumType`], [`ExperimentProperty`]) | OMPL benchmark logs: write and parse |
//! | [`PlannerArenaDatabase`] | the SQLite database Planner Arena reads |
//! | [`write_runs_csv`], [`write_runs_jsonl`] | raw runs |
//! | [`ExperimentFigure`], [`RunPicture`], [`ArmPicture`], [`planner_colours`] | figures of experiments; pictures of 2-D runs and of arm plans |
//! | [`ResultsFolder`], [`Figures`], [`kpi_markdown`], [`kpi_overview`], [`writable_folder`] | the results folder and its files; which figures it gets; `kpi.md` and its head |
//! | [`Shard`], [`SHARD_FILE`], [`merge_parts`], [`MergeReport`] | one of N disjoint parts of an experiment (`bench --shard K/N`); the parts' folders combined into one |
//! | [`CampaignComparison`], [`ComparedRow`], [`Change`] | two results folders side by side (`mit-star compare A B`) |
//! | [`commands`] | the `mit-star` command line (`plan`, `check-path`, `bench`, `merge`, `compare`, `problems`, `planners`, `robots`, `experiments`, `replan`) |
//! | [`budget_duration`], [`deadline_after`], [`BudgetError`], [`short_number`] | time budgets checked into durations; numbers for messages |
//! | [`HarnessError`] | everything that can go wrong, naming what is wrong |
//!
//! The command line and the output formats are described in `docs/guide/src/reference/experiment-files.md`.

#![forbid(unsafe_code)]

mod budget;
pub mod commands;
mod definition;
mod error;
mod execution;
mod formats;
mod outcome;
mod path_validation;
mod pictures;
pub mod replanning;
pub mod statistics;

pub use budget::{BudgetError, MAX_BUDGET_SECONDS, budget_duration, deadline_after, short_number};
pub use definition::cloud_option::CloudOption;
pub use definition::cloud_spec::CloudSpec;
pub use definition::cloud_summary::CloudSummary;
pub use definition::experiment::Experiment;
pub use definition::experiment_file;
pub use definition::file_contents::FileContents;
pub use definition::mbm_folder::MbmFolder;
pub use definition::parameter_overrides::ParameterOverrides;
pub use definition::planner_spec::{PlannerSpec, parse_configuration};
pub use definition::pose_goal_source::{PoseGoalSource, pose_goal_planner};
pub use definition::pose_goal_spec::PoseGoalSpec;
pub use definition::problem_instance::ProblemInstance;
pub use definition::problem_kind::InstanceProblem;
pub use definition::problem_source::{ProblemFile, ProblemSource};
pub use definition::problem_spec::{MAX_INSTANCES, MAX_SCHEDULED_RUNS, ProblemSpec};
pub use definition::robot_choice::RobotChoice;
pub use definition::shipped_experiment::ShippedExperiment;
pub use error::HarnessError;
pub use execution::executor::{ExecutionOptions, Executor, RecordSink, RunKey};
pub use execution::figures::Figures;
pub use execution::interrupt::Interrupt;
pub use execution::pending_run::AuditBatch;
pub use execution::results_folder::{
    DATABASE_FILE, ResultsFolder, kpi_markdown, kpi_overview, writable_folder,
};
pub use execution::run_job::{INSTANCE_SEED_STRIDE, RUN_RECORD_BYTES, RunJob};
pub use execution::run_journal::{DATABASE_COMMIT_INTERVAL, RunJournal, results_from_records};
pub use execution::shard::{SHARD_FILE, Shard};
pub use execution::shard_merge::{MergeReport, merge_parts};
pub use formats::campaign_comparison::{CampaignComparison, Change, ComparedRow};
pub use formats::kpi_table::{KpiRow, KpiTable, t_init_gain};
pub use formats::ompl_log::benchmark_log::{BenchmarkLog, OMPL_STATUS, PlannerLog};
pub use formats::ompl_log::log_value::{
    EnumType, ExperimentProperty, LogValue, Property, PropertyType,
};
pub use formats::planner_arena_database::PlannerArenaDatabase;
pub use formats::raw_runs::{CSV_COLUMNS, write_runs_csv, write_runs_jsonl};
pub use formats::scene_summary::{SceneRow, SceneSummary};
pub use outcome::experiment_results::ExperimentResults;
pub use outcome::machine_info::{MachineInfo, iso_timestamp};
pub use outcome::run_record::{RunRecord, RunStatus};
pub use outcome::scene::Scene;
pub use path_validation::{PathValidation, ValidationMethod};
pub use pictures::arm_picture::ArmPicture;
pub use pictures::experiment_figure::ExperimentFigure;
pub use pictures::plan_view::PlanView;
pub use pictures::plot_style::planner_colours;
pub use pictures::run_picture::RunPicture;
