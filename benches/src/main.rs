//! `mit-star`: the command-line tool of the mit-star framework (see `mit-star --help`).

#![forbid(unsafe_code)]

use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use clap::Parser;
use mit_star_benches::commands::Cli;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let interrupt = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&interrupt);
    // First Ctrl-C: stop starting runs, abandon running ones, write finished ones.
    // Second Ctrl-C: leave at once.
    let _ = ctrlc::set_handler(move || {
        if flag.swap(true, Ordering::SeqCst) {
            eprintln!("\ninterrupted twice: leaving without writing results");
            std::process::exit(130);
        }
        eprintln!(
            "\ninterrupted: finishing, then writing the finished runs (Ctrl-C again to quit)"
        );
    });
    match cli.run(interrupt) {
        Ok(outcome) => outcome.exit_code(),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(if e.is_input_error() { 2 } else { 1 })
        }
    }
}
