//! [`Builder`]: validated construction of an [`Eit`] configuration.

use mit_star_heuristics::{Euclidean, Heuristic};
use mit_star_problems::PlanningProblem;
use mit_star_samplers::Sampler;
use mit_star_spaces::StateSpace;
use mit_star_validity::{Counted, EdgeChecker, StateValidity};

use crate::components::graph_configuration_name;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::{EffortInformed, Guidance, RandomGeometric};
use crate::planner::validate_query;
use crate::{
    BuildError, CheckerPart, Connection, EisExpansionForm, EisExpansionRule, Eit, Observer,
    Parameters, SamplerPart,
};

/// Builds an [`Eit`] planner: the query and parts are required, every parameter has the spec's
/// default and a chained setter; [`build`](Self::build) validates everything once.
///
/// ```
/// use mit_star::{MitStar, Parameters};
/// use mit_star_spaces::RealVectorSpace;
/// use mit_star_validity::World;
///
/// let space = RealVectorSpace::cube(2, -0.5, 0.5)?;
/// let world = World::in_space(&space);
/// let planner = MitStar::builder(space, world, vec![-0.4, 0.0], vec![vec![0.4, 0.0]])
///     .batch_size(50)
///     .rewire_factor(1.2)
///     .seed(42)
///     .build()?;
/// assert_eq!(planner.parameters().batch_size, Some(50));
///
/// // Bad parameters are refused with a typed error naming them.
/// let space = RealVectorSpace::cube(2, -0.5, 0.5)?;
/// let err = MitStar::builder(space, World::new(vec![-0.5; 2], vec![0.5; 2]), vec![-0.4, 0.0], vec![vec![0.4, 0.0]])
///     .batch_size(0)
///     .build()
///     .unwrap_err();
/// assert_eq!(err.to_string(), "parameter `batch_size` is 0; it must be at least 1");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Builder<S, V, Smp, E, H = Euclidean, G = EffortInformed, N = RandomGeometric> {
    space: S,
    validity: V,
    start: Vec<f64>,
    goals: Vec<Vec<f64>>,
    parameters: Parameters,
    heuristic: H,
    sampler: Option<Smp>,
    checker: Option<E>,
    observer: Option<Box<dyn Observer>>,
    name: Option<String>,
    /// What was wrong with the problem given to [`Eit::for_problem`], reported by `build`.
    problem_error: Option<BuildError>,
    guidance: std::marker::PhantomData<fn() -> G>,
    neighbours: std::marker::PhantomData<fn() -> N>,
}

impl<S, V, Smp, E, H: Default, G, N: Default> Eit<S, V, Smp, E, H, G, N> {
    /// Starts building a planner for the query `start → goals` in `space` with `validity`.
    pub fn builder(
        space: S,
        validity: V,
        start: Vec<f64>,
        goals: Vec<Vec<f64>>,
    ) -> Builder<S, V, Smp, E, H, G, N> {
        Builder {
            space,
            validity,
            start,
            goals,
            parameters: Parameters::default(),
            heuristic: H::default(),
            sampler: None,
            checker: None,
            observer: None,
            name: None,
            problem_error: None,
            guidance: std::marker::PhantomData,
            neighbours: std::marker::PhantomData,
        }
    }
}

impl<S, V, Smp, E, H: Default, G, N: Default> Eit<S, V, Smp, E, H, G, N> {
    /// Starts building a planner for a [`PlanningProblem`] — a box-world benchmark
    /// [`Problem`](mit_star_problems::Problem), a robot-arm problem, or your own: its space, validity
    /// checker, start, goals and resolution, and the certification, reverse-search repair,
    /// sparse spacing, connection rule, batch size and batch growth it asks for. [`build`](Builder::build)
    /// refuses a problem that refuses its collision-check step or its certification
    /// ([`PlanningProblem::check_step`]: a box world whose
    /// step is coarser than its thinnest obstacle, unless the problem allows it).
    ///
    /// ```
    /// use mit_star::{EitStar, FirstSolution, Planner};
    /// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
    /// let mut planner = EitStar::for_problem(&problem).seed(1).build()?;
    /// let outcome = planner.solve(&FirstSolution)?;
    /// assert!(outcome.cost() >= problem.optimum().unwrap());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn for_problem<P>(problem: &P) -> Builder<S, V, Smp, E, H, G, N>
    where
        P: PlanningProblem<Space = S, Validity = V>,
        S: Clone,
        V: Clone,
    {
        let mut builder = Self::builder(
            problem.space().clone(),
            problem.validity().clone(),
            problem.start().to_vec(),
            problem.goals().to_vec(),
        );
        // The problem's defaults, decided as `build_planner` decides them, except the
        // near-terminal fraction: the sampler here is the type's own, and no wrapper reads it.
        match Parameters::default().for_problem(problem) {
            Ok(parameters) => {
                builder.parameters = Parameters {
                    near_terminals: None,
                    ..parameters
                };
            }
            Err(error) => builder.problem_error = Some(error),
        }
        builder
    }
}

impl<S, V, Smp, E, H, G, N> Builder<S, V, Smp, E, H, G, N> {
    /// Replaces every parameter.
    pub fn parameters(mut self, parameters: Parameters) -> Self {
        self.parameters = parameters;
        self
    }

    /// Samples per batch (default: the problem's, 50 on arms, else 100).
    pub fn batch_size(mut self, batch_size: usize) -> Self {
        self.parameters.batch_size = Some(batch_size);
        self
    }

    /// The fraction of the graph's vertices a batch holds at least (default: the problem's,
    /// 0.05 on arms, else 0: fixed batches).
    pub fn batch_growth(mut self, growth: f64) -> Self {
        self.parameters.batch_growth = Some(growth);
        self
    }

    /// The fraction of each batch placed along the best path once a solution exists
    /// (default: the problem's, 0.5 on arms, else 0: every sample from the sampler).
    pub fn solution_samples(mut self, fraction: f64) -> Self {
        self.parameters.solution_samples = Some(fraction);
        self
    }

    /// The RGG constant `η` (default 1.001).
    pub fn rewire_factor(mut self, eta: f64) -> Self {
        self.parameters.rewire_factor = eta;
        self
    }

    /// k-nearest or r-disc connection (default: the problem's with [`for_problem`](Eit::for_problem), r-disc on arms; else k-nearest).
    pub fn connection(mut self, connection: Connection) -> Self {
        self.parameters.connection = Some(connection);
        self
    }

    /// Pruning on (default) or off.
    pub fn pruning(mut self, pruning: bool) -> Self {
        self.parameters.pruning = pruning;
        self
    }

    /// Collision-check resolution, a fraction of the maximum extent (default 5e-6).
    pub fn resolution(mut self, resolution: f64) -> Self {
        self.parameters.resolution = resolution;
        self
    }

    /// Seed of the sampler (default 0).
    pub fn seed(mut self, seed: u64) -> Self {
        self.parameters.seed = seed;
        self
    }

    /// Whether the reverse search suspends when the forward queue is empty (default: the
    /// guidance's rule — yes for MIT*'s [`Suspending`](crate::Suspending) guidance and AIT*,
    /// no for EIT*).
    pub fn suspend_reverse_when_forward_empty(mut self, suspend: bool) -> Self {
        self.parameters.suspend_reverse_when_forward_empty = Some(suspend);
        self
    }

    /// Whether an invalid edge of the reverse tree is repaired in place (LPA*-style, OMPL's AIT*
    /// default) or restarts the reverse search (default: the problem's choice, restarting
    /// without one; [`Parameters::repair_reverse_search`]).
    pub fn repair_reverse_search(mut self, repair: bool) -> Self {
        self.parameters.repair_reverse_search = Some(repair);
        self
    }

    /// The adaptive sampler's `δ` as a fraction of the maximum extent (default 0.1).
    pub fn gaussian_std_fraction(mut self, fraction: f64) -> Self {
        self.parameters.gaussian_std_fraction = fraction;
        self
    }

    /// Certify forward-tree edges on a grid `factor` times finer than the check step (1: off;
    /// [`for_problem`](Eit::for_problem) takes the problem's).
    pub fn certification(mut self, factor: u32) -> Self {
        self.parameters.certification = Some(factor);
        self
    }

    /// With certification, certify an edge bringing a new vertex into the forward tree only
    /// once a solution's path uses it (`true`, the default) or before it joins (`false`);
    /// [`Parameters::lazy_certification`].
    pub fn lazy_certification(mut self, lazy: bool) -> Self {
        self.parameters.lazy_certification = lazy;
        self
    }

    /// The adaptive sampler's segment checks per repair (default: the problem's, 8 without
    /// one).
    pub fn bridge_checks(mut self, checks: usize) -> Self {
        self.parameters.bridge_checks = Some(checks);
        self
    }

    /// The length-related checker's `Δ₀` and floor (in steps `L`) and `Ω` (defaults: the
    /// problem's spacing — 2000 and 10 for the paper's problems, 4 and 2 for arms — and 0.5).
    pub fn sparse_spacing(mut self, initial_steps: f64, factor: f64, min_steps: f64) -> Self {
        self.parameters.sparse_initial_steps = Some(initial_steps);
        self.parameters.sparse_factor = factor;
        self.parameters.sparse_min_steps = Some(min_steps);
        self
    }

    /// How the estimated informed set computes and applies `e_γ`.
    pub fn eis_expansion(mut self, form: EisExpansionForm, rule: EisExpansionRule) -> Self {
        self.parameters.eis_expansion_form = form;
        self.parameters.eis_expansion_rule = rule;
        self
    }

    /// Whether a new estimated informed set asks for a batch at once (default `false`; see
    /// [`Parameters::eis_immediate_batch`]).
    pub fn eis_immediate_batch(mut self, immediate: bool) -> Self {
        self.parameters.eis_immediate_batch = immediate;
        self
    }

    /// The BIT*-family inflation and truncation (ABIT*; see [`Parameters::initial_inflation`],
    /// [`inflation_scaling`](Parameters::inflation_scaling) and
    /// [`truncation_scaling`](Parameters::truncation_scaling)). Only the a-priori guidance
    /// ([`APriori`](crate::APriori), BIT*) uses them.
    pub fn inflation(mut self, initial: f64, scaling: f64, truncation_scaling: f64) -> Self {
        self.parameters.initial_inflation = Some(initial);
        self.parameters.inflation_scaling = Some(scaling);
        self.parameters.truncation_scaling = Some(truncation_scaling);
        self
    }

    /// Whether a BIT*-family forward expansion queues rewirings (edges to vertices already in
    /// the tree) every time (ABIT*'s default), or only on a vertex's first such expansion
    /// (BIT*'s; [`Parameters::cascading_rewirings`]).
    pub fn cascading_rewirings(mut self, cascading: bool) -> Self {
        self.parameters.cascading_rewirings = Some(cascading);
        self
    }

    /// ABIT*'s inflation and truncation wherever they are not set
    /// ([`Parameters::abit_star`]).
    pub fn abit_star(mut self) -> Self {
        self.parameters = self.parameters.abit_star();
        self
    }

    /// Uses this heuristic instead of `H::default()`.
    pub fn heuristic(mut self, heuristic: H) -> Self {
        self.heuristic = heuristic;
        self
    }

    /// Uses this sampler instead of building one from the parameters.
    pub fn sampler(mut self, sampler: Smp) -> Self {
        self.sampler = Some(sampler);
        self
    }

    /// Uses this edge checker instead of building one from the parameters.
    pub fn edge_checker(mut self, checker: E) -> Self {
        self.checker = Some(checker);
        self
    }

    /// Installs an observer.
    pub fn observer(mut self, observer: Box<dyn Observer>) -> Self {
        self.observer = Some(observer);
        self
    }

    /// The name reports print (default: the configuration's name, e.g. `MIT*`).
    pub fn name(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }
}

impl<S, V, Smp, E, H, G, N> Builder<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + SamplerPart<S> + Clone,
    E: EdgeChecker<S, Counted<V>> + CheckerPart<S> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule + Default,
{
    /// Validates the parameters and the query and builds the planner.
    ///
    /// # Errors
    /// [`BuildError::Parameter`] for a parameter out of range, [`BuildError::Query`] for a
    /// malformed query, and the parts' own errors ([`BuildError::Sampler`],
    /// [`BuildError::Validity`]).
    // Seven parts are seven type parameters; an alias would only hide which planner it is.
    #[allow(clippy::type_complexity)]
    pub fn build(self) -> Result<Eit<S, V, Smp, E, H, G, N>, BuildError> {
        if let Some(error) = self.problem_error {
            return Err(error);
        }
        self.parameters.validate()?;
        let largest_batch = self
            .parameters
            .samples_per_batch()
            .max(self.parameters.eis_batch_size.unwrap_or(0));
        check_batch_memory(largest_batch, self.space.dimension())?;
        validate_query(&self.space, &self.validity, &self.start, &self.goals)?;
        let sampler = match self.sampler {
            Some(sampler) => sampler,
            None => Smp::build_part(&self.space, &self.start, &self.goals, &self.parameters)?,
        };
        let checker = match self.checker {
            Some(checker) => checker,
            None => E::build_part(&self.space, &self.parameters)?,
        };
        let name = self.name.unwrap_or_else(|| {
            let parts = (G::name(), Smp::part_name(), E::NAME);
            graph_configuration_name(&parts.0, &parts.1, parts.2, N::default().part_name())
        });
        let mut planner = Eit::with_parts(
            self.space,
            self.validity,
            self.start,
            self.goals,
            sampler,
            checker,
            self.heuristic,
            self.parameters,
        )
        .query_validated();
        planner.set_name(name);
        if let Some(observer) = self.observer {
            planner.set_observer(observer);
        }
        Ok(planner)
    }
}

/// Memory one sample takes in the planner, in `n` dimensions: its state three times (graph,
/// nearest-neighbour buffer, tree) plus its vertex record and neighbour list, generously.
fn bytes_per_sample(n: usize) -> u64 {
    24 * n as u64 + 512
}

/// Refuses a batch size whose one batch of samples could not fit in this machine's memory.
fn check_batch_memory(batch_size: usize, n: usize) -> Result<(), BuildError> {
    let bytes = mit_star_spaces::MemoryBudget::bytes_for(&[batch_size as u64, bytes_per_sample(n)]);
    let Err(budget) = mit_star_spaces::MemoryBudget::check_on_machine(bytes) else {
        return Ok(());
    };
    Err(BuildError::TooLarge {
        what: format!("a batch of {batch_size} samples in {n} dimensions"),
        needed: bytes.map_or_else(
            || "more than 16 EiB".to_owned(),
            mit_star_spaces::MemoryBudget::describe,
        ),
        available: mit_star_spaces::MemoryBudget::describe(budget.bytes()),
    })
}
