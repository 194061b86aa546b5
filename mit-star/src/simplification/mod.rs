//! Path simplification: shorter paths from a planner's path — vertex reduction, shortcuts
//! (`simplification_run.rs`) and smoothing (`path_smoothing.rs`), every new edge checked and
//! certified as the planners check theirs ([`PathSimplifier`]) — after planning or at every
//! solution of a planner ([`Simplifying`]), and again while a planner finds nothing cheaper
//! (`idle_polish.rs`).
//!
//! May use: the problem's space, validity checker, check step and certification (`problems`,
//! `validity`, `spaces`); of the planners only the [`Planner`](crate::Planner) trait.

mod idle_polish;
mod path_simplifier;
mod path_smoothing;
mod simplification_run;
mod simplifying;

pub(crate) use idle_polish::IdlePolish;
pub use path_simplifier::{PathSimplifier, Simplified};
pub use path_smoothing::SmoothingMoves;
pub use simplifying::Simplifying;
