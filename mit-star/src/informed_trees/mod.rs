//! The informed-trees skeleton: [`Eit`], the asymmetric bidirectional lazy search of EIT*
//! over a batched random geometric graph, and the guidances and type aliases that make MIT*,
//! EIT*, AIT*, BIT* and ABIT* of it.
//!
//! - `eit.rs`: [`Eit`], the planner — its parts, state, setup, solution and the
//!   [`Planner`](crate::Planner) implementation.
//! - `guidance.rs`: [`Guidance`] and its four parts ([`EffortInformed`], [`Suspending`],
//!   [`CostInformed`], [`APriori`]): how the forward search is led to the goals, the part that
//!   tells EIT*, MIT*, AIT* and BIT* apart.
//! - `neighbour_rule.rs`: [`NeighbourRule`] and its two parts, [`RandomGeometric`] (the
//!   k-nearest or r-disc graph of EIT*, MIT*, AIT*, BIT*) and [`FullyConnected`] (FCIT*'s
//!   complete graph): which vertices are neighbours in a batch.
//! - `aliases.rs`: the paper's configurations ([`MitStar`], [`EitStar`], the MIT* ablations)
//!   and comparison planners ([`AitStar`], [`BitStar`]) as type aliases of [`Eit`].
//! - `forward_search.rs` and `forward_queue.rs`: the forward search from the start (full edge
//!   checks, effort-greedy then A*) and its edge queue.
//! - `reverse_search.rs` and `reverse_queue.rs`: the lazy reverse search from the goals
//!   (sparse checks) and its edge queue; `reverse_repair/`: AIT*'s in-place repair of the
//!   reverse tree, with its tests.
//! - `lazy_successors.rs`: FCIT*'s forward expansion on a complete graph — each vertex's
//!   edges ranked once, from the graph's log or the vertices outside the tree rather than
//!   neighbour lists, and queued one at a time; `lazy_successors_tests.rs`, its tests.
//! - `offered_path.rs`: a path offered from outside (a warm start's, a simplified solution)
//!   grafted into the forward tree as the best solution.
//! - `frontier.rs`: the states the reverse search reached farthest from the goals, handed to
//!   the sampler at the end of a batch without a solution.
//! - `start_reach.rs`: the start's side of that frontier, for a start in a pocket (outside a
//!   reverse tree that holds most of the graph); `start_reach_tests.rs`, its tests.
//! - `solution_samples.rs`: states placed along the best path, part of each batch once a
//!   solution exists; `solution_samples_tests.rs`, its tests.
//! - `batch.rs`: adding a batch of samples — prune, sample, reconnect, restart the searches;
//!   `batch_tests.rs`: the sample count of its connection rules, and where ABIT*'s search of a
//!   batch ends.
//!
//! May use: `graph` (the RGG, its vertices, neighbour lists, forward tree and pruning),
//! `nearest` only through `graph`, the public API at the top of the crate (termination,
//! [`Parameters`](crate::Parameters), errors, observer, trace, counters) and the `spaces`,
//! `samplers`, `validity` and `heuristics` crates. Nothing of `rrt`.

mod aliases;
pub(crate) mod batch;
#[cfg(test)]
mod batch_tests;
mod eit;
mod forward_queue;
mod forward_search;
mod frontier;
#[cfg(test)]
mod frontier_tests;
mod guidance;
#[cfg(test)]
mod lazy_edge_tests;
mod lazy_successors;
#[cfg(test)]
mod lazy_successors_tests;
mod neighbour_rule;
mod offered_path;
mod reverse_queue;
mod reverse_repair;
mod reverse_search;
#[cfg(test)]
mod setup_tests;
mod solution_certification;
mod solution_samples;
#[cfg(test)]
mod solution_samples_tests;
mod start_reach;
#[cfg(test)]
mod start_reach_tests;

pub use aliases::{
    AitStar, AitStarEis, BitStar, EitStar, FcitStar, MitStar, MitStarAs, MitStarEis, MitStarSc,
    MitStarSr,
};
pub use eit::Eit;
pub use guidance::{APriori, CostInformed, EffortInformed, Guidance, ReverseSearch, Suspending};
pub use neighbour_rule::{
    BatchDensity, Connectivity, FullyConnected, NeighbourRule, RandomGeometric,
};
