//! Errors: [`ProblemError`] for problems built in Rust, [`ProblemFileError`] for problem files.

use std::fmt;
use std::path::PathBuf;

use mit_star_spaces::SpaceError;
use mit_star_validity::ValidityError;
use thiserror::Error;

/// Which end of a problem a state is: the start, or the goal with the given index.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Endpoint {
    /// The start state.
    Start,
    /// The goal state with this index (0 for the first goal).
    Goal(usize),
}

impl fmt::Display for Endpoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Start => f.write_str("start"),
            Self::Goal(index) => write!(f, "goal {index}"),
        }
    }
}

/// `1 value`, `3 values`.
fn count(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// A number for a message ([`mit_star_spaces::short_number`]).
pub(crate) fn short(value: f64) -> String {
    mit_star_spaces::short_number(value)
}

/// An optional extent for a message.
fn optional(value: Option<f64>) -> String {
    value.map_or_else(|| "none".to_owned(), short)
}

/// What is wrong with a planning problem or with the parameters of a problem family.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ProblemError {
    /// A problem family was asked for fewer dimensions than it is defined in.
    #[error("{problem} needs at least 2 dimensions, got {n}")]
    Dimension {
        /// The problem family.
        problem: &'static str,
        /// The dimension asked for.
        n: usize,
    },
    /// A parameter of a problem family is malformed.
    #[error("{problem}: `{parameter}` {reason}")]
    Parameter {
        /// The problem family.
        problem: &'static str,
        /// The parameter (its setter's name).
        parameter: &'static str,
        /// What is wrong with it, starting with its value.
        reason: String,
    },
    /// The bounds of the world do not make a state space.
    #[error("the bounds are malformed: {0}")]
    Bounds(#[source] SpaceError),
    /// A box, lattice or resolution is malformed.
    #[error(transparent)]
    Validity(#[from] ValidityError),
    /// The start or a goal has the wrong length, a non-finite coordinate, or lies out of bounds.
    #[error("{endpoint}: {source}")]
    State {
        /// Which state.
        endpoint: Endpoint,
        /// What is wrong with it.
        #[source]
        source: SpaceError,
    },
    /// The start or a goal lies inside an obstacle.
    #[error("{endpoint} {state:?} is in collision")]
    InCollision {
        /// Which state.
        endpoint: Endpoint,
        /// Its coordinates.
        state: Vec<f64>,
    },
    /// A problem was given no goal.
    #[error("a problem needs at least one goal")]
    NoGoals,
    /// A problem too large for this machine's memory, refused before allocating it.
    #[error("{what} would need about {needed} of memory; this machine has {available} available")]
    TooLarge {
        /// What was asked for.
        what: String,
        /// The estimated size.
        needed: String,
        /// What the machine has available.
        available: String,
    },
    /// The collision-check resolution is outside `(0, 1)`.
    #[error(
        "the collision-check resolution is {}; it must lie strictly between 0 and 1 (a fraction of the space's maximum extent)",
        short(*.value)
    )]
    Resolution {
        /// The value given.
        value: f64,
    },
    /// The collision-check step is larger than the thinnest obstacle or anti-obstacle, so an
    /// edge could pass through an obstacle between two checked points, and the problem did not
    /// allow that explicitly.
    #[error(
        "the collision-check step {} (resolution {} × maximum extent {}) is larger than the \
         thinnest obstacle ({}) or anti-obstacle ({}): an edge could cross an obstacle between \
         two checked points; use a resolution of at most {}, or allow a coarse step explicitly \
         (`allow_coarse_step = true` in a problem file, `--allow-coarse-step` on the command line)",
        short(*.step), short(*.resolution), short(*.extent), optional(*.obstacle),
        optional(*.anti_obstacle), short(*.largest_resolution)
    )]
    StepTooCoarse {
        /// The step `L = resolution × extent`.
        step: f64,
        /// The resolution.
        resolution: f64,
        /// The space's maximum extent.
        extent: f64,
        /// The smallest side of any obstacle (`None` without obstacles).
        obstacle: Option<f64>,
        /// The smallest side of any anti-obstacle (`None` without anti-obstacles).
        anti_obstacle: Option<f64>,
        /// The largest resolution whose step is not above either.
        largest_resolution: f64,
    },
    /// Motion checked only at grid points on a problem whose contacts can fall between them
    /// (an arm's spheres sweep further than they are thick between two checks): planners
    /// must certify the edges of their solutions (`certification` above 1) unless uncertified
    /// motion is explicitly allowed.
    #[error(
        "{}: certification = 1 checks edges only at grid points {} apart, and \
         a sphere can sweep up to {} m between two of them, past obstacles thinner than \
         that: leave certification on (any value above 1 certifies every configuration of a \
         solution's edges), or allow uncertified motion explicitly (`--allow-coarse-step`, \
         `allow_coarse_step = true` in an experiment, `ArmProblem::allowing_uncertified_motion` \
         in the library)",
        .problem, short(*.step), short(*.sweep)
    )]
    Uncertified {
        /// The problem's name.
        problem: String,
        /// The check step.
        step: f64,
        /// How far the fastest sphere can move over one step (metres).
        sweep: f64,
    },
    /// A claimed optimal cost is not finite or is below the straight-line distance to the
    /// nearest goal, which no path can beat.
    #[error(
        "optimum {value} is impossible: it must be finite and at least the straight-line \
         distance {lower_bound} from the start to the nearest goal"
    )]
    Optimum {
        /// The value given.
        value: f64,
        /// The straight-line lower bound.
        lower_bound: f64,
    },
    /// Random rectangles could not place its boxes within the attempt budget (almost every
    /// drawn box contained the start or the goal).
    #[error(
        "random-rectangles: gave up after {attempts} draws with only {accepted} of {wanted} \
         boxes accepted; boxes keep containing the start or the goal (smaller sides or a larger \
         `max_attempts` may help)"
    )]
    RedrawLimit {
        /// Boxes drawn in total.
        attempts: usize,
        /// Boxes accepted.
        accepted: usize,
        /// Boxes wanted.
        wanted: usize,
    },
    /// [`builtin`](crate::builtin) was asked for a name it does not know.
    #[error("unknown problem `{name}`; known problems: {known}")]
    UnknownProblem {
        /// The name asked for.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
}

/// A position in a problem file: 1-based line and column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Location {
    /// Line, counting from 1.
    pub line: usize,
    /// Column (in characters), counting from 1.
    pub column: usize,
}

impl Location {
    /// The location of byte `offset` in `text` (clamped to the text, rounded down to a
    /// character boundary).
    pub(crate) fn of_offset(text: &str, offset: usize) -> Self {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let before = &text[..offset];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        Self { line, column }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}", self.line, self.column)
    }
}

/// Formats an optional location as a prefix: `"line 3, column 1: "` or nothing.
fn at(location: &Option<Location>) -> String {
    location.map_or_else(String::new, |l| format!("{l}: "))
}

/// What is wrong with a problem file. Every variant names the offending field where there is
/// one (`obstacles[2].widths`, `bounds.lower[1]`, `goals[0]`, …).
#[derive(Debug, Error)]
pub enum ProblemFileError {
    /// The file could not be read.
    #[error("cannot read problem file `{}`: {source}", path.display())]
    Io {
        /// The path given.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// The file defines nothing (it is empty or holds only comments).
    #[error("the problem file is empty: it needs at least `name`, `start`, a goal and `[bounds]`")]
    Empty,
    /// The file is not valid TOML.
    #[error("TOML syntax error: {}{message}", at(location))]
    Syntax {
        /// Where the parser stopped.
        location: Option<Location>,
        /// The parser's message.
        message: String,
    },
    /// The file is valid TOML but does not have the problem schema: a missing field, an
    /// unknown field, or a value of the wrong type. The message names the field.
    #[error("{}{message}", at(location))]
    Schema {
        /// The table or value the problem was found in.
        location: Option<Location>,
        /// What is wrong, naming the field.
        message: String,
    },
    /// A number is not acceptable for its field (not finite, a negative width, a non-positive
    /// resolution, …).
    #[error("`{field}` is {}; {requirement}", short(*.value))]
    BadValue {
        /// The field, with indices.
        field: String,
        /// The value found.
        value: f64,
        /// What the value must satisfy.
        requirement: &'static str,
    },
    /// A lattice has zero cubes per dimension.
    #[error("`{field}` is 0; a lattice needs at least one cube per dimension")]
    EmptyLattice {
        /// The field, with index.
        field: String,
    },
    /// A vector has a different number of values than the bounds have dimensions.
    #[error("`{field}` has {}, but the bounds have {expected}", count(*.got, "value"))]
    Dimension {
        /// The field, with index.
        field: String,
        /// Number of values found.
        got: usize,
        /// The dimension given by the bounds.
        expected: usize,
    },
    /// `bounds.lower` and `bounds.upper` differ in length.
    #[error(
        "`bounds.lower` has {} but `bounds.upper` has {}",
        count(*.lower, "value"),
        count(*.upper, "value")
    )]
    BoundsLength {
        /// Length of `bounds.lower`.
        lower: usize,
        /// Length of `bounds.upper`.
        upper: usize,
    },
    /// The bounds have no dimensions.
    #[error("`bounds.lower` and `bounds.upper` are empty; a problem needs at least one dimension")]
    NoDimensions,
    /// A lower bound is not strictly below its upper bound.
    #[error(
        "`bounds.lower[{index}]` = {} is not below `bounds.upper[{index}]` = {}",
        short(*.lower),
        short(*.upper)
    )]
    EmptyInterval {
        /// Coordinate index.
        index: usize,
        /// The lower bound.
        lower: f64,
        /// The upper bound.
        upper: f64,
    },
    /// Both `goal` and `goals` are given.
    #[error("give either `goal` or `goals`, not both")]
    GoalAndGoals,
    /// Neither `goal` nor `goals` is given, or `goals` is empty.
    #[error("no goal: give `goal = [...]` or a non-empty `goals = [[...], ...]`")]
    NoGoal,
    /// The start or a goal lies outside the bounds.
    #[error(
        "`{field}` is outside the bounds: coordinate {index} is {}, not in [{}, {}]",
        short(*.value),
        short(*.lower),
        short(*.upper)
    )]
    OutOfBounds {
        /// `start`, `goal` or `goals[i]`.
        field: String,
        /// Coordinate index.
        index: usize,
        /// The coordinate's value.
        value: f64,
        /// Lower bound of that coordinate.
        lower: f64,
        /// Upper bound of that coordinate.
        upper: f64,
    },
    /// The start or a goal lies inside an obstacle.
    #[error("`{field}` = {state:?} is in collision with an obstacle")]
    InCollision {
        /// `start`, `goal` or `goals[i]`.
        field: String,
        /// The state.
        state: Vec<f64>,
    },
    /// The problem the file describes is rejected for another reason (for example an `optimum`
    /// below the straight-line distance).
    #[error(transparent)]
    Problem(#[from] ProblemError),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locations_count_lines_and_characters() {
        let text = "a = 1\nbé = 2\n";
        assert_eq!(
            Location::of_offset(text, 0),
            Location { line: 1, column: 1 }
        );
        let offset = text.find('=').unwrap();
        assert_eq!(Location::of_offset(text, offset).line, 1);
        let offset = text.rfind('=').unwrap();
        assert_eq!(
            Location::of_offset(text, offset),
            Location { line: 2, column: 4 }
        );
        // Past the end: clamped, never a panic.
        assert_eq!(Location::of_offset(text, 999).line, 3);
    }

    #[test]
    fn endpoints_read_naturally() {
        assert_eq!(Endpoint::Start.to_string(), "start");
        assert_eq!(Endpoint::Goal(2).to_string(), "goal 2");
    }
}
