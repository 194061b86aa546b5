//! The steps the samplers share: drawing from the informed set, the Gaussian perturbation, and
//! the search along a segment.
//!
//! - `informed_draws.rs`: `InformedDraws`, what every informed sampler owns — the informed set,
//!   the seeded generator and the work counters — and the steps built from them (draw, perturb,
//!   check, search a segment, count).
//! - `lookahead.rs`: `Lookahead`, candidates drawn ahead and decided a checker's batch at a
//!   time (the informed draws' and the uniform sampler's draw-and-check).
//! - `gaussian_partners.rs`: `GaussianPartners`, the Gaussian neighbours of a lookahead batch's
//!   invalid candidates, drawn and checked together (the adaptive sampler's repair).
//! - [`GaussianStep`] (`gaussian_step.rs`): the Gaussian perturbation of the Gaussian,
//!   bridge-test and adaptive samplers and of [`NearTerminals`](crate::NearTerminals).
//! - [`SegmentSearch`] (`segment_search.rs`): a valid state on a segment, in bisection order —
//!   the bridge test's midpoint and the adaptive sampler's repair.
//! - `segments_ahead.rs`: `SegmentsAhead`, the segment searches of a lookahead batch's failed
//!   repairs, decided together where a checker's batch holds several searches' points.
//!
//! May use: `informed_sets`, the [`Sampler`](crate::Sampler) trait's types,
//! [`SamplerError`](crate::SamplerError), and the `spaces`, `validity`, `rand` and `rand_distr`
//! crates. Knows no sampler: used by the informed, Gaussian, bridge-test and adaptive samplers
//! and by `wrappers`.

mod gaussian_partners;
mod gaussian_step;
mod informed_draws;
mod lookahead;
mod segment_search;
mod segments_ahead;
#[cfg(test)]
mod test_checkers;

pub(crate) use gaussian_partners::{GaussianPartners, Partner, PartnerDraw};
pub use gaussian_step::GaussianStep;
pub(crate) use informed_draws::InformedDraws;
pub(crate) use lookahead::{Lookahead, MOST_BATCHED};
pub use segment_search::SegmentSearch;
pub(crate) use segments_ahead::SegmentsAhead;
