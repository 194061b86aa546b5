//! [`HarnessError`]: everything that can go wrong in the harness, each naming what is wrong.

use std::path::PathBuf;

use thiserror::Error;

/// What went wrong. Input errors (unknown names, bad values, malformed files, unwritable
/// folders) are found before any planning starts; each message names the offending item and,
/// where there is a fixed set of valid names, lists them.
#[derive(Debug, Error)]
pub enum HarnessError {
    /// A planner configuration name is not known.
    #[error("unknown planner `{name}`; valid planners: {known}")]
    UnknownPlanner {
        /// The name given.
        name: String,
        /// The valid names, comma separated.
        known: String,
    },
    /// A built-in problem name is not known (and no file of that name exists).
    #[error(
        "unknown problem `{name}` (not a built-in problem and no such file); built-in problems: {known}"
    )]
    UnknownProblem {
        /// The name given.
        name: String,
        /// The built-in names, comma separated.
        known: String,
    },
    /// A shipped experiment name is not known.
    #[error("unknown experiment `{name}`; shipped experiments: {known}")]
    UnknownExperiment {
        /// The name given.
        name: String,
        /// The shipped names, comma separated.
        known: String,
    },
    /// A problem could not be built (for example a dimension the family does not support).
    #[error("problem `{name}` in {dimension} dimensions: {source}")]
    Problem {
        /// The problem's name.
        name: String,
        /// The dimension asked for.
        dimension: usize,
        /// Why the problem refused.
        #[source]
        source: mit_star_problems::ProblemError,
    },
    /// A problem file could not be read or parsed.
    #[error("problem file `{}`: {source}", path.display())]
    ProblemFile {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        #[source]
        source: mit_star_problems::ProblemFileError,
    },
    /// A parameter override is malformed: unknown key, wrong type, or a value the planner
    /// refuses.
    #[error("parameter `{key}`: {message}")]
    Parameter {
        /// The parameter's name.
        key: String,
        /// What is wrong.
        message: String,
    },
    /// The planner refused its parameters or the problem.
    #[error("planner `{planner}`: {source}")]
    Build {
        /// The planner's name.
        planner: String,
        /// Why it refused.
        #[source]
        source: mit_star::BuildError,
    },
    /// A planner refused the query while planning.
    #[error("planner `{planner}`: {source}")]
    Planning {
        /// The planner's name.
        planner: String,
        /// Why it refused.
        #[source]
        source: mit_star::PlannerError,
    },
    /// An experiment file is not valid TOML or does not follow the experiment schema.
    #[error("experiment file `{file}`: {message}")]
    ExperimentFile {
        /// The file (or shipped experiment) name.
        file: String,
        /// The parser's message (it names the field and the line).
        message: String,
    },
    /// A field of an experiment (file or command line) has a value that cannot be used.
    #[error("experiment `{experiment}`: `{field}` {message}")]
    ExperimentField {
        /// The experiment's file or name.
        experiment: String,
        /// The field, e.g. `problems[1].time`.
        field: String,
        /// What is wrong with its value.
        message: String,
    },
    /// A time budget that no clock can hold (zero, negative, non-finite or absurdly large).
    #[error(
        "{what}: {} is not a usable time budget; give a positive number of seconds, at most {:e} (about 116 days)",
        crate::short_number(source.0),
        crate::MAX_BUDGET_SECONDS
    )]
    Budget {
        /// Where the budget was given, e.g. `--time` or `problems[0].time`.
        what: String,
        /// The value and the rule.
        #[source]
        source: crate::BudgetError,
    },
    /// The command line combines options that do not go together, or lacks a required one.
    #[error("{0}")]
    Usage(String),
    /// A rule of the re-planning experiment (`mit-star replan`) has a value it cannot use.
    #[error("re-planning rule `{field}` {message}")]
    ReplanningRule {
        /// The rule, e.g. `window`.
        field: String,
        /// What is wrong with its value.
        message: String,
    },
    /// A robot (`--robot`, an experiment's `robot`) could not be found or loaded.
    #[error(transparent)]
    Robot(#[from] mit_star_robot::RobotSourceError),
    /// A URDF could not be spherised (`mit-star spherise`).
    #[error(transparent)]
    Spherise(#[from] mit_star_robot::SpheriseError),

    /// A point cloud file, or a cloud sampled from a scene, that cannot be read or filtered.
    #[error(transparent)]
    CloudInput(#[from] mit_star_robot::CloudInputError),

    /// A point cloud refused as an obstacle (empty, too many points, a bad radius).
    #[error("point cloud `{name}`: {source}")]
    Cloud {
        /// Where the cloud came from.
        name: String,
        /// What is wrong.
        #[source]
        source: mit_star_robot::CloudError,
    },
    /// A point cloud option of a problem (an experiment's `cloud` table, the command line's
    /// `--cloud`, `--voxel`, …) that cannot be used: it names the problem entry and the option.
    #[error("problem {problem}: cloud option {option}: {source}")]
    CloudOption {
        /// The problem: `` `table_pick_panda` #1 (problems[0]) ``.
        problem: String,
        /// The option: `` `cloud.voxel` (--voxel) ``.
        option: String,
        /// What is wrong with it.
        #[source]
        source: Box<HarnessError>,
    },
    /// A cloud filter (or the reading and sampling before them) left no point: an empty cloud
    /// would silently be an empty scene.
    #[error(
        "problem {problem}: cloud option {option} leaves none of the {before} points (an empty \
         cloud would silently be an empty scene)"
    )]
    CloudEmptied {
        /// The problem entry.
        problem: String,
        /// The option whose step left no point.
        option: String,
        /// The points before that step.
        before: usize,
    },
    /// A MotionBenchMaker folder or arm problem could not be read.
    #[error("arm problem `{name}`: {source}")]
    Arm {
        /// The folder or problem.
        name: String,
        /// Why.
        source: mit_star_robot::ArmError,
    },
    /// A path file names joints that are not the robot's (`check-path`): its states cannot be
    /// put into the robot's coordinate order.
    #[error(
        "{}: the path's joints are not the robot's ({mismatch}); the robot's joints, in coordinate order: {robot}",
        path.display()
    )]
    PathJoints {
        /// The path file.
        path: PathBuf,
        /// The names missing, unknown or repeated.
        mismatch: String,
        /// The robot's joint names in coordinate order, comma separated.
        robot: String,
    },
    /// An arm problem's start or goal in collision or out of reach of certified motions,
    /// the problem named by the [`ArmError`](mit_star_robot::ArmError).
    #[error(transparent)]
    ArmEnd(mit_star_robot::ArmError),
    /// A pose goal the inverse kinematics refuses: a link the robot lacks, a quaternion of
    /// norm 0, a negative tolerance.
    #[error("pose goal: {0}")]
    PoseGoal(#[from] mit_star_robot::IkError),
    /// The output folder cannot be created or written.
    #[error("output folder `{}` is not writable: {source}", path.display())]
    OutputFolder {
        /// The folder.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// A file the user gave (a path file, an experiment's problem file) cannot be used as
    /// input: a device or folder, larger than its kind's limit, or not text.
    #[error("{what} `{}`: {source}", path.display())]
    InputFile {
        /// What the file should be, e.g. `path file`.
        what: &'static str,
        /// The file.
        path: PathBuf,
        /// What is wrong (it names the limit).
        #[source]
        source: mit_star_problems::BoundedReadError,
    },
    /// Reading or writing a file failed.
    #[error("`{}`: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// The Planner Arena database could not be written or read.
    #[error("database `{}`: {source}", path.display())]
    Database {
        /// The database file.
        path: PathBuf,
        /// SQLite's error.
        #[source]
        source: rusqlite::Error,
    },
    /// A plot or picture could not be drawn.
    #[error("plot `{}`: {message}", path.display())]
    Plot {
        /// The image file.
        path: PathBuf,
        /// The drawing backend's message.
        message: String,
    },
    /// A 3-D view page could not be made or written.
    #[error("view `{}`: {source}", path.display())]
    View {
        /// The page.
        path: PathBuf,
        /// What went wrong.
        source: mit_star_view::ViewError,
    },
    /// Raw results could not be serialised.
    #[error("`{}`: {message}", path.display())]
    Serialise {
        /// The file.
        path: PathBuf,
        /// The serialiser's message.
        message: String,
    },
    /// Another process holds the results folder: one process writes a folder at a time, and
    /// a folder being written is not read.
    #[error("results folder `{}` is in use by {holder}; {advice}", path.display())]
    FolderLocked {
        /// The folder.
        path: PathBuf,
        /// The holder's process id, if it is a writer that recorded it.
        pid: Option<u32>,
        /// Who holds it (process id and command line, as the holder recorded them).
        holder: String,
        /// What to do.
        advice: String,
    },
    /// The files of a results folder disagree about the runs it holds.
    #[error(
        "results folder `{}` disagrees with itself: {counts}; {advice}",
        path.display()
    )]
    FolderInconsistent {
        /// The folder.
        path: PathBuf,
        /// What each file holds, and the first difference.
        counts: String,
        /// What to do.
        advice: String,
    },
    /// Two results folders whose numbers cannot be compared (different time budgets, a shard
    /// or an unfinished folder against a whole one).
    #[error(
        "`{}` and `{}` cannot be compared: {}; pass --allow-mismatch to compare them anyway \
         (with a warning)",
        a.display(),
        b.display(),
        reasons.join("; ")
    )]
    IncomparableFolders {
        /// Folder A.
        a: PathBuf,
        /// Folder B.
        b: PathBuf,
        /// Every difference found.
        reasons: Vec<String>,
    },
    /// An OMPL benchmark log does not follow the grammar.
    #[error("benchmark log line {line}: {message}")]
    LogSyntax {
        /// 1-based line number.
        line: usize,
        /// What was expected.
        message: String,
    },
}

impl HarnessError {
    /// A cloud error ([`CloudOption`](Self::CloudOption), [`CloudEmptied`](Self::CloudEmptied))
    /// with its problem named as the experiment's entry `entry` (`problems[2]`); other errors
    /// as they are.
    pub(crate) fn in_problem_entry(self, entry: &str) -> Self {
        match self {
            Self::CloudOption {
                problem,
                option,
                source,
            } => Self::CloudOption {
                problem: format!("{problem} ({entry})"),
                option,
                source,
            },
            Self::CloudEmptied {
                problem,
                option,
                before,
            } => Self::CloudEmptied {
                problem: format!("{problem} ({entry})"),
                option,
                before,
            },
            other => other,
        }
    }

    /// `true` for errors in what the user gave (names, values, files, folders): the command
    /// line reports them with exit code 2; other errors exit with 1.
    pub fn is_input_error(&self) -> bool {
        !matches!(
            self,
            Self::Io { .. }
                | Self::Database { .. }
                | Self::Plot { .. }
                | Self::Serialise { .. }
                | Self::Planning { .. }
        )
    }
}

/// The longest line of input echoed in an error message, in characters.
pub(crate) const ECHO_LIMIT: usize = 160;

/// `message` with every line cut to [`ECHO_LIMIT`] characters (a parser that quotes the
/// offending line of a 200 KB one-line file does not print it whole).
pub(crate) fn clip_lines(message: &str) -> String {
    message
        .lines()
        .map(|line| mit_star_problems::excerpt(line, ECHO_LIMIT))
        .collect::<Vec<_>>()
        .join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_culprit_and_list_alternatives() {
        let e = HarnessError::UnknownPlanner {
            name: "rrt".into(),
            known: "mit-star, eit-star".into(),
        };
        assert_eq!(
            e.to_string(),
            "unknown planner `rrt`; valid planners: mit-star, eit-star"
        );
        assert!(e.is_input_error());
        let e = HarnessError::ExperimentField {
            experiment: "x.toml".into(),
            field: "problems[1].time".into(),
            message: "is -1; it must be positive".into(),
        };
        assert_eq!(
            e.to_string(),
            "experiment `x.toml`: `problems[1].time` is -1; it must be positive"
        );
        let e = HarnessError::Io {
            path: "a".into(),
            source: std::io::Error::other("x"),
        };
        assert!(!e.is_input_error());
    }
}
