//! State spaces for sampling-based motion planning.
//!
//! The geometry every other crate of the framework is written against: a [`StateSpace`] trait
//! (OMPL's vocabulary: dimension, distance, interpolation, bounds, measure, maximum extent,
//! uniform sampling), two implementations, contiguous state storage, and the [`Stop`] condition
//! every long-running loop polls.
//!
//! ```
//! use mit_star_spaces::{RealVectorSpace, SeededRng, StateSpace, States};
//! use rand::SeedableRng;
//!
//! let space = RealVectorSpace::cube(8, -0.5, 0.5)?;
//! let mut rng = SeededRng::seed_from_u64(7);
//! let mut states = States::new(space.dimension());
//! for _ in 0..100 {
//!     space.sample_uniform(&mut rng, states.push_zeroed());
//! }
//! assert!(states.iter().all(|s| space.contains(s)));
//! let mut mid = vec![0.0; 8];
//! space.interpolate(&states[0], &states[1], 0.5, &mut mid);
//! let half = space.distance(&states[0], &states[1]) / 2.0;
//! assert!((space.distance(&states[0], &mid) - half).abs() < 1e-12);
//! # Ok::<(), mit_star_spaces::SpaceError>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`StateSpace`] | the trait: metric, interpolation, bounds, measure, extent, uniform sampling |
//! | [`RealVectorSpace`] | `R^n` with box bounds, dimension chosen at run time |
//! | [`JointSpace`], [`Joint`], [`JointKind`] | robot joint spaces: limited revolute/prismatic joints and wrapping continuous joints |
//! | [`States`] | contiguous storage for many states |
//! | [`Stop`], [`Deadline`], [`Never`] | stop conditions polled by every loop |
//! | [`SeededRng`] | the project's portable, seedable random generator |
//! | [`unit_ball_measure`], [`euclidean_distance`], [`wrap_angle`], [`reflect_into_interval`] | geometric helpers |
//! | [`short_number`] | numbers for messages (`1e308`, not 309 digits) |
//! | [`MemoryBudget`] | memory a request may claim, checked before allocating |
//! | [`SpaceError`] | what is wrong with a space or a state |

#![forbid(unsafe_code)]

mod error;
mod joint_space;
mod memory_budget;
mod real_vector_space;
mod short_number;
mod state_space;
mod states;
mod stop;

pub use error::SpaceError;
pub use joint_space::{Joint, JointKind, JointSpace, wrap_angle};
pub use memory_budget::MemoryBudget;
pub use real_vector_space::{RealVectorSpace, euclidean_distance};
pub use short_number::short_number;
pub use state_space::{StateSpace, reflect_into_interval, unit_ball_measure};
pub use states::States;
pub use stop::{Deadline, Never, Stop};

/// The project's random generator: PCG-64 (MCG variant) — fast, small, and with an output
/// sequence that is fixed by its algorithm, so a seed means the same run on every platform and
/// every release. Every seeded component of the framework owns one.
pub type SeededRng = rand_pcg::Pcg64Mcg;

pub use rand;
