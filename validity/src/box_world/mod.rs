//! The box world: axis-aligned obstacles and anti-obstacles, the indices that make large worlds
//! fast, and the exact tests of straight segments against them.
//!
//! - [`World`], [`AxisBox`], [`Lattice`] (`world.rs`): the world and its point test (PDT
//!   semantics); `box_set.rs`: one kind of box (obstacles or anti-obstacles) with its rows and
//!   indices, shared between clones; `box_tree.rs` (a bounding-volume hierarchy) and
//!   `slab_index.rs` (per-coordinate bitsets, for large boxes in many dimensions): which boxes
//!   can hold a point.
//! - [`Segment`], [`Preparation`] (`segment.rs`): a straight edge prepared for batched point
//!   checks; `world_segment.rs`: the world's per-edge broad phase and SIMD point checks along
//!   it; `crossing.rs`: the exact fractions at which a segment's computed points lie in a box.
//! - [`SegmentVerdict`], [`SegmentCause`] (`segment_validation.rs`): exact validation of a
//!   segment by slab tests, no grid; `segment_certification.rs`: the same work in steps that
//!   poll the stop condition and resume ([`World::certify_exact`]).
//!
//! May use: the `spaces` crate, [`crate::state_validity`] (the world implements
//! [`StateValidity`](crate::StateValidity)), [`crate::error`], and from
//! [`crate::edge_checking`] only the outcome and resume types of a certification
//! ([`EdgeStatus`](crate::EdgeStatus), [`MotionProgress`](crate::MotionProgress)); tests also
//! drive a [`GridWalker`](crate::GridWalker). Used by `edge_checking` (the walker owns a
//! [`Segment`]) and by the traits (their prepared-segment vocabulary).

mod box_set;
mod box_tree;
mod crossing;
mod segment;
mod segment_certification;
mod segment_validation;
mod slab_index;
mod world;
mod world_segment;

pub use segment::{Preparation, Segment};
pub use segment_validation::{SegmentCause, SegmentVerdict};
pub use world::{AxisBox, Lattice, TREE_THRESHOLD, World};
