//! Command-line arguments shared by the `first_solution_work` and `anytime_rate` examples: a
//! configuration name, a built-in problem and parameter switches, each refused with exit code 2
//! and a message.

use mit_star::{Configuration, Parameters};
use mit_star_problems::Problem;

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
    mit_star_problems::builtin(family, dimension, layout).unwrap_or_else(|e| {
        eprintln!("{family} in {dimension} dimensions: {e}");
        std::process::exit(2)
    })
}

/// Takes the `name=true|false` arguments out of `args` and sets those switches of `parameters`:
/// `repair_reverse_search`, `cascading_rewirings`, `accelerated_checks`, `pruning`. Anything
/// else of that form exits with code 2.
pub(crate) fn take_switches(args: &mut Vec<String>, parameters: &mut Parameters) {
    args.retain(|a| {
        let Some((name, value)) = a.split_once('=') else {
            return true;
        };
        let Ok(on) = value.parse::<bool>() else {
            eprintln!("`{a}`: a switch is `true` or `false`");
            std::process::exit(2)
        };
        match name {
            "repair_reverse_search" => parameters.repair_reverse_search = Some(on),
            "cascading_rewirings" => parameters.cascading_rewirings = Some(on),
            "accelerated_checks" => parameters.accelerated_checks = on,
            "pruning" => parameters.pruning = on,
            _ => {
                eprintln!(
                    "`{name}`: not a switch (repair_reverse_search, cascading_rewirings, \
                     accelerated_checks, pruning)"
                );
                std::process::exit(2)
            }
        }
        false
    });
}
