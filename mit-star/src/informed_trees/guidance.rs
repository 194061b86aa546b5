//! [`Guidance`]: how the forward search of the [`Eit`](crate::Eit) skeleton is led to the
//! goals — the part that tells EIT*, AIT* and BIT* apart.

use std::marker::PhantomData;

/// What the reverse search from the goals does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReverseSearch {
    /// EIT*: a lazy search over the graph that sparse-checks every edge it uses and computes
    /// cost-to-go bounds, estimates and the effort (state checks) to the goals.
    SparseChecked,
    /// AIT*: a lazy search over the graph that checks no edge (only edges the forward search
    /// found invalid are left out) and computes cost-to-go bounds.
    Unchecked,
    /// BIT*: no reverse search; the forward search is guided by the a-priori heuristic `ĥ`.
    None,
}

/// How the forward search is guided: a type parameter of [`Eit`](crate::Eit), so EIT*, AIT*
/// and BIT* are one skeleton — one random geometric graph, one forward queue, one reverse
/// search, one batch and pruning step — with different parts.
///
/// | type | reverse search | forward order before the first solution | paper |
/// |---|---|---|---|
/// | [`EffortInformed`] | [`SparseChecked`](ReverseSearch::SparseChecked) | least effort | EIT* |
/// | [`Suspending`]`<EffortInformed>` | as EIT*, yielding while the forward queue is empty | least effort | MIT* |
/// | [`CostInformed`] | [`Unchecked`](ReverseSearch::Unchecked) | least cost estimate | AIT* |
/// | [`APriori`] | [`None`](ReverseSearch::None) | least (inflated) cost estimate | BIT*, ABIT* |
///
/// After the first solution every guidance orders the forward queue by cost (A*); BIT*-family
/// searches may inflate the heuristic in that order and truncate a batch's search
/// ([`Parameters::initial_inflation`](crate::Parameters), `inflation_scaling`,
/// `truncation_scaling`: ABIT*).
pub trait Guidance: 'static {
    /// What the reverse search does.
    const REVERSE: ReverseSearch;
    /// Before the first solution, expand the edge with the least estimated effort (EIT*'s
    /// `ε = ∞` front) rather than the least cost estimate.
    const EFFORT_FIRST: bool;
    /// The reverse search yields to the forward search while the forward queue is empty,
    /// instead of exhausting its own queue (spec §3.2). The parameter
    /// [`suspend_reverse_when_forward_empty`](crate::Parameters) overrides it.
    const SUSPEND_WHEN_FORWARD_EMPTY: bool;

    /// Short name used in planner names (`"effort-informed"`, …).
    fn name() -> String;
}

/// EIT*'s guidance (Strub and Gammell, IJRR 2022): a sparse-checked reverse search supplies
/// cost and effort heuristics; effort-greedy until the first solution. MIT* wraps it in
/// [`Suspending`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct EffortInformed;

impl Guidance for EffortInformed {
    const REVERSE: ReverseSearch = ReverseSearch::SparseChecked;
    const EFFORT_FIRST: bool = true;
    const SUSPEND_WHEN_FORWARD_EMPTY: bool = false;

    fn name() -> String {
        "effort-informed".into()
    }
}

/// AIT*'s guidance (Strub and Gammell, ICRA 2020 / IJRR 2022): an unchecked lazy reverse search
/// supplies an adaptive cost-to-go heuristic; the forward search is A* on it throughout. When
/// the forward search finds an edge of the reverse tree invalid, the reverse search restarts
/// from the goals (OMPL's AIT* with `repair_reverse_search = false`). OMPL's default repairs
/// only the branch below that edge, LPA*-style; here that is the parameter
/// [`repair_reverse_search`](crate::Parameters), off by default on the paper's problems because
/// it led our AIT* to check more edges there (`docs/guide/src/reference/faithfulness-map.md`
/// §6), on for arms, where the problem asks for it.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CostInformed;

impl Guidance for CostInformed {
    const REVERSE: ReverseSearch = ReverseSearch::Unchecked;
    const EFFORT_FIRST: bool = false;
    const SUSPEND_WHEN_FORWARD_EMPTY: bool = true;

    fn name() -> String {
        "cost-informed".into()
    }
}

/// BIT*'s guidance (Gammell, Barfoot and Srinivasa, IJRR 2020): no reverse search; edges are
/// ordered by `g(u) + ĉ(u,v) + ε·ĥ(v)` with the a-priori heuristic `ĥ`. With the default
/// parameters `ε = 1` (BIT*); ABIT*'s inflation and truncation factors (Strub and Gammell, ICRA
/// 2020) are parameters of the same planner type.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct APriori;

impl Guidance for APriori {
    const REVERSE: ReverseSearch = ReverseSearch::None;
    const EFFORT_FIRST: bool = false;
    const SUSPEND_WHEN_FORWARD_EMPTY: bool = false;

    fn name() -> String {
        "a-priori".into()
    }
}

/// The MIT* authors' suspension rule around another guidance: the reverse search also yields
/// while the forward queue is empty (spec §3.2). Upstream EIT* exhausts the reverse queue
/// instead; MIT* keeps the rule, so `Suspending<EffortInformed>` is MIT*'s guidance and
/// removing the wrapper is the ablation ([`MitStarSr`](crate::MitStarSr) is EIT* with only
/// this part).
///
/// ```
/// use mit_star::{EffortInformed, Guidance, Suspending};
/// assert!(!EffortInformed::SUSPEND_WHEN_FORWARD_EMPTY);
/// assert!(Suspending::<EffortInformed>::SUSPEND_WHEN_FORWARD_EMPTY);
/// assert_eq!(Suspending::<EffortInformed>::name(), "effort-informed+suspending");
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Suspending<G = EffortInformed>(PhantomData<G>);

impl<G: Guidance> Guidance for Suspending<G> {
    const REVERSE: ReverseSearch = G::REVERSE;
    const EFFORT_FIRST: bool = G::EFFORT_FIRST;
    const SUSPEND_WHEN_FORWARD_EMPTY: bool = true;

    fn name() -> String {
        format!("{}+suspending", G::name())
    }
}
