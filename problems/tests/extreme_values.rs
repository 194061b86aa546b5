//! Extreme values in every field of a problem file, and in every builder of a built-in
//! family: a typed error or a correct problem, never a panic.

use mit_star_problems::{Problem, ProblemFileError};
use proptest::prelude::*;

/// The values a careless or hostile user writes.
const EXTREMES: [&str; 16] = [
    "0",
    "-0.0",
    "1e308",
    "-1e308",
    "5e-324",
    "-5e-324",
    "nan",
    "inf",
    "-inf",
    "1e-300",
    "18446744073709551615",
    "-1",
    "0.5",
    "1e19",
    "2.2250738585072014e-308",
    "\"x\"",
];

/// A valid file whose `slot` is replaced by one extreme value.
fn file_with(slot: usize, value: &str) -> String {
    let mut fields = [
        "0.0", "0.0", "0.3", "0.0", "-0.5", "-0.5", "0.5", "0.5", "0.0", "0.0", "0.1", "0.8",
        "5e-6", "3", "0.2", "0.05",
    ]
    .map(str::to_owned);
    fields[slot % fields.len()] = value.to_owned();
    let f = |i: usize| fields[i].as_str();
    format!(
        "name = \"x\"\nresolution = {}\nstart = [{}, {}]\ngoal = [{}, {}]\n\
         [bounds]\nlower = [{}, {}]\nupper = [{}, {}]\n\
         [[obstacles]]\ncenter = [{}, {}]\nwidths = [{}, {}]\n\
         [[lattices]]\ncount = {}\nspacing = {}\nside = {}\n",
        f(12),
        f(0).replace("0.0", "-0.3"),
        f(1),
        f(2),
        f(3),
        f(4),
        f(5),
        f(6),
        f(7),
        f(8),
        f(9),
        f(10),
        f(11),
        f(13),
        f(14),
        f(15)
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn problem_files_with_extreme_values_are_errors_or_problems(
        slot in 0usize..16,
        value in prop::sample::select(EXTREMES.to_vec()),
        second in 0usize..16,
        other in prop::sample::select(EXTREMES.to_vec()),
    ) {
        let text = file_with(slot, value);
        let text = if slot == second { text } else {
            // A second extreme value elsewhere (second file built the same way).
            let again = file_with(second, other);
            if again.len() < text.len() { again } else { text }
        };
        match Problem::from_toml_str(&text) {
            Ok(problem) => {
                prop_assert!(problem.validate().is_ok());
                prop_assert!(problem.step().is_finite() && problem.step() > 0.0);
                prop_assert!(problem.resolution() > 0.0 && problem.resolution() < 1.0);
                let _ = problem.check_step();
            }
            Err(e) => {
                let message = e.to_string();
                prop_assert!(!message.is_empty() && message.len() < 400, "{}", message);
                prop_assert!(!message.contains("000000000000000000"), "{}", message);
                let io = matches!(e, ProblemFileError::Io { .. });
                prop_assert!(!io, "{}", message);
            }
        }
    }

    #[test]
    fn built_in_families_take_any_dimension_and_seed(
        family in 0usize..11,
        n in prop::sample::select(vec![0usize, 1, 2, 3, 5, 33, 100]),
        seed in any::<u64>(),
    ) {
        let family = &mit_star_problems::catalogue()[family];
        match family.build(n, seed) {
            Ok(problem) => {
                prop_assert_eq!(problem.dimension(), n);
                prop_assert!(problem.validate().is_ok());
            }
            Err(e) => prop_assert!(n < 2, "{} in {}: {}", family.name(), n, e),
        }
    }
}

#[test]
fn dimensions_no_machine_holds_are_refused() {
    for family in mit_star_problems::catalogue() {
        for n in [1_000_000, usize::MAX] {
            let e = family.build(n, 0).unwrap_err().to_string();
            assert!(e.contains("memory") || e.contains("dimensions"), "{e}");
        }
    }
}
