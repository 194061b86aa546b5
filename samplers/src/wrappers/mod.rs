//! Sampler wrappers: a sampler around another sampler, changing where its states come from.
//!
//! - [`Estimated`] (`estimated.rs`): gives any sampler MIT*'s estimated informed set under
//!   [`CostBound::Estimated`](crate::CostBound::Estimated), driven by the planner's feedback
//!   hooks ([`LazyPathFailure`](crate::LazyPathFailure)).
//! - [`NearTerminals`] (`near_terminals.rs`): draws a fraction of the states near the start and
//!   the goals at every scale (goals deep in pockets, such as grasps in shelf slots).
//!
//! May use: the [`Sampler`](crate::Sampler) trait and its types, `informed_sets` (the
//! estimated set), `sampling_steps` (informed draws and the Gaussian step),
//! [`SamplerError`](crate::SamplerError), and the `spaces`, `validity` and `rand` crates. Wraps
//! any sampler; no sampler uses them.

mod estimated;
mod near_terminals;

pub use estimated::Estimated;
pub use near_terminals::NearTerminals;
