//! [`RunJob`]: one run of one planner on one problem instance, its place in the schedule, and
//! its execution.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use mit_star::{
    Counters, FirstSolution, Planner, Progress, Termination, TerminationExt, TimeLimit, TracePoint,
};
use mit_star_spaces::SeededRng;
use rand::SeedableRng;
use rand::seq::SliceRandom;

use crate::budget::deadline_after;
use crate::definition::planner_spec::PlannerSpec;
use crate::definition::problem_instance::ProblemInstance;
use crate::execution::pending_run::PendingRun;
use crate::outcome::run_record::{RunRecord, RunStatus};
use crate::path_validation::PathValidation;

/// Memory a finished run's record takes until the results are written, generously (counters,
/// trace, path): the unit of the run-count limit.
pub const RUN_RECORD_BYTES: u64 = 4096;

/// Decorrelates the planner-order shuffle from the planners' own seeds.
const SHUFFLE_SALT: u64 = 0x5eed_0f0b_de5a_1700;

/// How far apart the seeds of consecutive instances start: run `i` on the experiment's `k`-th
/// instance (from 0) uses seed `base_seed + k · INSTANCE_SEED_STRIDE + i`. Every planner of one
/// run still draws from the same seed (paired runs), but no two instances share their draws: a
/// seed whose first draws suit one problem of a scene suits every problem that shares the
/// scene's start, and one seed for all would make a scene's runs one sample of that luck, not
/// a hundred.
pub const INSTANCE_SEED_STRIDE: u64 = 100_000;

/// One unit of work: run `run` (seed `seed`) of planner `planner` on instance `instance`
/// (indices into the experiment's planners and instances).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunJob {
    /// Index of the problem instance.
    pub instance: usize,
    /// Index of the planner.
    pub planner: usize,
    /// Run index `i`.
    pub run: usize,
    /// The planner's seed, `base_seed + k · INSTANCE_SEED_STRIDE + i` on the `k`-th instance
    /// ([`INSTANCE_SEED_STRIDE`]).
    pub seed: u64,
    /// Stop at the first solution ([`Experiment::first_solution`](crate::Experiment)).
    pub first_solution: bool,
}

/// Stops a run when the experiment is interrupted (Ctrl-C).
pub(crate) struct Interrupted<'a>(pub(crate) &'a AtomicBool);

impl Termination for Interrupted<'_> {
    fn should_terminate(&self, _: &Progress) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

impl RunJob {
    /// The identity of this job's run in a results folder of `experiment` on `instances`.
    pub fn key(
        &self,
        experiment: &crate::Experiment,
        instances: &[ProblemInstance],
    ) -> crate::RunKey {
        (
            instances[self.instance].id.clone(),
            experiment.planners[self.planner].name().to_owned(),
            self.run,
        )
    }

    /// The schedule of an experiment: instance after instance; within an instance run index
    /// after run index; within a run index every planner once, in an order shuffled with a
    /// generator seeded by the run index (PDT's protocol, spreading machine drift evenly over
    /// the planners). Run `i` on instance `k` (from 0) is seeded `base_seed + k ·`
    /// [`INSTANCE_SEED_STRIDE`] `+ i` for every planner. The same inputs always give the same
    /// schedule.
    ///
    /// ```
    /// use mit_star_benches::RunJob;
    /// // Two instances, three planners, two runs each, base seed 10.
    /// let jobs = RunJob::schedule(2, 3, 2, 10);
    /// assert_eq!(jobs.len(), 12);
    /// assert!(jobs[..3].iter().all(|j| j.instance == 0 && j.run == 0 && j.seed == 10));
    /// assert!(jobs[3..6].iter().all(|j| j.run == 1 && j.seed == 11));
    /// assert!(jobs[6..9].iter().all(|j| j.instance == 1 && j.run == 0 && j.seed == 100_010));
    /// let mut planners: Vec<usize> = jobs[..3].iter().map(|j| j.planner).collect();
    /// planners.sort();
    /// assert_eq!(planners, [0, 1, 2]);
    /// assert_eq!(jobs, RunJob::schedule(2, 3, 2, 10));
    /// ```
    pub fn schedule(instances: usize, planners: usize, runs: usize, base_seed: u64) -> Vec<Self> {
        let mut jobs = Vec::with_capacity(instances * planners * runs);
        for instance in 0..instances {
            let first =
                base_seed.wrapping_add((instance as u64).wrapping_mul(INSTANCE_SEED_STRIDE));
            for run in 0..runs {
                let seed = first.wrapping_add(run as u64);
                // The order by run index alone: every instance runs its planners in one order
                // per run index.
                let order_seed = base_seed.wrapping_add(run as u64) ^ SHUFFLE_SALT;
                let mut order: Vec<usize> = (0..planners).collect();
                order.shuffle(&mut SeededRng::seed_from_u64(order_seed));
                jobs.extend(order.into_iter().map(|planner| Self {
                    instance,
                    planner,
                    run,
                    seed,
                    first_solution: false,
                }));
            }
        }
        jobs
    }

    /// Runs the job: builds the planner (its construction counts against the budget), solves
    /// until the budget's deadline, records the anytime trace, counters, initial and final
    /// solutions, and validates the returned path independently at full resolution.
    ///
    /// Returns `None` if `interrupt` was raised before the run finished (an interrupted run is
    /// discarded, not recorded as a failure).
    ///
    /// A planner that panics does not take the experiment down: the run is recorded as
    /// [`RunStatus::Error`] with the panic's message.
    pub fn execute(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        interrupt: &AtomicBool,
    ) -> Option<RunRecord> {
        self.execute_unaudited(instance, planner, interrupt)
            .map(|pending| pending.audit(instance))
    }

    /// [`execute`](Self::execute) without the audit of the returned path: the run as it
    /// finished, to be audited later with [`PendingRun::audit`]. The executor audits its
    /// workers' runs in batches, so that a short solve does not start with the caches the
    /// previous run's audit left ([`AuditBatch`](crate::execution::pending_run::AuditBatch)).
    pub(crate) fn execute_unaudited(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        interrupt: &AtomicBool,
    ) -> Option<PendingRun> {
        let run = std::panic::AssertUnwindSafe(|| {
            self.build_and_solve(instance, planner, interrupt)
                .map(|(pending, _)| pending)
        });
        match std::panic::catch_unwind(run) {
            Ok(pending) => pending,
            Err(payload) => {
                let mut record = self.blank_record(instance, planner);
                record.status = RunStatus::Error;
                record.error = Some(format!(
                    "the planner panicked: {}",
                    panic_message(&*payload)
                ));
                Some(PendingRun::judged(record))
            }
        }
    }

    /// A record of this job with nothing measured yet.
    fn blank_record(&self, instance: &ProblemInstance, planner: &PlannerSpec) -> RunRecord {
        RunRecord {
            instance: instance.id.clone(),
            planner: planner.name().to_owned(),
            configuration: planner.configuration(),
            run: self.run,
            seed: self.seed,
            budget: instance.budget,
            status: RunStatus::Unsolved,
            setup_time: 0.0,
            run_time: 0.0,
            initial_time: None,
            initial_cost: None,
            final_cost: None,
            trace: Vec::new(),
            path: Vec::new(),
            joints: Vec::new(),
            wrapping: Vec::new(),
            validation: None,
            counters: Counters::default(),
            error: None,
        }
    }

    /// As [`execute`](Self::execute), also returning the planner after the run (for pictures
    /// and inspection; `None` if it could not be built).
    pub fn execute_keeping_planner(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        interrupt: &AtomicBool,
    ) -> Option<(RunRecord, Option<Box<dyn Planner + Send>>)> {
        let (pending, built) = self.build_and_solve(instance, planner, interrupt)?;
        Some((pending.audit(instance), built))
    }

    /// Builds the planner and solves, leaving the returned path unaudited; also the planner
    /// (`None` if it could not be built).
    fn build_and_solve(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        interrupt: &AtomicBool,
    ) -> Option<(PendingRun, Option<Box<dyn Planner + Send>>)> {
        if interrupt.load(Ordering::Relaxed) {
            return None;
        }
        let started = Instant::now();
        let failed = |e: &dyn std::fmt::Display| {
            let record = self.failed(instance, planner, started, e);
            Some((PendingRun::judged(record), None))
        };
        let deadline = match deadline_after(started, instance.budget) {
            Ok(deadline) => deadline,
            Err(e) => return failed(&e),
        };
        match instance.build_planner(planner, self.seed) {
            Ok((built, goal_source)) => {
                let times = (started, deadline);
                let (record, built) =
                    self.solve_unaudited(instance, planner, built, times, interrupt)?;
                Some((PendingRun::new(record, goal_source), Some(built)))
            }
            Err(e) => failed(&e),
        }
    }

    /// A record of a run that failed before planning (a budget no clock holds, a planner that
    /// could not be built).
    fn failed(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        started: Instant,
        error: &dyn std::fmt::Display,
    ) -> RunRecord {
        let mut record = self.blank_record(instance, planner);
        record.status = RunStatus::Error;
        record.error = Some(error.to_string());
        record.setup_time = started.elapsed().as_secs_f64();
        record.run_time = record.setup_time;
        record
    }

    /// Runs a planner built by the caller since `started` (so its construction counts against
    /// the budget) until `deadline`, and records the run as [`execute`](Self::execute) does.
    /// Used by `mit-star plan`, which builds the planner itself to report build errors as typed
    /// errors — and builds it once.
    ///
    /// Returns `None` if `interrupt` was raised before the run finished.
    pub fn solve_built(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        built: Box<dyn Planner + Send>,
        times: (Instant, Instant),
        interrupt: &AtomicBool,
    ) -> Option<(RunRecord, Option<Box<dyn Planner + Send>>)> {
        let validate = |path: &[Vec<f64>], cost: f64| instance.problem.validate(path, cost);
        self.solve_built_validating(instance, planner, built, times, interrupt, &validate)
    }

    /// [`solve_built`](Self::solve_built) with the returned path judged by `validate` rather
    /// than by the instance's own ends: for goals drawn while planning (a hand pose), which
    /// the instance does not know.
    pub fn solve_built_validating(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        built: Box<dyn Planner + Send>,
        times: (Instant, Instant),
        interrupt: &AtomicBool,
        validate: &dyn Fn(&[Vec<f64>], f64) -> PathValidation,
    ) -> Option<(RunRecord, Option<Box<dyn Planner + Send>>)> {
        let (mut record, built) =
            self.solve_unaudited(instance, planner, built, times, interrupt)?;
        audit_record(&mut record, validate);
        Some((record, Some(built)))
    }

    /// The run of [`solve_built_validating`](Self::solve_built_validating) up to the audit: a
    /// record whose path, if any, is not judged yet (its status [`RunStatus::Solved`] until
    /// [`audit_record`] says otherwise).
    fn solve_unaudited(
        &self,
        instance: &ProblemInstance,
        planner: &PlannerSpec,
        mut built: Box<dyn Planner + Send>,
        (started, deadline): (Instant, Instant),
        interrupt: &AtomicBool,
    ) -> Option<(RunRecord, Box<dyn Planner + Send>)> {
        let mut record = self.blank_record(instance, planner);
        let setup = started.elapsed();
        record.setup_time = setup.as_secs_f64();
        let stop = TimeLimit::until(deadline).or(Interrupted(interrupt));
        let outcome = if self.first_solution {
            built.solve(&stop.or(FirstSolution))
        } else {
            built.solve(&stop)
        };
        record.run_time = started.elapsed().as_secs_f64();
        if interrupt.load(Ordering::Relaxed) {
            return None;
        }
        record.counters = built.counters();
        let offset = record.setup_time;
        for p in built.trace().points() {
            let point = TracePoint {
                time: p.time + offset,
                cost: p.cost,
            };
            // Progress rows are keyed by time: keep one (the best) per instant.
            match record.trace.last_mut() {
                Some(last) if last.time >= point.time => last.cost = last.cost.min(point.cost),
                _ => record.trace.push(point),
            }
        }
        record.initial_time = record.trace.first().map(|p| p.time);
        record.initial_cost = record.trace.first().map(|p| p.cost);
        match outcome {
            Err(e) => {
                record.status = RunStatus::Error;
                record.error = Some(e.to_string());
            }
            Ok(outcome) => match outcome.solution() {
                None => record.status = RunStatus::Unsolved,
                Some(solution) => {
                    record.final_cost = Some(solution.cost);
                    record.path = solution.path.iter().map(<[f64]>::to_vec).collect();
                    if let Some((joints, wrapping)) = instance.problem.joints() {
                        (record.joints, record.wrapping) = (joints, wrapping);
                    }
                    record.status = RunStatus::Solved;
                }
            },
        }
        Some((record, built))
    }
}

/// Judges a finished run's path with `validate`: [`RunStatus::InvalidPath`] if the audit
/// rejects it, and the audit's findings in `record.validation`. Runs without a path are left
/// as they are.
pub(crate) fn audit_record(
    record: &mut RunRecord,
    validate: &dyn Fn(&[Vec<f64>], f64) -> PathValidation,
) {
    let Some(cost) = record.final_cost else {
        return;
    };
    if record.status != RunStatus::Solved {
        return;
    }
    let validation = validate(&record.path, cost);
    if !validation.valid {
        record.status = RunStatus::InvalidPath;
    }
    record.validation = Some(validation);
}

/// The message a panic carried, or "unknown panic".
pub(crate) fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::definition::parameter_overrides::ParameterOverrides;
    use crate::definition::problem_source::ProblemSource;
    use crate::definition::problem_spec::ProblemSpec;

    #[test]
    fn orders_differ_between_runs_but_cover_every_planner() {
        let jobs = RunJob::schedule(2, 5, 20, 0);
        assert_eq!(jobs.len(), 200);
        let orders: Vec<Vec<usize>> = jobs
            .chunks(5)
            .map(|c| c.iter().map(|j| j.planner).collect())
            .collect();
        assert!(orders.iter().any(|o| o != &orders[0]), "shuffled");
        for o in &orders {
            let mut s = o.clone();
            s.sort_unstable();
            assert_eq!(s, [0, 1, 2, 3, 4]);
        }
        // Instance 1 repeats instance 0's orders (same run indices), with its own seeds.
        assert_eq!(orders[..20], orders[20..]);
        assert_eq!(jobs[0].seed, 0);
        assert_eq!(jobs[100].seed, INSTANCE_SEED_STRIDE);
        assert_eq!(jobs[199].seed, INSTANCE_SEED_STRIDE + 19);
    }

    /// The R^2 instance of built-in problem `name` with one budget and resolution, and a
    /// planner of `configuration` with the default parameters.
    fn instance_and_planner(
        name: &str,
        (budget, resolution): (f64, f64),
        configuration: mit_star::Configuration,
    ) -> (ProblemInstance, PlannerSpec) {
        let instance = ProblemSpec {
            source: ProblemSource::parse(name, None).unwrap(),
            dimensions: vec![2],
            budgets: vec![budget],
            instances: vec![0],
            resolution: Some(resolution),
            allow_coarse_step: false,
            padding: mit_star_robot::Padding::ZERO,
            cloud: None,
            pose_goal: None,
        }
        .instances()
        .unwrap()
        .remove(0);
        let planner =
            PlannerSpec::new(configuration, None, &ParameterOverrides::default()).unwrap();
        (instance, planner)
    }

    #[test]
    fn a_run_records_a_validated_solution() {
        let (instance, planner) = instance_and_planner(
            "obstacle-free",
            (0.02, 1e-3),
            mit_star::Configuration::EitStar,
        );
        let job = RunJob {
            instance: 0,
            planner: 0,
            run: 3,
            seed: 3,
            first_solution: false,
        };
        let r = job
            .execute(&instance, &planner, &AtomicBool::new(false))
            .unwrap();
        assert_eq!(r.status, RunStatus::Solved, "{r:?}");
        assert!(r.validation.as_ref().unwrap().valid);
        assert_eq!((r.run, r.seed), (3, 3));
        assert!(r.initial_time.unwrap() >= r.setup_time);
        assert!(
            r.trace
                .windows(2)
                .all(|w| w[1].time > w[0].time && w[1].cost < w[0].cost)
        );
        // An interrupted experiment records nothing.
        assert!(
            job.execute(&instance, &planner, &AtomicBool::new(true))
                .is_none()
        );
    }

    #[test]
    fn a_first_solution_run_stops_at_its_first_solution() {
        let (instance, planner) = instance_and_planner(
            "dividing-walls",
            (5.0, 1e-4),
            mit_star::Configuration::MitStar,
        );
        let job = RunJob {
            instance: 0,
            planner: 0,
            run: 0,
            seed: 1,
            first_solution: true,
        };
        let r = job
            .execute(&instance, &planner, &AtomicBool::new(false))
            .unwrap();
        assert_eq!(r.status, RunStatus::Solved, "{r:?}");
        // One solution and no anytime phase (5 s of it would improve the first path).
        assert_eq!(r.trace.len(), 1);
        assert_eq!(r.initial_cost, r.final_cost);
    }
}
