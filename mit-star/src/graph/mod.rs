//! The random geometric graph (RGG) the informed trees search, and the structures that keep
//! its neighbourhoods and trees.
//!
//! - [`RandomGeometricGraph`] (`random_geometric_graph.rs`): the samples, start and goals as
//!   nodes of a petgraph `StableGraph`, per-vertex data beside it, and the edges the planner
//!   has checked with their progress and white/black status.
//! - `vertex.rs`: [`VertexId`], [`VertexKind`] and [`Vertex`], the per-vertex search data
//!   (forward-tree links, reverse-search values, keys) the planner keeps in the graph.
//! - `neighbour_cache.rs`: each vertex's neighbour list, computed on first expansion, cached,
//!   and brought up to date incrementally in later batches.
//! - `recent_states.rs` (the last committed samples in columns, for the vectorised update of
//!   those lists) and `state_chunks.rs` (the states in fixed-size chunks that never move).
//! - `outside_tree.rs`: for FCIT*, the vertices that may be outside the forward tree, so that
//!   an expansion that may no longer rewire reads those instead of its whole list.
//! - `forward_tree.rs`: the forward tree's links inside the graph, and pruning ([`Pruning`]).
//! - `edge_hasher.rs`: the packed `(source, target)` edge key and its fast hasher, shared with
//!   the forward queue.
//!
//! May use: `nearest` (the neighbour queries and its chunked storage) and the `spaces`,
//! `heuristics`, `validity` and `petgraph` crates. Knows nothing of the searches: used by
//! `informed_trees` (and by the public [`Snapshot`](crate::Snapshot)), not by `rrt`.

mod edge_hasher;
mod forward_tree;
mod neighbour_cache;
mod outside_tree;
mod random_geometric_graph;
mod recent_states;
mod state_chunks;
mod vertex;

pub(crate) use edge_hasher::{BuildEdgeHasher, edge_key};
pub(crate) use forward_tree::Pruning;
pub use random_geometric_graph::RandomGeometricGraph;
pub(crate) use random_geometric_graph::{EdgeRecord, Neighbourhood};
pub(crate) use vertex::{NO_EFFORT, NONE, Vertex};
pub use vertex::{VertexId, VertexKind};
