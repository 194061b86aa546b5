//! `mit-star check-path`: judge a path produced anywhere by the rules our planners' paths pass.

use std::path::PathBuf;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::commands::problem_args::ProblemArgs;
use crate::error::HarnessError;
use crate::formats::kpi_table::number;
use crate::formats::path_joints::{NamedPaths, json_paths, reorder, robot_order, take_joints_line};

/// Options of `mit-star check-path`.
#[derive(Debug, Args)]
pub struct CheckPathArgs {
    /// The problem.
    #[command(flatten)]
    pub problem: ProblemArgs,
    /// The path: a text file with one state per line (coordinates separated by spaces or
    /// commas); `#` starts a comment. Blank lines separate several paths, each checked. For
    /// an arm, a line `joints: NAME, NAME, …` before the first state names the joints the
    /// coordinates are (without it: the robot's coordinate order, as `mit-star robots` lists
    /// it); states are put into the robot's order by name, and names that are not the robot's
    /// joints, each once, are refused. The JSON `plan --json` and `runs.jsonl` write (one
    /// object per line, its `path` and `joints`) is read too.
    #[arg(long)]
    pub path: PathBuf,
    /// How far the path's ends may lie from the start and a goal, per coordinate (paths from
    /// planners that compute in `f32` differ in the last digits); ends that close are moved
    /// onto the start and the goal before the checks.
    #[arg(long, default_value_t = 1e-5)]
    pub tolerance: f64,
}

impl CheckPathArgs {
    /// Reads the paths, checks each on the problem's grid with its certification (as our
    /// planners' solutions are checked) and independently (exactly for box worlds,
    /// continuously for arms), and prints one verdict per path.
    ///
    /// # Errors
    /// An unknown problem, an unreadable path file, a line that is not numbers, a state of the
    /// wrong dimension, a path of fewer than two states.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        let instance = self.problem.build(1.0)?;
        let text = std::fs::read_to_string(&self.path).map_err(|source| HarnessError::Io {
            path: self.path.clone(),
            source,
        })?;
        let in_file =
            |message: String| HarnessError::Usage(format!("{}: {message}", self.path.display()));
        let NamedPaths { mut paths, joints } = match json_paths(&text) {
            Some(read) => read.map_err(in_file)?,
            None => {
                let (text, joints) = take_joints_line(&text).map_err(in_file)?;
                let paths = parse_paths(&text).map_err(in_file)?;
                NamedPaths { paths, joints }
            }
        };
        let reordered = self.robot_order(&instance, joints.as_deref(), &mut paths)?;
        if paths.is_empty() {
            return Err(HarnessError::Usage(format!(
                "{}: no path in the file",
                self.path.display()
            )));
        }
        say!("{} on {}", self.path.display(), instance.title());
        if let Some(note) = reordered {
            say!("  {note}");
        }
        let mut all_valid = true;
        for (i, path) in paths.iter_mut().enumerate() {
            instance.problem.snap_ends(path, self.tolerance);
            let verdict = instance
                .problem
                .check_path(path, self.tolerance)
                .map_err(|source| HarnessError::Build {
                    planner: format!("path {}", i + 1),
                    source,
                })?;
            let audit = instance.problem.validate(path, verdict.cost);
            let grid = match (verdict.valid, verdict.invalid_state, verdict.invalid_edge) {
                (true, _, _) => "valid".to_owned(),
                (false, Some(s), _) => {
                    format!("invalid: state {s} is out of bounds or in collision")
                }
                (false, None, Some(e)) => format!(
                    "invalid: {} of {} edges fail, the first from state {e} to {}",
                    verdict.invalid_edges,
                    path.len() - 1,
                    e + 1
                ),
                (false, None, None) => "invalid".to_owned(),
            };
            say!(
                "  path {}: {} states, cost {}; {}; the planners' checks (grid and certification): {grid}; independent check: {}",
                i + 1,
                path.len(),
                number(verdict.cost),
                if verdict.joins_query {
                    "joins the start to a goal"
                } else {
                    "does NOT join the start to a goal"
                },
                if audit.valid {
                    "valid".to_owned()
                } else {
                    format!(
                        "invalid ({})",
                        audit.failure.as_deref().unwrap_or("no reason given")
                    )
                }
            );
            all_valid &= verdict.valid && verdict.joins_query && audit.valid;
        }
        Ok(if all_valid {
            CommandOutcome::Success
        } else {
            CommandOutcome::InvalidPaths
        })
    }
}

impl CheckPathArgs {
    /// Puts `paths` into the robot's coordinate order by the file's joint names `joints`;
    /// the note to print if it reordered them.
    ///
    /// # Errors
    /// [`HarnessError::PathJoints`] for names that are not the robot's joints, each once;
    /// [`HarnessError::Usage`] for joint names on a box world's path.
    fn robot_order(
        &self,
        instance: &crate::definition::problem_instance::ProblemInstance,
        joints: Option<&[String]>,
        paths: &mut [Vec<Vec<f64>>],
    ) -> Result<Option<String>, HarnessError> {
        let Some(file) = joints else {
            return Ok(None);
        };
        let Some((robot, _)) = instance.problem.joints() else {
            return Err(HarnessError::Usage(format!(
                "{}: the file names joints, but {} is a box world (coordinates without names)",
                self.path.display(),
                instance.title()
            )));
        };
        let order = robot_order(file, &robot).map_err(|mismatch| HarnessError::PathJoints {
            path: self.path.clone(),
            mismatch: mismatch.to_string(),
            robot: robot.join(", "),
        })?;
        if order.iter().enumerate().all(|(i, &j)| i == j) {
            return Ok(None);
        }
        reorder(paths, &order);
        Ok(Some(format!(
            "the file's joints reordered by name into the robot's coordinate order: {}",
            robot.join(", ")
        )))
    }
}

/// The paths of `text`: states one per line, paths separated by blank lines, `#` comments.
fn parse_paths(text: &str) -> Result<Vec<Vec<Vec<f64>>>, String> {
    let mut paths = Vec::new();
    let mut current: Vec<Vec<f64>> = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            if !current.is_empty() {
                paths.push(std::mem::take(&mut current));
            }
            continue;
        }
        let state = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
            .map(str::parse::<f64>)
            .collect::<Result<Vec<f64>, _>>()
            .map_err(|e| format!("line {}: {e}", number + 1))?;
        current.push(state);
    }
    if !current.is_empty() {
        paths.push(current);
    }
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_read_with_comments_separators_and_blank_lines() {
        let text = "# two paths\n0 0\n1, 1 # end\n\n\n2 2\n3 3\n";
        let paths = parse_paths(text).unwrap();
        assert_eq!(paths.len(), 2);
        assert_eq!(paths[0], vec![vec![0.0, 0.0], vec![1.0, 1.0]]);
        assert!(parse_paths("0 x\n").unwrap_err().contains("line 1"));
    }
}
