//! The built-in problem families of the Planner Developer Tools (PDT) benchmarks: one parameter
//! struct per family, with PDT's defaults for any dimension `n ≥ 2`, that builds a [`Problem`].
//!
//! - Walls and slots: [`NarrowPassage`] (`narrow_passage.rs`), [`WallGap`] (`wall_gap.rs`),
//!   [`FlankingGap`] (`flanking_gap.rs`), [`DividingWalls`] (`dividing_walls.rs`).
//! - Single boxes and scatters: [`ObstacleFree`] (`obstacle_free.rs`), [`CenterSquare`]
//!   (`center_square.rs`), [`RandomRectangles`] (`random_rectangles.rs`, also
//!   `cluttered-rectangles`), [`RepeatingRectangles`] (`repeating_rectangles.rs`).
//! - [`enclosures`]: the goal, start and double enclosures and their shared builder
//!   [`Enclosure`].
//! - `shared.rs`: the plumbing every family uses (the unit-cube world, walls and slots across
//!   it, parameter checks, points on the x-axis); `optimum.rs`: the closed-form optimal costs
//!   (slab crossing, enclosure escape).
//!
//! May use: the `validity` crate (boxes, lattices, worlds), `spaces` and `rand` (the seeded
//! scatter), and from this crate [`Problem`], [`ProblemError`] and [`Parameter`] (a family's
//! parameters as the catalogue lists them); unit tests also use `test_support`. Nothing here
//! reads or writes problem files. Used by the [catalogue](fn@crate::catalogue), which names every
//! family.
//!
//! [`Problem`]: crate::Problem
//! [`ProblemError`]: crate::ProblemError
//! [`Parameter`]: crate::Parameter

mod center_square;
mod dividing_walls;
mod enclosures;
mod flanking_gap;
mod narrow_passage;
mod obstacle_free;
mod optimum;
mod random_rectangles;
mod repeating_rectangles;
mod shared;
mod wall_gap;

pub use center_square::CenterSquare;
pub use dividing_walls::DividingWalls;
pub use enclosures::{
    BothEnclosed, DoubleEnclosure, EnclosedEnds, Enclosure, GoalEnclosed, GoalEnclosure,
    StartEnclosed, StartEnclosure,
};
pub use flanking_gap::FlankingGap;
pub use narrow_passage::NarrowPassage;
pub use obstacle_free::ObstacleFree;
pub use random_rectangles::RandomRectangles;
pub use repeating_rectangles::RepeatingRectangles;
pub use wall_gap::WallGap;
