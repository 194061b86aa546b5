//! [`RandomGeometricGraph`]: the planner's samples, their neighbourhoods and the edges it has
//! touched, on a petgraph [`StableGraph`].

use std::collections::HashMap;

use mit_star_validity::{EdgeGrid, EdgeProgress, EdgeStatus};
use petgraph::Undirected;
use petgraph::graph::NodeIndex;
use petgraph::stable_graph::StableGraph;

use crate::graph::edge_hasher::{BuildEdgeHasher, edge_key};
use crate::graph::neighbour_cache::MERGE_LIMIT;
use crate::graph::outside_tree::OutsideTree;
use crate::graph::recent_states::RecentStates;
use crate::graph::state_chunks::StateChunks;
use crate::graph::vertex::{NONE, Vertex, VertexId, VertexKind};
use crate::nearest::{Alive, Chunked, NearestNeighbors, Neighbours};

/// The key of the undirected edge `u — v`.
#[inline]
fn pair(u: u32, v: u32) -> u64 {
    edge_key(u.min(v), u.max(v))
}

/// What the planner knows about an edge it has checked (the value of a stored edge in the
/// graph's edge index).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct EdgeRecord {
    /// Grid points tested so far, or "invalid".
    pub(crate) progress: EdgeProgress,
    /// Whitelisted (`Valid`), blacklisted (`Invalid`) or not yet decided.
    pub(crate) status: EdgeStatus,
    /// Certified on the finer grid ([`Parameters::certification`](crate::Parameters)).
    pub(crate) certified: bool,
}

/// One cached neighbour of a vertex: who (id and birth stamp, so a pruned or reused id is
/// recognised), the admissible edge cost `ĉ`, and the metric distance (which sizes the edge's
/// check grid and orders the list).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Neighbour {
    pub(crate) id: u32,
    pub(crate) birth: u32,
    pub(crate) cost: f64,
    pub(crate) distance: f64,
}

/// How vertices are connected in the current batch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Neighbourhood {
    /// The `k` nearest vertices.
    Nearest(usize),
    /// Every vertex within the radius.
    Radius(f64),
}

/// Birth stamp of a removed vertex.
pub(crate) const DEAD: u32 = u32::MAX;

/// The random geometric graph (RGG) over every sample the planner keeps.
///
/// Vertices are the samples, the start and the goals: nodes of a petgraph [`StableGraph`] (so
/// ids stay valid when pruning removes vertices), whose states and search data live beside it
/// in arrays indexed by vertex id, in fixed-size chunks so that growing the graph never copies
/// them (an unbounded copy is a deadline missed). The graph is implicit: a
/// vertex's neighbours — its `k` nearest vertices or those within a radius, found with
/// [`NearestNeighbors`] — are computed when it is first expanded and cached with their `ĉ` and
/// distance; in later batches the cached list is brought up to date by dropping pruned vertices
/// and merging in the samples added since (exactly the list a fresh query would give). Only
/// edges the planner has checked are stored: as petgraph edges, so that removing a vertex finds
/// its edges, and with their checking progress and white/black status in a hash index keyed
/// by the vertex pair, so that a lookup touches one table entry.
///
/// The planner owns one; [`Eit::graph`](crate::Eit::graph) exposes it read-only for inspection
/// (tests, plots).
#[derive(Debug, Clone)]
pub struct RandomGeometricGraph {
    pub(crate) graph: StableGraph<(), (), Undirected, u32>,
    pub(crate) states: StateChunks,
    /// Search data per id (stale for ids not in use).
    vertices: Chunked<Vertex>,
    /// Birth stamp per id (`DEAD` once removed); a new vertex gets a fresh stamp.
    pub(crate) births: Chunked<u32>,
    next_birth: u32,
    /// What is known about each stored edge, by its (smaller, larger) vertex pair.
    edges: HashMap<u64, EdgeRecord, BuildEdgeHasher>,
    pub(crate) nn: NearestNeighbors,
    /// The metric is the plain Euclidean one (no scales).
    pub(crate) euclidean: bool,
    /// Neighbours come from `nn`'s kd-trees: a Euclidean metric, plain or weighted
    /// ([`StateSpace::euclidean_scales`](mit_star_spaces::StateSpace::euclidean_scales)).
    pub(crate) indexed: bool,
    /// Cached neighbour list per id, nearest first (`neighbours_len` entries used this batch).
    pub(crate) lists: Chunked<Vec<Neighbour>>,
    /// Batch tag: lists validated with another tag must be brought up to date.
    pub(crate) tag: u32,
    /// Every vertex ever committed, in order: a list covering `log[..p]` misses `log[p..]`.
    pub(crate) log: Chunked<(u32, u32)>,
    /// The states of the last [`MERGE_LIMIT`] log entries, contiguous in log order (scaled
    /// like the kd-trees' under a weighted metric).
    pub(crate) recent: RecentStates,
    /// Scratch for [`RecentStates::squared_distances`] (at most [`MERGE_LIMIT`] values).
    pub(crate) merge_distances: Vec<f64>,
    /// Scratch of `merge_added`: the new samples that enter a list, before they are merged in.
    pub(crate) merge_entries: Vec<Neighbour>,
    pub(crate) neighbourhood: Neighbourhood,
    /// Under r-disc, the most neighbours (the nearest) a vertex is joined to in a batch
    /// (`usize::MAX`: every one within the radius); with a cap, lists are kept nearest first.
    pub(crate) neighbour_cap: usize,
    pub(crate) found: Neighbours,
    /// Scratch for a fresh neighbour list (kept apart from the cached one until the query
    /// completes).
    pub(crate) scratch_list: Vec<Neighbour>,
    pub(crate) linear_queries: u64,
    /// Vertices removed so far (a list made since the last removal needs no filtering).
    pub(crate) removals: u64,
    /// The vertices the current or last pruning removes, ascending.
    pub(crate) prune_ids: Vec<u32>,
    /// The next of `prune_ids` to remove, while a pruning is interrupted.
    pub(crate) prune_next: Option<usize>,
    /// Live vertices whose states do not count toward the sampling density (drawn near the
    /// terminals: [`SampleOrigin::counts_toward_density`](mit_star_samplers::SampleOrigin)).
    clustered: usize,
    /// The vertices that may be outside the forward tree (kept for FCIT* only).
    pub(crate) outside: OutsideTree,
}

impl RandomGeometricGraph {
    /// An empty graph for the states of `space`: neighbours found with kd-trees under a
    /// Euclidean metric, plain or weighted, otherwise by a linear scan with the space's metric.
    pub(crate) fn for_space<S: mit_star_spaces::StateSpace + ?Sized>(space: &S) -> Self {
        let n = space.dimension();
        if space.is_euclidean() {
            return Self::new(n, true);
        }
        match space.euclidean_scales() {
            Some(scales) if scales.len() == n => Self {
                nn: NearestNeighbors::with_scales(scales),
                recent: RecentStates::with_scales(scales, MERGE_LIMIT),
                indexed: true,
                ..Self::new(n, false)
            },
            _ => Self::new(n, false),
        }
    }

    /// An empty graph for states of `dimension` coordinates. With `euclidean` the neighbours
    /// are found with kd-trees, otherwise by a linear scan with the space's metric.
    pub(crate) fn new(dimension: usize, euclidean: bool) -> Self {
        Self {
            graph: StableGraph::default(),
            states: StateChunks::new(dimension),
            vertices: Chunked::new(),
            births: Chunked::new(),
            next_birth: 0,
            edges: HashMap::default(),
            nn: NearestNeighbors::new(dimension),
            euclidean,
            indexed: euclidean,
            lists: Chunked::new(),
            tag: 1,
            log: Chunked::new(),
            recent: RecentStates::new(dimension, MERGE_LIMIT),
            merge_distances: Vec::with_capacity(MERGE_LIMIT),
            merge_entries: Vec::new(),
            neighbourhood: Neighbourhood::Nearest(1),
            neighbour_cap: usize::MAX,
            found: Neighbours::new(),
            scratch_list: Vec::new(),
            linear_queries: 0,
            removals: 0,
            prune_ids: Vec::new(),
            prune_next: None,
            clustered: 0,
            outside: OutsideTree::default(),
        }
    }

    /// Adds a vertex at `state` (not yet visible to neighbour queries until
    /// [`commit`](Self::commit)).
    pub(crate) fn add_vertex(&mut self, state: &[f64], vertex: Vertex) -> u32 {
        let id = self.graph.add_node(()).index();
        self.clustered += usize::from(!vertex.origin.counts_toward_density());
        if id == self.states.len() {
            self.states.push(state);
            self.vertices.push(vertex);
            self.births.push(DEAD);
            self.lists.push(Vec::new());
        } else {
            self.states[id].copy_from_slice(state);
            self.vertices[id] = vertex;
            self.lists[id].clear();
        }
        self.births[id] = self.next_birth;
        self.next_birth = self.next_birth.wrapping_add(1) % DEAD;
        id as u32
    }

    /// Makes room for `additional` more vertices, so that adding a batch does not grow arrays
    /// while it samples. Only petgraph's node array (12 bytes per vertex) still grows by
    /// copying; the per-vertex data are chunked and never move.
    pub(crate) fn reserve(&mut self, additional: usize) {
        self.graph.reserve_nodes(additional);
        self.vertices.reserve(additional);
        self.births.reserve(additional);
        self.lists.reserve(additional);
        self.log.reserve(additional);
        if self.indexed {
            self.nn.reserve_pending(additional);
        }
    }

    /// Makes `ids` visible to neighbour queries and starts a new batch.
    pub(crate) fn commit(&mut self, ids: &[u32]) {
        self.note_committed(self.log.len(), ids);
        let (states, births) = (&self.states, &self.births);
        if self.indexed {
            self.nn.insert_born(
                ids.iter()
                    .map(|&id| (id, births[id as usize], &states[id as usize])),
            );
        }
        self.log
            .extend(ids.iter().map(|&id| (id, births[id as usize])));
        // Only the tail can be read: a list missing more than MERGE_LIMIT entries is requeried.
        let tail = ids.len().saturating_sub(MERGE_LIMIT);
        self.recent.skip(tail);
        self.recent
            .extend(ids[tail..].iter().map(|&id| &states[id as usize]));
        self.new_batch();
    }

    /// Builds the committed samples waiting in the nearest-neighbour buffer into trees if the
    /// buffer is large, unless `stop` fires (then they stay in the exact linear buffer).
    pub(crate) fn index_pending(&mut self, stop: &dyn mit_star_spaces::Stop) {
        if self.indexed {
            self.nn.maintain(Alive::Current(&self.births), stop);
        }
    }

    /// Starts a new batch: cached lists must be brought up to date before use.
    pub(crate) fn new_batch(&mut self) {
        self.tag = self.tag.wrapping_add(1).max(1);
    }

    /// Sets the connection rule for the current batch.
    pub(crate) fn set_neighbourhood(&mut self, neighbourhood: Neighbourhood) {
        self.neighbourhood = neighbourhood;
    }

    /// Caps the neighbours of a vertex under r-disc at its `cap` nearest within the radius
    /// (`usize::MAX`: no cap).
    pub(crate) fn set_neighbour_cap(&mut self, cap: usize) {
        self.neighbour_cap = cap;
    }

    /// The state of vertex `v`.
    #[inline]
    pub(crate) fn state(&self, v: u32) -> &[f64] {
        &self.states[v as usize]
    }

    /// The search data of vertex `v`.
    #[inline]
    pub(crate) fn vertex(&self, v: u32) -> &Vertex {
        &self.vertices[v as usize]
    }

    /// The search data of vertex `v`, mutably.
    #[inline]
    pub(crate) fn vertex_mut(&mut self, v: u32) -> &mut Vertex {
        &mut self.vertices[v as usize]
    }

    /// Neighbour queries answered so far (full queries; incremental updates not counted).
    pub(crate) fn neighbour_queries(&self) -> u64 {
        self.nn.queries() + self.linear_queries
    }

    /// The `i`-th cached neighbour of `v`.
    #[inline]
    pub(crate) fn neighbour(&self, v: u32, i: usize) -> Neighbour {
        self.lists[v as usize][i]
    }

    /// The first `len` cached neighbours of `v`, nearest first (in no order on a complete
    /// graph).
    #[inline]
    pub(crate) fn neighbour_slice(&self, v: u32, len: usize) -> &[Neighbour] {
        &self.lists[v as usize][..len]
    }

    /// `true` if `w` is in `v`'s neighbour list of the current batch (`false` while `v` has
    /// none).
    pub(crate) fn in_neighbour_list(&self, v: u32, w: u32) -> bool {
        let x = self.vertex(v);
        x.neighbours_tag == self.tag
            && self.lists[v as usize][..x.neighbours_len as usize]
                .iter()
                .any(|n| n.id == w)
    }

    /// The `i`-th cached neighbour of `v` if it is `w` (a hint from a queued edge).
    #[inline]
    pub(crate) fn hinted(&self, v: u32, i: u32, w: u32) -> Option<Neighbour> {
        self.lists[v as usize]
            .get(i as usize)
            .filter(|n| n.id == w)
            .copied()
    }

    /// What is known about the edge `u — v`: its record if it was checked before.
    #[inline]
    pub(crate) fn edge(&self, u: u32, v: u32) -> Option<EdgeRecord> {
        self.edges.get(&pair(u, v)).copied()
    }

    /// Progress of the edge `u — v` (untested if never checked).
    #[inline]
    pub(crate) fn progress(&self, u: u32, v: u32) -> EdgeProgress {
        self.edge(u, v)
            .map_or(EdgeProgress::UNTESTED, |r| r.progress)
    }

    /// Stores what a check learned about the edge `u — v`.
    pub(crate) fn store_edge(&mut self, u: u32, v: u32, record: EdgeRecord) {
        if self.edges.insert(pair(u, v), record).is_none() {
            self.graph
                .add_edge(NodeIndex::new(u as usize), NodeIndex::new(v as usize), ());
        }
    }

    /// Removes vertex `v` and its stored edges.
    pub(crate) fn remove_vertex(&mut self, v: u32) {
        let node = NodeIndex::new(v as usize);
        let mut edges = self.graph.neighbors(node).detach();
        while let Some((_, w)) = edges.next(&self.graph) {
            self.edges.remove(&pair(v, w.index() as u32));
        }
        self.graph.remove_node(node);
        if !self.vertices[v as usize].origin.counts_toward_density() {
            self.clustered -= 1;
        }
        self.births[v as usize] = DEAD;
        self.lists[v as usize].clear();
        self.removals += 1;
    }

    // ----- read-only view -----

    /// One more than the largest vertex id ever handed out (ids of removed vertices included):
    /// the length of an array indexed by vertex id.
    pub(crate) fn id_bound(&self) -> usize {
        self.states.len()
    }

    /// Number of vertices (samples, start and goals).
    pub fn vertex_count(&self) -> usize {
        self.graph.node_count()
    }

    /// Number of vertices that count in the sample number `q` of the connection rules `k(q)`
    /// and `r(q)`: the start, the goals and every sample but those drawn near the terminals
    /// ([`SampleOrigin::counts_toward_density`](mit_star_samplers::SampleOrigin::counts_toward_density)),
    /// which would make the graph look denser than the sampler's coverage of its set.
    pub fn density_count(&self) -> usize {
        self.vertex_count() - self.clustered
    }

    /// Number of stored (checked) edges, white-, black- or not yet listed.
    pub fn edge_count(&self) -> usize {
        self.graph.edge_count()
    }

    /// Every vertex with its state, in id order.
    pub fn vertices(&self) -> impl Iterator<Item = (VertexId, &[f64])> + '_ {
        self.graph
            .node_indices()
            .map(|n| (VertexId(n.index() as u32), &self.states[n.index()]))
    }

    /// The search data of a vertex (`None` if the id is not in use).
    fn live_vertex(&self, v: VertexId) -> Option<&Vertex> {
        self.graph
            .contains_node(NodeIndex::new(v.index()))
            .then(|| &self.vertices[v.index()])
    }

    /// The state of a vertex (`None` if the id is not in use).
    pub fn state_of(&self, v: VertexId) -> Option<&[f64]> {
        self.graph
            .contains_node(NodeIndex::new(v.index()))
            .then(|| &self.states[v.index()])
    }

    /// What a vertex stands for (`None` if the id is not in use).
    pub fn kind(&self, v: VertexId) -> Option<VertexKind> {
        self.live_vertex(v).map(|x| x.kind)
    }

    /// Which step of the sampler produced a vertex's state ([`SampleOrigin::Drawn`](mit_star_samplers::SampleOrigin) for
    /// the start, the goals and ids not in use).
    pub fn origin(&self, v: VertexId) -> mit_star_samplers::SampleOrigin {
        self.live_vertex(v)
            .map_or(mit_star_samplers::SampleOrigin::Drawn, |x| x.origin)
    }

    /// The cost-to-come of a vertex in the forward tree (∞ if not in it).
    pub fn cost_to_come(&self, v: VertexId) -> f64 {
        self.live_vertex(v).map_or(f64::INFINITY, |x| x.g)
    }

    /// The forward-tree parent of a vertex.
    pub fn forward_parent(&self, v: VertexId) -> Option<VertexId> {
        let x = self.live_vertex(v)?;
        (x.parent != NONE).then_some(VertexId(x.parent))
    }

    /// Every forward-tree edge as `(parent, child)`.
    pub fn forward_edges(&self) -> impl Iterator<Item = (VertexId, VertexId)> + '_ {
        self.graph.node_indices().filter_map(|n| {
            let p = self.vertices[n.index()].parent;
            (p != NONE).then_some((VertexId(p), VertexId(n.index() as u32)))
        })
    }

    /// The white/black status of the edge `a — b` whose check grid has step `step`: `Valid` if
    /// every grid point was tested valid (or the grid has none), `Invalid` if one was invalid,
    /// `Unknown` otherwise or if the edge was never checked.
    pub fn edge_status(&self, a: VertexId, b: VertexId, distance: f64, step: f64) -> EdgeStatus {
        let grid = EdgeGrid::new(distance, step);
        self.progress(a.0, b.0).status(&grid)
    }
}
