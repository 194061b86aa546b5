//! Exact nearest-neighbour search: static kd-trees kept in a logarithmic forest.
//!
//! - [`NearestNeighbors`] (`forest.rs`): points that arrive in batches and leave by pruning,
//!   held as a few static kd-trees of doubling sizes plus a linear buffer of pending points
//!   (Bentley and Saxe's logarithmic method); exact k-nearest and radius queries.
//! - [`KdTree`] (`kd_tree.rs`): one static, bucketed kd-tree and its queries;
//!   `kd_tree_build.rs` builds one (median splits, stop condition polled);
//!   `kd_tree_build_tests.rs`, its tests.
//! - [`Neighbours`] (`neighbours.rs`): the reusable result buffer of a query.
//! - `pending_points.rs`: the forest's buffer of points not yet in a tree.
//! - `lanes.rs`: coordinates by groups of four points and the kernels that compute four
//!   distances at once, for the trees' leaves and the pending points.
//! - `chunked.rs`: [`Chunked`], a growable array in fixed-size chunks (never moves what it
//!   holds), used for the birth stamps here and for the graph's per-vertex data.
//!
//! May use: the `spaces` crate (the stop condition) and nothing else of this crate — it is the
//! bottom layer. Used by `graph` (the RGG's neighbourhoods) and `rrt` (each tree's index).

mod chunked;
mod forest;
mod kd_tree;
mod kd_tree_build;
#[cfg(test)]
mod kd_tree_build_tests;
mod lanes;
mod neighbours;
mod pending_points;

pub(crate) use chunked::Chunked;
pub use forest::NearestNeighbors;
pub use kd_tree::KdTree;
pub(crate) use kd_tree::{Alive, Poll};
pub use neighbours::Neighbours;
