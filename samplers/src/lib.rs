//! Valid-state samplers for informed, sampling-based planners.

#![forbid(unsafe_code)]

mod sampler;

pub use sampler::{CostBound, SampleError, Sampler, SamplerCounters};
