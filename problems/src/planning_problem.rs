//! [`PlanningProblem`]: what every planner needs from a problem, whatever its space and world.

use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;

use crate::{Problem, ProblemError};

/// A motion-planning query with everything a planner needs to answer it: the state space, the
/// validity checker, the start, the goals, and the collision-check resolution.
///
/// Implemented by the box-world benchmark [`Problem`] (a point in `R^n` among axis-aligned
/// boxes) and by robot-arm problems (the `robot` crate's `ArmProblem`: a joint space and a
/// sphere-model collision checker). Planner builders and the experiment harness accept any
/// implementation, so every planner plans for every kind of problem through one front door.
///
/// ```
/// use mit_star_problems::PlanningProblem;
/// use mit_star_spaces::StateSpace;
/// fn describe<P: PlanningProblem>(p: &P) -> String {
///     let step = p.check_step().unwrap();
///     format!("{}: {} dimensions, step {step}", p.name(), p.space().dimension())
/// }
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-3)?;
/// assert!(describe(&problem).starts_with("dividing-walls: 2 dimensions"));
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
pub trait PlanningProblem {
    /// The configuration space.
    type Space: StateSpace + Clone + Send + 'static;
    /// The state validity checker.
    type Validity: StateValidity + Clone + Send + 'static;

    /// A short name for logs and outputs.
    fn name(&self) -> &str;

    /// The configuration space.
    fn space(&self) -> &Self::Space;

    /// The state validity checker.
    fn validity(&self) -> &Self::Validity;

    /// The start state.
    fn start(&self) -> &[f64];

    /// The goal states.
    fn goals(&self) -> &[Vec<f64>];

    /// The collision-check resolution, a fraction of the space's maximum extent (OMPL's
    /// convention): edges are checked every `resolution × maximum_extent`.
    fn resolution(&self) -> f64;

    /// The collision-check step `resolution × maximum_extent`, or an error if the problem knows
    /// that this step would miss obstacles (a box world whose thinnest box is thinner than the
    /// step, see [`Problem::check_step`]).
    ///
    /// # Errors
    /// [`ProblemError::StepTooCoarse`] (box worlds) or the problem's own refusal.
    fn check_step(&self) -> Result<f64, ProblemError> {
        Ok(self.resolution() * self.space().maximum_extent())
    }

    /// How many times finer than the check step a planner should certify the edges of its
    /// solution tree (1: not at all). A problem whose contacts can fall between grid points
    /// (an arm's spheres grazing a corner, a segment clipping a box's corner) asks for more.
    /// A validity checker that decides segments exactly (a box world) certifies exactly
    /// whatever the factor (`mit_star_validity::GridWalker::certify`).
    fn certification(&self) -> u32 {
        1
    }

    /// Whether planners may check this problem's edges with certification `factor` (the
    /// value a planner will use, after its parameters): a problem whose grid cannot be trusted
    /// refuses `1` unless told otherwise. Called once, when a planner is built.
    ///
    /// # Errors
    /// [`ProblemError::Uncertified`] (arms) or the problem's own refusal.
    fn check_certification(&self, factor: u32) -> Result<(), ProblemError> {
        let _ = factor;
        Ok(())
    }

    /// The fraction of samples a planner of the EIT* family should draw near the start and the
    /// goals (0: none, the paper's sampling). A problem whose terminals sit deep in pockets (an
    /// arm's grasp in a shelf slot) asks for some.
    fn near_terminals(&self) -> f64 {
        0.0
    }

    /// Whether planners with a lazy reverse search (MIT*, EIT*, AIT*) should repair it in
    /// place when the forward search finds one of its edges invalid, instead of restarting it
    /// from the goals (false: the paper's rule). A problem whose lazy paths fail often and far
    /// from the goals (an arm in a cage) asks for repairs.
    fn repair_reverse_search(&self) -> bool {
        false
    }

    /// The initial spacing `Δ₀` and the finest spacing of MIT*'s length-related sparse checks,
    /// in check steps `L` ([`PAPER_SPARSE_SPACING`], the MIT* authors' constants, by default).
    /// A sparse check tests an edge every `Δ` (at least its midpoint), so these decide how
    /// much of an edge the lazy reverse search sees before the forward search checks it fully.
    /// A problem whose edges are only tens of steps long (an arm: 16 steps per radian) and
    /// mostly invalid asks for denser checks, which the authors' 2000 and 10 would reduce to
    /// one or two points per edge.
    fn sparse_spacing(&self) -> (f64, f64) {
        PAPER_SPARSE_SPACING
    }

    /// Whether planners of the EIT* family should join each sample to every sample within the
    /// r-disc radius rather than to its k nearest (false: k-nearest, the paper's and OMPL's
    /// default). Both rules keep the planners asymptotically optimal; in 7 or 8 dimensions the
    /// radius gives each state many more neighbours than `k = η e (1 + 1/n) ln q` (its constant
    /// grows as `2ⁿ`), which a lazy search with denser sparse checks turns into shorter paths
    /// sooner; a problem whose lazy edges are cheap to test (an arm) asks for it.
    fn radius_connection(&self) -> bool {
        false
    }

    /// Samples per batch for planners of the EIT* family ([`PAPER_BATCH_SIZE`] by default).
    /// A batch ends with both searches restarted over the whole graph, so a problem most of
    /// whose queries the first few dozen samples solve (an arm in a MotionBenchMaker scene)
    /// reaches its first path sooner with smaller batches.
    fn batch_size(&self) -> usize {
        PAPER_BATCH_SIZE
    }

    /// The fraction of the graph's vertices below which a batch of the EIT* family does not
    /// fall (0 by default: every batch holds [`batch_size`](Self::batch_size) samples, as in
    /// the papers). Each batch restarts the searches over the whole graph, so on a query that
    /// fixed batches leave unsolved for tens of thousands of samples the restarts cost a number
    /// of passes over the graph that grows with it; batches growing with the graph bound that
    /// number, and a problem whose hard queries run so long (an arm) asks for them.
    fn batch_growth(&self) -> f64 {
        0.0
    }

    /// Segment points MIT*'s adaptive sampler tests per repair, between an invalid draw and its
    /// invalid Gaussian partner ([`DEFAULT_BRIDGE_CHECKS`] by default, the planner spec's 8; the
    /// paper gives no number). Where most repairs that find a state find it among the first
    /// points of the bisection order, a smaller budget makes the failing ones cheaper and
    /// changes only the few that would have found theirs further along (an arm asks for 4).
    fn bridge_checks(&self) -> usize {
        DEFAULT_BRIDGE_CHECKS
    }

    /// The fraction of each batch a planner of the EIT* family draws along its best path once
    /// it has one (0 by default: every sample from the sampler, as in the papers). In many
    /// dimensions uniform samples seldom fall where the path could be straightened, so a
    /// problem that wants short paths soon (an arm) asks for some.
    fn solution_samples(&self) -> f64 {
        0.0
    }

    /// The extension range RRT-Connect, AORRTC and Informed RRT* should step by when none is
    /// set (`None`, the default: the planners' own rule, `mit_star::default_range`). A robot
    /// arm's was measured per robot, as VAMP sets one per robot: the joint-space diagonal's
    /// fifth that the planners' rule takes is several radians for joints of a turn or more.
    fn default_range(&self) -> Option<f64> {
        None
    }
}

/// Segment points MIT*'s adaptive sampler tests per repair unless a problem asks for another
/// number ([`PlanningProblem::bridge_checks`]'s default): 8, the planner spec's choice where the
/// paper gives none.
pub const DEFAULT_BRIDGE_CHECKS: usize = 8;

/// The batch size of the MIT* and EIT* papers' experiments, 100 samples
/// ([`PlanningProblem::batch_size`]'s default).
pub const PAPER_BATCH_SIZE: usize = 100;

/// The MIT* authors' sparse spacing, in check steps `L`: `Δ₀ = 2000 L`, never finer than
/// `10 L` ([`PlanningProblem::sparse_spacing`]'s default).
pub const PAPER_SPARSE_SPACING: (f64, f64) = (2000.0, 10.0);

impl PlanningProblem for Problem {
    type Space = mit_star_spaces::RealVectorSpace;
    type Validity = mit_star_validity::World;

    fn name(&self) -> &str {
        Problem::name(self)
    }

    fn space(&self) -> &Self::Space {
        Problem::space(self)
    }

    fn validity(&self) -> &Self::Validity {
        self.world()
    }

    fn start(&self) -> &[f64] {
        Problem::start(self)
    }

    fn goals(&self) -> &[Vec<f64>] {
        Problem::goals(self)
    }

    fn resolution(&self) -> f64 {
        Problem::resolution(self)
    }

    fn check_step(&self) -> Result<f64, ProblemError> {
        Problem::check_step(self)?;
        Ok(Problem::resolution(self) * Problem::space(self).maximum_extent())
    }

    /// 2: edges joining a solution tree are certified — exactly, by the world's slab tests —
    /// so no planner returns a path that clips a box's corner between two grid points (a
    /// validity checker without segment tests walks a grid twice as fine instead).
    fn certification(&self) -> u32 {
        2
    }
}

impl<P: PlanningProblem + ?Sized> PlanningProblem for &P {
    type Space = P::Space;
    type Validity = P::Validity;

    fn name(&self) -> &str {
        (**self).name()
    }
    fn space(&self) -> &Self::Space {
        (**self).space()
    }
    fn validity(&self) -> &Self::Validity {
        (**self).validity()
    }
    fn start(&self) -> &[f64] {
        (**self).start()
    }
    fn goals(&self) -> &[Vec<f64>] {
        (**self).goals()
    }
    fn resolution(&self) -> f64 {
        (**self).resolution()
    }
    fn check_step(&self) -> Result<f64, ProblemError> {
        (**self).check_step()
    }
    fn certification(&self) -> u32 {
        (**self).certification()
    }
    fn near_terminals(&self) -> f64 {
        (**self).near_terminals()
    }
    fn repair_reverse_search(&self) -> bool {
        (**self).repair_reverse_search()
    }
    fn sparse_spacing(&self) -> (f64, f64) {
        (**self).sparse_spacing()
    }
    fn radius_connection(&self) -> bool {
        (**self).radius_connection()
    }
    fn batch_size(&self) -> usize {
        (**self).batch_size()
    }
    fn batch_growth(&self) -> f64 {
        (**self).batch_growth()
    }
    fn solution_samples(&self) -> f64 {
        (**self).solution_samples()
    }
    fn bridge_checks(&self) -> usize {
        (**self).bridge_checks()
    }
}
