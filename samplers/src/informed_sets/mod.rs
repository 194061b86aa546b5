//! Informed sets: where a sampler may draw under a cost bound — the prolate hyperspheroids of a
//! path-length objective, and MIT*'s estimate of the informed set before a solution exists.
//!
//! - [`InformedSet`] (`informed_set.rs`): the informed set for one or several goals —
//!   membership, measure, uniform draws with a rejection fallback.
//! - `hyperspheroid.rs`: the geometry of one prolate hyperspheroid — its rotation, its measure
//!   ([`prolate_hyperspheroid_measure`]) and uniform draws of the unit ball it is mapped from.
//! - [`EstimatedInformedSet`], [`ExpansionForm`], [`ExpansionRule`]
//!   (`estimated_informed_set.rs`): MIT*'s estimate `s̃_est`, its reliability and expansion.
//!
//! May use: the [`Sampler`](crate::Sampler) trait's types ([`CostBound`](crate::CostBound),
//! [`SampleError`](crate::SampleError), [`SamplerCounters`](crate::SamplerCounters)),
//! [`SamplerError`](crate::SamplerError), and the `spaces`, `rand` and `rand_distr` crates.
//! Knows nothing of the samplers: the bottom layer, used by `sampling_steps`, the samplers and
//! `wrappers`.

mod estimated_informed_set;
mod hyperspheroid;
mod informed_set;

pub use estimated_informed_set::{EstimatedInformedSet, ExpansionForm, ExpansionRule};
pub use hyperspheroid::prolate_hyperspheroid_measure;
pub use informed_set::InformedSet;
