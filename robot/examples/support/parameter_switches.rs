//! What the arm examples take after their positional arguments: `name=value` switches setting
//! the planners' [`Parameters`], parsed one way for all of them.

use mit_star::{Connection, EisExpansionForm, EisExpansionRule, Parameters};

/// Sets the parameter `name` of `parameters` to `value` (`true`/`false` for a switch, a number,
/// or `k-nearest`/`r-disc` for `connection`); `false` if no parameter has that name, so an
/// example can read its own options first. Panics on a value that does not parse: these are
/// measurement scripts, and a typo must not run the default silently.
pub(crate) fn set_parameter(parameters: &mut Parameters, name: &str, value: &str) -> bool {
    let on = || value.parse::<bool>().expect("true or false");
    let number = || value.parse::<f64>().expect("a number");
    match name {
        "rrt_valid_samples" => parameters.rrt_valid_samples = on(),
        "rrt_dynamic_domain" => parameters.rrt_dynamic_domain = on(),
        "rrt_forced_redraws" => {
            parameters.rrt_forced_redraws = value.parse().expect("a whole number");
        }
        "rrt_balance" => parameters.rrt_balance = on(),
        "rrt_halton" => parameters.rrt_halton = on(),
        "rrt_halton_shift" => parameters.rrt_halton_shift = on(),
        "lazy_certification" => parameters.lazy_certification = on(),
        "simplify_solutions" => parameters.simplify_solutions = on(),
        "simplify_smoothing" => parameters.simplify_smoothing = on(),
        "warm_start" => parameters.warm_start = on(),
        "aorrtc_simplify" => parameters.aorrtc_simplify = on(),
        "polish_when_idle" => parameters.polish_when_idle = on(),
        "batch_size" => parameters.batch_size = Some(number() as usize),
        "eis_batch_size" => parameters.eis_batch_size = Some(number() as usize),
        "batch_growth" => parameters.batch_growth = Some(number()),
        "solution_samples" => parameters.solution_samples = Some(number()),
        "neighbour_cap" => parameters.neighbour_cap = Some(number()),
        "solution_corner_pulls" => parameters.solution_corner_pulls = on(),
        "solution_corner_weights" => parameters.solution_corner_weights = number(),
        "range" => parameters.range = Some(number()),
        "rewire_factor" => parameters.rewire_factor = number(),
        "near_terminals" => parameters.near_terminals = Some(number()),
        "near_frontier" => parameters.near_frontier = number() as usize,
        "frontier_rays" => parameters.frontier_rays = on(),
        "sparse_initial_steps" => parameters.sparse_initial_steps = Some(number()),
        "sparse_min_steps" => parameters.sparse_min_steps = Some(number()),
        "eis_expansion_form" => {
            parameters.eis_expansion_form = match value {
                "paper" => EisExpansionForm::Paper,
                "authors" => EisExpansionForm::Authors,
                other => panic!("eis_expansion_form is paper or authors, not {other}"),
            };
        }
        "eis_expansion_rule" => {
            parameters.eis_expansion_rule = match value {
                "per-batch" => EisExpansionRule::PerBatch,
                "per-invalid-edge" => EisExpansionRule::PerInvalidEdge,
                other => panic!("eis_expansion_rule is per-batch or per-invalid-edge, not {other}"),
            };
        }
        "connection" => {
            parameters.connection = Some(match value {
                "k-nearest" => Connection::KNearest,
                "r-disc" => Connection::RDisc,
                other => panic!("connection is k-nearest or r-disc, not {other}"),
            });
        }
        _ => return false,
    }
    true
}
