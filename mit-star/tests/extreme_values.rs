//! Extreme values in every planner parameter, through the run-time front door
//! (`build_planner`): a typed error, or a planner that runs, keeps its deadline and returns a
//! valid path — never a panic.

use crate::common;

use std::time::Duration;

use common::scheduled::Scheduled;

use mit_star::{
    Configuration, IterationLimit, Parameters, TerminationExt, TimeLimit, build_planner,
};
use proptest::prelude::*;

const FLOATS: [f64; 14] = [
    0.0,
    -0.0,
    -1.0,
    1e308,
    -1e308,
    5e-324,
    f64::MIN_POSITIVE,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e-300,
    0.5,
    1.0,
    1e19,
];

const COUNTS: [usize; 7] = [0, 1, 2, 7, 1 << 20, usize::MAX / 2, usize::MAX];

fn with_field(field: usize, float: f64, count: usize, seed: u64) -> Parameters {
    let mut p = Parameters {
        seed,
        ..Parameters::default()
    };
    match field {
        0 => p.batch_size = Some(count),
        1 => p.rewire_factor = float,
        2 => p.resolution = float,
        3 => p.gaussian_std_fraction = float,
        4 => p.bridge_checks = Some(count),
        5 => p.sparse_initial_steps = Some(float),
        6 => p.sparse_factor = float,
        _ => p.sparse_min_steps = Some(float),
    }
    p
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    #[test]
    fn any_parameter_value_is_an_error_or_a_sound_run(
        field in 0usize..8,
        float in prop::sample::select(FLOATS.to_vec()),
        count in prop::sample::select(COUNTS.to_vec()),
        configuration in prop::sample::select(Configuration::ALL.to_vec()),
        seed in any::<u64>(),
    ) {
        let problem = mit_star_problems::builtin("wall-gap", 2, 0).unwrap();
        let parameters = with_field(field, float, count, seed);
        let clock = Scheduled::start();
        match build_planner(configuration, &problem, &parameters) {
            Err(e) => {
                let text = e.to_string();
                prop_assert!(!text.is_empty() && text.len() < 300, "{}", text);
                prop_assert!(!text.contains("0000000000000"), "{}", text);
            }
            Ok(mut planner) => {
                let budget = Duration::from_millis(30);
                let stop = TimeLimit::until(clock.started() + budget).or(IterationLimit::new(3_000));
                let outcome = planner.solve(&stop).unwrap();
                // On the time this thread was scheduled: a loaded machine does not fail it.
                let took = clock.elapsed();
                prop_assert!(took < budget + Duration::from_millis(200), "took {:?} of {}", took, clock.source());
                if let Some(solution) = outcome.solution() {
                    prop_assert!(common::path_is_valid(problem.world(), &solution.path, problem.step()));
                }
            }
        }
    }
}
