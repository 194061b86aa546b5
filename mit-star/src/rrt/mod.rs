//! The RRT family: RRT-Connect and Informed RRT*, built from the same parts (space, validity,
//! sampler, edge checker) as the informed trees but on trees of their own instead of the
//! random geometric graph.
//!
//! - [`RrtConnect`] (`rrt_connect.rs`): Kuffner and LaValle's bidirectional RRT, and
//!   [`default_range`], its extension range.
//! - [`Aorrtc`] (`aorrtc/`): Wilson et al.'s AORRTC — RRT-Connect's first solution, then
//!   repeated cost-bounded searches (`search.rs`) under the best cost, each path simplified.
//! - [`InformedRrtStar`] (`informed_rrt_star/`): Gammell, Srinivasa and Barfoot's Informed
//!   RRT* — the planner (`mod.rs`), its resumable iteration (`iteration.rs`) and its tests.
//! - `rrt_core.rs`: [`RrtCore`](rrt_core::RrtCore), what both planners hold besides their
//!   trees (query, parts, parameters, best solution, trace and counters) and how it is built.
//! - `tree.rs`: the tree of states with its nearest-neighbour index, and steering by at most a
//!   range; `cost_tree.rs`: Informed RRT*'s tree on top of it, with costs-to-come, children for
//!   rewiring, cost propagation and pruning.
//!
//! May use: `nearest` (each tree's index) and the public API at the top of the crate
//! ([`Planner`](crate::Planner), termination, [`Parameters`](crate::Parameters), errors,
//! trace, counters, [`Snapshot`](crate::Snapshot) and its [`VertexKind`](crate::VertexKind)).
//! Nothing of `informed_trees` or `graph`'s search structures.

mod aorrtc;
mod cost_tree;
mod informed_rrt_star;
mod rrt_connect;
mod rrt_core;
mod tree;

pub use aorrtc::Aorrtc;
pub use informed_rrt_star::InformedRrtStar;
pub use rrt_connect::{RrtConnect, default_range};
