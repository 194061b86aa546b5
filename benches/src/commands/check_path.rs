//! `mit-star check-path`: judge a path produced anywhere by the rules our planners' paths pass.

use std::path::PathBuf;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::commands::problem_args::ProblemArgs;
use crate::error::HarnessError;
use crate::formats::kpi_table::number;
use crate::formats::path_joints::{NamedPaths, json_paths, reorder, robot_order, take_joints_line};
use crate::pictures::plan_view::PlanView;

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
    #[arg(long, required_unless_present = "trajectory")]
    pub path: Option<PathBuf>,
    /// How far the path's ends may lie from the start and a goal, per coordinate (paths from
    /// planners that compute in `f32` differ in the last digits); ends that close are moved
    /// onto the start and the goal before the checks. At most 1e-3 (`MAX_TOLERANCE`): a
    /// path whose ends lie farther from the query does not join it.
    #[arg(long, default_value_t = 1e-5, allow_negative_numbers = true)]
    pub tolerance: f64,
    /// Instead of a path, a trajectory file (`plan --trajectory`'s JSON or CSV): checked for
    /// the joint position, velocity and acceleration limits (relative 1e-9), continuity,
    /// increasing times, rest at both ends, and collisions between consecutive samples.
    #[arg(long, value_name = "FILE", conflicts_with = "path")]
    pub trajectory: Option<PathBuf>,
    /// The limits a `--trajectory` is checked against.
    #[command(flatten)]
    pub limits: crate::commands::LimitArgs,
    /// Write an interactive 3-D view of the paths (or the trajectory) to this HTML file, the
    /// configurations in collision marked in red.
    #[arg(long, value_name = "FILE.html")]
    pub view: Option<PathBuf>,
    /// With `--trajectory`: draw it (each joint's position, velocity and acceleration against
    /// time, the limits dashed) into this PNG (or `.svg`) file.
    #[arg(long, value_name = "FILE.png", requires = "trajectory")]
    pub plot: Option<PathBuf>,
}

/// The largest `--tolerance` accepted: 1e-3 per coordinate, a hundred times the `f32`
/// rounding of a coordinate of size 10⁴ and far below any problem's features.
pub(crate) const MAX_TOLERANCE: f64 = 1e-3;

/// The largest path file read: 256 MiB (a million states of seven joints at full precision
/// take about 140 MB).
pub(crate) const PATH_FILE_LIMIT: u64 = 256 << 20;

impl CheckPathArgs {
    /// Reads the paths, checks each on the problem's grid with its certification (as our
    /// planners' solutions are checked) and independently (exactly for box worlds,
    /// continuously for arms), and prints one verdict per path.
    ///
    /// # Errors
    /// A tolerance outside `[0, MAX_TOLERANCE]`, an unknown problem, an unreadable path
    /// file (a device, a folder, larger than `PATH_FILE_LIMIT`, not text), a line that is
    /// not numbers, a coordinate that is not finite, a state of the wrong dimension, a path
    /// of fewer than two states: each naming the line.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        if !(self.tolerance >= 0.0 && self.tolerance <= MAX_TOLERANCE) {
            return Err(HarnessError::Usage(format!(
                "--tolerance {}: it must lie in [0, {MAX_TOLERANCE:e}] (per coordinate); a \
                 path whose ends lie farther from the start and the goal does not join them",
                crate::budget::short_number(self.tolerance)
            )));
        }
        let view = crate::commands::ViewArgs {
            view: self.view.clone(),
            view_search: false,
            view_package_root: Vec::new(),
        };
        let page = view.prepare()?;
        let instance = self.problem.build(1.0)?;
        if let Some(file) = &self.trajectory {
            let arm = instance.problem.as_arm().map(|a| &**a);
            return crate::commands::trajectory_args::check_trajectory_file(
                arm,
                file,
                &self.limits,
                Some(&instance),
                (page, self.plot.as_deref()),
            );
        }
        let text = mit_star_problems::read_bounded(self.path(), PATH_FILE_LIMIT, "path file")
            .map_err(|source| HarnessError::InputFile {
                what: "path file",
                path: self.path().to_path_buf(),
                source,
            })?;
        let dimension = instance.problem.dimension();
        let in_file = |message: String| {
            HarnessError::Usage(format!("path file `{}`: {message}", self.path().display()))
        };
        let NamedPaths { mut paths, joints } = match json_paths(&text) {
            Some(read) => {
                let read = read.map_err(in_file)?;
                check_json_paths(&read.paths, dimension).map_err(in_file)?;
                read
            }
            None => {
                let (text, joints) = take_joints_line(&text).map_err(in_file)?;
                let paths = parse_paths(&text, dimension).map_err(in_file)?;
                NamedPaths { paths, joints }
            }
        };
        let reordered = self.robot_order(&instance, joints.as_deref(), &mut paths)?;
        if paths.is_empty() {
            return Err(HarnessError::Usage(format!(
                "path file `{}`: no path in the file",
                self.path().display()
            )));
        }
        say!("{} on {}", self.path().display(), instance.title());
        if let Some(note) = reordered {
            say!("  {note}");
        }
        let mut all_valid = true;
        let mut drawn = match page {
            Some(_) => {
                let mut drawn = PlanView::new(
                    &instance.problem,
                    format!("{} on {}", self.path().display(), instance.title()),
                    None,
                )?;
                if let Some(resolver) = instance.mesh_resolver() {
                    drawn.meshes(&resolver);
                }
                Some(drawn)
            }
            None => None,
        };
        for (i, path) in paths.iter_mut().enumerate() {
            instance.problem.snap_ends(path, self.tolerance);
            let verdict = instance
                .problem
                .check_path(path, self.tolerance)
                .map_err(|source| {
                    HarnessError::Usage(format!(
                        "path file `{}`, path {}: {source}",
                        self.path().display(),
                        i + 1
                    ))
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
            let valid = verdict.valid && verdict.joins_query && audit.valid;
            all_valid &= valid;
            if let Some(drawn) = &mut drawn {
                let label = format!(
                    "path {}: {}",
                    i + 1,
                    if valid { "valid" } else { "INVALID" }
                );
                drawn.subtitle(format!("{label}: {grid}"));
                drawn.path(label, path);
            }
        }
        if let (Some(drawn), Some(page)) = (&drawn, page) {
            drawn.write(page)?;
            say!("  view: {}", page.display());
        }
        Ok(if all_valid {
            CommandOutcome::Success
        } else {
            CommandOutcome::InvalidPaths
        })
    }
}

impl CheckPathArgs {
    /// The `--path` file (clap requires it without `--trajectory`).
    fn path(&self) -> &std::path::Path {
        self.path.as_deref().unwrap_or(std::path::Path::new(""))
    }

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
                self.path().display(),
                instance.title()
            )));
        };
        let order = robot_order(file, &robot).map_err(|mismatch| HarnessError::PathJoints {
            path: self.path().to_path_buf(),
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

/// The paths read from JSON lines: each of at least two states of `dimension` coordinates
/// (JSON has no NaN, so every coordinate is a finite number).
fn check_json_paths(paths: &[Vec<Vec<f64>>], dimension: usize) -> Result<(), String> {
    for (i, path) in paths.iter().enumerate() {
        if path.len() < 2 {
            return Err(format!(
                "path {} has {} state(s); a path needs at least two",
                i + 1,
                path.len()
            ));
        }
        if let Some((k, state)) = path.iter().enumerate().find(|(_, s)| s.len() != dimension) {
            return Err(format!(
                "path {}, state {}: {} coordinates where the problem has {dimension}",
                i + 1,
                k + 1,
                state.len()
            ));
        }
    }
    Ok(())
}

/// The paths of `text`: states one per line, paths separated by blank lines, `#` comments;
/// each state of `dimension` finite coordinates, each path of at least two states. Errors
/// name the line (and the coordinate).
fn parse_paths(text: &str, dimension: usize) -> Result<Vec<Vec<Vec<f64>>>, String> {
    let mut paths = Vec::new();
    let mut current: Vec<Vec<f64>> = Vec::new();
    let mut first_line = 0;
    let mut close = |current: &mut Vec<Vec<f64>>, first: usize| {
        if current.len() == 1 {
            return Err(format!(
                "line {first}: path {} has one state; a path needs at least two",
                paths.len() + 1
            ));
        }
        if !current.is_empty() {
            paths.push(std::mem::take(current));
        }
        Ok(())
    };
    for (number, line) in text.lines().enumerate() {
        let number = number + 1;
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            close(&mut current, first_line)?;
            continue;
        }
        if current.is_empty() {
            first_line = number;
        }
        let mut state = Vec::with_capacity(dimension);
        for (k, token) in line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
            .enumerate()
        {
            let x = token.parse::<f64>().map_err(|_| {
                format!(
                    "line {number}, coordinate {}: `{}` is not a number",
                    k + 1,
                    mit_star_problems::excerpt(token, 40)
                )
            })?;
            if !x.is_finite() {
                return Err(format!(
                    "line {number}, coordinate {}: the coordinate is {}; a state's \
                     coordinates must be finite numbers",
                    k + 1,
                    if x.is_nan() { "NaN" } else { "infinite" }
                ));
            }
            state.push(x);
        }
        if state.len() != dimension {
            return Err(format!(
                "line {number} has {} coordinates; the problem's states have {dimension}",
                state.len()
            ));
        }
        current.push(state);
    }
    close(&mut current, first_line)?;
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_read_with_comments_separators_and_blank_lines() {
        let text = "# two paths\n0 0\n1, 1 # end\n\n\n2 2\n3 3\n";
        let paths = parse_paths(text, 2).unwrap();
        assert_eq!(paths.len(), 2);
        assert_eq!(paths[0], vec![vec![0.0, 0.0], vec![1.0, 1.0]]);
        assert!(parse_paths("0 x\n", 2).unwrap_err().contains("line 1"));
    }

    #[test]
    fn bad_states_name_their_line_and_coordinate() {
        let e = parse_paths("0 0\n0 NaN\n", 2).unwrap_err();
        assert!(
            e.contains("line 2, coordinate 2") && e.contains("NaN"),
            "{e}"
        );
        let e = parse_paths("0 0\ninf 0\n", 2).unwrap_err();
        assert!(
            e.contains("line 2, coordinate 1") && e.contains("infinite"),
            "{e}"
        );
        let e = parse_paths("0 0\n0 0 0\n", 2).unwrap_err();
        assert!(e.contains("line 2 has 3 coordinates"), "{e}");
        let e = parse_paths("0 0\n1 1\n\n# one state\n2 2\n", 2).unwrap_err();
        assert!(e.contains("line 5: path 2 has one state"), "{e}");
    }
}
