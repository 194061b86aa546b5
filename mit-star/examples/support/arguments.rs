//! Command-line arguments shared by the `first_solution_work` and `anytime_rate` examples: a
//! configuration name and a built-in problem, each refused with exit code 2 and the library's
//! message.

use mit_star::Configuration;
use problems::Problem;

/// The configuration named `name` (`mit-star`, `eit-star`, …).
pub(crate) fn configuration(name: &str) -> Configuration {
    name.parse().unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(2)
    })
}

/// The built-in problem `family` in `dimension` dimensions; a seeded family's layout goes
/// after a colon (`random-rectangles:2`, layout 1 without one).
pub(crate) fn problem(family: &str, dimension: usize) -> Problem {
    let (family, layout) = match family.split_once(':') {
        Some((f, l)) => (f, l.parse().unwrap_or(1)),
        None => (family, 1),
    };
    problems::builtin(family, dimension, layout).unwrap_or_else(|e| {
        eprintln!("{family} in {dimension} dimensions: {e}");
        std::process::exit(2)
    })
}
