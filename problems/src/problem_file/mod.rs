//! The TOML problem file format: [`Problem::from_toml_str`], [`Problem::from_file`] and
//! [`Problem::to_toml_string`].
//!
//! A problem file defines a [`Problem`] without Rust. Its fields:
//!
//! | field | required | meaning |
//! |---|---|---|
//! | `name` | yes | the problem's name |
//! | `resolution` | no (5e-6) | collision-check resolution, a fraction of the maximum extent |
//! | `allow_coarse_step` | no (false) | allow a collision-check step larger than the thinnest obstacle or anti-obstacle ([`Problem::check_step`]) |
//! | `optimum` | no | the optimal cost, only if known exactly |
//! | `start` | yes | the start state |
//! | `goal` / `goals` | exactly one | one goal state, or a non-empty list of them |
//! | `[bounds]` `lower`, `upper` | yes | the corners of the space; their length is the dimension |
//! | `[[obstacles]]` `center`, `widths` | no, repeated | axis-aligned boxes: centre and **full** side lengths |
//! | `[[anti_obstacles]]` `center`, `widths` | no, repeated | boxes of free space carved out of obstacles |
//! | `[[lattices]]` `count`, `spacing`, `side` | no, repeated | `count^n` cubes of side `side`, centred at `lower_d + (j + 1)·spacing` |
//!
//! A state is valid iff it lies in the bounds and inside some anti-obstacle or inside no
//! obstacle (PDT's semantics, [`mit_star_validity::World`]); membership is closed. Integers are accepted
//! wherever numbers are. A full example (also in `problems/examples/`):
//!
//! ```toml
//! name = "wall-with-slot"
//! resolution = 5e-6
//! start = [-0.3, 0.0]
//! goal = [0.3, 0.0]
//!
//! [bounds]
//! lower = [-0.5, -0.5]
//! upper = [0.5, 0.5]
//!
//! [[obstacles]]          # a wall from y = -0.5 to y = 0.3
//! center = [0.0, -0.1]
//! widths = [0.2, 0.8]
//!
//! [[anti_obstacles]]     # a slot through it
//! center = [0.0, 0.1]
//! widths = [0.2, 0.04]
//! ```
//!
//! Reading checks everything and reports the first problem as a [`ProblemFileError`] that
//! names the field (`obstacles[2].widths has 3 values, but the bounds have 2`): TOML syntax
//! (with line and column), missing and unknown fields, wrong types, wrong lengths, values that
//! are not finite (TOML allows `nan` and `inf`), negative widths, empty bound intervals,
//! `goal` and `goals` together or neither, a resolution outside `(0, 1)`, start or goals out of
//! bounds or in collision.

use std::path::Path;

use mit_star_spaces::StateSpace;
use mit_star_validity::{AxisBox, Lattice, World};
use serde::Deserialize;

use crate::{Endpoint, Location, Problem, ProblemError, ProblemFileError};

/// The file's top level.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileSpec {
    name: String,
    resolution: Option<f64>,
    #[serde(default)]
    allow_coarse_step: bool,
    optimum: Option<f64>,
    start: Vec<f64>,
    goal: Option<Vec<f64>>,
    goals: Option<Vec<Vec<f64>>>,
    bounds: BoundsSpec,
    #[serde(default)]
    obstacles: Vec<BoxSpec>,
    #[serde(default)]
    anti_obstacles: Vec<BoxSpec>,
    #[serde(default)]
    lattices: Vec<LatticeSpec>,
}

/// `[bounds]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct BoundsSpec {
    lower: Vec<f64>,
    upper: Vec<f64>,
}

/// `[[obstacles]]` and `[[anti_obstacles]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct BoxSpec {
    center: Vec<f64>,
    widths: Vec<f64>,
}

/// `[[lattices]]`.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct LatticeSpec {
    count: usize,
    spacing: f64,
    side: f64,
}

impl Problem {
    /// Reads a problem from the text of a problem file (schema in the
    /// [module docs](crate::problem_file); examples in `problems/examples/`).
    ///
    /// ```
    /// use mit_star_problems::Problem;
    /// use mit_star_validity::StateValidity;
    ///
    /// let text = r#"
    ///     name = "wall-with-slot"
    ///     start = [-0.3, 0.0]
    ///     goal = [0.3, 0.0]
    ///     [bounds]
    ///     lower = [-0.5, -0.5]
    ///     upper = [0.5, 0.5]
    ///     [[obstacles]]
    ///     center = [0.0, -0.1]
    ///     widths = [0.2, 0.8]
    ///     [[anti_obstacles]]
    ///     center = [0.0, 0.1]
    ///     widths = [0.2, 0.04]
    /// "#;
    /// let problem = Problem::from_toml_str(text)?;
    /// assert!(problem.world().is_valid(&[0.0, 0.1]));
    /// assert_eq!(Problem::from_toml_str(&problem.to_toml_string())?, problem);
    ///
    /// let err = Problem::from_toml_str(&text.replace("[0.2, 0.04]", "[0.2, 0.04, 1]"))
    ///     .unwrap_err();
    /// assert_eq!(err.to_string(), "`anti_obstacles[0].widths` has 3 values, but the bounds have 2");
    /// # Ok::<(), mit_star_problems::ProblemFileError>(())
    /// ```
    ///
    /// # Errors
    /// A [`ProblemFileError`] naming the first problem found (module docs).
    pub fn from_toml_str(text: &str) -> Result<Self, ProblemFileError> {
        // Large worlds: plain box blocks are read line by line, the rest by the TOML parser.
        if let Some((rest, obstacles, antis)) = box_blocks::split_box_blocks(text)
            && !(obstacles.is_empty() && antis.is_empty())
            && let Ok(mut spec) = toml::from_str::<FileSpec>(&rest)
            && spec.obstacles.is_empty()
            && spec.anti_obstacles.is_empty()
        {
            spec.obstacles = obstacles;
            spec.anti_obstacles = antis;
            return spec.into_problem();
        }
        // One parse on the happy path; the error path parses again as a plain table to tell
        // a syntax error and an empty file from a schema error.
        let spec: FileSpec = match toml::from_str(text) {
            Ok(spec) => spec,
            Err(schema) => {
                let table: toml::Table = text.parse().map_err(|e| syntax_error(text, &e))?;
                if table.is_empty() {
                    return Err(ProblemFileError::Empty);
                }
                return Err(schema_error(text, &schema));
            }
        };
        spec.into_problem()
    }

    /// Reads a problem file.
    ///
    /// # Errors
    /// [`ProblemFileError::Io`] if the file cannot be read, otherwise as
    /// [`from_toml_str`](Self::from_toml_str).
    pub fn from_file(path: impl AsRef<Path>) -> Result<Self, ProblemFileError> {
        let path = path.as_ref();
        let text =
            crate::read_bounded(path, crate::TEXT_INPUT_LIMIT, "problem file").map_err(|e| {
                ProblemFileError::Io {
                    path: path.to_path_buf(),
                    source: e.into(),
                }
            })?;
        Self::from_toml_str(&text)
    }
}

/// Turns a parse error into [`ProblemFileError::Syntax`] with its location.
fn syntax_error(text: &str, error: &toml::de::Error) -> ProblemFileError {
    ProblemFileError::Syntax {
        location: error
            .span()
            .map(|span| Location::of_offset(text, span.start)),
        message: crate::excerpt(error.message(), 200),
    }
}

/// Turns a deserialisation error into [`ProblemFileError::Schema`], quoting the offending line
/// when the error points at something.
fn schema_error(text: &str, error: &toml::de::Error) -> ProblemFileError {
    let span = error.span().filter(|span| span.start < span.end);
    let location = span
        .as_ref()
        .map(|span| Location::of_offset(text, span.start));
    // The message may quote the input (a 200 KB string): a short excerpt of it.
    let mut message = crate::excerpt(&humanise(error.message()), 200);
    if let Some(location) = location
        && let Some(line) = text.lines().nth(location.line - 1)
    {
        message.push_str(&format!(", in `{}`", crate::excerpt(line.trim(), 120)));
    }
    ProblemFileError::Schema { location, message }
}

/// A TOML deserialiser's message in the file's words: no Rust type names (`usize`, `f64`), no
/// 300-digit numbers. Shared by every TOML file format of the project.
///
/// ```
/// let m = mit_star_problems::humanise("invalid type: floating point `100000000000000000000.0`, expected usize");
/// assert_eq!(m, "invalid type: number `1e20`, expected a whole number, 0 or more");
/// ```
pub fn humanise(message: &str) -> String {
    let mut text = message.to_owned();
    for (rust, words) in [
        ("expected usize", "expected a whole number, 0 or more"),
        ("expected u64", "expected a whole number, 0 or more"),
        ("expected u32", "expected a whole number, 0 or more"),
        ("expected i64", "expected a whole number"),
        ("expected f64", "expected a number"),
        ("floating point", "number"),
    ] {
        text = text.replace(rust, words);
    }
    // Shorten long numbers quoted in backticks.
    let mut out = String::with_capacity(text.len());
    let mut rest = text.as_str();
    while let Some(open) = rest.find('`') {
        let Some(close) = rest[open + 1..].find('`') else {
            break;
        };
        let quoted = &rest[open + 1..open + 1 + close];
        out.push_str(&rest[..=open]);
        match quoted.parse::<f64>() {
            Ok(value) if quoted.len() > 12 => out.push_str(&mit_star_spaces::short_number(value)),
            _ => out.push_str(quoted),
        }
        out.push('`');
        rest = &rest[open + close + 2..];
    }
    out.push_str(rest);
    out
}

impl FileSpec {
    /// Checks every value, naming the field, and builds the problem.
    fn into_problem(self) -> Result<Problem, ProblemFileError> {
        let n = check_bounds(&self.bounds)?;
        if let Some(resolution) = self.resolution
            && !(resolution > 0.0 && resolution < 1.0)
        {
            return Err(bad_value(
                "resolution",
                resolution,
                "it must lie strictly between 0 and 1 (a fraction of the maximum extent)",
            ));
        }
        if let Some(optimum) = self.optimum
            && !(optimum.is_finite() && optimum >= 0.0)
        {
            return Err(bad_value(
                "optimum",
                optimum,
                "it must be finite and not negative",
            ));
        }

        let single_goal = self.goal.is_some();
        let goals = match (self.goal, self.goals) {
            (Some(_), Some(_)) => return Err(ProblemFileError::GoalAndGoals),
            (Some(goal), None) => vec![goal],
            (None, Some(goals)) if !goals.is_empty() => goals,
            (None, _) => return Err(ProblemFileError::NoGoal),
        };
        let field = |endpoint: Endpoint| match endpoint {
            Endpoint::Start => "start".to_owned(),
            Endpoint::Goal(_) if single_goal => "goal".to_owned(),
            Endpoint::Goal(i) => format!("goals[{i}]"),
        };
        check_state(&field(Endpoint::Start), &self.start, &self.bounds)?;
        for (i, goal) in goals.iter().enumerate() {
            check_state(&field(Endpoint::Goal(i)), goal, &self.bounds)?;
        }

        let mut world = World::new(self.bounds.lower, self.bounds.upper);
        for (i, b) in self.obstacles.into_iter().enumerate() {
            let b = check_box(("obstacles", i), b, n)?;
            world.add_obstacle(b).map_err(ProblemError::from)?;
        }
        for (i, b) in self.anti_obstacles.into_iter().enumerate() {
            let b = check_box(("anti_obstacles", i), b, n)?;
            world.add_anti_obstacle(b).map_err(ProblemError::from)?;
        }
        for (i, l) in self.lattices.into_iter().enumerate() {
            let lattice = check_lattice(&format!("lattices[{i}]"), l)?;
            world = world.with_lattice(lattice).map_err(ProblemError::from)?;
        }

        let problem = Problem::new(self.name, world, self.start, goals).map_err(|e| match e {
            ProblemError::InCollision { endpoint, state } => ProblemFileError::InCollision {
                field: field(endpoint),
                state,
            },
            other => ProblemFileError::Problem(other),
        })?;
        let problem = match self.resolution {
            Some(resolution) => problem.with_resolution(resolution)?,
            None => problem,
        };
        Ok(problem
            .allowing_coarse_step(self.allow_coarse_step)
            .with_optimum(self.optimum)?)
    }
}

/// Checks the bounds and returns the dimension.
fn check_bounds(bounds: &BoundsSpec) -> Result<usize, ProblemFileError> {
    let (lower, upper) = (&bounds.lower, &bounds.upper);
    if lower.len() != upper.len() {
        return Err(ProblemFileError::BoundsLength {
            lower: lower.len(),
            upper: upper.len(),
        });
    }
    if lower.is_empty() {
        return Err(ProblemFileError::NoDimensions);
    }
    check_finite("bounds.lower", lower)?;
    check_finite("bounds.upper", upper)?;
    for (index, (&lower, &upper)) in lower.iter().zip(upper).enumerate() {
        if lower >= upper {
            return Err(ProblemFileError::EmptyInterval {
                index,
                lower,
                upper,
            });
        }
    }
    Ok(lower.len())
}

/// Checks a start or goal: length, finite, inside the bounds.
fn check_state(field: &str, state: &[f64], bounds: &BoundsSpec) -> Result<(), ProblemFileError> {
    check_length(field, state, bounds.lower.len())?;
    check_finite(field, state)?;
    let space = mit_star_spaces::RealVectorSpace::new(bounds.lower.clone(), bounds.upper.clone())
        .map_err(ProblemError::Bounds)?;
    if let Err(mit_star_spaces::SpaceError::OutOfBounds {
        index,
        value,
        lower,
        upper,
    }) = space.check_state(state)
    {
        return Err(ProblemFileError::OutOfBounds {
            field: field.to_owned(),
            index,
            value,
            lower,
            upper,
        });
    }
    Ok(())
}

/// Checks an obstacle or anti-obstacle: lengths, finite, widths not negative.
fn check_box(
    (table, index): (&str, usize),
    b: BoxSpec,
    n: usize,
) -> Result<AxisBox, ProblemFileError> {
    let plain = b.center.len() == n
        && b.widths.len() == n
        && b.center.iter().all(|x| x.is_finite())
        && b.widths.iter().all(|w| w.is_finite() && *w >= 0.0);
    if plain {
        return Ok(AxisBox::new(b.center, b.widths));
    }
    // Only a box with a problem pays for its field names.
    let field = format!("{table}[{index}]");
    let (center, widths) = (format!("{field}.center"), format!("{field}.widths"));
    check_length(&center, &b.center, n)?;
    check_length(&widths, &b.widths, n)?;
    check_finite(&center, &b.center)?;
    check_finite(&widths, &b.widths)?;
    if let Some((i, &w)) = b.widths.iter().enumerate().find(|(_, w)| **w < 0.0) {
        return Err(bad_value(
            &format!("{widths}[{i}]"),
            w,
            "widths are full side lengths and must not be negative",
        ));
    }
    Ok(AxisBox::new(b.center, b.widths))
}

/// Checks a lattice: at least one cube, spacing and side finite and positive.
fn check_lattice(field: &str, l: LatticeSpec) -> Result<Lattice, ProblemFileError> {
    if l.count == 0 {
        return Err(ProblemFileError::EmptyLattice {
            field: format!("{field}.count"),
        });
    }
    for (name, value) in [("spacing", l.spacing), ("side", l.side)] {
        if !(value.is_finite() && value > 0.0) {
            return Err(bad_value(
                &format!("{field}.{name}"),
                value,
                "it must be finite and positive",
            ));
        }
    }
    Ok(Lattice {
        count: l.count,
        spacing: l.spacing,
        side: l.side,
    })
}

/// Checks that a vector has `n` values.
fn check_length(field: &str, values: &[f64], n: usize) -> Result<(), ProblemFileError> {
    if values.len() != n {
        return Err(ProblemFileError::Dimension {
            field: field.to_owned(),
            got: values.len(),
            expected: n,
        });
    }
    Ok(())
}

/// Checks that every value is finite.
fn check_finite(field: &str, values: &[f64]) -> Result<(), ProblemFileError> {
    match values.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        Some((i, &value)) => Err(bad_value(
            &format!("{field}[{i}]"),
            value,
            "values must be finite",
        )),
        None => Ok(()),
    }
}

/// A [`ProblemFileError::BadValue`].
fn bad_value(field: &str, value: f64, requirement: &'static str) -> ProblemFileError {
    ProblemFileError::BadValue {
        field: field.to_owned(),
        value,
        requirement,
    }
}

mod box_blocks;
mod writer;

#[cfg(test)]
mod tests;
