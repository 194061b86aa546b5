//! Benchmark planning problems.
//!
//! A [`Problem`] is a named, fully specified planning problem in `R^n`: a box world
//! ([`mit_star_validity::World`]), a start, one or more goals, the collision-check resolution, and the
//! optimal cost when it is known exactly. Problems come from the built-in families of the
//! Planner Developer Tools (PDT) benchmarks — each a parameter struct with PDT's defaults for
//! any dimension `n ≥ 2` — or from a TOML [problem file](problem_file).
//!
//! ```
//! use mit_star_problems::{DividingWalls, Problem};
//! use mit_star_spaces::StateSpace;
//! use mit_star_validity::StateValidity;
//!
//! // PDT's dividing walls in R^4: the straight line is blocked.
//! let problem = DividingWalls::new(4).build()?;
//! assert!(problem.validate().is_ok());
//! assert!(!problem.world().is_valid(&[0.0; 4]));
//! assert!(problem.optimum().unwrap() > problem.straight_line_cost());
//! // Collision checks every 5e-6 of the diagonal (2 in R^4).
//! assert!((problem.step() - 1e-5).abs() < 1e-18);
//!
//! // The same family by name, and the same problem through a problem file.
//! assert_eq!(mit_star_problems::builtin("dividing-walls", 4, 0)?, problem);
//! let text = problem.to_toml_string();
//! assert_eq!(Problem::from_toml_str(&text)?, problem);
//! assert_eq!(problem.space().dimension(), 4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`PlanningProblem`] | the trait every planner accepts: space, validity checker, start, goals, resolution (box worlds here, arms in the `robot` crate) |
//! | [`Problem`] | a named box-world problem: space, world, start, goals, resolution, known optimum |
//! | [`FlankingGap`] | `flanking-gap`: a wall short of the bounds with a small square hole |
//! | [`DividingWalls`] | `dividing-walls`: three full walls crossed through six slots |
//! | [`GoalEnclosure`] | `goal-enclosure`: the goal in a hollow cube opening away from the start |
//! | [`RandomRectangles`] | `random-rectangles`: 35 seeded random boxes; `cluttered-rectangles`: the variant calibrated to block the straight line |
//! | [`ObstacleFree`] | `obstacle-free`: the empty cube |
//! | [`CenterSquare`] | `center-square`: one cube between start and goal |
//! | [`WallGap`] | `wall-gap`: a wall with a slot and a corridor past its end |
//! | [`NarrowPassage`] | `narrow-passage`: a full wall with one slot |
//! | [`StartEnclosure`] | `start-enclosure`: the start in a hollow cube opening away from the goal |
//! | [`DoubleEnclosure`] | `double-enclosure`: both ends enclosed |
//! | [`Enclosure`], [`EnclosedEnds`] | the three enclosure families' shared builder, and which ends it encloses ([`GoalEnclosed`], [`StartEnclosed`], [`BothEnclosed`]) |
//! | [`RepeatingRectangles`] | `repeating-rectangles`: a lattice of `49^n` small cubes |
//! | [`catalogue`], [`builtin`], [`Family`], [`Parameter`] | the families by name, with descriptions and default parameters |
//! | [`problem_file`] | the TOML problem file format ([`Problem::from_toml_str`], [`Problem::from_file`], [`Problem::to_toml_string`]); [`humanise`] for TOML messages |
//! | [`ProblemError`], [`ProblemFileError`], [`Endpoint`], [`Location`] | what is wrong, and where |
//! | [`read_bounded`], [`read_bounded_bytes`], [`BoundedReadError`], [`TEXT_INPUT_LIMIT`], [`excerpt`] | reading a user's file with a size limit, refusing devices and binary files; quoting input in errors briefly |
//!
//! Every family lives in `[-0.5, 0.5]^n` (add 0.5 for the paper's unit-cube coordinates), gives
//! obstacles by centre and full side lengths, and uses PDT's validity rule: a state is valid iff
//! it is in the bounds and inside some anti-obstacle or inside no obstacle. Known optima are
//! exact closed forms (each family's docs say when one applies); they are infima, approached
//! from above, since the closed obstacles touch the optimal paths.

#![forbid(unsafe_code)]

mod bounded_read;
mod catalogue;
mod error;
mod families;
mod planning_problem;
mod problem;
pub mod problem_file;
#[cfg(test)]
mod test_support;

pub use bounded_read::{
    BoundedReadError, TEXT_INPUT_LIMIT, excerpt, read_bounded, read_bounded_bytes,
};
pub use catalogue::{Family, Parameter, builtin, catalogue};
pub use error::{Endpoint, Location, ProblemError, ProblemFileError};
pub use families::{
    BothEnclosed, CenterSquare, DividingWalls, DoubleEnclosure, EnclosedEnds, Enclosure,
    FlankingGap, GoalEnclosed, GoalEnclosure, NarrowPassage, ObstacleFree, RandomRectangles,
    RepeatingRectangles, StartEnclosed, StartEnclosure, WallGap,
};
pub use planning_problem::{
    DEFAULT_BRIDGE_CHECKS, PAPER_BATCH_SIZE, PAPER_SPARSE_SPACING, PlanningProblem,
};
pub use problem::Problem;
pub use problem_file::humanise;
