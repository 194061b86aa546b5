//! What `cloud_loop` and `cloud_profile` share: the planner named on the command line with its
//! `--set` overrides, and a problem line of standard input made into a problem with its cloud.

use std::sync::Arc;

use clap::Parser;
use mit_star_benches::commands::ProblemArgs;
use mit_star_benches::{
    HarnessError, InstanceProblem, ParameterOverrides, PlannerSpec, ProblemInstance,
    parse_configuration,
};

/// One problem's options, as `plan` takes them.
#[derive(Debug, Parser)]
struct Run {
    #[command(flatten)]
    problem: ProblemArgs,
}

/// The planner called `name`, with `sets` (`--set KEY=VALUE` pairs) applied.
///
/// # Panics
/// On an unknown planner, a malformed pair or a refused value (a tool's usage error).
pub(crate) fn planner_spec(name: &str, sets: &[String]) -> PlannerSpec {
    let mut overrides = ParameterOverrides::default();
    for pair in sets.chunks(2) {
        match pair {
            [flag, value] if flag == "--set" => overrides.push_assignment(value).expect("--set"),
            _ => panic!("expected --set KEY=VALUE, got {pair:?}"),
        }
    }
    let configuration = parse_configuration(name).expect("a planner");
    PlannerSpec::new(configuration, None, &overrides).expect("parameters")
}

/// The problem of `words` (`plan`'s problem options), its cloud applied for an arm problem;
/// with the cloud's report lines (each filter step's and the tree's time). `tool` names the
/// program in usage errors.
///
/// # Errors
/// What `plan` refuses: the options ([`HarnessError::Usage`]), the problem, the cloud, or an
/// end touching the cloud.
pub(crate) fn problem_with_cloud<'a>(
    tool: &'a str,
    words: impl Iterator<Item = &'a str>,
) -> Result<(ProblemInstance, Vec<String>), HarnessError> {
    let mut problem = Run::try_parse_from(std::iter::once(tool).chain(words))
        .map_err(|e| HarnessError::Usage(e.to_string()))?
        .problem;
    let clouds = std::mem::take(&mut problem.clouds);
    let mut instance = problem.build(1.0)?;
    let mut lines = Vec::new();
    if clouds.any() {
        let arm = instance
            .problem
            .as_arm()
            .ok_or_else(|| HarnessError::Usage("clouds need an arm problem".into()))?;
        let label = format!("#{}", instance.instance);
        let (with_cloud, summary) = clouds.apply(arm, instance.instance, &label)?;
        lines.extend(summary.steps.iter().map(|s| format!("cloud: {s}")));
        with_cloud.check_ends().map_err(HarnessError::ArmEnd)?;
        instance.problem = InstanceProblem::Arm(Arc::new(with_cloud));
    }
    Ok((instance, lines))
}
