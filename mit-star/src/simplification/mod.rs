//! Path simplification: shorter paths from a planner's path, every new edge checked and
//! certified as the planners check theirs ([`PathSimplifier`]).
//!
//! May use: the problem's space, validity checker, check step and certification (`problems`,
//! `validity`, `spaces`); nothing of the planners.

mod path_simplifier;

pub use path_simplifier::{PathSimplifier, Simplified};
