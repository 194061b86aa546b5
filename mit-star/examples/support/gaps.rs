//! A termination condition that records where a planner went longest without polling it,
//! shared by the `poll_gaps` and `deadline_stress` examples (and the `robot` crate's
//! `arm_deadline_stress`).

use std::backtrace::Backtrace;
use std::cell::RefCell;
use std::time::{Duration, Instant};

use mit_star::{Configuration, Parameters, Progress, Termination, build_planner};

// The test suite's clock: wall-clock time less the thread's run-queue wait.
#[path = "../../tests/common/scheduled.rs"]
mod scheduled;
use scheduled::Scheduled;

/// Gaps shorter than this after the deadline are not recorded (except the one that crosses it).
const LONG_GAP: Duration = Duration::from_micros(300);

/// One recorded gap: its length, the poll that ended it, and (when traced) the one that began it.
struct Gap {
    length: Duration,
    ended: Backtrace,
    began: Option<Backtrace>,
}

/// A deadline that records the backtraces of the polls ending long gaps after it.
pub(crate) struct Gaps {
    deadline: Instant,
    /// From this instant on, every poll captures its backtrace (kept until the next poll), so
    /// a long gap can name where it began as well as where it ended. `None`: ends only.
    trace_from: Option<Instant>,
    last: RefCell<(Instant, Option<Backtrace>)>,
    worst: RefCell<Vec<Gap>>,
    after: RefCell<u64>,
}

impl Gaps {
    /// A deadline `budget` after `started`. With `trace_starts`, the polls of the last 30 % of
    /// the budget capture their backtraces too (which slows the planner there: a diagnostic).
    pub(crate) fn new(started: Instant, budget: Duration, trace_starts: bool) -> Self {
        Self {
            deadline: started + budget,
            trace_from: trace_starts.then(|| started + budget.mul_f64(0.7)),
            last: RefCell::new((started, None)),
            worst: RefCell::new(Vec::new()),
            after: RefCell::new(0),
        }
    }

    /// How many polls came at or after the deadline, then the planner frames of the (at most)
    /// `most` longest recorded gaps, longest first: the poll that crossed the deadline and every
    /// later poll that ended a gap over 0.3 ms (and, when traced, the polls that began them).
    pub(crate) fn report(&self, most: usize) -> String {
        let mut worst = self.worst.borrow_mut();
        worst.sort_by_key(|g| std::cmp::Reverse(g.length));
        let mut out = format!("{} polls after the deadline\n", self.after.borrow());
        for gap in worst.iter().take(most) {
            out.push_str(&format!("=== gap {:?}, ended by\n", gap.length));
            out.push_str(&frames(&gap.ended));
            if let Some(began) = &gap.began {
                out.push_str("--- and begun after\n");
                out.push_str(&frames(began));
            }
        }
        out
    }
}

/// The frames of `bt` in the planner's crates, without the kd-tree's recursion.
fn frames(bt: &Backtrace) -> String {
    let mut out = String::new();
    for line in bt
        .to_string()
        .lines()
        .filter(|l| {
            [
                "mit_star::",
                "mit-star/src",
                "mit_star_samplers::",
                "samplers/src",
                "mit_star_validity::",
                "mit_star_robot::",
                "robot/src",
            ]
            .iter()
            .any(|p| l.contains(p))
        })
        .filter(|l| !l.contains("kd_tree_build.rs:2") && !l.contains("kd_tree.rs:2"))
        .take(16)
    {
        out.push_str(line);
        out.push('\n');
    }
    out
}

impl Termination for Gaps {
    fn should_terminate(&self, _: &Progress) -> bool {
        let now = Instant::now();
        let mut last = self.last.borrow_mut();
        let gap = now - last.0;
        if now >= self.deadline {
            *self.after.borrow_mut() += 1;
        }
        let straddles = now >= self.deadline && now - gap < self.deadline;
        if straddles || (now >= self.deadline && gap > LONG_GAP) {
            self.worst.borrow_mut().push(Gap {
                length: gap,
                ended: Backtrace::force_capture(),
                began: last.1.take(),
            });
        }
        let traced = self.trace_from.is_some_and(|from| now >= from);
        // Taken after the capture above, so the gap to the next poll excludes it.
        *last = (Instant::now(), traced.then(Backtrace::force_capture));
        now >= self.deadline
    }
}

/// Builds `configuration` for `problem` and solves until `budget` seconds after the clock was
/// taken (construction counts against the budget): solved, how late `solve` returned (before
/// the planner is dropped), and the poll gaps. Exits on a build error.
///
/// The lateness is measured on the time the thread was scheduled: wall-clock time less the
/// time it waited in the run queue (`/proc/thread-self/schedstat`; wall-clock where that
/// cannot be read), so that another process on the core does not make a run late — a planner
/// that skips its polls still does. The gaps are wall-clock.
#[allow(dead_code)] // `poll_gaps` includes this file and measures its own way.
pub(crate) fn measure<P: mit_star_problems::PlanningProblem>(
    configuration: Configuration,
    problem: &P,
    parameters: &Parameters,
    budget: f64,
    trace: bool,
) -> (bool, f64, Gaps) {
    let clock = Scheduled::start();
    let started = clock.started();
    let gaps = Gaps::new(started, Duration::from_secs_f64(budget), trace);
    match build_planner(configuration, problem, parameters) {
        Ok(mut planner) => {
            let outcome = planner.solve(&gaps);
            let late = clock.elapsed().as_secs_f64() - budget;
            (outcome.is_ok_and(|o| o.is_solved()), late, gaps)
        }
        Err(e) => {
            eprintln!("{}: {e}", configuration.name());
            std::process::exit(1);
        }
    }
}
