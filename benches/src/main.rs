//! `mit-star`: the command-line tool of the mit-star framework (see `mit-star --help`).

#![forbid(unsafe_code)]

use std::process::ExitCode;

use clap::Parser;
use mit_star_benches::Interrupt;
use mit_star_benches::commands::{Cli, CommandOutcome};

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
