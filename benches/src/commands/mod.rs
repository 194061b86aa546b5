//! The `mit-star` command line: [`Cli`] and its subcommands.

/// `println!` that ignores a closed stdout (`mit-star problems | head` must not panic).
macro_rules! say {
    () => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout().lock());
    }};
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout().lock(), $($arg)*);
    }};
}

mod bench;
mod check_path;
mod check_state;
mod cloud_args;
mod compare;
mod listings;
mod merge;
mod plan;
mod pose_goal_args;
mod problem_args;
mod replan;
mod spherise;
mod trajectory_args;
mod view_args;

use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use clap::{Parser, Subcommand};

pub use bench::BenchArgs;
pub use check_path::CheckPathArgs;
pub use check_state::CheckStateArgs;
pub use cloud_args::CloudArgs;
pub use compare::CompareArgs;
pub use listings::{ExperimentsArgs, ProblemsArgs, RobotsArgs};
pub use merge::MergeArgs;
pub use plan::PlanArgs;
pub use problem_args::ProblemArgs;
pub use replan::ReplanArgs;
pub use spherise::SpheriseArgs;
pub use trajectory_args::{Corners, LimitArgs, Timed, TrajectoryArgs};
pub use view_args::ViewArgs;

use crate::error::HarnessError;

/// `mit-star`: run MIT*, EIT* and their ablations on benchmark problems, and the paper's
/// experiments, producing OMPL logs, Planner Arena databases, plots and KPI tables.
#[derive(Debug, Parser)]
#[command(
    name = "mit-star",
    version,
    about = "Run MIT*, EIT* and their ablations on benchmark problems, and the paper's experiments: OMPL logs, Planner Arena databases, plots and KPI tables.",
    long_about = None
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run one planner on one problem; print the result and draw 2-D runs and arm plans.
    Plan(PlanArgs),
    /// Check a path from a file (another planner's) against a problem by the rules our
    /// planners' paths pass: the problem's grid with its certification, and the independent
    /// check (exact for box worlds, continuous for arms).
    CheckPath(CheckPathArgs),
    /// Diagnose an arm configuration (or a problem's start and goals): joints outside their
    /// limits, links meeting obstacles or each other, by name, and the nearest obstacle.
    CheckState(CheckStateArgs),
    /// Run an experiment (file, shipped name, or flags) and write its results folder.
    Bench(BenchArgs),
    /// Combine the results folders of an experiment's shards (`bench --shard K/N`) into one.
    Merge(MergeArgs),
    /// Compare two results folders of an experiment: per planner and problem, the change in
    /// median time to first solution, success rate and final cost, with confidence intervals.
    Compare(CompareArgs),
    /// List the built-in problems with their parameters and defaults.
    Problems(ProblemsArgs),
    /// List the planner configurations and their parameters' defaults.
    Planners,
    /// List the shipped robots (`--robot NAME`): joints, spheres, and their problem sets; or
    /// describe one robot (shipped, a URDF, or a folder): its joints in coordinate order,
    /// spheres per link, planning groups.
    Robots(RobotsArgs),
    /// List the shipped experiments, or print one.
    Experiments(ExperimentsArgs),
    /// The paper's re-planning experiment on the Panda: the arm travels between two blocks
    /// five times among moving obstacles, re-planning with 0.1 s per plan; success rates and
    /// travelled costs per planner and scene.
    Replan(ReplanArgs),
    /// Cover a URDF's collision meshes with spheres (every point of each mesh's solid inside
    /// them, none farther than the tolerance from it) and write the spherised URDF.
    Spherise(SpheriseArgs),
}

impl Command {
    /// `true` for the commands that poll the interrupt flag and write what they finished
    /// when it is raised (`plan`, `bench`, `replan`; `spherise` stops its covers and writes
    /// nothing); the others leave at the first signal.
    pub fn polls_interrupt(&self) -> bool {
        matches!(
            self,
            Self::Plan(_) | Self::Bench(_) | Self::Replan(_) | Self::Spherise(_)
        )
    }
}

/// How a successful command ended, for the exit code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CommandOutcome {
    /// Everything went well (exit code 0).
    Success,
    /// Some returned paths failed the independent validation (exit code 3; results written).
    InvalidPaths,
    /// Interrupted by SIGINT or SIGTERM (finished runs written; the binary exits with 130 or
    /// 143, after the signal).
    Interrupted,
    /// Every run was written, but some ended in an error (exit code 1).
    RunErrors,
}

impl CommandOutcome {
    /// How a command that records runs ends: interrupted (the signal's exit code) before runs
    /// that ended in an error (exit code 1, whenever any recorded run did) before invalid paths
    /// (3) before success.
    pub fn of_runs(interrupted: bool, errors: usize, invalid: usize) -> Self {
        if interrupted {
            Self::Interrupted
        } else if errors > 0 {
            Self::RunErrors
        } else if invalid > 0 {
            Self::InvalidPaths
        } else {
            Self::Success
        }
    }

    /// The process exit code.
    pub fn exit_code(self) -> ExitCode {
        match self {
            Self::Success => ExitCode::SUCCESS,
            Self::InvalidPaths => ExitCode::from(3),
            Self::Interrupted => ExitCode::from(130),
            Self::RunErrors => ExitCode::from(1),
        }
    }
}

impl Cli {
    /// Runs the command. `interrupt` is raised by the caller's Ctrl-C handler.
    ///
    /// # Errors
    /// Whatever the command reports; input errors are found before any planning.
    pub fn run(&self, interrupt: Arc<AtomicBool>) -> Result<CommandOutcome, HarnessError> {
        // Commands that poll no flag leave at the first signal: every command honours it.
        let _leave_at_once = (!self.command.polls_interrupt())
            .then(crate::execution::interrupt::NothingToSave::begin);
        match &self.command {
            Command::Plan(args) => args.run(&interrupt),
            Command::CheckPath(args) => args.run(),
            Command::CheckState(args) => args.run(),
            Command::Bench(args) => args.run(interrupt),
            Command::Merge(args) => args.run(),
            Command::Compare(args) => args.run(),
            Command::Problems(args) => args.run(),
            Command::Planners => listings::print_planners(),
            Command::Robots(args) => args.run(),
            Command::Experiments(args) => args.run(),
            Command::Replan(args) => args.run(&interrupt),
            Command::Spherise(args) => args.run(&interrupt),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_exit_1_unless_interrupted_and_before_invalid_paths() {
        // (interrupted, runs in error, invalid paths) → outcome.
        for (interrupted, errors, invalid, outcome) in [
            (false, 0, 0, CommandOutcome::Success),
            (false, 0, 2, CommandOutcome::InvalidPaths),
            (false, 1, 2, CommandOutcome::RunErrors),
            (true, 1, 2, CommandOutcome::Interrupted),
        ] {
            assert_eq!(
                CommandOutcome::of_runs(interrupted, errors, invalid),
                outcome
            );
        }
        assert_eq!(CommandOutcome::RunErrors.exit_code(), ExitCode::from(1));
    }
}
