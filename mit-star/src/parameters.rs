//! [`Parameters`]: every tunable number of the EIT*/MIT* family, validated once.

use serde::{Deserialize, Serialize};

use crate::BuildError;

/// How the random geometric graph connects a vertex (spec §3.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Connection {
    /// The `k = ⌈η · e · (1 + 1/n) · ln q⌉` nearest vertices (the default).
    #[default]
    KNearest,
    /// Every vertex within `r = η · 2 · ((1 + 1/n) · λ / ζ_n · ln q / q)^(1/n)`, `λ` the measure
    /// of the set the sampler draws from.
    RDisc,
}

/// How MIT*'s estimated informed set grows its cost from the reliability `γ` (spec §6): the
/// `samplers` crate's [`ExpansionForm`](mit_star_samplers::ExpansionForm), under the planner's name.
pub use mit_star_samplers::ExpansionForm as EisExpansionForm;

/// When MIT*'s estimated informed set expands (spec §6): the `samplers` crate's
/// [`ExpansionRule`](mit_star_samplers::ExpansionRule), under the planner's name.
pub use mit_star_samplers::ExpansionRule as EisExpansionRule;

/// The parameters of an [`Eit`](crate::Eit) planner and its parts, with the spec's defaults
/// (§9). Serialisable, so benchmark output can record exactly what ran.
///
/// ```
/// use mit_star::Parameters;
/// let p = Parameters::default();
/// assert_eq!((p.samples_per_batch(), p.rewire_factor), (100, 1.001));
/// assert!(p.validate().is_ok());
/// let bad = Parameters { batch_size: Some(0), ..Parameters::default() };
/// assert_eq!(bad.validate().unwrap_err().to_string(),
///            "parameter `batch_size` is 0; it must be at least 1");
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Parameters {
    /// Samples per batch (`None`: the problem's,
    /// [`PlanningProblem::batch_size`](mit_star_problems::PlanningProblem::batch_size) — 50 on arms;
    /// the papers' 100 for box worlds and a planner built without a problem;
    /// [`samples_per_batch`](Self::samples_per_batch) reads it).
    pub batch_size: Option<usize>,
    /// A batch holds at least this fraction of the vertices already in the graph, so batches
    /// grow geometrically once the graph holds `batch_size / batch_growth` vertices and a
    /// search restarted every batch costs a bounded number of passes over the graph (`None`:
    /// the problem's, [`PlanningProblem::batch_growth`](mit_star_problems::PlanningProblem::batch_growth)
    /// — 0, fixed batches as in the papers, for box worlds and a planner built without a
    /// problem). Not in the paper.
    pub batch_growth: Option<f64>,
    /// Once a solution exists, the fraction of each batch of the EIT* family drawn along the
    /// best path rather than by the sampler: states on the segment between two of its vertices
    /// that are not neighbours on it (a shortcut), half of them displaced by a Gaussian step,
    /// kept if valid and inside the informed set (`None`: the problem's,
    /// [`PlanningProblem::solution_samples`](mit_star_problems::PlanningProblem::solution_samples) — 0,
    /// the papers' sampling, for box worlds and a planner built without a problem). The
    /// forward search then finds a shortcut that is free as a chain of graph edges. Such states
    /// do not count in the sample number `q` of `k(q)` and `r(q)`, so the uniform samples keep
    /// the connection rules that make the planners asymptotically optimal. Not in the paper.
    pub solution_samples: Option<f64>,
    /// With [`solution_samples`](Self::solution_samples), a third of the states placed along
    /// the best path move one of its corners part of the way towards the chord of its two
    /// neighbours on the path (`true`), instead of every state lying on a shortcut (`false`,
    /// the default: on the Panda the pulls made paths longer on more problems than shorter,
    /// `docs/guide/src/performance-switches.md`). Not in the paper.
    pub solution_corner_pulls: bool,
    /// With [`solution_samples`](Self::solution_samples), the share of the placed states that
    /// gather at the path's bends, in `[0, 1]`: for such a state the vertex a shortcut spans
    /// (or the corner a pull moves) is drawn in proportion to how much longer the path is
    /// through it than along the chord of its two neighbours; for the others the shortcut's
    /// two ends are uniform over the path. 0 is the placement before 2026-12-07; the default,
    /// 0.5, gave shorter paths than 0 at 10 ms, 100 ms and 1 s on the Panda, 1 shorter at 1 s
    /// but longer at 10 ms (`docs/guide/src/performance-switches.md`). Not in the paper.
    pub solution_corner_weights: f64,
    /// The RGG constant `η > 0` scaling `k` or `r`.
    pub rewire_factor: f64,
    /// k-nearest or r-disc connection (`None`: the problem's,
    /// [`PlanningProblem::radius_connection`](mit_star_problems::PlanningProblem::radius_connection) —
    /// r-disc on arms; k-nearest, the paper's, for box worlds and a planner built without a
    /// problem).
    pub connection: Option<Connection>,
    /// With r-disc connection, a vertex is joined to at most its `⌈c · k(q)⌉` nearest within
    /// the radius, `k(q)` the k-nearest rule's number (`None`: every one within it, the
    /// rule as published). With `c ≥ 1` each vertex keeps at least the neighbours of the
    /// k-nearest rule or all within the radius, so either rule's asymptotic optimality holds;
    /// in 7 dimensions the radius's `2ⁿ` constant joins each vertex to hundreds of others, and
    /// in a thin informed set to most of the graph. Not in the paper.
    pub neighbour_cap: Option<f64>,
    /// Remove samples that cannot improve the solution at each new batch.
    pub pruning: bool,
    /// Collision-check resolution, a fraction of the space's maximum extent (`L = r · extent`).
    pub resolution: f64,
    /// Seed of the sampler's random generator.
    pub seed: u64,
    /// Suspend the reverse search when the forward queue is empty (`true`: the MIT* authors'
    /// rule; `false`: keep exhausting the reverse queue, as upstream EIT* does; `None`: the
    /// planner's [`Guidance`](crate::Guidance) decides — MIT* suspends, EIT* does not).
    pub suspend_reverse_when_forward_empty: Option<bool>,
    /// When the forward search finds an edge of the reverse tree invalid, repair the reverse
    /// search in place (`true`: LPA*-style, only the branch below the edge is searched again,
    /// OMPL's AIT* default) or restart it from the goals (`false`: EIT*'s rule, the paper's,
    /// and the faster one for our AIT* in the box worlds,
    /// `docs/guide/src/reference/faithfulness-map.md` §6). `None` (the default): the problem
    /// decides ([`PlanningProblem::repair_reverse_search`](mit_star_problems::PlanningProblem::repair_reverse_search):
    /// arms repair, the paper's problems restart); a planner built without a problem restarts.
    /// Without a reverse search (BIT*) there is nothing to repair. Not in the paper.
    pub repair_reverse_search: Option<bool>,
    /// Standard deviation `δ` of the adaptive sampler, as a fraction of the maximum extent.
    pub gaussian_std_fraction: f64,
    /// Segment points the adaptive sampler tests per repair (`None`: the problem's
    /// [`bridge_checks`](mit_star_problems::PlanningProblem::bridge_checks) — 8, the spec's
    /// default, for the paper's problems; 4 for arms; 8 for a planner built without a problem).
    pub bridge_checks: Option<usize>,
    /// Initial sparse spacing `Δ₀` of the length-related checker (MIT*'s sparse checks), in
    /// steps `L` (`None`: the problem's
    /// [`sparse_spacing`](mit_star_problems::PlanningProblem::sparse_spacing) — 2000, the MIT* authors'
    /// constant, for the paper's problems; 4 for arms; 2000 for a planner built without a
    /// problem).
    pub sparse_initial_steps: Option<f64>,
    /// Refinement factor `Ω ∈ (0, 1)` of the length-related checker.
    pub sparse_factor: f64,
    /// Finest sparse spacing of the length-related checker, in steps `L` (`None`: the
    /// problem's [`sparse_spacing`](mit_star_problems::PlanningProblem::sparse_spacing) — 10 for the
    /// paper's problems, 2 for arms; 10 without a problem).
    pub sparse_min_steps: Option<f64>,
    /// How the estimated informed set computes `e_γ`.
    pub eis_expansion_form: EisExpansionForm,
    /// When the estimated informed set expands.
    pub eis_expansion_rule: EisExpansionRule,
    /// Samples per batch drawn under MIT*'s estimated informed set (`None`: `batch_size`).
    pub eis_batch_size: Option<usize>,
    /// A new estimated informed set asks for a batch drawn in it at once (`true`: the MIT*
    /// authors' code, spec §3.1 step 1), or bounds the next batch the search asks for
    /// (`false`, the default: the paper's Alg. 1; `docs/guide/src/reference/ablation-study.md` has the evidence).
    pub eis_immediate_batch: bool,
    /// Certify the forward tree's edges on a grid this many times finer than the check step,
    /// when [`lazy_certification`](Self::lazy_certification) says (1: no certification;
    /// `None`: the problem's [`certification`](mit_star_problems::PlanningProblem::certification), 4
    /// for arms). Not in the paper: it makes returned paths hold at the finer grid too, for a
    /// few edges' work.
    pub certification: Option<u32>,
    /// With certification, an edge that brings a new vertex into the forward tree joins it
    /// uncertified, and is certified when a solution's path first goes through it, before
    /// that solution is recorded (`true`, the default): most tree edges never lie on a
    /// solution, and a failure detaches the edge's subtree and restarts both searches. A
    /// vertex already in the tree moves to a new parent only once that edge and the parent's
    /// path are certified, so the best solution's path is certified at every moment. `false`
    /// certifies every edge before it joins the tree. The paths returned are certified either
    /// way. Not in the paper.
    pub lazy_certification: bool,
    /// Fraction of the samples the EIT* family (MIT*, EIT*, AIT*, BIT*, ABIT*) draws near the
    /// start and the goals, at every scale, through the [`NearTerminals`](mit_star_samplers::NearTerminals)
    /// wrapper (0: no wrapper; `None`: the problem's
    /// [`near_terminals`](mit_star_problems::PlanningProblem::near_terminals), 0 for the paper's
    /// problems, 0.15 for arms). Not in the paper: it joins starts and goals that sit deep in
    /// pockets (grasps in shelf slots), which uniform samples in 7 dimensions seldom reach.
    pub near_terminals: Option<f64>,
    /// How many of the states its reverse search reached farthest from the goals the EIT*
    /// family hands the [`NearTerminals`](mit_star_samplers::NearTerminals) wrapper at the end of each
    /// batch without a solution ([`Sampler::observe_frontier`](mit_star_samplers::Sampler::observe_frontier)),
    /// half of whose draws then centre on one of them (0: none, every draw centres on a
    /// terminal). No effect without the wrapper (`near_terminals` 0, the paper's problems).
    /// Not in the paper: a goal in a pocket is left one batch at a time.
    pub near_frontier: usize,
    /// While the [`NearTerminals`](mit_star_samplers::NearTerminals) wrapper has frontier states, half
    /// of its draws first try straight lines from them over the largest scale, up to
    /// [`NearTerminals::RAY_TRIES`](mit_star_samplers::NearTerminals::RAY_TRIES), and take two states
    /// of the first line found free
    /// ([`NearTerminals::with_frontier_rays`](mit_star_samplers::NearTerminals::with_frontier_rays)):
    /// RRT-Connect's extension as a sample. `true` by default (chosen by measurement on the
    /// Panda, the UR5 and the Fetch); `false` keeps every draw Gaussian. No effect without the
    /// wrapper or without frontier states. Not in the paper.
    pub frontier_rays: bool,
    /// With a frontier (`near_frontier` > 0), when the reverse search of MIT* or EIT* ends
    /// holding more than half of the graph's vertices but not the start, the start is the end
    /// in a pocket: the planner then searches from the start over the edges that pass the
    /// sparse checks and hands the sampler the `near_frontier` states that side reached
    /// farthest, instead of the reverse tree's. A start in a pocket (planning out of a shelf)
    /// is then left as a goal in one is. `true` by default; `false` keeps every frontier on
    /// the goals' side. No effect without the wrapper. Not in the paper.
    pub start_frontier: bool,
    /// With a frontier (`near_frontier` > 0), the goals' frontier is taken from the part of
    /// the reverse tree that full checks confirm: MIT*, EIT* and AIT* walk their reverse tree
    /// from the goals, nearest first, fully checking each tree edge before going through it
    /// (at most [`VALIDATED_FRONTIER_CHECKS`](Self::VALIDATED_FRONTIER_CHECKS) new checks
    /// per batch; what they learn is stored, an invalid edge is blacklisted), and send the
    /// farthest states reached so. The reverse tree's edges pass only sparse checks, and from
    /// a goal in a pocket its long edges out (a midpoint tested) are mostly invalid, so its
    /// farthest states lie far outside the pocket, where no valid path goes yet. `false` by
    /// default (the farthest states of the whole reverse tree): on the Fetch it helps goals in
    /// pockets a little and hurts starts in pockets more (`docs/guide/src/performance-switches.md`).
    /// No effect without the wrapper. Not in the paper.
    pub validated_frontier: bool,
    /// Accelerated point checks (`true`, the default): each edge is first prepared by the
    /// validity checker — a box world keeps only the boxes near it and decides a free edge
    /// without a test — and its points go to the checker in batches (SIMD lanes). The answers
    /// and the points counted are the same either way; `false` interpolates and tests one
    /// state at a time, as OMPL's discrete motion validator does (for side-by-side timing).
    /// Not in the paper.
    pub accelerated_checks: bool,
    /// RRT-Connect's maximum extension length (`None`: the problem's
    /// [`default_range`](mit_star_problems::PlanningProblem::default_range) — an arm's, measured per
    /// robot — else [`default_range`](crate::default_range), the paper's per dimension or 0.2
    /// of the maximum extent). Unused by the EIT* family.
    pub range: Option<f64>,
    /// RRT-Connect steers towards valid samples only (`true`, OMPL's valid-state sampler:
    /// every draw costs a state check and invalid draws are redrawn) or towards any state of
    /// the space (`false`, the default, as OMPL's RRT-Connect with its plain state sampler and
    /// VAMP do): an extension towards an invalid draw stops where its motion does. Chosen by
    /// measurement on the Panda (the arm-planning reference page, "RRT-Connect's switches").
    pub rrt_valid_samples: bool,
    /// RRT-Connect's dynamic domain (Yershova et al., 2005): a state from which an extension
    /// failed gets a radius (4 ranges, then shrinking by 0.01 % per failure down to one range,
    /// growing as much per success), and draws farther from their nearest state than its
    /// radius are skipped without a check, except by a tree that balancing forces to grow (a
    /// tree stuck at a goal would otherwise stall the search), which redraws them instead
    /// ([`rrt_forced_redraws`](Self::rrt_forced_redraws)). `true` (the default, chosen by
    /// measurement on the Panda) or `false` (plain RRT-Connect, as OMPL's).
    pub rrt_dynamic_domain: bool,
    /// With `rrt_dynamic_domain`, how many times RRT-Connect's tree that balancing forces to
    /// grow redraws a sample outside its nearest state's dynamic domain, within one iteration,
    /// before it steps towards the last draw anyway (AORRTC's first search too; its later,
    /// cost-bounded searches step at once). 0 steps towards every draw; a large number
    /// amounts to VAMP's skipping, which stalls a tree stuck at a goal in 8 dimensions. A
    /// redraw costs a draw and a nearest-neighbour query, a step a motion check. Default 4,
    /// chosen by measurement on the Panda, the UR5 and the Fetch (the arm-planning reference
    /// page, "RRT-Connect's switches").
    pub rrt_forced_redraws: u32,
    /// RRT-Connect grows the smaller tree while one tree has at least twice the states of the
    /// other (`true`, the default, chosen by measurement), instead of alternating strictly
    /// (`false`, as OMPL's).
    pub rrt_balance: bool,
    /// RRT-Connect draws from a Halton sequence (`true`; VAMP's planners draw from one too)
    /// instead of independent uniform draws (`false`, the default, chosen by measurement).
    pub rrt_halton: bool,
    /// With `rrt_halton`, the sequence is shifted by the seed (`true`, the default: each seed
    /// draws other points, equally even) or not (`false`: the plain sequence, the same points
    /// in every run, as VAMP's; its first search is then the same for every seed).
    pub rrt_halton_shift: bool,
    /// Every new solution is shortened by a [`PathSimplifier`](crate::PathSimplifier) before it
    /// is reported (`true`; [`build_planner`](crate::build_planner) wraps the planner in
    /// [`Simplifying`](crate::Simplifying)), or reported as the planner found it (`false`, the
    /// default: the paper's planners and their ablations as published). Not in the paper.
    pub simplify_solutions: bool,
    /// With [`simplify_solutions`](Self::simplify_solutions), and in AORRTC's own
    /// simplification ([`aorrtc_simplify`](Self::aorrtc_simplify)) when
    /// [`polish_when_idle`](Self::polish_when_idle) is off, each simplification ends
    /// with smoothing sweeps ([`PathSimplifier::smoothing_rounds`](crate::PathSimplifier::smoothing_rounds):
    /// interior states moved off the path where it gets shorter, every new edge checked and
    /// certified) (`true`, the default), or with the shortcuts (`false`, the ablation). Not in
    /// the paper.
    pub simplify_smoothing: bool,
    /// An asymptotically optimal planner starts from RRT-Connect's first solution (`true`;
    /// [`build_planner`](crate::build_planner) wraps it in [`WarmStarted`](crate::WarmStarted))
    /// or finds its own (`false`, the default: the paper's planners). RRT-Connect and AORRTC
    /// (whose first search is RRT-Connect) ignore it. Not in the paper.
    pub warm_start: bool,
    /// AORRTC shortens each solution it finds with a [`PathSimplifier`](crate::PathSimplifier)
    /// before the next cost-bounded search starts, so that search is bounded by the shorter
    /// cost (`true`, the default, as its authors' planner), or searches under the cost of the
    /// path as found (`false`).
    pub aorrtc_simplify: bool,
    /// While an anytime planner that simplifies its solutions (AORRTC with
    /// [`aorrtc_simplify`](Self::aorrtc_simplify); any planner with
    /// [`simplify_solutions`](Self::simplify_solutions)) finds nothing cheaper for 2 000
    /// iterations, its best path is polished: shortcuts of whole configurations and of single
    /// joints, then smoothing rounds of midpoint relaxation and random perturbations, every new
    /// edge checked and certified, for at most about one edge check per idle iteration. A polish
    /// that gains nothing doubles the wait before the next (`true`, the default), or nothing is
    /// done between solutions (`false`: AORRTC as its authors' planner). With it on, AORRTC
    /// leaves the smoothing to the polishes and only shortcuts each new solution
    /// ([`Aorrtc::smooths_solutions`](crate::Aorrtc::smooths_solutions)). Not in the papers.
    pub polish_when_idle: bool,
    /// AORRTC's cost-bound resampling: after a new state joins a tree, up to this many more
    /// parents are sought under redrawn cost bounds, each taken if its edge is valid and
    /// cheaper (1000, as its authors' planner; 0: the first parent stays).
    pub aorrtc_resamples: u32,
    /// Informed RRT*'s probability of sampling a goal instead of the sampler's state.
    pub goal_bias: f64,
    /// Informed RRT*'s k-nearest rewiring factor (OMPL's `rewire_factor` of RRT*; the EIT*
    /// family and BIT* use `rewire_factor`).
    pub rrt_rewire_factor: f64,
    /// BIT*-family inflation `ε₀ ≥ 1` of the heuristic in the edge order of each batch's first
    /// search (`None`: 1 for BIT*, 10⁶ for ABIT*).
    pub initial_inflation: Option<f64>,
    /// ABIT*'s inflation scaling `s ≥ 0`: a batch's second search orders by
    /// `g + ĉ + (1 + s/q)·ĥ` (`None`: 0 for BIT*, 10 for ABIT*).
    pub inflation_scaling: Option<f64>,
    /// ABIT*'s truncation scaling `t ≥ 0`: a batch's search stops at the first edge it takes
    /// whose `(1 + t/q)·(g + ĉ + ĥ)` reaches the solution cost, or once every queued edge's does
    /// (`None`: 0 for BIT*, 5 for ABIT*).
    pub truncation_scaling: Option<f64>,
    /// BIT*-family rewirings: a forward expansion queues edges to vertices already in the tree
    /// on every expansion (`true`), or only on a vertex's first expansion that meets any
    /// (`false`). Edges to new samples and to the vertex's own children are queued either way.
    /// `None`: as OMPL 2.0 — off for BIT*, on for ABIT* ([`abit_star`](Self::abit_star)). The
    /// EIT* family (EIT*, MIT*, AIT*) always queues them, as upstream EIT* does.
    pub cascading_rewirings: Option<bool>,
}

impl Default for Parameters {
    fn default() -> Self {
        Self {
            batch_size: None,
            batch_growth: None,
            solution_samples: None,
            solution_corner_pulls: false,
            solution_corner_weights: DEFAULT_SOLUTION_CORNER_WEIGHTS,
            rewire_factor: 1.001,
            connection: None,
            neighbour_cap: None,
            pruning: true,
            resolution: 5e-6,
            seed: 0,
            suspend_reverse_when_forward_empty: None,
            repair_reverse_search: None,
            gaussian_std_fraction: 0.1,
            bridge_checks: None,
            sparse_initial_steps: None,
            sparse_factor: 0.5,
            sparse_min_steps: None,
            eis_expansion_form: EisExpansionForm::Paper,
            eis_expansion_rule: EisExpansionRule::PerBatch,
            eis_batch_size: None,
            eis_immediate_batch: false,
            certification: None,
            lazy_certification: true,
            near_terminals: None,
            near_frontier: 4,
            frontier_rays: true,
            start_frontier: true,
            validated_frontier: false,
            accelerated_checks: true,
            range: None,
            rrt_valid_samples: false,
            rrt_dynamic_domain: true,
            rrt_forced_redraws: 4,
            rrt_balance: true,
            rrt_halton: false,
            rrt_halton_shift: true,
            simplify_solutions: false,
            simplify_smoothing: true,
            warm_start: false,
            aorrtc_simplify: true,
            polish_when_idle: true,
            aorrtc_resamples: 1000,
            goal_bias: 0.05,
            rrt_rewire_factor: 1.2,
            initial_inflation: None,
            inflation_scaling: None,
            truncation_scaling: None,
            cascading_rewirings: None,
        }
    }
}

/// The default of [`Parameters::solution_corner_weights`]: half of the placed states at the
/// bends (`docs/guide/src/performance-switches.md`).
const DEFAULT_SOLUTION_CORNER_WEIGHTS: f64 = 0.5;

/// ABIT*'s initial inflation factor (OMPL 2.0's default).
const ABIT_INITIAL_INFLATION: f64 = 1e6;
/// ABIT*'s inflation scaling parameter (OMPL 2.0's default).
const ABIT_INFLATION_SCALING: f64 = 10.0;
/// ABIT*'s truncation scaling parameter (OMPL 2.0's default).
const ABIT_TRUNCATION_SCALING: f64 = 5.0;

/// The largest `rewire_factor` and `rrt_rewire_factor` accepted: 100 (the RGG constant is
/// about 1; 100 connects every sample to a hundred times the neighbours the theory asks).
pub const MAX_REWIRE_FACTOR: f64 = 100.0;
/// The largest `gaussian_std_fraction` accepted: 10 maximum extents (wider than the space
/// itself: the adaptive sampler is then uniform in effect).
pub const MAX_GAUSSIAN_STD_FRACTION: f64 = 10.0;
/// The largest `sparse_initial_steps` and `sparse_min_steps` accepted: 10⁹ steps (far
/// coarser than any edge: one sparse point per edge).
pub const MAX_SPARSE_STEPS: f64 = 1e9;
/// The largest `range` accepted: 10⁶ (in the space's units: radians, metres, or the box
/// worlds' unit cube; an extension stops at its target whatever the range).
pub const MAX_RANGE: f64 = 1e6;

/// [`BuildError::Parameter`] unless `value` lies in `(0, max]`.
fn within(
    name: &'static str,
    value: f64,
    max: f64,
    requirement: &'static str,
) -> Result<(), BuildError> {
    if value > 0.0 && value <= max {
        Ok(())
    } else {
        Err(BuildError::Parameter {
            name,
            value,
            requirement,
        })
    }
}

impl Parameters {
    /// New full checks a [`validated_frontier`](Self::validated_frontier) walk makes at most
    /// per batch (edges already decided cost nothing). Untuned.
    pub const VALIDATED_FRONTIER_CHECKS: usize = 64;

    /// These parameters for `problem`: its resolution replaces `resolution`, and its
    /// certification, near-terminal fraction, sparse spacing, reverse-search repair,
    /// connection rule, batch size, batch growth, solution samples, bridge checks and RRT
    /// range apply
    /// wherever unset ([`Configuration::effective_parameters`](crate::Configuration::effective_parameters)
    /// also decides the planner's own defaults).
    ///
    /// # Errors
    /// [`BuildError::Problem`] if the problem refuses its check step or certification.
    pub(crate) fn for_problem<P: mit_star_problems::PlanningProblem>(
        &self,
        problem: &P,
    ) -> Result<Self, BuildError> {
        problem.check_step()?;
        let mut parameters = self.clone();
        parameters.resolution = problem.resolution();
        parameters.certification = self.certification.or(Some(problem.certification()));
        problem.check_certification(parameters.certification.unwrap_or(1).max(1))?;
        parameters.near_terminals = self.near_terminals.or(Some(problem.near_terminals()));
        parameters.batch_size = self.batch_size.or(Some(problem.batch_size()));
        parameters.batch_growth = self.batch_growth.or(Some(problem.batch_growth()));
        parameters.solution_samples = self.solution_samples.or(Some(problem.solution_samples()));
        parameters.bridge_checks = self.bridge_checks.or(Some(problem.bridge_checks()));
        parameters.range = self.range.or(problem.default_range());
        let (initial, finest) = problem.sparse_spacing();
        parameters.sparse_initial_steps = self.sparse_initial_steps.or(Some(initial));
        parameters.sparse_min_steps = self.sparse_min_steps.or(Some(finest));
        parameters.repair_reverse_search = self
            .repair_reverse_search
            .or(Some(problem.repair_reverse_search()));
        parameters.connection = self.connection.or(Some(if problem.radius_connection() {
            Connection::RDisc
        } else {
            Connection::KNearest
        }));
        Ok(parameters)
    }

    /// Samples per batch: [`batch_size`](Self::batch_size), or the papers' 100
    /// ([`mit_star_problems::PAPER_BATCH_SIZE`]) where unset and no problem decided it.
    pub fn samples_per_batch(&self) -> usize {
        self.batch_size
            .unwrap_or(mit_star_problems::PAPER_BATCH_SIZE)
    }

    /// The samples [`batch_growth`](Self::batch_growth) asks of a batch added to a graph of
    /// `vertices` vertices: `⌈batch_growth · vertices⌉` (0 where unset). A batch holds this or
    /// the batch size, whichever is more.
    ///
    /// ```
    /// use mit_star::Parameters;
    /// let p = Parameters { batch_growth: Some(0.25), ..Parameters::default() };
    /// assert_eq!((p.grown_batch(100), p.grown_batch(999)), (25, 250));
    /// assert_eq!(Parameters::default().grown_batch(1_000_000), 0);
    /// let bad = Parameters { batch_growth: Some(1.5), ..Parameters::default() };
    /// assert_eq!(bad.validate().unwrap_err().to_string(),
    ///            "parameter `batch_growth` is 1.5; it must lie in [0, 1] (a fraction of the graph's vertices)");
    /// ```
    pub fn grown_batch(&self, vertices: usize) -> usize {
        let growth = self.batch_growth.unwrap_or(0.0);
        (growth * vertices as f64).ceil() as usize
    }

    /// These parameters with ABIT*'s inflation, truncation and rewirings (Strub and Gammell,
    /// ICRA 2020, as OMPL 2.0 sets them: initial inflation 10⁶, inflation scaling 10, truncation
    /// scaling 5, cascading rewirings) wherever they are not set: [`BitStar`](crate::BitStar) with them is ABIT*.
    pub fn abit_star(mut self) -> Self {
        self.initial_inflation.get_or_insert(ABIT_INITIAL_INFLATION);
        self.inflation_scaling.get_or_insert(ABIT_INFLATION_SCALING);
        self.truncation_scaling
            .get_or_insert(ABIT_TRUNCATION_SCALING);
        self.cascading_rewirings.get_or_insert(true);
        self
    }

    /// Checks every parameter.
    ///
    /// # Errors
    /// [`BuildError::Parameter`] naming the first parameter out of range: a batch size or bridge
    /// count of 0, a batch growth outside `[0, 1]`, a resolution or `Ω` outside `(0, 1)`, and
    /// values outside their documented ranges: `η` in `(0, 100]` ([`MAX_REWIRE_FACTOR`]), `δ`
    /// in `(0, 10]` ([`MAX_GAUSSIAN_STD_FRACTION`]), sparse spacings in `(0, 10⁹]` steps
    /// ([`MAX_SPARSE_STEPS`]), `range` in `(0, 10⁶]` ([`MAX_RANGE`]); NaN never passes.
    pub fn validate(&self) -> Result<(), BuildError> {
        if self.batch_size == Some(0) {
            return Err(BuildError::Parameter {
                name: "batch_size",
                value: 0.0,
                requirement: "it must be at least 1",
            });
        }
        if let Some(growth) = self.batch_growth
            && !(0.0..=1.0).contains(&growth)
        {
            return Err(BuildError::Parameter {
                name: "batch_growth",
                value: growth,
                requirement: "it must lie in [0, 1] (a fraction of the graph's vertices)",
            });
        }
        if let Some(fraction) = self.solution_samples
            && !(0.0..=1.0).contains(&fraction)
        {
            return Err(BuildError::Parameter {
                name: "solution_samples",
                value: fraction,
                requirement: "it must lie in [0, 1] (a fraction of each batch)",
            });
        }
        if !(0.0..=1.0).contains(&self.solution_corner_weights) {
            return Err(BuildError::Parameter {
                name: "solution_corner_weights",
                value: self.solution_corner_weights,
                requirement: "it must lie in [0, 1] (a share of the states placed along the path)",
            });
        }
        if let Some(cap) = self.neighbour_cap
            && !(1.0..=1e6).contains(&cap)
        {
            return Err(BuildError::Parameter {
                name: "neighbour_cap",
                value: cap,
                requirement: "it must lie in [1, 10⁶] (a multiple of the k-nearest rule's k)",
            });
        }
        if self.eis_batch_size == Some(0) {
            return Err(BuildError::Parameter {
                name: "eis_batch_size",
                value: 0.0,
                requirement: "it must be at least 1",
            });
        }
        if let Some(range) = self.range {
            within(
                "range",
                range,
                MAX_RANGE,
                "it must lie in (0, 1e6] (`MAX_RANGE`)",
            )?;
        }
        if self.certification == Some(0) {
            return Err(BuildError::Parameter {
                name: "certification",
                value: 0.0,
                requirement: "it must be at least 1 (1: no certification)",
            });
        }
        if let Some(fraction) = self.near_terminals
            && !(0.0..1.0).contains(&fraction)
        {
            return Err(BuildError::Parameter {
                name: "near_terminals",
                value: fraction,
                requirement: "it must lie in [0, 1)",
            });
        }
        if self.bridge_checks == Some(0) {
            return Err(BuildError::Parameter {
                name: "bridge_checks",
                value: 0.0,
                requirement: "it must be at least 1",
            });
        }
        let rewire = "it must lie in (0, 100] (`MAX_REWIRE_FACTOR`; about 1 is the theory's)";
        within(
            "rewire_factor",
            self.rewire_factor,
            MAX_REWIRE_FACTOR,
            rewire,
        )?;
        within(
            "rrt_rewire_factor",
            self.rrt_rewire_factor,
            MAX_REWIRE_FACTOR,
            rewire,
        )?;
        if !(0.0..=1.0).contains(&self.goal_bias) {
            return Err(BuildError::Parameter {
                name: "goal_bias",
                value: self.goal_bias,
                requirement: "it must lie in [0, 1] (a probability)",
            });
        }
        if let Some(inflation) = self.initial_inflation
            && !(inflation.is_finite() && inflation >= 1.0)
        {
            return Err(BuildError::Parameter {
                name: "initial_inflation",
                value: inflation,
                requirement: "it must be finite and at least 1",
            });
        }
        for (name, value) in [
            ("inflation_scaling", self.inflation_scaling),
            ("truncation_scaling", self.truncation_scaling),
        ] {
            if let Some(v) = value
                && !(v.is_finite() && v >= 0.0)
            {
                return Err(BuildError::Parameter {
                    name,
                    value: v,
                    requirement: "it must be finite and non-negative",
                });
            }
        }
        if !(self.resolution > 0.0 && self.resolution < 1.0) {
            return Err(BuildError::Parameter {
                name: "resolution",
                value: self.resolution,
                requirement: "it must lie strictly between 0 and 1 (a fraction of the maximum extent)",
            });
        }
        within(
            "gaussian_std_fraction",
            self.gaussian_std_fraction,
            MAX_GAUSSIAN_STD_FRACTION,
            "it must lie in (0, 10] (`MAX_GAUSSIAN_STD_FRACTION`: maximum extents)",
        )?;
        let steps_rule = "it must lie in (0, 1e9] steps (`MAX_SPARSE_STEPS`)";
        if let Some(steps) = self.sparse_initial_steps {
            within("sparse_initial_steps", steps, MAX_SPARSE_STEPS, steps_rule)?;
        }
        if let Some(steps) = self.sparse_min_steps {
            within("sparse_min_steps", steps, MAX_SPARSE_STEPS, steps_rule)?;
        }
        if !(self.sparse_factor > 0.0 && self.sparse_factor < 1.0) {
            return Err(BuildError::Parameter {
                name: "sparse_factor",
                value: self.sparse_factor,
                requirement: "the refinement factor Ω must lie in (0, 1)",
            });
        }
        Ok(())
    }

    /// The parameters as `(name, value)` text pairs, for benchmark logs (OMPL's "common
    /// properties").
    pub fn settings(&self) -> Vec<(String, String)> {
        let connection = match self.connection {
            Some(Connection::KNearest) => "k-nearest",
            Some(Connection::RDisc) => "r-disc",
            None => "problem's",
        };
        let form = match self.eis_expansion_form {
            EisExpansionForm::Paper => "paper",
            EisExpansionForm::Authors => "authors",
        };
        let rule = match self.eis_expansion_rule {
            EisExpansionRule::PerBatch => "per-batch",
            EisExpansionRule::PerInvalidEdge => "per-invalid-edge",
        };
        [
            (
                "batch_size",
                self.batch_size
                    .map_or_else(|| "problem's".to_owned(), |b| b.to_string()),
            ),
            (
                "batch_growth",
                self.batch_growth
                    .map_or_else(|| "problem's".to_owned(), |g| g.to_string()),
            ),
            (
                "solution_samples",
                self.solution_samples
                    .map_or_else(|| "problem's".to_owned(), |f| f.to_string()),
            ),
            (
                "solution_corner_pulls",
                self.solution_corner_pulls.to_string(),
            ),
            (
                "solution_corner_weights",
                self.solution_corner_weights.to_string(),
            ),
            ("rewire_factor", self.rewire_factor.to_string()),
            ("connection", connection.to_string()),
            (
                "neighbour_cap",
                self.neighbour_cap
                    .map_or_else(|| "none".to_owned(), |c| c.to_string()),
            ),
            ("pruning", self.pruning.to_string()),
            ("resolution", self.resolution.to_string()),
            ("seed", self.seed.to_string()),
            (
                "suspend_reverse_when_forward_empty",
                self.suspend_reverse_when_forward_empty
                    .map_or_else(|| "planner's".to_owned(), |v| v.to_string()),
            ),
            (
                "repair_reverse_search",
                self.repair_reverse_search
                    .map_or_else(|| "problem's".to_owned(), |v| v.to_string()),
            ),
            (
                "gaussian_std_fraction",
                self.gaussian_std_fraction.to_string(),
            ),
            (
                "bridge_checks",
                self.bridge_checks
                    .map_or_else(|| "problem's".to_owned(), |b| b.to_string()),
            ),
            (
                "sparse_initial_steps",
                self.sparse_initial_steps
                    .map_or_else(|| "problem's".to_owned(), |s| s.to_string()),
            ),
            ("sparse_factor", self.sparse_factor.to_string()),
            (
                "sparse_min_steps",
                self.sparse_min_steps
                    .map_or_else(|| "problem's".to_owned(), |s| s.to_string()),
            ),
            ("eis_expansion_form", form.to_string()),
            ("eis_expansion_rule", rule.to_string()),
            (
                "eis_batch_size",
                self.eis_batch_size
                    .map_or_else(|| "batch_size".to_owned(), |b| b.to_string()),
            ),
            ("eis_immediate_batch", self.eis_immediate_batch.to_string()),
            (
                "range",
                self.range
                    .map_or_else(|| "default".to_owned(), |r| r.to_string()),
            ),
            (
                "certification",
                self.certification
                    .map_or_else(|| "problem's".to_owned(), |k| k.to_string()),
            ),
            ("lazy_certification", self.lazy_certification.to_string()),
            (
                "near_terminals",
                self.near_terminals
                    .map_or_else(|| "problem's".to_owned(), |f| f.to_string()),
            ),
            ("near_frontier", self.near_frontier.to_string()),
            ("frontier_rays", self.frontier_rays.to_string()),
            ("start_frontier", self.start_frontier.to_string()),
            ("validated_frontier", self.validated_frontier.to_string()),
            ("accelerated_checks", self.accelerated_checks.to_string()),
            ("rrt_valid_samples", self.rrt_valid_samples.to_string()),
            ("rrt_dynamic_domain", self.rrt_dynamic_domain.to_string()),
            ("rrt_forced_redraws", self.rrt_forced_redraws.to_string()),
            ("rrt_balance", self.rrt_balance.to_string()),
            ("rrt_halton", self.rrt_halton.to_string()),
            ("rrt_halton_shift", self.rrt_halton_shift.to_string()),
            ("simplify_solutions", self.simplify_solutions.to_string()),
            ("simplify_smoothing", self.simplify_smoothing.to_string()),
            ("warm_start", self.warm_start.to_string()),
            ("aorrtc_simplify", self.aorrtc_simplify.to_string()),
            ("polish_when_idle", self.polish_when_idle.to_string()),
            ("aorrtc_resamples", self.aorrtc_resamples.to_string()),
            ("goal_bias", self.goal_bias.to_string()),
            ("rrt_rewire_factor", self.rrt_rewire_factor.to_string()),
            (
                "initial_inflation",
                self.initial_inflation
                    .map_or_else(|| "planner's".to_owned(), |v| v.to_string()),
            ),
            (
                "inflation_scaling",
                self.inflation_scaling
                    .map_or_else(|| "planner's".to_owned(), |v| v.to_string()),
            ),
            (
                "truncation_scaling",
                self.truncation_scaling
                    .map_or_else(|| "planner's".to_owned(), |v| v.to_string()),
            ),
            (
                "cascading_rewirings",
                self.cascading_rewirings
                    .map_or_else(|| "planner's".to_owned(), |v| v.to_string()),
            ),
        ]
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect()
    }
}

/// `k = ⌈η · e · (1 + 1/n) · ln q⌉` for `q` samples in `n` dimensions (at least 1). Unlike
/// OMPL, `e · (1 + 1/n)` is not truncated to an integer.
///
/// ```
/// // q = 100 samples in R^4 with η = 1.001: ⌈1.001 · e · 1.25 · ln 100⌉ = 16.
/// assert_eq!(mit_star::k_nearest(100, 4, 1.001), 16);
/// ```
pub fn k_nearest(q: usize, n: usize, eta: f64) -> usize {
    // Never far more neighbours than vertices: a huge `η` connects everything, it does not
    // overflow the neighbour lists (the floor of 64 keeps the formula's value for small `q`).
    let count = q.max(2);
    let cap = count.max(64);
    let q = count as f64;
    let n = n.max(1) as f64;
    let k = (eta * std::f64::consts::E * (1.0 + 1.0 / n) * q.ln()).ceil();
    if k.is_finite() {
        (k as usize).clamp(1, cap)
    } else {
        1
    }
}

/// `r = η · 2 · ((1 + 1/n) · λ / ζ_n · ln q / q)^(1/n)` (Karaman and Frazzoli's PRM* radius as
/// OMPL codes it, spec §3.4), `λ` the measure of the sampled set.
///
/// ```
/// let r = mit_star::r_disc(1000, 2, 1.0, 1.0);
/// let expected = 2.0 * (1.5 / std::f64::consts::PI * (1000f64).ln() / 1000.0).sqrt();
/// assert!((r - expected).abs() < 1e-12);
/// ```
pub fn r_disc(q: usize, n: usize, eta: f64, measure: f64) -> f64 {
    let q = (q.max(2)) as f64;
    let nf = n.max(1) as f64;
    let zeta = mit_star_spaces::unit_ball_measure(n.max(1));
    eta * 2.0 * ((1.0 + 1.0 / nf) * measure / zeta * q.ln() / q).powf(1.0 / nf)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_bad_parameter_is_named() {
        let cases: [(Parameters, &str); 7] = [
            (
                Parameters {
                    rewire_factor: 0.0,
                    ..Default::default()
                },
                "rewire_factor",
            ),
            (
                Parameters {
                    rewire_factor: f64::NAN,
                    ..Default::default()
                },
                "rewire_factor",
            ),
            (
                Parameters {
                    resolution: -1.0,
                    ..Default::default()
                },
                "resolution",
            ),
            (
                Parameters {
                    gaussian_std_fraction: 0.0,
                    ..Default::default()
                },
                "gaussian_std_fraction",
            ),
            (
                Parameters {
                    sparse_factor: 1.0,
                    ..Default::default()
                },
                "sparse_factor",
            ),
            (
                Parameters {
                    sparse_min_steps: Some(f64::INFINITY),
                    ..Default::default()
                },
                "sparse_min_steps",
            ),
            (
                Parameters {
                    bridge_checks: Some(0),
                    ..Default::default()
                },
                "bridge_checks",
            ),
        ];
        for (p, name) in cases {
            match p.validate() {
                Err(BuildError::Parameter { name: got, .. }) => assert_eq!(got, name),
                other => panic!("{name}: {other:?}"),
            }
        }
    }

    #[test]
    fn connection_formulas() {
        // ln 2 · e · 1.5 · 1.001 = 2.83 → 3 (OMPL would truncate e·1.5 to 4 → 3 as well).
        assert_eq!(k_nearest(2, 2, 1.001), 3);
        assert!(k_nearest(10_000, 8, 1.001) > k_nearest(100, 8, 1.001));
        // The radius shrinks as samples accumulate and grows with the measure.
        assert!(r_disc(1000, 4, 1.001, 1.0) < r_disc(100, 4, 1.001, 1.0));
        assert!(r_disc(100, 4, 1.001, 2.0) > r_disc(100, 4, 1.001, 1.0));
        // Unset, the rule is the problem's; set, it is named.
        let shown = |connection| {
            Parameters {
                connection,
                ..Parameters::default()
            }
            .settings()
            .into_iter()
            .find(|(k, _)| k == "connection")
            .map(|(_, v)| v)
        };
        assert_eq!(shown(None).as_deref(), Some("problem's"));
        assert_eq!(
            shown(Some(Connection::KNearest)).as_deref(),
            Some("k-nearest")
        );
        assert_eq!(shown(Some(Connection::RDisc)).as_deref(), Some("r-disc"));
    }
}
