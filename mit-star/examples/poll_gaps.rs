//! `poll_gaps`: where a planner goes longest without polling its termination condition — the
//! diagnostic behind the deadline stress matrix's late runs.
//!
//! ```text
//! cargo run --release -p mit-star --example poll_gaps -- mit-star-sc 16 100 1 0
//! ```
//!
//! Arguments: configuration, dimension (goal enclosure), batch size, budget in seconds, seed.
//! Prints how late `solve` returned and how many polls came after the deadline; for a run more
//! than 1 ms late, the backtraces (planner frames only) of the poll that crossed the deadline
//! and of every later poll that ended a gap of more than 0.3 ms, longest gap first.

use std::cell::RefCell;
use std::time::{Duration, Instant};

use mit_star::{Configuration, Parameters, Progress, Termination, build_planner};

/// A termination condition at `deadline` that records the gaps between its polls.
struct Gaps {
    deadline: Instant,
    last: RefCell<Instant>,
    worst: RefCell<Vec<(Duration, std::backtrace::Backtrace)>>,
    after: RefCell<u64>,
}

impl Termination for Gaps {
    fn should_terminate(&self, _: &Progress) -> bool {
        let now = Instant::now();
        let gap = now - *self.last.borrow();
        *self.last.borrow_mut() = now;
        if now >= self.deadline {
            *self.after.borrow_mut() += 1;
        }
        let straddles = now >= self.deadline && now - gap < self.deadline;
        if straddles || (now >= self.deadline && gap > Duration::from_micros(300)) {
            let bt = std::backtrace::Backtrace::force_capture();
            self.worst.borrow_mut().push((gap, bt));
        }
        now >= self.deadline
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: poll_gaps CONFIGURATION DIMENSION BATCH BUDGET SEED";
    let [configuration, dimension, batch, budget, seed] = args.as_slice() else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let parsed = (
        configuration.parse::<Configuration>(),
        dimension.parse::<usize>(),
        batch.parse::<usize>(),
        budget.parse::<f64>(),
        seed.parse::<u64>(),
    );
    let (Ok(configuration), Ok(dimension), Ok(batch), Ok(budget), Ok(seed)) = parsed else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let problem = problems::builtin("goal-enclosure", dimension, 0).unwrap();
    let parameters = Parameters {
        batch_size: batch,
        seed,
        ..Parameters::default()
    };
    let started = Instant::now();
    let gaps = Gaps {
        deadline: started + Duration::from_secs_f64(budget),
        last: RefCell::new(started),
        worst: RefCell::new(Vec::new()),
        after: RefCell::new(0),
    };
    let mut planner = build_planner(configuration, &problem, &parameters).unwrap();
    planner.solve(&gaps).unwrap();
    let late = started
        .elapsed()
        .saturating_sub(Duration::from_secs_f64(budget));
    println!(
        "late by {late:?}; {} polls after the deadline",
        gaps.after.borrow()
    );
    if late < Duration::from_millis(1) {
        return;
    }
    let mut worst = gaps.worst.into_inner();
    worst.sort_by_key(|w| std::cmp::Reverse(w.0));
    for (gap, bt) in worst.iter().take(4) {
        println!("=== gap {gap:?}");
        for line in bt
            .to_string()
            .lines()
            .map(str::to_owned)
            .collect::<Vec<_>>()
            .iter()
            .filter(|l| l.contains("mit_star::") || l.contains("mit-star/src"))
            .filter(|l| !l.contains("kd_tree_build.rs:2") && !l.contains("kd_tree.rs:2"))
            .take(12)
        {
            println!("{line}");
        }
    }
}
