//! The free-text setup description of an OMPL log (`<<<| … |>>>`).

use crate::outcome::experiment_results::ExperimentResults;

/// Describes how instance `index` of `results` was run: the experiment, the problem (as a
/// problem file), the protocol (seeds, shuffling, budget), how many runs executed
/// concurrently, and the point cloud's preparation step by step. Every line ends with a line break; no line is `|>>>`.
pub(crate) fn setup_description(results: &ExperimentResults, index: usize) -> String {
    let e = &results.experiment;
    let i = &results.instances[index];
    let p = &i.problem;
    let optimum = p
        .optimum()
        .map_or_else(|| "unknown".to_owned(), |o| o.to_string());
    let planners: Vec<String> = e
        .planners
        .iter()
        .map(|s| format!("{} ({})", s.name(), s.configuration().name()))
        .collect();
    let mut text = format!(
        "mit-star experiment `{name}`{description}\n\
         problem instance: {title} (id {id}), {dimension} dimensions\n\
         collision-check resolution {resolution} of the maximum extent (step {step}); \
         straight line {line}; optimum {optimum}\n\
         planners: {planners}\n\
         runs per planner: {runs}; run i uses seed {seed} + i; the planner order is shuffled per run index\n\
         time budget per run: {budget} s of wall-clock time, planner construction included\n\
         concurrent runs: {concurrency} (worker threads on {available} available hardware threads; concurrency changes timings)\n\
         statistics: unsolved runs and runs whose path fails the independent full-resolution validation count as +inf\n\
         run property `time`: seconds to the first solution, or the budget without one; `run time`: wall-clock seconds used\n\
         interrupted: {interrupted}\n",
        name = e.name,
        description = if e.description.is_empty() {
            String::new()
        } else {
            format!(": {}", e.description)
        },
        title = i.title(),
        id = i.id,
        dimension = i.dimension,
        resolution = p.resolution(),
        step = p.step(),
        line = p.straight_line_cost(),
        planners = planners.join(", "),
        runs = e.runs,
        seed = e.seed,
        budget = i.budget,
        concurrency = results.concurrency,
        available = results.machine.available_threads,
        interrupted = if results.interrupted {
            "yes (Ctrl-C): only finished runs are recorded"
        } else {
            "no"
        },
    );
    if let Some(cloud) = &i.cloud {
        text.push_str(&format!(
            "point cloud: {}, once before the runs\n",
            cloud.line()
        ));
        for step in &cloud.steps {
            text.push_str("  cloud: ");
            text.push_str(step);
            text.push('\n');
        }
    }
    text.push_str("problem file:\n");
    for line in p.describe().lines() {
        text.push_str("  ");
        text.push_str(line);
        text.push('\n');
    }
    text
}
