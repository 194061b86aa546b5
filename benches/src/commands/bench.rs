//! `mit-star bench`: run an experiment and write its results folder.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::SystemTime;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::commands::cloud_args::CloudArgs;
use crate::definition::experiment::Experiment;
use crate::definition::parameter_overrides::ParameterOverrides;
use crate::definition::planner_spec::{PlannerSpec, parse_configuration};
use crate::definition::problem_instance::ProblemInstance;
use crate::definition::problem_source::ProblemSource;
use crate::definition::problem_spec::ProblemSpec;
use crate::definition::robot_choice::RobotChoice;
use crate::definition::shipped_experiment::ShippedExperiment;
use crate::error::HarnessError;
use crate::execution::executor::{ExecutionOptions, Executor};
use crate::execution::figures::Figures;
use crate::execution::pending_run::AuditBatch;
use crate::execution::results_folder::ResultsFolder;
use crate::execution::run_job::RunJob;
use crate::execution::run_journal::{RunJournal, results_from_records};
use crate::execution::shard::Shard;
use crate::formats::kpi_table::KpiTable;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::machine_info::{MachineInfo, iso_timestamp};
use crate::outcome::run_record::RunRecord;

/// Options of `mit-star bench`.
///
/// Either an experiment (a file, or `--experiment NAME` for a shipped one) or the flags
/// `--planners`, `--problem`, `--dim`/`--dims`, `--time`, `--instances`, `--resolution`
/// describing one. `--runs`, `--seed`, `--confidence`, `--set`, `--threads` and `--output`
/// apply to both.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// An experiment file (TOML); see `mit-star experiments --print smoke` for the format.
    pub file: Option<PathBuf>,
    /// A shipped experiment: paper-table, ablation, ablation-study, smoke, panda-mbm, paper-planners, panda-pose-goals (`mit-star experiments` lists them).
    #[arg(long, short, conflicts_with = "file")]
    pub experiment: Option<String>,
    /// Planner configurations, comma separated (flags mode; default mit-star,eit-star).
    #[arg(long, value_delimiter = ',')]
    pub planners: Vec<String>,
    /// Built-in problem names or problem file paths, comma separated or repeated (flags mode).
    #[arg(long = "problem", value_delimiter = ',')]
    pub problems: Vec<String>,
    /// The robot MotionBenchMaker folders (`--problem mbm:PATH`) are planned for (flags mode):
    /// a shipped robot (`mit-star robots`; default panda), a URDF file (the SRDF beside it, if
    /// any) or a folder holding one URDF and one SRDF. Experiment files say `robot = "ur5"` in
    /// the problem entry.
    #[arg(long, value_name = "NAME|URDF|DIR")]
    pub robot: Option<String>,
    /// Plan only this SRDF planning group of the robot (flags mode; experiment files:
    /// `group = "right_arm"`); the other joints are held at each request's start values.
    #[arg(long, value_name = "GROUP")]
    pub group: Option<String>,
    /// Refuse SRDF and allowed-collision entries naming links the robot lacks (flags mode;
    /// experiment files: `strict_robot = true`).
    #[arg(long)]
    pub strict_robot: bool,
    /// Point clouds among the obstacles of every MotionBenchMaker problem (flags mode;
    /// experiment files: a `cloud` table in the problem entry), prepared once per problem
    /// instance before the runs.
    #[command(flatten)]
    pub clouds: CloudArgs,
    /// The seed of `--scene-as-cloud`'s sampling for every problem (flags mode; default: each
    /// problem's index in its folder).
    #[arg(long, value_name = "SEED")]
    pub cloud_seed: Option<u64>,
    /// Dimension of the built-in problems (flags mode).
    #[arg(long, conflicts_with = "dims")]
    pub dim: Option<usize>,
    /// Dimensions, comma separated (flags mode).
    #[arg(long, value_delimiter = ',')]
    pub dims: Vec<usize>,
    /// Seconds per run: one value, or one per dimension (flags mode).
    #[arg(long, value_delimiter = ',')]
    pub time: Vec<f64>,
    /// Instances (flags mode): `K` — layout seeds 0..K of seeded problems
    /// (random-rectangles), or the first K problems of a MotionBenchMaker folder; `A-B` —
    /// seeds or problem indices A to B inclusive (`mbm:PATH --instances 1-100`).
    #[arg(long)]
    pub instances: Option<String>,
    /// Collision-check resolution instead of the problems' (flags mode).
    #[arg(long)]
    pub resolution: Option<f64>,
    /// Name of the experiment (flags mode; names the default output folder).
    #[arg(long)]
    pub name: Option<String>,
    /// Runs per planner and problem instance (default: the experiment's, or 100).
    #[arg(long)]
    pub runs: Option<usize>,
    /// Base seed: run i on the k-th instance uses seed + k·100000 + i (default: the experiment's,
    /// or 0).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Confidence of the medians' and success rates' intervals (default 0.99).
    #[arg(long)]
    pub confidence: Option<f64>,
    /// Run only these planners of the experiment: configuration names (`mit-star`) or planner
    /// names (`MIT*`), comma separated.
    #[arg(long, value_delimiter = ',', value_name = "PLANNERS")]
    pub only: Vec<String>,
    /// Stop each run at its first solution (or its budget): a study of the time and work to
    /// a first solution.
    #[arg(long)]
    pub first_solution: bool,
    /// Allow checks that can miss thin obstacles, for every problem: a box world's step
    /// coarser than its thinnest obstacle, an arm planned with certification off
    /// (`--set certification=1`). For measuring what the safe checks cost, never for results
    /// a robot relies on.
    #[arg(long)]
    pub allow_coarse_step: bool,
    /// Keep every robot sphere this many metres from every obstacle, for every arm problem
    /// (`0.01`: a centimetre; at most 1), certified along every edge and re-checked by the
    /// `f64` audit; replaces an experiment file's `padding`. Recorded in the results folder,
    /// which is not resumed with another.
    #[arg(long, value_name = "METRES", allow_negative_numbers = true)]
    pub padding: Option<mit_star_robot::Padding>,
    /// Parameter override for every planner, e.g. `--set batch_size=200` (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Runs executing at the same time (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Results folder (default results/NAME, NAME the experiment's); an existing database is appended to.
    #[arg(long, short)]
    pub output: Option<PathBuf>,
    /// Run only the K-th of N disjoint parts of the experiment's runs (e.g. `--shard 2/8`),
    /// each with the seed it has in the whole experiment; `mit-star merge` combines the parts'
    /// folders. Default folder: results/NAME-shard-K-of-N.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<Shard>,
    /// Audit each run's path the moment the run ends. By default a worker solves short runs
    /// (together at most 32 runs or 0.25 s) back to back and audits them afterwards, so that
    /// no solve starts with the caches the previous path's audit left; SIGKILL or a crash then
    /// lose at most those runs.
    #[arg(long)]
    pub audit_every_run: bool,
    /// Do not draw the figures.
    #[arg(long)]
    pub no_plots: bool,
    /// Per-problem detail: print every problem's KPIs and list every file, and draw a figure
    /// and a 3-D view of every problem instance besides each scene's (by default: the summary
    /// by scene, one figure per scene; `kpi.md` always holds every problem's KPIs).
    #[arg(long)]
    pub per_problem: bool,
    /// No progress bar.
    #[arg(long, short)]
    pub quiet: bool,
}

impl BenchArgs {
    /// The experiment the arguments describe, with the command-line overrides applied.
    ///
    /// # Errors
    /// Every input error: unknown names (listing the valid ones), malformed files (naming the
    /// field), bad values, options that do not combine.
    pub fn experiment(&self) -> Result<Experiment, HarnessError> {
        let flags_mode = !self.planners.is_empty()
            || !self.problems.is_empty()
            || self.dim.is_some()
            || !self.dims.is_empty()
            || !self.time.is_empty()
            || self.instances.is_some()
            || self.resolution.is_some()
            || self.robot.is_some()
            || self.group.is_some()
            || self.strict_robot
            || self.clouds.any()
            || self.cloud_seed.is_some()
            || self.name.is_some();
        let experiment = match (&self.file, &self.experiment) {
            (Some(_), _) | (_, Some(_)) if flags_mode => {
                return Err(HarnessError::Usage(
                    "--planners, --problem, --dim(s), --time, --instances, --resolution, \
                     --robot, --group, --strict-robot, the cloud options (--cloud, \
                     --scene-as-cloud, …) and --name describe an experiment on the command \
                     line; they cannot be combined with an experiment file or --experiment \
                     (whose problem entries take `robot`, `group`, `strict_robot` keys and a \
                     `cloud` table)"
                        .into(),
                ));
            }
            (Some(path), _)
                if !path.exists() && ShippedExperiment::find(&path.to_string_lossy()).is_ok() =>
            {
                Experiment::shipped(&path.to_string_lossy())?
            }
            (Some(path), _) => Experiment::from_file(path)?,
            (None, Some(name)) => Experiment::shipped(name)?,
            (None, None) => self.flags_experiment()?,
        };
        let mut overrides = ParameterOverrides::default();
        for s in &self.set {
            overrides.push_assignment(s)?;
        }
        let mut experiment = experiment.with_overrides(&overrides)?;
        if let Some(runs) = self.runs {
            experiment.runs = runs;
        }
        if let Some(seed) = self.seed {
            experiment.seed = seed;
        }
        if let Some(confidence) = self.confidence {
            experiment.confidence = confidence;
        }
        experiment.first_solution |= self.first_solution;
        if self.allow_coarse_step {
            for problem in &mut experiment.problems {
                problem.allow_coarse_step = true;
            }
        }
        if let Some(padding) = self.padding {
            for problem in &mut experiment.problems {
                problem.padding = padding;
            }
        }
        if !self.only.is_empty() {
            let named = |p: &PlannerSpec, w: &str| p.name() == w || p.configuration().name() == w;
            if let Some(wanted) = self
                .only
                .iter()
                .find(|w| !experiment.planners.iter().any(|p| named(p, w)))
            {
                let known: Vec<String> = experiment
                    .planners
                    .iter()
                    .map(|p| format!("{} ({})", p.configuration().name(), p.name()))
                    .collect();
                return Err(HarnessError::Usage(format!(
                    "--only {wanted}: the experiment has no such planner; it has {}",
                    known.join(", ")
                )));
            }
            experiment
                .planners
                .retain(|p| self.only.iter().any(|w| named(p, w)));
        }
        experiment.validate("command line")?;
        Ok(experiment)
    }

    /// The experiment of flags mode.
    fn flags_experiment(&self) -> Result<Experiment, HarnessError> {
        let usage = |m: &str| HarnessError::Usage(m.to_owned());
        if self.problems.is_empty() {
            return Err(usage(
                "give an experiment file, --experiment NAME, or --problem NAME (with --dim and --time)",
            ));
        }
        if self.time.is_empty() {
            return Err(usage("give the time budget per run with --time SECONDS"));
        }
        let planner_names = if self.planners.is_empty() {
            vec!["mit-star".to_owned(), "eit-star".to_owned()]
        } else {
            self.planners.clone()
        };
        let planners = planner_names
            .iter()
            .map(|n| {
                PlannerSpec::new(
                    parse_configuration(n)?,
                    None,
                    &ParameterOverrides::default(),
                )
            })
            .collect::<Result<Vec<_>, _>>()?;
        let dims: Vec<usize> = match self.dim {
            Some(d) => vec![d],
            None => self.dims.clone(),
        };
        let robot = RobotChoice::parse(self.robot.as_deref(), None, self.strict_robot)?
            .with_group(self.group.as_deref());
        let cloud = if self.clouds.any() || self.cloud_seed.is_some() {
            if let Some(path) = &self.clouds.save_cloud {
                return Err(HarnessError::Usage(format!(
                    "--save-cloud `{}` writes one problem's cloud; bench prepares one per problem \
                     instance: save one with `mit-star plan --save-cloud`",
                    path.display()
                )));
            }
            Some(self.clouds.spec(self.cloud_seed)?)
        } else {
            None
        };
        let mut problems = Vec::new();
        for text in &self.problems {
            let source = ProblemSource::parse_for_robot(text, None, &robot)?;
            if let Some(cloud) = &cloud {
                let named = format!("`{text}`");
                if !matches!(source, ProblemSource::Mbm(_)) {
                    return Err(HarnessError::CloudOption {
                        problem: named,
                        option: cloud.first_option().describe(),
                        source: Box::new(HarnessError::Usage(
                            "point clouds are obstacles of arm problems (--problem mbm:PATH); \
                             this is a box world"
                                .into(),
                        )),
                    });
                }
                cloud.check(&named, false)?;
            }
            if !robot.is_default() && !matches!(source, ProblemSource::Mbm(_)) {
                return Err(HarnessError::Usage(format!(
                    "--robot, --group and --strict-robot apply to MotionBenchMaker problems (mbm:PATH), not `{text}`"
                )));
            }
            let dimensions = match source.fixed_dimension()? {
                Some(n) if dims.is_empty() || dims == [n] => vec![n],
                Some(n) => {
                    return Err(HarnessError::Usage(format!(
                        "problem file `{text}` is {n}-dimensional; --dim/--dims do not apply"
                    )));
                }
                None if dims.is_empty() => {
                    return Err(usage("give the dimension with --dim N or --dims N1,N2,…"));
                }
                None => dims.clone(),
            };
            let budgets = match self.time.len() {
                1 => vec![self.time[0]; dimensions.len()],
                n if n == dimensions.len() => self.time.clone(),
                n => {
                    return Err(HarnessError::Usage(format!(
                        "--time has {n} values for {} dimensions; give one, or one per dimension",
                        dimensions.len()
                    )));
                }
            };
            let instances = match self.instances.as_deref() {
                None if source.is_seeded() => vec![first_instance(&source)],
                None => vec![0],
                Some(_) if !source.is_seeded() => {
                    return Err(HarnessError::Usage(format!(
                        "`{text}` does not depend on a seed: --instances does not apply"
                    )));
                }
                Some(range) => instance_range(range, &source)?,
            };
            problems.push(ProblemSpec {
                source,
                dimensions,
                budgets,
                instances,
                resolution: self.resolution,
                allow_coarse_step: self.allow_coarse_step,
                padding: self.padding.unwrap_or_default(),
                cloud: cloud.clone(),
                pose_goal: None,
            });
        }
        let name = self.name.clone().unwrap_or_else(|| {
            let first = &problems[0];
            let dims: Vec<String> = first.dimensions.iter().map(|d| format!("n{d}")).collect();
            let more = if problems.len() > 1 { "-and-more" } else { "" };
            // Among a cloud, another experiment: another default folder.
            let cloud = if first.cloud.is_some() { "-cloud" } else { "" };
            // Padded, another experiment: another default folder.
            let padding = match self.padding {
                Some(p) if !p.is_zero() => {
                    format!(
                        "-padding{}mm",
                        mit_star_spaces::short_number(p.metres() * 1e3)
                    )
                }
                _ => String::new(),
            };
            crate::definition::experiment::safe_name(&format!(
                "{}-{}{cloud}{padding}{more}",
                first.source.label(),
                dims.join("-")
            ))
        });
        Ok(Experiment {
            name,
            description: String::new(),
            planners,
            problems,
            runs: 100,
            seed: 0,
            confidence: 0.99,
            first_solution: false,
        })
    }

    /// Checks everything, runs the experiment, writes the results folder, prints the KPIs.
    ///
    /// # Errors
    /// Input errors before any planning; write errors after.
    pub fn run(&self, interrupt: Arc<AtomicBool>) -> Result<CommandOutcome, HarnessError> {
        let experiment = self.experiment()?;
        let instances = experiment.instances()?;
        for instance in &instances {
            if let Some(cloud) = &instance.cloud {
                eprintln!("cloud: `{}`: {}", instance.id, cloud.line());
            }
        }
        check_planners_build(&experiment, &instances)?;
        let threads = match self.threads {
            Some(0) => return Err(HarnessError::Usage("--threads must be at least 1".into())),
            Some(t) => t,
            None => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let output = self.output.clone().unwrap_or_else(|| {
            let name = match self.shard {
                Some(s) => format!("{}-shard-{}-of-{}", experiment.name, s.index(), s.count()),
                None => experiment.name.clone(),
            };
            Path::new("results").join(name)
        });
        let mut folder = ResultsFolder::prepare(&output)?;
        folder.claim(&experiment)?;
        folder.claim_shard(self.shard)?;
        // Every finished run goes to the raw files once audited, short runs in small batches
        // (`AuditBatch`), the database following in batches of its own: SIGTERM keeps every
        // finished run, SIGKILL or a crash lose at most the runs in flight and those awaiting
        // their audit. Runs recorded by an earlier bench of this experiment are not rerun.
        let journal = RunJournal::open(folder.path(), &experiment, &instances)?;
        if journal.healed() > 0 {
            eprintln!(
                "note: `{}` recorded {} runs a second time (two processes wrote the folder at \
                 once); kept the first record of each, rebuilt runs.csv, and the summaries are \
                 rebuilt from the distinct runs",
                folder.path().join("runs.jsonl").display(),
                journal.healed()
            );
        }
        let recorded = journal.recorded().clone();
        let (jobs, budget) = shard_work(&experiment, &instances, self.shard);
        let concurrency = threads.min(jobs.saturating_sub(recorded.len()).max(1));
        eprintln!(
            "experiment `{}`{}: {} planners × {} problem instances × {} runs{} = {jobs} runs{}; \
             {:.1} s of budget on {concurrency} threads ≈ {}{:.1} s",
            experiment.name,
            self.shard.map_or(String::new(), |s| format!(", shard {s}")),
            experiment.planners.len(),
            instances.len(),
            experiment.runs,
            self.shard
                .map_or(String::new(), |s| format!(" ÷ {}", s.count())),
            if recorded.is_empty() {
                String::new()
            } else {
                format!(
                    " ({} already recorded in the folder: resuming)",
                    recorded.len()
                )
            },
            budget,
            if experiment.first_solution {
                "at most "
            } else {
                ""
            },
            budget / concurrency as f64
        );
        let template = ExperimentResults {
            experiment: experiment.clone(),
            instances: instances.clone(),
            runs: vec![Vec::new(); instances.len()],
            started_at: iso_timestamp(SystemTime::now()),
            total_time: 0.0,
            concurrency,
            interrupted: false,
            machine: MachineInfo::detect(),
        };
        let journal = Arc::new(Mutex::new(journal));
        let failure: Arc<Mutex<Option<HarnessError>>> = Arc::new(Mutex::new(None));
        let sink = {
            let (journal, failure, interrupt) = (
                Arc::clone(&journal),
                Arc::clone(&failure),
                Arc::clone(&interrupt),
            );
            move |index: usize, record: &RunRecord| {
                let written = journal
                    .lock()
                    .map_err(|_| HarnessError::Usage("the run journal was poisoned".into()))
                    .and_then(|mut j| j.append(&template, index, record));
                if let Err(e) = written
                    && let Ok(mut slot) = failure.lock()
                {
                    // Stop: results that cannot be written must not be computed.
                    slot.get_or_insert(e);
                    interrupt.store(true, Ordering::SeqCst);
                }
            }
        };
        let executor = Executor::new(ExecutionOptions {
            threads,
            progress: !self.quiet,
            interrupt,
            recorded,
            on_record: Some(Arc::new(sink)),
            shard: self.shard,
            audit_batch: if self.audit_every_run {
                AuditBatch::EACH_RUN
            } else {
                AuditBatch::DEFAULT
            },
        });
        let results = executor.run(&experiment, instances)?;
        // Close the raw files and the journal's database connection before rebuilding.
        drop(executor);
        drop(journal);
        if let Some(e) = failure.lock().ok().and_then(|mut f| f.take()) {
            return Err(e);
        }
        if results.interrupted {
            eprintln!(
                "interrupted: {} runs finished in this session; rebuilding the summaries from every recorded run",
                results.run_count()
            );
        }
        let new_runs = results.run_count();
        let all = results_from_records(
            &results,
            RunJournal::read_records(folder.path())?,
            &results.instances,
        );
        let figures = Figures::from_flags(self.no_plots, self.per_problem);
        let files = folder.finish(&all, figures)?;
        let table = KpiTable::from_results(&all);
        if self.per_problem {
            say!("{}", crate::kpi_markdown(&all, &table));
        } else {
            say!("{}\n", crate::kpi_overview(&all, &table, true).trim_end());
        }
        say!(
            "Results in {} ({new_runs} runs added, {} recorded):",
            folder.path().display(),
            all.run_count()
        );
        for line in file_listing(folder.path(), &files, self.per_problem) {
            say!("  {line}");
        }
        if !self.per_problem {
            say!(
                "Every problem's KPIs are in kpi.md; --per-problem prints them and draws every problem."
            );
        }
        if let Some(line) = audit_summary(&all) {
            say!("{line}");
        }
        let invalid = all.invalid_runs();
        if !invalid.is_empty() {
            eprintln!(
                "WARNING: {} runs returned paths that failed the independent validation (see kpi.md)",
                invalid.len()
            );
        }
        let errors = all.failed_runs().len();
        let outcome = CommandOutcome::of_runs(results.interrupted, errors, invalid.len());
        if errors > 0 {
            eprintln!(
                "ERROR: {errors} of {} recorded runs ended in an error (see the `error` column of \
                 runs.csv){}",
                all.run_count(),
                if outcome == CommandOutcome::RunErrors {
                    "; exit code 1"
                } else {
                    ""
                }
            );
        }
        Ok(outcome)
    }
}

/// The lines listing `files` of the results folder `root`: every file with `per_problem`;
/// else every file but those of a subfolder holding more than [`LISTED_PER_FOLDER`] of them,
/// which gets one line with the count (`results/x/logs/ (100 files)`) where its first file
/// would have been.
pub(crate) fn file_listing(root: &Path, files: &[PathBuf], per_problem: bool) -> Vec<String> {
    let folder_of = |f: &PathBuf| f.parent().map(Path::to_path_buf);
    let count = |folder: &Option<PathBuf>| files.iter().filter(|f| folder_of(f) == *folder).count();
    let mut lines = Vec::new();
    let mut summarised: Vec<Option<PathBuf>> = Vec::new();
    for f in files {
        let folder = folder_of(f);
        let n = count(&folder);
        if per_problem || n <= LISTED_PER_FOLDER || folder.as_deref() == Some(root) {
            lines.push(f.display().to_string());
        } else if !summarised.contains(&folder) {
            let name = folder
                .as_deref()
                .map_or(String::new(), |d| d.display().to_string());
            lines.push(format!("{name}/ ({n} files)"));
            summarised.push(folder);
        }
    }
    lines
}

/// The most files of one folder [`file_listing`] lists one by one by default.
pub(crate) const LISTED_PER_FOLDER: usize = 8;

/// The runs of `shard` of `experiment` (all of them without one) and their total budget.
fn shard_work(
    experiment: &Experiment,
    instances: &[ProblemInstance],
    shard: Option<Shard>,
) -> (usize, f64) {
    RunJob::schedule(
        instances.len(),
        experiment.planners.len(),
        experiment.runs,
        experiment.seed,
    )
    .iter()
    .enumerate()
    .filter(|&(position, _)| shard.is_none_or(|s| s.owns(position)))
    .fold((0, 0.0), |(jobs, budget), (_, job)| {
        (jobs + 1, budget + instances[job.instance].budget)
    })
}

/// Builds every planner once on every instance, so that a planner refusing a problem or its
/// parameters is reported before any run.
fn check_planners_build(
    experiment: &Experiment,
    instances: &[ProblemInstance],
) -> Result<(), HarnessError> {
    for instance in instances {
        for spec in &experiment.planners {
            instance
                .problem
                .build_planner(
                    spec.configuration(),
                    &spec.parameters_for_seed(experiment.seed),
                )
                .map_err(|source| HarnessError::Build {
                    planner: format!("{} on {}", spec.name(), instance.id),
                    source,
                })?;
        }
    }
    Ok(())
}

/// The default instance: seed 0, or a MotionBenchMaker folder's first problem.
pub(crate) fn first_instance(source: &ProblemSource) -> u64 {
    match source {
        ProblemSource::Mbm(folder) => folder.indices()[0] as u64,
        _ => 0,
    }
}

/// `--instances`: `K` (seeds 0..K, or a folder's first K problems) or `A-B` (inclusive); at
/// most [`MAX_INSTANCES`](crate::definition::problem_spec::MAX_INSTANCES), and for a folder
/// no more problems than it holds, each refused alike.
fn instance_range(text: &str, source: &ProblemSource) -> Result<Vec<u64>, HarnessError> {
    let bad = || {
        HarnessError::Usage(format!(
            "--instances `{}`: give a count K or an inclusive range A-B (e.g. 1-100)",
            mit_star_problems::excerpt(text, 40)
        ))
    };
    let number = |s: &str| s.trim().parse::<u64>().map_err(|_| bad());
    let too_many = |count: Option<u64>| {
        crate::definition::problem_spec::check_instance_count(count).map_err(|message| {
            HarnessError::Usage(format!(
                "--instances `{}` {message}",
                mit_star_problems::excerpt(text, 40)
            ))
        })
    };
    let (first, count) = match text.split_once('-') {
        Some((a, b)) => {
            let (a, b) = (number(a)?, number(b)?);
            if a > b {
                return Err(bad());
            }
            (Some(a), (b - a).checked_add(1))
        }
        None => {
            let k = number(text)?;
            if k == 0 {
                return Err(HarnessError::Usage("--instances must be at least 1".into()));
            }
            (None, Some(k))
        }
    };
    if let ProblemSource::Mbm(folder) = source
        && first.is_none()
        && count.is_none_or(|k| k > folder.indices().len() as u64)
    {
        let indices = folder.indices();
        return Err(HarnessError::Usage(format!(
            "--instances `{}`: `{}` holds {} problems ({} to {}); give at most {} or a range \
             of its indices",
            mit_star_problems::excerpt(text, 40),
            folder.path().display(),
            indices.len(),
            indices.first().copied().unwrap_or(0),
            indices.last().copied().unwrap_or(0),
            indices.len()
        )));
    }
    too_many(count)?;
    let count = count.unwrap_or(0);
    Ok(match (first, source) {
        (Some(a), _) => (a..=a + (count - 1)).collect(),
        (None, ProblemSource::Mbm(folder)) => folder
            .indices()
            .iter()
            .take(count as usize)
            .map(|&i| i as u64)
            .collect(),
        (None, _) => (0..count).collect(),
    })
}

/// The independent audit's time over every recorded run with a checked path, apart from
/// and against the planning time (`run_time`, construction included) of those runs; `None`
/// when no path was checked.
fn audit_summary(all: &ExperimentResults) -> Option<String> {
    let (mut paths, mut audit, mut planning) = (0usize, 0.0, 0.0);
    for run in all.all_runs() {
        if let Some(v) = &run.validation {
            paths += 1;
            audit += v.seconds;
            planning += run.run_time;
        }
    }
    (paths > 0).then(|| {
        format!(
            "Independent audit of {paths} paths: {} in all, {}x the planning time of those runs ({}); not counted in any planner's time.",
            crate::commands::plan::audit_time(audit),
            crate::formats::kpi_table::number(audit / planning.max(f64::MIN_POSITIVE)),
            crate::commands::plan::audit_time(planning)
        )
    })
}
