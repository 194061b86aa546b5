//! State validity and edge checking.
//!
//! Two separate questions, two traits (OMPL's `StateValidityChecker` and `MotionValidator`):
//! is a state valid ([`StateValidity`]), and is the straight edge between two valid states valid
//! ([`EdgeChecker`]). Edge checkers test the points of one canonical grid per edge, in bisection
//! order ([`EdgeGrid`]), and keep per-edge memory in a caller-owned [`EdgeProgress`], so a sparse
//! check's work is never repeated by a later, finer check.
//!
//! ```
//! use mit_star_spaces::{Never, RealVectorSpace, StateSpace};
//! use mit_star_validity::{Counted, EdgeChecker, EdgeProgress, EdgeStatus, LengthAdaptiveChecker, StateValidity};
//!
//! // A disc of radius 0.1 at the centre of the unit square is an obstacle.
//! struct Disc;
//! impl StateValidity for Disc {
//!     fn is_valid(&self, s: &[f64]) -> bool {
//!         (s[0] - 0.5).powi(2) + (s[1] - 0.5).powi(2) > 0.01
//!     }
//! }
//! let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
//! let world = Counted::new(Disc);
//! let mut checker = LengthAdaptiveChecker::from_resolution(&space, 1e-3).unwrap();
//! let (a, b) = ([0.1, 0.5], [0.9, 0.5]);
//! let mut progress = EdgeProgress::default();
//! // The sparse check's first point is the midpoint, inside the disc.
//! assert_eq!(checker.check_sparse(&space, &world, &a, &b, &mut progress, &Never), EdgeStatus::Invalid);
//! assert_eq!(world.count(), 1);
//! # Ok::<(), mit_star_spaces::SpaceError>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`StateValidity`] | the trait: is one state valid |
//! | [`World`], [`AxisBox`], [`Lattice`] | axis-aligned box obstacles and anti-obstacles in any dimension (PDT semantics) |
//! | [`World::segment_verdict`], [`SegmentVerdict`], [`SegmentCause`] | exact validation of a straight segment against a world (slab tests, no grid) |
//! | [`Segment`], [`Preparation`] | a straight edge prepared for batched point checks (per-edge broad phase, SIMD lanes) |
//! | [`AllValid`] | the empty world |
//! | [`Counted`] | wrapper counting validity calls |
//! | [`EdgeChecker`] | the trait: sparse and full edge checks with per-edge memory |
//! | [`DenseChecker`] | fixed resolution, no sparse phase (OMPL's discrete motion validator) |
//! | [`FixedSparseChecker`] | EIT*'s sparse levels: 1, 3, 7, 15, … checks per edge |
//! | [`LengthAdaptiveChecker`] | MIT*'s length-related adaptive sparse checks |
//! | [`EdgeGrid`], [`BisectionOrder`] | the canonical grid of an edge and its bisection order |
//! | [`MotionProgress`] | how far the certification of a motion came (a stopped one resumes) |
//! | [`EdgeProgress`], [`EdgeStatus`], [`EdgeCounters`], [`GridWalker`], [`canonical_ends`] | per-edge memory, outcomes, counters, the shared walker, the end every walk starts from |
//! | [`LengthBuckets`], [`LENGTH_BUCKET_BOUNDS`], [`LENGTH_BUCKET_LABELS`] | checks and points by edge length |
//! | [`ValidityError`] | malformed parameters or worlds |

#![forbid(unsafe_code)]

mod box_world;
mod edge_checking;
mod error;
mod state_validity;

pub use box_world::{
    AxisBox, Lattice, Preparation, Segment, SegmentCause, SegmentVerdict, TREE_THRESHOLD, World,
};
pub use edge_checking::{
    BisectionOrder, DenseChecker, EdgeChecker, EdgeCounters, EdgeGrid, EdgeProgress, EdgeStatus,
    FixedSparseChecker, GridWalker, LENGTH_BUCKET_BOUNDS, LENGTH_BUCKET_LABELS,
    LengthAdaptiveChecker, LengthBuckets, MAX_BATCH, MotionProgress, STOP_POLL, canonical_ends,
};
pub use error::ValidityError;
pub use state_validity::{AllValid, Counted, StateValidity};

/// The full-resolution step `L = resolution × maximum extent` (OMPL's convention, spec §2).
///
/// # Errors
/// If `resolution` is not finite and positive.
pub fn step_from_resolution<S: mit_star_spaces::StateSpace + ?Sized>(
    space: &S,
    resolution: f64,
) -> Result<f64, ValidityError> {
    if !(resolution.is_finite() && resolution > 0.0) {
        return Err(ValidityError::NotPositive {
            name: "collision-check resolution",
            value: resolution,
        });
    }
    Ok(resolution * space.maximum_extent())
}
