//! Edge checking: the checkers, the canonical grid of an edge and its bisection order, the walk
//! that tests it, and the per-edge memory and counters of that work.
//!
//! - [`EdgeChecker`] (`edge_checker.rs`): the trait, sparse and full checks with per-edge
//!   memory; its implementations [`DenseChecker`] (`dense_checker.rs`, OMPL's fixed
//!   resolution), [`FixedSparseChecker`] (`fixed_sparse_checker.rs`, EIT*'s levels) and
//!   [`LengthAdaptiveChecker`] (`length_adaptive_checker.rs`, MIT*'s length-related levels).
//! - [`EdgeGrid`], [`BisectionOrder`] (`bisection_order.rs`): the canonical grid of an edge and
//!   the one order every check tests its points in.
//! - [`GridWalker`], [`EdgeCounters`], [`canonical_ends`], [`STOP_POLL`], [`MAX_BATCH`] (`grid_walker.rs`): the
//!   walk shared by every checker, with certification on a finer grid or by the validity
//!   checker's own motion test.
//! - [`EdgeProgress`], [`EdgeStatus`] (`edge_progress.rs`): per-edge memory and outcomes;
//!   [`MotionProgress`] (`motion_progress.rs`): where a stopped certification resumes;
//!   [`LengthBuckets`] (`length_buckets.rs`): checks and points by edge length.
//!
//! May use: the `spaces` crate, [`crate::state_validity`] (the checkers test states through
//! [`StateValidity`](crate::StateValidity)), [`crate::error`], [`crate::step_from_resolution`],
//! and from [`crate::box_world`] only the prepared edge ([`Segment`](crate::Segment),
//! [`Preparation`](crate::Preparation)); nothing here knows boxes. Used by `box_world` and the
//! traits only for [`EdgeStatus`] and [`MotionProgress`].

mod bisection_order;
mod dense_checker;
mod edge_checker;
mod edge_progress;
mod fixed_sparse_checker;
mod grid_walker;
mod length_adaptive_checker;
mod length_buckets;
mod motion_progress;

pub use bisection_order::{BisectionOrder, EdgeGrid};
pub use dense_checker::DenseChecker;
pub use edge_checker::EdgeChecker;
pub use edge_progress::{EdgeProgress, EdgeStatus};
pub use fixed_sparse_checker::FixedSparseChecker;
pub use grid_walker::{EdgeCounters, GridWalker, MAX_BATCH, STOP_POLL, canonical_ends};
pub use length_adaptive_checker::LengthAdaptiveChecker;
pub use length_buckets::{LENGTH_BUCKET_BOUNDS, LENGTH_BUCKET_LABELS, LengthBuckets};
pub use motion_progress::MotionProgress;
