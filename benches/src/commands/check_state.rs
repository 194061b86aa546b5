//! `mit-star check-state`: what one arm configuration touches, by name.

use clap::Args;

use crate::commands::CommandOutcome;
use crate::commands::problem_args::ProblemArgs;
use crate::error::HarnessError;

/// Options of `mit-star check-state`.
#[derive(Debug, Args)]
pub struct CheckStateArgs {
    /// The problem (an arm problem: `mbm:FOLDER/N`, with `--robot` for robots other than the
    /// Panda).
    #[command(flatten)]
    pub problem: ProblemArgs,
    /// The configuration, joint values separated by commas or spaces, in the order `mit-star
    /// robots` lists the joints. Without it, the problem's start and goals are checked.
    #[arg(long, allow_hyphen_values = true)]
    pub state: Option<String>,
}

impl CheckStateArgs {
    /// Prints the diagnosis of the configuration (or of the problem's start and goals): the
    /// planners' verdict, joints outside their limits, links meeting obstacles or each other,
    /// and the nearest obstacle. Exit code 3 if any is invalid.
    ///
    /// # Errors
    /// An unknown problem, a box-world problem, a state that is not numbers or has the wrong
    /// number of values.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        let instance = self.problem.build_with_any_ends(1.0)?;
        let Some(arm) = instance.problem.as_arm() else {
            return Err(HarnessError::Usage(format!(
                "check-state diagnoses arm configurations; {} is a box world",
                instance.title()
            )));
        };
        let dimension = arm.robot().joint_space().joints().len();
        let states: Vec<(String, Vec<f64>)> = match &self.state {
            Some(text) => {
                let q =
                    parse_state(text).map_err(|m| HarnessError::Usage(format!("--state: {m}")))?;
                if q.len() != dimension {
                    return Err(HarnessError::Usage(format!(
                        "--state has {} values; the robot has {dimension} joints, in this order: {}",
                        q.len(),
                        arm.robot().joint_names().join(", ")
                    )));
                }
                vec![("state".to_owned(), q)]
            }
            None => {
                let problem = mit_star_problems::PlanningProblem::start(&**arm).to_vec();
                std::iter::once(("start".to_owned(), problem))
                    .chain(
                        mit_star_problems::PlanningProblem::goals(&**arm)
                            .iter()
                            .enumerate()
                            .map(|(i, g)| (format!("goal {}", i + 1), g.clone())),
                    )
                    .collect()
            }
        };
        say!("{}", instance.title());
        let mut all_valid = true;
        for (what, q) in &states {
            let diagnosis = arm.diagnose(q);
            let joinable = !diagnosis.valid || arm.joinable(q);
            all_valid &= diagnosis.valid && joinable;
            say!("{what}: {diagnosis}");
            if !joinable {
                let beyond = if arm.padding().is_zero() {
                    "the margin".to_owned()
                } else {
                    format!("the margin and the padding of {}", arm.padding())
                };
                say!(
                    "  within the certification floor ({} µm beyond {beyond}): no certified motion reaches it",
                    mit_star_robot::CERTIFICATION_FLOOR * 1e6
                );
            }
        }
        Ok(if all_valid {
            CommandOutcome::Success
        } else {
            CommandOutcome::InvalidPaths
        })
    }
}

/// Joint values separated by commas or white space.
fn parse_state(text: &str) -> Result<Vec<f64>, String> {
    text.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f64>().map_err(|e| format!("`{t}`: {e}")))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn states_are_read_with_commas_or_spaces_and_bad_numbers_are_named() {
        assert_eq!(parse_state("0, -1.5 2").unwrap(), vec![0.0, -1.5, 2.0]);
        assert!(parse_state("0, x").unwrap_err().contains("`x`"));
    }
}
