//! The paper's configurations (spec §8) and its comparison planners AIT*, BIT* and ABIT* as
//! type aliases of [`Eit`]: each is nothing but a choice of parts.

use mit_star_heuristics::Euclidean;
use mit_star_samplers::{AdaptiveSampler, Estimated, InformedSampler};
use mit_star_spaces::RealVectorSpace;
use mit_star_validity::{DenseChecker, FixedSparseChecker, LengthAdaptiveChecker, World};

use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::{APriori, CostInformed, Suspending};
use crate::informed_trees::neighbour_rule::FullyConnected;

/// **MIT*** (Zhang et al. 2025): adaptive sampler inside the estimated informed set
/// ([`Estimated`] wrapper), length-related sparse collision checks, and the MIT* authors'
/// rule that the reverse search yields while the forward queue is empty ([`Suspending`]).
pub type MitStar<S = RealVectorSpace, V = World> =
    Eit<S, V, Estimated<AdaptiveSampler>, LengthAdaptiveChecker, Euclidean, Suspending>;

/// **EIT*** (Strub and Gammell 2022) as upstream builds it: direct informed sampling (uniform
/// until a solution exists), fixed sparse levels of 1, 3, 7, 15, … checks per edge, and a
/// reverse search that keeps going while the forward queue is empty.
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

/// **MIT*-SR** — an ablation the paper does not run: EIT* with only the MIT* authors'
/// suspension rule ([`Suspending`]), the fourth way MIT*'s code differs from EIT*'s.
pub type MitStarSr<S = RealVectorSpace, V = World> =
    Eit<S, V, InformedSampler, FixedSparseChecker, Euclidean, Suspending>;

/// **AIT*** (Strub and Gammell, ICRA 2020 / IJRR 2022): direct informed sampling, an unchecked
/// lazy reverse search ([`CostInformed`]) supplying the forward search's heuristic, full
/// checks in the forward search only.
pub type AitStar<S = RealVectorSpace, V = World> =
    Eit<S, V, InformedSampler, DenseChecker, Euclidean, CostInformed>;

/// **BIT*** (Gammell, Barfoot and Srinivasa, IJRR 2020): direct informed sampling, no reverse
/// search ([`APriori`]), full checks of the edges the forward search processes in order of
/// `g + ĉ + ĥ`.
///
/// **ABIT*** (Strub and Gammell, ICRA 2020) is this same type with ABIT*'s inflation and
/// truncation factors ([`Builder::abit_star`](crate::Builder::abit_star),
/// [`Parameters::abit_star`](crate::Parameters::abit_star)):
///
/// ```
/// use mit_star::{BitStar, FirstSolution, Planner};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut abit = BitStar::for_problem(&problem)
///     .abit_star()
///     .name("ABIT*")
///     .build()?;
/// assert!(abit.solve(&FirstSolution)?.is_solved());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type BitStar<S = RealVectorSpace, V = World> =
    Eit<S, V, InformedSampler, DenseChecker, Euclidean, APriori>;

/// **AIT*-EIS** — *not in the paper*: AIT* sampling inside MIT*'s estimated informed set
/// before its first solution (the [`Estimated`] wrapper reacts to AIT*'s invalid lazy-path
/// edges as it does to EIT*'s). Remove the wrapper and it is [`AitStar`].
///
/// ```
/// use mit_star::{AitStarEis, FirstSolution, Planner};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = AitStarEis::for_problem(&problem).seed(3).build()?;
/// assert_eq!(planner.name(), "AIT*[estimated(informed) sampler, dense checks]");
/// let outcome = planner.solve(&FirstSolution)?;
/// assert!(outcome.cost() >= problem.optimum().unwrap());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type AitStarEis<S = RealVectorSpace, V = World> =
    Eit<S, V, Estimated<InformedSampler>, DenseChecker, Euclidean, CostInformed>;

/// **FCIT*** (Wilson, Thomason, Kingston, Kavraki and Gammell, ICRA 2025) as VAMP's code has
/// it: BIT*'s parts — direct informed sampling, no reverse search ([`APriori`]: edges in order
/// of `g + ĉ + ĥ` with the straight-line `ĥ`), full checks of the edges the forward search
/// takes — on a fully connected graph ([`FullyConnected`]): every sample is a neighbour of
/// every other, with no radius, no `k` and no neighbour queries beyond a scan, and each
/// expanded vertex's edges are queued one at a time, best first. How faithful this is to the
/// paper: the guide's *Faithfulness* chapter.
///
/// ```
/// use mit_star::{FcitStar, FirstSolution, Planner};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = FcitStar::for_problem(&problem).seed(3).build()?;
/// assert_eq!(planner.name(), "FCIT*");
/// let outcome = planner.solve(&FirstSolution)?;
/// assert!(outcome.cost() >= problem.optimum().unwrap());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type FcitStar<S = RealVectorSpace, V = World> =
    Eit<S, V, InformedSampler, DenseChecker, Euclidean, APriori, FullyConnected>;
