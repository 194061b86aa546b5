//! `mit-star`: the command-line tool of the mit-star framework (see `mit-star --help`).

#![forbid(unsafe_code)]

use std::process::ExitCode;

use clap::Parser;
use mit_star_benches::Interrupt;
use mit_star_benches::commands::{Cli, CommandOutcome};

/// mimalloc rather than the system allocator: a planner is built for every run, and its
/// construction allocates (on the Panda, RRT-Connect's construction in `bench` took 15.9 µs
/// with glibc's allocator and 9.7 µs with this one; the solves were unchanged).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let interrupt = match Interrupt::install() {
        Ok(interrupt) => interrupt,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(1);
        }
    };
    match cli.run(interrupt.flag()) {
        Ok(CommandOutcome::Interrupted) => ExitCode::from(interrupt.exit_code()),
        Ok(outcome) => outcome.exit_code(),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(if e.is_input_error() { 2 } else { 1 })
        }
    }
}
