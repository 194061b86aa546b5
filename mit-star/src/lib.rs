//! MIT* and EIT*: asymptotically optimal, almost-surely anytime motion planners assembled from
//! swappable parts.
//!
//! [`Eit`] is the search skeleton of EIT* (Strub and Gammell, IJRR 2022): a lazy reverse search
//! from the goals guides an effort-greedy forward search over a batched random geometric graph.
//! MIT* (Zhang et al., IEEE T-ASE 2025) adds three parts — an adaptive sampler, an estimated
//! informed set before the first solution, and length-related sparse collision checks — and the
//! paper's ablations are the other compositions. Each configuration is only a type alias.
//!
//! ```
//! use std::time::Duration;
//! use mit_star::{CostThreshold, MitStar, Planner, TerminationExt, TimeLimit};
//!
//! // PDT's dividing walls in R^4 (coarser resolution to keep the example quick).
//! let problem = mit_star_problems::DividingWalls::new(4).build()?.with_resolution(1e-4)?;
//! let mut planner = MitStar::for_problem(&problem).seed(42).build()?;
//! let stop = TimeLimit::new(Duration::from_millis(200)).or(CostThreshold::new(1.0));
//! let outcome = planner.solve(&stop)?;
//! if let Some(solution) = outcome.solution() {
//!     assert!(solution.cost >= problem.optimum().unwrap() - 1e-9);
//!     assert_eq!(solution.path[0], *problem.start());
//! }
//! // Anytime: the trace records every improvement, costs decreasing.
//! let costs: Vec<f64> = planner.trace().points().iter().map(|p| p.cost).collect();
//! assert!(costs.windows(2).all(|w| w[1] < w[0]));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`Eit`] | the planner, generic over space, validity, sampler, edge checker and heuristic |
//! | [`MitStar`], [`EitStar`], [`MitStarAs`], [`MitStarEis`], [`MitStarSc`], [`MitStarSr`] | the paper's configurations (spec §8) as type aliases, and EIT* with only MIT*'s suspension rule |
//! | [`AitStar`], [`BitStar`] (and ABIT* as `BitStar` with [`Builder::abit_star`]), [`AitStarEis`] | the paper's comparison planners of the same skeleton, and a composition not in the paper |
//! | [`Guidance`]: [`EffortInformed`], [`Suspending`], [`CostInformed`], [`APriori`]; [`ReverseSearch`] | how the skeleton's forward search is guided (EIT*, MIT*, AIT*, BIT*) |
//! | [`Builder`], [`Parameters`], [`Connection`], [`EisExpansionForm`], [`EisExpansionRule`] | validated construction and every parameter with its default |
//! | [`SamplerPart`], [`CheckerPart`] | how the builder makes parts from parameters |
//! | [`Configuration`], [`build_planner`], [`build_planner_with`] | choose a configuration at run time (`Box<dyn Planner + Send>`), optionally with your own validity checker |
//! | [`Planner`], [`Outcome`], [`Solution`] | the trait every planner implements and what `solve` returns |
//! | [`RrtConnect`], [`Aorrtc`], [`InformedRrtStar`] | comparison planners from the same parts: RRT-Connect; AORRTC (RRT-Connect, then repeated cost-bounded searches with informed sampling and simplification); Informed RRT* (k-nearest RRT* with direct informed sampling and pruning) |
//! | [`PathSimplifier`], [`Simplified`], [`Simplifying`] | shorter paths: vertex reduction, random and per-joint shortcuts, every new edge checked and certified; after planning, or at every solution of a wrapped planner |
//! | [`WarmStarted`] | an anytime planner started from a feasibility planner's first solution (RRT-Connect's, with `warm_start`) |
//! | [`LazyGoals`], [`GoalSource`] | plan towards a goal region whose states are drawn while planning (a hand pose through inverse kinematics) |
//! | [`check_path`], [`PathVerdict`], [`snap_ends`] | judge a path from anywhere (another planner's) by the rules our solutions pass |
//! | [`Termination`], [`TimeLimit`], [`IterationLimit`], [`CostThreshold`], [`FirstSolution`], [`TerminationExt`] | termination conditions and their `or` / `and` combinators |
//! | [`Trace`], [`Counters`] | the anytime `(time, cost)` record and work counters |
//! | [`Snapshot`] | a read-only copy of samples, trees and cost bounds, for pictures of runs |
//! | [`Observer`], [`SolutionEvent`], [`BatchEvent`], [`RestartEvent`] | callbacks on solutions, batches and restarts |
//! | [`RandomGeometricGraph`], [`VertexId`], [`VertexKind`] | the RGG on a petgraph `StableGraph`, read-only |
//! | [`KdTree`], [`NearestNeighbors`], [`Neighbours`] | exact nearest neighbours: static kd-trees in a logarithmic forest |
//! | [`k_nearest`], [`r_disc`] | the connection formulas |
//! | [`PlannerError`], [`BuildError`], [`Endpoint`] | what is wrong with a query or parameters |
//!
//! The mapping of every equation and algorithm line of the paper to this code is in
//! `docs/guide/src/reference/faithfulness-map.md`.

#![forbid(unsafe_code)]

// Source layout. The public API sits at the top of `src/`: the `Planner` trait and query
// validation (planner.rs), termination conditions, parameters, errors, the builder and the parts
// it makes (components.rs), configurations chosen at run time (configuration.rs), and what a run
// reports (trace, counters, observer, snapshot). These files may use the four modules below;
// the modules use them only for the API's own types. The machinery, lowest layer first (each
// module's doc says what it holds and what it may use):
// - `nearest`: exact nearest-neighbour search, kd-trees in a logarithmic forest. Uses nothing
//   else of the crate.
// - `graph`: the random geometric graph, its vertices, neighbour caches, forward tree and
//   pruning. Uses `nearest`.
// - `informed_trees`: the EIT* skeleton `Eit` (forward and reverse searches, queues, batches),
//   its guidances, and the MIT*, EIT*, AIT*, BIT* type aliases. Uses `graph`.
// - `rrt`: RRT-Connect and Informed RRT*. Uses `nearest`.
mod builder;
mod components;
mod configuration;
mod configuration_settings;
mod counters;
mod effective_parameters;
mod error;
mod goal_source;
mod graph;
mod informed_trees;
mod lazy_goals;
mod nearest;
mod observer;
mod parameters;
mod path_check;
mod planner;
mod rrt;
mod simplification;
mod snapshot;
mod termination;
mod trace;
mod warm_started;

pub use builder::Builder;
pub use components::{CheckerPart, SamplerPart};
pub use configuration::{Configuration, build_planner, build_planner_with};
pub use counters::{COUNT_NAMES, COUNT_NAMES_LEN, Counters, REAL_NAMES};
pub use error::{BuildError, Endpoint, PlannerError};
pub use goal_source::GoalSource;
pub use graph::{RandomGeometricGraph, VertexId, VertexKind};
pub use informed_trees::{
    APriori, AitStar, AitStarEis, BatchDensity, BitStar, Connectivity, CostInformed,
    EffortInformed, Eit, EitStar, FcitStar, FullyConnected, Guidance, MitStar, MitStarAs,
    MitStarEis, MitStarSc, MitStarSr, NeighbourRule, RandomGeometric, ReverseSearch, Suspending,
};
pub use lazy_goals::LazyGoals;
pub use nearest::{KdTree, NearestNeighbors, Neighbours};
pub use observer::{BatchEvent, Observer, RestartEvent, SolutionEvent};
pub use parameters::{
    Connection, EisExpansionForm, EisExpansionRule, MAX_GAUSSIAN_STD_FRACTION, MAX_RANGE,
    MAX_REWIRE_FACTOR, MAX_SPARSE_STEPS, Parameters, k_nearest, r_disc,
};
pub use path_check::{PathVerdict, check_path, snap_ends};
pub use planner::{Outcome, Planner, Solution};
pub use rrt::{Aorrtc, InformedRrtStar, RrtConnect, default_range};
pub use simplification::{PathSimplifier, Simplified, Simplifying, SmoothingMoves};
pub use snapshot::Snapshot;
pub use termination::{
    And, CostThreshold, FirstSolution, IterationLimit, Or, Progress, Termination, TerminationExt,
    TimeLimit,
};
pub use trace::{Trace, TracePoint};
pub use warm_started::WarmStarted;
