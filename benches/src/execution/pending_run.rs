//! [`PendingRun`]: a finished run whose path the independent audit has not judged yet, and
//! [`AuditBatch`]: how many of them a worker lets wait.
//!
//! The audit of an arm path (a continuous proof in `f64` with parry, about 3 ms on the Panda)
//! walks other data than the planner's checks. A solve of 40–90 µs that starts right after it
//! starts with the audit's caches: measured on the Panda's MotionBenchMaker problems
//! (RRT-Connect to the first solution, four scenes, six rounds, the same seeds, a build that
//! audited only the start state against one that audited every path), construction took 10.2
//! against 7.1 µs and the time to the first solution with construction 92.4 against 81.7 µs
//! (0.884×). So a worker solves a few short runs back to back and audits them together
//! afterwards; long runs, where the audit's trace in the caches is lost in the solve, are
//! audited one by one as before.

use crate::definition::pose_goal_source::PoseGoalSource;
use crate::definition::problem_instance::ProblemInstance;
use crate::execution::run_job::{audit_record, panic_message};
use crate::outcome::run_record::{RunRecord, RunStatus};

/// A finished run, its path not yet audited. [`audit`](Self::audit) makes it a record.
#[derive(Debug)]
pub(crate) struct PendingRun {
    record: RunRecord,
    /// The goal region drawn while planning (a pose goal), which judges the path's end in place
    /// of the instance's goals; `None` for the instance's own goals.
    goal_source: Option<PoseGoalSource>,
    /// Whether the path still awaits the audit.
    unaudited: bool,
}

impl PendingRun {
    /// A run whose path (if it has one) awaits the audit.
    pub(crate) fn new(record: RunRecord, goal_source: Option<PoseGoalSource>) -> Self {
        Self {
            record,
            goal_source,
            unaudited: true,
        }
    }

    /// A run with nothing to audit (it failed before or while planning).
    pub(crate) fn judged(record: RunRecord) -> Self {
        Self {
            record,
            goal_source: None,
            unaudited: false,
        }
    }

    /// The seconds the run took, construction included.
    pub(crate) fn run_time(&self) -> f64 {
        self.record.run_time
    }

    /// The record, its path judged by the independent audit: against the pose goal it was
    /// planned to, or `instance`'s problem. An audit that panics makes the run an
    /// [`RunStatus::Error`] naming the panic; the path is never taken as valid unaudited.
    pub(crate) fn audit(self, instance: &ProblemInstance) -> RunRecord {
        let Self {
            mut record,
            goal_source,
            unaudited,
        } = self;
        if !unaudited {
            return record;
        }
        // `audit_record` writes the record only once the audit has returned, so a panic leaves
        // it as it was.
        let audited =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| match &goal_source {
                Some(source) => audit_record(&mut record, &|p, c| source.validate(p, c)),
                None => audit_record(&mut record, &|p, c| instance.problem.validate(p, c)),
            }));
        if let Err(payload) = audited {
            record.status = RunStatus::Error;
            record.error = Some(format!("the audit panicked: {}", panic_message(&*payload)));
        }
        record
    }
}

/// How many finished runs a worker keeps before auditing them: at most [`runs`](Self::runs),
/// and at most [`seconds`](Self::seconds) of their run time together: a run that alone takes
/// `seconds` or longer is audited at once. On an interruption the waiting runs are audited and
/// recorded before the worker stops, so Ctrl-C and SIGTERM keep every finished run; SIGKILL or
/// a crash lose at most these.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AuditBatch {
    /// Runs at most (at least 1; 1 audits every run at once).
    pub runs: usize,
    /// Their run times together, in seconds, at most.
    pub seconds: f64,
}

impl AuditBatch {
    /// 32 runs or a quarter of a second of planning, whichever comes first.
    pub const DEFAULT: Self = Self {
        runs: 32,
        seconds: 0.25,
    };

    /// Every run audited the moment it finishes.
    pub const EACH_RUN: Self = Self {
        runs: 1,
        seconds: 0.0,
    };

    /// Whether `waiting` runs that took `seconds` together are due for their audit.
    pub fn is_due(&self, waiting: usize, seconds: f64) -> bool {
        waiting >= self.runs.max(1) || seconds >= self.seconds
    }
}

impl Default for AuditBatch {
    fn default() -> Self {
        Self::DEFAULT
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_batch_is_due_at_its_run_count_or_its_time() {
        let batch = AuditBatch::DEFAULT;
        assert!(!batch.is_due(1, 1e-4));
        assert!(!batch.is_due(31, 0.2));
        assert!(batch.is_due(32, 1e-3));
        assert!(batch.is_due(2, 0.25));
        assert!(batch.is_due(1, 1.0), "a run of a second is audited at once");
        assert!(AuditBatch::EACH_RUN.is_due(1, 0.0));
        let zero = AuditBatch {
            runs: 0,
            seconds: 1.0,
        };
        assert!(zero.is_due(1, 0.0), "zero runs means one");
    }
}
