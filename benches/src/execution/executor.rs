//! [`Executor`]: runs an experiment's jobs in parallel, with progress, interruption and
//! deterministic per-run seeds.

use std::collections::HashSet;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Instant, SystemTime};

use indicatif::{ProgressBar, ProgressStyle};

use crate::definition::experiment::Experiment;
use crate::definition::problem_instance::ProblemInstance;
use crate::error::HarnessError;
use crate::execution::pending_run::{AuditBatch, PendingRun};
use crate::execution::run_job::RunJob;
use crate::execution::shard::Shard;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::machine_info::{MachineInfo, iso_timestamp};
use crate::outcome::run_record::{RunRecord, RunStatus};

/// A run's identity in a results folder: instance id, planner name, run index.
pub type RunKey = (String, String, usize);

/// Called with each finished run (its instance's index and record), from the worker thread
/// that ran it, once its path is audited: before the worker takes the next job, or, for the
/// short runs an [`AuditBatch`] lets wait, within that batch.
pub type RecordSink = dyn Fn(usize, &RunRecord) + Send + Sync;

/// How to execute an experiment.
#[derive(Clone)]
pub struct ExecutionOptions {
    /// Worker threads: runs executing at the same time (at least 1).
    pub threads: usize,
    /// Draw a progress bar with an ETA on the terminal (stderr).
    pub progress: bool,
    /// Raised (e.g. by a Ctrl-C handler) to stop: running runs are abandoned, finished runs
    /// are kept.
    pub interrupt: Arc<AtomicBool>,
    /// Runs already recorded (by an earlier, interrupted `bench` into the same folder): they
    /// are not run again.
    pub recorded: HashSet<RunKey>,
    /// Where each finished run goes the moment it finishes (e.g. a [`RunJournal`](crate::RunJournal)).
    pub on_record: Option<Arc<RecordSink>>,
    /// Run only this part of the experiment (`None`: all of it).
    pub shard: Option<Shard>,
    /// How many finished runs a worker solves before it audits them together
    /// ([`AuditBatch::DEFAULT`]; [`AuditBatch::EACH_RUN`] audits each run the moment it ends).
    pub audit_batch: AuditBatch,
}

impl std::fmt::Debug for ExecutionOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ExecutionOptions")
            .field("threads", &self.threads)
            .field("progress", &self.progress)
            .field("interrupt", &self.interrupt)
            .field("recorded", &self.recorded.len())
            .field("on_record", &self.on_record.is_some())
            .field("shard", &self.shard)
            .field("audit_batch", &self.audit_batch)
            .finish()
    }
}

impl Default for ExecutionOptions {
    /// Every core, no progress bar, never interrupted.
    fn default() -> Self {
        Self {
            threads: std::thread::available_parallelism().map_or(1, |n| n.get()),
            progress: false,
            interrupt: Arc::new(AtomicBool::new(false)),
            recorded: HashSet::new(),
            on_record: None,
            shard: None,
            audit_batch: AuditBatch::DEFAULT,
        }
    }
}

/// Executes experiments on a rayon thread pool.
///
/// The jobs ([`RunJob::schedule`]) are handed out in schedule order to `threads` workers, so
/// run `i` of every planner executes close in time; each run's seed and planner order depend
/// only on its run index, never on scheduling. Runs whose path fails validation are reported
/// on stderr as they are audited.
///
/// A worker audits short runs in batches ([`ExecutionOptions::audit_batch`]): the audit of a
/// path walks other data than the planner, and a solve of a few dozen microseconds that starts
/// right after it starts with cold caches. Every run is audited and recorded before the
/// worker stops, interrupted or not.
///
/// ```no_run
/// use mit_star_benches::{ExecutionOptions, Executor, Experiment};
/// let experiment = Experiment::shipped("smoke")?;
/// let instances = experiment.instances()?;
/// let results = Executor::new(ExecutionOptions::default()).run(&experiment, instances)?;
/// println!("{} runs in {:.1} s", results.run_count(), results.total_time);
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Executor {
    options: ExecutionOptions,
}

impl Executor {
    /// An executor with these options.
    pub fn new(options: ExecutionOptions) -> Self {
        Self { options }
    }

    /// Runs every job of `experiment` on `instances` (from [`Experiment::instances`]).
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for zero threads or if the thread pool cannot be created.
    pub fn run(
        &self,
        experiment: &Experiment,
        instances: Vec<ProblemInstance>,
    ) -> Result<ExperimentResults, HarnessError> {
        if self.options.threads == 0 {
            return Err(HarnessError::Usage("--threads must be at least 1".into()));
        }
        let recorded = &self.options.recorded;
        let jobs: Vec<RunJob> = RunJob::schedule(
            instances.len(),
            experiment.planners.len(),
            experiment.runs,
            experiment.seed,
        )
        .into_iter()
        .enumerate()
        .filter(|&(position, _)| self.options.shard.is_none_or(|s| s.owns(position)))
        .map(|(_, job)| RunJob {
            first_solution: experiment.first_solution,
            ..job
        })
        .filter(|job| !recorded.contains(&job.key(experiment, &instances)))
        .collect();
        let concurrency = self.options.threads.min(jobs.len().max(1));
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(concurrency)
            .thread_name(|i| format!("mit-star-run-{i}"))
            .build()
            .map_err(|e| HarnessError::Usage(format!("cannot start {concurrency} threads: {e}")))?;
        let started_at = iso_timestamp(SystemTime::now());
        let clock = Instant::now();
        let progress = self.progress_bar(&jobs, &instances);
        let next = AtomicUsize::new(0);
        let done = AtomicUsize::new(0);
        let slots: Mutex<Vec<Option<RunRecord>>> = Mutex::new(vec![None; jobs.len()]);
        let interrupt = &*self.options.interrupt;
        let audit_batch = self.options.audit_batch;
        pool.scope(|scope| {
            for _ in 0..concurrency {
                scope.spawn(|_| {
                    // Finished runs awaiting their audit, with their job's index.
                    let mut waiting: Vec<(usize, PendingRun)> = Vec::new();
                    let record = |index: usize, pending: PendingRun| {
                        let job = &jobs[index];
                        let instance = &instances[job.instance];
                        let record = pending.audit(instance);
                        report(&progress, &record);
                        if let Some(sink) = &self.options.on_record {
                            sink(job.instance, &record);
                        }
                        let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
                        progress.set_message(format!(
                            "{finished}/{} runs · {}",
                            jobs.len(),
                            instance.id
                        ));
                        progress.inc(budget_millis(instance.budget));
                        if let Ok(mut slots) = slots.lock() {
                            slots[index] = Some(record);
                        }
                    };
                    loop {
                        if interrupt.load(Ordering::Relaxed) {
                            break;
                        }
                        let index = next.fetch_add(1, Ordering::Relaxed);
                        let Some(job) = jobs.get(index) else { break };
                        let instance = &instances[job.instance];
                        let planner = &experiment.planners[job.planner];
                        let Some(pending) = job.execute_unaudited(instance, planner, interrupt)
                        else {
                            break;
                        };
                        waiting.push((index, pending));
                        let seconds = waiting.iter().map(|(_, p)| p.run_time()).sum();
                        if audit_batch.is_due(waiting.len(), seconds) {
                            for (index, pending) in waiting.drain(..) {
                                record(index, pending);
                            }
                        }
                    }
                    // Finished runs are kept, interrupted or not.
                    for (index, pending) in waiting.drain(..) {
                        record(index, pending);
                    }
                });
            }
        });
        progress.finish_and_clear();
        let slots = slots.into_inner().unwrap_or_else(|e| e.into_inner());
        let mut grouped: Vec<Vec<(usize, RunRecord)>> = vec![Vec::new(); instances.len()];
        for (job, record) in jobs.iter().zip(slots) {
            if let Some(record) = record {
                grouped[job.instance].push((job.planner, record));
            }
        }
        let runs = grouped
            .into_iter()
            .map(|mut list| {
                list.sort_by_key(|(planner, r)| (*planner, r.run));
                list.into_iter().map(|(_, r)| r).collect()
            })
            .collect();
        Ok(ExperimentResults {
            experiment: experiment.clone(),
            instances,
            runs,
            started_at,
            total_time: clock.elapsed().as_secs_f64(),
            concurrency,
            interrupted: interrupt.load(Ordering::Relaxed),
            machine: MachineInfo::detect(),
        })
    }

    /// A progress bar measured in budget-milliseconds, so its ETA accounts for the different
    /// budgets of the instances.
    fn progress_bar(&self, jobs: &[RunJob], instances: &[ProblemInstance]) -> ProgressBar {
        if !self.options.progress {
            return ProgressBar::hidden();
        }
        let total: u64 = jobs
            .iter()
            .map(|j| budget_millis(instances[j.instance].budget))
            .sum();
        let bar = ProgressBar::new(total);
        if let Ok(style) = ProgressStyle::with_template(
            "[{elapsed_precise}] {wide_bar} {percent:>3}% ETA {eta_precise} {msg}",
        ) {
            bar.set_style(style);
        }
        bar
    }
}

/// Budget in whole milliseconds (at least 1), the progress bar's unit.
fn budget_millis(budget: f64) -> u64 {
    ((budget * 1000.0).round() as u64).max(1)
}

/// Reports invalid paths and planner errors loudly as they happen.
fn report(progress: &ProgressBar, record: &RunRecord) {
    let message = match record.status {
        RunStatus::InvalidPath => format!(
            "INVALID PATH: {} run {} (seed {}) on {}: {}",
            record.planner,
            record.run,
            record.seed,
            record.instance,
            record
                .validation
                .as_ref()
                .and_then(|v| v.failure.clone())
                .unwrap_or_default()
        ),
        RunStatus::Error => format!(
            "PLANNER ERROR: {} run {} on {}: {}",
            record.planner,
            record.run,
            record.instance,
            record.error.clone().unwrap_or_default()
        ),
        _ => return,
    };
    if progress.is_hidden() {
        eprintln!("{message}");
    } else {
        progress.println(message);
    }
}
