//! [`Snapshot`]: a read-only copy of a planner's samples, trees and cost bounds, for pictures
//! of runs and for inspection.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, States};
use mit_star_validity::{Counted, EdgeChecker, StateValidity};
use petgraph::visit::NodeIndexable;

use crate::graph::NONE;
use crate::informed_trees::Guidance;
use crate::informed_trees::NeighbourRule;
use crate::{Eit, VertexKind};

/// A copy of what a planner holds at one moment: every vertex of its graph, the forward tree,
/// the reverse tree of the current reverse search, the best solution, and the cost bounds its
/// sampler works under (the informed set of `c_best`, MIT*'s estimated informed set).
///
/// Made for pictures of 2-D runs (the `mit-star plan` command draws one) and for tests. Taking
/// one copies every vertex state: `O(vertices · n)` time and memory. Obtain it through
/// [`Planner::snapshot`](crate::Planner::snapshot), which works on `Box<dyn Planner>` too.
///
/// ```
/// use mit_star::{EitStar, IterationLimit, Planner};
/// let problem = mit_star_problems::ObstacleFree::new(2).build()?;
/// let mut planner = EitStar::for_problem(&problem).seed(1).build()?;
/// planner.solve(&IterationLimit::new(200))?;
/// let snapshot = planner.snapshot().expect("EIT* offers snapshots");
/// assert_eq!(snapshot.states.len(), snapshot.kinds.len());
/// // The straight line is free: the solution is start → goal.
/// assert_eq!(snapshot.solution.len(), 2);
/// assert!((snapshot.best_cost - problem.straight_line_cost()).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Every vertex's state (start, goals and samples), in the order of `kinds`.
    pub states: States,
    /// What each vertex stands for.
    pub kinds: Vec<VertexKind>,
    /// Which step of the sampler produced each vertex (the adaptive sampler's branches).
    pub origins: Vec<mit_star_samplers::SampleOrigin>,
    /// Forward-tree edges as `(parent, child)` indices into `states`.
    pub forward_edges: Vec<(usize, usize)>,
    /// Edges of the current reverse tree as `(parent, child)` indices into `states`; the parent
    /// is the vertex nearer to a goal.
    pub reverse_edges: Vec<(usize, usize)>,
    /// The best solution's vertices as indices into `states`, start first (empty without one).
    pub solution: Vec<usize>,
    /// Cost of the best solution (`∞` if none): the cost of the informed set.
    pub best_cost: f64,
    /// The cost `s̃_est` of MIT*'s estimated informed set, if the sampler has one.
    pub estimated_informed_cost: Option<f64>,
}

impl<S, V, Smp, E, H, G, N> Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule,
{
    /// A [`Snapshot`] of the planner's graph, trees and cost bounds.
    pub fn graph_snapshot(&self) -> Snapshot {
        let graph = &self.graph;
        let dimension = self.space.dimension();
        // Vertex ids may have holes (pruned vertices): map ids to dense positions.
        let mut position = vec![NONE as usize; graph.graph.node_bound()];
        let mut states = States::with_capacity(dimension, graph.vertex_count());
        let mut kinds = Vec::with_capacity(graph.vertex_count());
        let mut origins = Vec::with_capacity(graph.vertex_count());
        for (i, (id, state)) in graph.vertices().enumerate() {
            position[id.index()] = i;
            states.push(state);
            kinds.push(graph.kind(id).unwrap_or(VertexKind::Sample));
            origins.push(graph.origin(id));
        }
        let at = |id: u32| {
            position
                .get(id as usize)
                .copied()
                .filter(|&p| p != NONE as usize)
        };
        let forward_edges = graph
            .forward_edges()
            .filter_map(|(parent, child)| Some((at(parent.0)?, at(child.0)?)))
            .collect();
        let tag = self.reverse_tag;
        let reverse_edges = graph
            .vertices()
            .filter_map(|(id, _)| {
                let parent = graph.vertex(id.0).reverse_parent(tag);
                (parent != NONE).then_some((parent, id.0))
            })
            .filter_map(|(parent, child)| Some((at(parent)?, at(child)?)))
            .collect();
        let solution = self
            .solution_vertices()
            .into_iter()
            .filter_map(|v| at(v.0))
            .collect();
        Snapshot {
            states,
            kinds,
            origins,
            forward_edges,
            reverse_edges,
            solution,
            best_cost: self.best_cost,
            estimated_informed_cost: self.sampler.estimated_cost(),
        }
    }
}
