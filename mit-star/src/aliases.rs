//! The paper's configurations (spec §8) as type aliases of [`Eit`]: each is nothing but a
//! choice of parts.

use samplers::{AdaptiveSampler, Estimated, InformedSampler};
use spaces::RealVectorSpace;
use validity::{FixedSparseChecker, LengthAdaptiveChecker, World};

use crate::Eit;

/// **MIT*** (Zhang et al. 2025): adaptive sampler inside the estimated informed set
/// ([`Estimated`] wrapper), length-related sparse collision checks.
pub type MitStar<S = RealVectorSpace, V = World> =
    Eit<S, V, Estimated<AdaptiveSampler>, LengthAdaptiveChecker>;

/// **EIT*** (Strub and Gammell 2022): direct informed sampling (uniform until a solution
/// exists), fixed sparse levels of 1, 3, 7, 15, … checks per edge.
pub type EitStar<S = RealVectorSpace, V = World> = Eit<S, V, InformedSampler, FixedSparseChecker>;

/// **MIT*-AS**: EIT* with MIT*'s adaptive sampler only.
pub type MitStarAs<S = RealVectorSpace, V = World> = Eit<S, V, AdaptiveSampler, FixedSparseChecker>;

/// **MIT*-EIS**: EIT* with MIT*'s estimated informed set only (the informed sampler inside
/// the [`Estimated`] wrapper).
pub type MitStarEis<S = RealVectorSpace, V = World> =
    Eit<S, V, Estimated<InformedSampler>, FixedSparseChecker>;

/// **MIT*-SC**: EIT* with MIT*'s length-related sparse collision checks only.
pub type MitStarSc<S = RealVectorSpace, V = World> =
    Eit<S, V, InformedSampler, LengthAdaptiveChecker>;
