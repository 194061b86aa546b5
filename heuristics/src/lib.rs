//! Heuristics for path-length objectives.
//!
//! Admissible lower bounds on edge cost, cost-to-come and cost-to-go, plus effort estimates
//! (state checks left to validate an edge), behind one [`Heuristic`] trait.
//!
//! ```
//! use mit_star_heuristics::{Euclidean, Heuristic, Zero};
//! use mit_star_spaces::RealVectorSpace;
//!
//! let space = RealVectorSpace::cube(2, -0.5, 0.5)?;
//! let goals = vec![vec![0.45, 0.0]];
//! let h = Euclidean;
//! assert!((h.cost_to_go(&space, &[-0.45, 0.0], &goals) - 0.9).abs() < 1e-12);
//! // 0.9 long at step 0.01 → 90 intervals → 89 interior grid points to check.
//! assert_eq!(h.effort(&space, &[-0.45, 0.0], &[0.45, 0.0], 0.01), 89);
//! assert_eq!(Zero.cost_to_go(&space, &[-0.45, 0.0], &goals), 0.0);
//! # Ok::<(), mit_star_spaces::SpaceError>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`Heuristic`] | the trait: `ĉ(a,b)`, cost-to-come, cost-to-go, effort |
//! | [`Euclidean`] | coordinate Euclidean norm (the `R^n` path-length bound) |
//! | [`SpaceMetric`] | the space's own metric (the joint-space bound: weights, wrapping joints) |
//! | [`Zero`] | zero everywhere (Dijkstra-like search) |
//! | [`Weighted`] | wrapper inflating cost-to-go (weighted A*) |
//! | [`grid_points`] | interior points of an edge's canonical grid: the effort of checking it |

#![forbid(unsafe_code)]

mod heuristic;
mod metric;
mod weighted;
mod zero;

pub use heuristic::{Heuristic, grid_points};
pub use metric::{Euclidean, SpaceMetric};
pub use weighted::Weighted;
pub use zero::Zero;
