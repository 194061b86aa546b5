//! Tests of FCIT*'s lazy successors: on the complete graph, the forward queue holds about one
//! edge per expanded vertex, and the search finds what queueing every edge finds.

use mit_star_heuristics::Euclidean;
use mit_star_samplers::InformedSampler;
use mit_star_validity::{DenseChecker, World};

use crate::graph::NONE;
use crate::informed_trees::{APriori, BatchDensity, Connectivity, Eit, NeighbourRule};
use crate::termination::SolveStop;
use crate::{FcitStar, IterationLimit, Parameters};

/// The complete graph with every edge of an expanded vertex queued at once.
#[derive(Debug, Clone, Copy, Default)]
struct EagerComplete;

impl NeighbourRule for EagerComplete {
    fn part_name(&self) -> &'static str {
        "eager complete"
    }

    fn connectivity(&self, _: &BatchDensity, _: &dyn Fn() -> f64) -> Connectivity {
        Connectivity::Complete
    }
}

type Eager = Eit<
    mit_star_spaces::RealVectorSpace,
    World,
    InformedSampler,
    DenseChecker,
    Euclidean,
    APriori,
    EagerComplete,
>;

#[test]
fn the_queue_holds_about_one_edge_per_expanded_vertex() {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let parameters = Parameters {
        batch_size: Some(100),
        ..Parameters::default()
    };
    let mut lazy = FcitStar::for_problem(&problem)
        .parameters(parameters.clone())
        .build()
        .unwrap();
    let mut eager = Eager::for_problem(&problem)
        .parameters(parameters)
        .build()
        .unwrap();
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    lazy.setup(&stop).unwrap();
    eager.setup(&stop).unwrap();
    let (mut lazy_peak, mut eager_peak) = (0, 0);
    for _ in 0..4_000 {
        lazy.iterate(&stop);
        eager.iterate(&stop);
        let expanded = lazy
            .successors
            .iter()
            .filter(|s| s.tag == lazy.graph.tag)
            .count();
        // One list edge per expanded vertex, plus tree edges queued beside the lists.
        assert!(
            lazy.forward.len() <= expanded + lazy.graph.vertex_count(),
            "{} queued for {expanded} expanded vertices",
            lazy.forward.len()
        );
        lazy_peak = lazy_peak.max(lazy.forward.len());
        eager_peak = eager_peak.max(eager.forward.len());
    }
    assert!(
        eager_peak > 10 * lazy_peak,
        "eager peak {eager_peak}, lazy peak {lazy_peak}"
    );
    // Both searches found a path through the walls, neither shorter than the optimum.
    let optimum = problem.optimum().unwrap();
    for cost in [lazy.best_cost, eager.best_cost] {
        assert!(cost.is_finite() && cost >= optimum - 1e-9, "{cost}");
    }
}

/// FCIT* on dividing walls in `R^dim` at `resolution`, with batches of `batch_size`, set up.
fn fcit_on_walls(dim: usize, resolution: f64, batch_size: usize) -> FcitStar {
    let problem = mit_star_problems::DividingWalls::new(dim)
        .build()
        .unwrap()
        .with_resolution(resolution)
        .unwrap();
    let mut planner = FcitStar::for_problem(&problem)
        .parameters(Parameters {
            batch_size: Some(batch_size),
            ..Parameters::default()
        })
        .build()
        .unwrap();
    let limit = IterationLimit::new(u64::MAX);
    planner.setup(&SolveStop::new(&limit)).unwrap();
    planner
}

/// The targets `v`'s walk queues from here on, one after the other, to its end.
fn walk(planner: &mut FcitStar, v: u32) -> Vec<u32> {
    let mut walked = Vec::new();
    while planner.successors[v as usize].queued != NONE {
        walked.push(planner.successors[v as usize].queued);
        planner.queue_next_successor(v);
    }
    walked
}

#[test]
fn an_expansion_that_may_not_rewire_orders_no_edge_into_the_tree() {
    let mut planner = fcit_on_walls(4, 1e-3, 100);
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    for _ in 0..4_000 {
        planner.iterate(&stop);
    }
    let v = planner.start_id;
    let len = planner
        .graph
        .neighbours(v, &planner.space, &planner.heuristic, &stop)
        .unwrap();
    let into_tree = |p: &FcitStar, i: usize| p.is_rewiring(v, p.graph.neighbour(v, i).id);
    let mut kept: Vec<u32> = (0..len)
        .filter(|&i| !into_tree(&planner, i))
        .map(|i| i as u32)
        .collect();
    assert!(
        kept.len() < len,
        "the tree holds some of the start's neighbours"
    );
    // Its first expansion sorts the edges out of the tree and keeps those into it apart, in a
    // heap (`a_walk_queues_the_edges_a_full_sort_orders_with_one_rewiring` checks the walk);
    // once it has rewired, only those out of the tree are ranked.
    planner.graph.vertex_mut(v).rewiring_expanded = false;
    assert!(planner.expand_forward_lazily(v, len, NONE, &stop));
    assert_eq!(planner.successors[v as usize].order.len(), kept.len());
    planner.graph.vertex_mut(v).rewiring_expanded = true;
    assert!(planner.expand_forward_lazily(v, len, NONE, &stop));
    // Ranked from the vertices outside the tree and the children, not from the list: each
    // target is found in the list, and the order is the list's (key, then position).
    let listed = |w: u32| {
        (0..len)
            .find(|&i| planner.graph.neighbour(v, i).id == w)
            .expect("a ranked vertex is in the list")
    };
    let ranked = &planner.successors[v as usize].order;
    let mut order: Vec<u32> = ranked.iter().map(|&(_, _, w)| listed(w) as u32).collect();
    let keys: Vec<(f64, u32)> = order
        .iter()
        .map(|&i| {
            let n = planner.graph.neighbour(v, i as usize);
            (n.cost + planner.graph.vertex(n.id).cost_to_go_bound, i)
        })
        .collect();
    assert!(
        keys.windows(2)
            .all(|w| w[0].0.total_cmp(&w[1].0).then(w[0].1.cmp(&w[1].1)).is_lt()),
        "{keys:?}"
    );
    order.sort_unstable();
    kept.sort_unstable();
    assert_eq!(order, kept);
}

/// The targets a vertex's walk queues, one after the other, as the rules read with every
/// edge sorted at once: by `ĉ + ĥ` (then list position), passing over `exclude`, known-invalid
/// edges, and every rewiring after the first one queued, and stopping at the first edge with
/// `g(v) + ĉ + ĥ ≥ best` (the walk's bound test, summed as the walk sums it).
fn walk_by_full_sort(planner: &FcitStar, v: u32, len: usize, exclude: u32, best: f64) -> Vec<u32> {
    let mut all: Vec<(f64, usize, u32, f64)> = (0..len)
        .map(|i| {
            let n = planner.graph.neighbour(v, i);
            let h = planner.graph.vertex(n.id).cost_to_go_bound;
            (n.cost + h, i, n.id, n.cost)
        })
        .collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let x = planner.graph.vertex(v);
    let (g, mut rewired) = (x.g, x.rewiring_expanded);
    let mut targets = Vec::new();
    for (_, _, w, cost) in all {
        if g + cost + planner.graph.vertex(w).cost_to_go_bound >= best {
            break;
        }
        let rewiring = planner.is_rewiring(v, w);
        if w == exclude || (rewiring && rewired) || planner.is_blacklisted(v, w) {
            continue;
        }
        rewired |= rewiring;
        targets.push(w);
    }
    targets
}

#[test]
fn a_walk_queues_the_edges_a_full_sort_orders_with_one_rewiring() {
    let mut planner = fcit_on_walls(4, 1e-3, 100);
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    for _ in 0..4_000 {
        planner.iterate(&stop);
    }
    // Without a solution no edge is held back by the bound, so a walk runs to its end.
    planner.best_cost = f64::INFINITY;
    let tree: Vec<u32> = (0..planner.graph.vertex_count() as u32)
        .filter(|&v| planner.graph.vertex(v).g.is_finite())
        .take(12)
        .collect();
    let mut rewirings_seen = 0;
    for v in tree {
        let len = planner
            .graph
            .neighbours(v, &planner.space, &planner.heuristic, &stop)
            .unwrap();
        let exclude = planner.graph.vertex(v).parent;
        planner.graph.vertex_mut(v).rewiring_expanded = false;
        let expected = walk_by_full_sort(&planner, v, len, exclude, f64::INFINITY);
        rewirings_seen += expected
            .iter()
            .filter(|&&w| planner.is_rewiring(v, w))
            .count();
        assert!(planner.expand_forward_lazily(v, len, exclude, &stop));
        assert_eq!(walk(&mut planner, v), expected, "vertex {v}");
        assert!(planner.successors[v as usize].rewirings.is_empty());
    }
    assert!(rewirings_seen > 0, "no walk met a rewiring");
}

#[test]
fn every_live_vertex_outside_the_tree_is_a_candidate_through_pruning() {
    let mut planner = fcit_on_walls(4, 1e-3, 50);
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    assert!(planner.graph.outside.enabled);
    let (mut checked, mut detached) = (0, 0);
    for round in 0..60 {
        for _ in 0..500 {
            planner.iterate(&stop);
        }
        let graph = &planner.graph;
        for &(w, birth) in graph.log.iter_from(0) {
            let x = graph.vertex(w);
            if graph.births[w as usize] != birth || x.g.is_finite() {
                continue;
            }
            let position = graph
                .log_position(w)
                .expect("a logged vertex has a position");
            assert!(
                graph
                    .outside
                    .entries
                    .iter()
                    .any(|c| c.id == w && c.birth == birth && c.position == position),
                "round {round}: vertex {w} is outside the tree and not a candidate"
            );
            checked += 1;
            // Committed before the batch that cut it out: it joined the tree, then left it.
            detached += usize::from(x.forward_expanded != 0);
        }
        // No duplicates.
        let mut ids: Vec<(u32, u32)> = graph
            .outside
            .entries
            .iter()
            .map(|c| (c.id, c.birth))
            .collect();
        ids.sort_unstable();
        assert!(
            ids.windows(2).all(|p| p[0] != p[1]),
            "round {round}: a duplicate"
        );
    }
    assert!(planner.best_cost.is_finite());
    assert!(planner.counters.pruned > 0, "no pruning");
    assert!(
        checked > 0 && detached > 0,
        "{checked} checked, {detached} cut out"
    );
}

/// A stop condition that has fired.
struct Fired;

impl mit_star_spaces::Stop for Fired {
    fn should_stop(&self) -> bool {
        true
    }
}

#[test]
fn a_ranking_of_the_log_stops_when_told_and_changes_nothing() {
    let mut planner = fcit_on_walls(8, 3e-3, 800);
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    // More logged vertices than one poll's share (16 384 coordinates: 2 048 states in R^8).
    while planner.graph.log.len() <= 2_048 {
        planner.iterate(&stop);
    }
    let v = planner.start_id;
    let (order, tag) = {
        let s = &planner.successors[v as usize];
        (s.order.clone(), s.tag)
    };
    planner.graph.vertex_mut(v).rewiring_expanded = false;
    assert!(!planner.expand_forward_lazily(v, 0, NONE, &Fired));
    let s = &planner.successors[v as usize];
    assert_eq!((&s.order, s.tag), (&order, tag));
    // Told to go on, the same ranking completes.
    assert!(planner.expand_forward_lazily(v, 0, NONE, &stop));
}

#[test]
fn with_a_solution_a_walk_stops_where_a_full_sort_would_and_ranks_fewer_edges() {
    let mut planner = fcit_on_walls(4, 1e-3, 100);
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    for _ in 0..6_000 {
        planner.iterate(&stop);
    }
    let best = planner.best_cost;
    assert!(best.is_finite(), "no solution to bound the walks");
    let tree: Vec<u32> = (0..planner.graph.vertex_count() as u32)
        .filter(|&v| planner.graph.vertex(v).g.is_finite() && !planner.graph.vertex(v).is_goal())
        .collect();
    let mut left_out = 0;
    for &v in tree.iter().take(20) {
        let len = planner
            .graph
            .neighbours(v, &planner.space, &planner.heuristic, &stop)
            .unwrap();
        let exclude = planner.graph.vertex(v).parent;
        planner.graph.vertex_mut(v).rewiring_expanded = false;
        let expected = walk_by_full_sort(&planner, v, len, exclude, best);
        assert!(planner.expand_forward_lazily(v, len, exclude, &stop));
        assert_eq!(walk(&mut planner, v), expected, "vertex {v}");
        // Once it may not rewire, its order holds only the edges out of the tree that could
        // still beat the solution.
        planner.graph.vertex_mut(v).rewiring_expanded = true;
        assert!(planner.expand_forward_lazily(v, len, exclude, &stop));
        let out_of_tree = (0..len)
            .filter(|&i| !planner.is_rewiring(v, planner.graph.neighbour(v, i).id))
            .count();
        left_out += out_of_tree - planner.successors[v as usize].order.len();
    }
    assert!(left_out > 0, "no edge was left out of an order");
}
