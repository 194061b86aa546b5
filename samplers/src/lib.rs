//! Valid-state samplers for informed, sampling-based planners.
//!
//! A planner asks a [`Sampler`] for valid states under a [`CostBound`]: the whole space before
//! anything is known, MIT*'s estimated informed set once a lazy solution failed, the informed set
//! of `c_best` once a valid solution exists. Every sampler here is seeded, allocation-free per
//! sample, polls a stop condition in every loop, and reports an empty informed set instead of
//! looping on it. The geometry — prolate hyperspheroids, their rotation, measure and direct
//! sampling — lives in one place, [`InformedSet`], which all informed samplers compose.
//!
//! ```
//! use mit_star_samplers::{CostBound, InformedSampler, Sampler};
//! use mit_star_spaces::{Never, RealVectorSpace, StateSpace, euclidean_distance};
//! use mit_star_validity::{AxisBox, StateValidity, World};
//!
//! // R^4, a box obstacle in the middle, start and goal on either side of it.
//! let space = RealVectorSpace::cube(4, -1.0, 1.0)?;
//! let world = World::in_space(&space).with_obstacle(AxisBox::cube(vec![0.0; 4], 0.4))?;
//! let (start, goal) = ([-0.6, 0.0, 0.0, 0.0], [0.6, 0.0, 0.0, 0.0]);
//! let mut sampler = InformedSampler::new(&space, &start, &[goal], 7)?;
//!
//! let c_best = 1.5; // a solution of this cost exists: only cheaper paths are of interest
//! let mut x = [0.0; 4];
//! for _ in 0..200 {
//!     sampler.sample(&space, &world, CostBound::Solution(c_best), &Never, &mut x)?;
//!     // Inside the prolate hyperspheroid with foci start and goal, inside the bounds, valid.
//!     assert!(euclidean_distance(&start, &x) + euclidean_distance(&x, &goal) < c_best);
//!     assert!(space.contains(&x) && world.is_valid(&x));
//! }
//! // The r-disc radius uses the measure of the set sampled: here the hyperspheroid's,
//! // ζ_4 · (c/2) · (√(c² − 1.2²)/2)³ ≈ 0.337, a small part of the 16 of the cube.
//! let measure = Sampler::<RealVectorSpace, World>::sampled_measure(
//!     &sampler, &space, CostBound::Solution(c_best));
//! assert!((measure - 0.3373).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`Sampler`], [`CostBound`], [`SampleError`], [`SamplerCounters`], [`SampleOrigin`] | the trait, the bound a planner passes, why no state came back, work counters, which step made a state |
//! | [`UniformSampler`] | uniform over the whole space, bound ignored (the uninformed baseline); random or a shifted Halton sequence |
//! | [`HaltonSequence`] | low-discrepancy points of the unit cube, shifted per seed |
//! | [`InformedSampler`] | uniform over the informed set of the bound: direct informed sampling, and MIT*'s estimated-informed-set sampler under [`CostBound::Estimated`] |
//! | [`GaussianSampler`] | Boor et al.'s Gaussian sampling near obstacle boundaries, within the informed set |
//! | [`BridgeSampler`] | Hsu et al.'s bridge test for narrow passages, within the informed set |
//! | [`AdaptiveSampler`] | MIT*'s adaptive sampler: informed draw, Gaussian repair, bisection along the bridge |
//! | [`InformedSet`], [`prolate_hyperspheroid_measure`] | hyperspheroid geometry for one or several goals: membership, measure, uniform draws with rejection fallback |
//! | [`Estimated`] | wrapper giving any sampler MIT*'s estimated informed set, driven by the planner's feedback hooks ([`LazyPathFailure`]) |
//! | [`NearTerminals`] | wrapper drawing a fraction of the states near the start and the goals at every scale (goals deep in pockets, such as grasps in shelf slots) |
//! | [`EstimatedInformedSet`], [`ExpansionForm`], [`ExpansionRule`] | MIT*'s estimate `s̃_est`, its reliability and expansion |
//! | [`GaussianStep`], [`SegmentSearch`] | shared pieces: the Gaussian perturbation and the bisection-order segment search |
//! | [`SamplerError`] | malformed problems or parameters |

#![forbid(unsafe_code)]

mod adaptive_sampler;
mod bridge_sampler;
mod error;
mod gaussian_sampler;
mod halton_sequence;
mod informed_sampler;
mod informed_sets;
mod sampler;
mod sampling_steps;
mod uniform_sampler;
mod wrappers;

pub use adaptive_sampler::AdaptiveSampler;
pub use bridge_sampler::BridgeSampler;
pub use error::SamplerError;
pub use gaussian_sampler::GaussianSampler;
pub use halton_sequence::HaltonSequence;
pub use informed_sampler::InformedSampler;
pub use informed_sets::{
    EstimatedInformedSet, ExpansionForm, ExpansionRule, InformedSet, prolate_hyperspheroid_measure,
};
pub use sampler::{
    CostBound, LazyPathFailure, SampleError, SampleOrigin, Sampler, SamplerCounters,
};
pub use sampling_steps::{GaussianStep, SegmentSearch};
pub use uniform_sampler::UniformSampler;
pub use wrappers::{Estimated, NearTerminals};
