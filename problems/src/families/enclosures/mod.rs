//! The enclosure families: an end of the problem sits in a hollow cube whose one opening faces
//! away from the other end.
//!
//! - [`Enclosure`], [`EnclosedEnds`] (`enclosure.rs`): the builder the three share, generic over
//!   which ends it encloses (the sealed `Ends` trait), with the sizes, checks and optimum.
//! - [`GoalEnclosure`], [`GoalEnclosed`] (`goal_enclosure.rs`), [`StartEnclosure`],
//!   [`StartEnclosed`] (`start_enclosure.rs`), [`DoubleEnclosure`], [`BothEnclosed`]
//!   (`double_enclosure.rs`): the three families, each a name for one choice of ends.
//!
//! May use: what the other families may (the `validity` crate, the crate's [`Problem`],
//! [`ProblemError`] and [`Parameter`]), and from the parent folder `shared.rs` and
//! `optimum.rs` (the enclosure escape).
//!
//! [`Problem`]: crate::Problem
//! [`ProblemError`]: crate::ProblemError
//! [`Parameter`]: crate::Parameter

mod double_enclosure;
mod enclosure;
mod goal_enclosure;
mod start_enclosure;

pub use double_enclosure::{BothEnclosed, DoubleEnclosure};
pub use enclosure::{EnclosedEnds, Enclosure};
pub use goal_enclosure::{GoalEnclosed, GoalEnclosure};
pub use start_enclosure::{StartEnclosed, StartEnclosure};
