//! [`Observer`]: callbacks a planner invokes on notable events (argmin's observer pattern).

use mit_star_samplers::CostBound;

/// A new best solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolutionEvent {
    /// Planning time in seconds (summed over `solve` calls).
    pub time: f64,
    /// The new best cost.
    pub cost: f64,
    /// The planner's iteration count at the time.
    pub iteration: u64,
    /// Vertices in the graph at the time.
    pub vertices: usize,
}

/// A batch of samples was added.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatchEvent {
    /// Batches so far, this one included.
    pub batch: u64,
    /// Samples added by this batch.
    pub samples: usize,
    /// Vertices removed by pruning before the batch.
    pub pruned: usize,
    /// Vertices in the graph after the batch.
    pub vertices: usize,
    /// The bound the samples were drawn under, as the sampler applied it (an estimated informed
    /// set shows as [`CostBound::Estimated`]).
    pub bound: CostBound,
    /// The connection parameter now: `k` (k-nearest) or the radius (r-disc).
    pub connection: f64,
}

/// The reverse search was restarted because a lazy edge turned out invalid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestartEvent {
    /// Restarts so far, this one included.
    pub restarts: u64,
    /// The sparse-check level after refinement.
    pub sparse_level: u32,
    /// `true` if a valid solution existed.
    pub solved: bool,
}

/// Receives planner events. Every method has an empty default, so an observer implements only
/// what it needs.
///
/// ```
/// use mit_star::{Observer, SolutionEvent};
/// #[derive(Default)]
/// struct Costs(Vec<f64>);
/// impl Observer for Costs {
///     fn on_solution(&mut self, event: &SolutionEvent) {
///         self.0.push(event.cost);
///     }
/// }
/// let mut costs = Costs::default();
/// costs.on_solution(&SolutionEvent { time: 0.1, cost: 2.0, iteration: 7, vertices: 102 });
/// assert_eq!(costs.0, [2.0]);
/// ```
pub trait Observer: Send {
    /// A new best solution was found.
    fn on_solution(&mut self, _event: &SolutionEvent) {}

    /// A batch of samples was added.
    fn on_batch(&mut self, _event: &BatchEvent) {}

    /// The reverse search restarted after an invalid lazy edge.
    fn on_reverse_restart(&mut self, _event: &RestartEvent) {}
}
