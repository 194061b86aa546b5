//! Tests that the forward search is offered the first edge of every expanded vertex's lazy
//! path, also after the reverse search changed it.

use mit_star_validity::EdgeStatus;

use crate::graph::NONE;
use crate::termination::SolveStop;
use crate::{EitStar, IterationLimit, MitStar, Parameters};

/// A test that steps `$planner` on `$problem` for 20 000 iterations and after every one checks
/// each lazy-path edge `v → u` that no expansion can have queued — `v` expanded in this batch,
/// `u` its current reverse parent outside `v`'s cached neighbours: it must be queued, checked
/// in full, or useless (`g(v) + ĉ ≥ g(u)`). Without `queue_lazy_edge` (the call in
/// `reverse_step`) every one of these tests fails.
macro_rules! lazy_edges_are_offered {
    ($planner:ty, $problem:expr, $name:ident) => {
        #[test]
        fn $name() {
            let problem = $problem.build().unwrap().with_resolution(1e-3).unwrap();
            let parameters = Parameters {
                batch_size: Some(200),
                ..Parameters::default()
            };
            let mut planner = <$planner>::for_problem(&problem)
                .parameters(parameters)
                .build()
                .unwrap();
            let limit = IterationLimit::new(u64::MAX);
            let stop = SolveStop::new(&limit);
            planner.setup(&stop).unwrap();
            let mut checked = 0;
            for _ in 0..20_000 {
                planner.iterate(&stop);
                let (graph, tag, batch) = (&planner.graph, planner.reverse_tag, planner.graph.tag);
                for (id, _) in graph.vertices() {
                    let v = id.0;
                    let x = graph.vertex(v);
                    let u = x.reverse_parent(tag);
                    if x.forward_expanded != batch
                        || u == NONE
                        || x.parent == u
                        || x.is_goal()
                        || graph.in_neighbour_list(v, u)
                    {
                        continue;
                    }
                    checked += 1;
                    let status = graph.edge(v, u).map(|r| r.status);
                    let decided = matches!(status, Some(EdgeStatus::Valid | EdgeStatus::Invalid));
                    let (cost, _) = planner.edge_geometry(v, u, NONE);
                    let useless = x.g + cost >= graph.vertex(u).g;
                    assert!(
                        decided || useless || planner.forward.contains(v, u),
                        "the lazy edge {v} → {u} was never offered to the forward search"
                    );
                }
            }
            assert!(checked > 0, "no lazy edge outside a neighbour list");
            assert!(planner.counters.reverse_restarts > 0, "no reverse restart");
        }
    };
}

lazy_edges_are_offered!(
    MitStar,
    mit_star_problems::DividingWalls::new(8),
    mit_star_offers_every_lazy_edge_among_dividing_walls
);
lazy_edges_are_offered!(
    EitStar,
    mit_star_problems::DividingWalls::new(8),
    eit_star_offers_every_lazy_edge_among_dividing_walls
);
lazy_edges_are_offered!(
    MitStar,
    mit_star_problems::RepeatingRectangles::new(4),
    mit_star_offers_every_lazy_edge_among_repeating_rectangles
);
lazy_edges_are_offered!(
    EitStar,
    mit_star_problems::RepeatingRectangles::new(4),
    eit_star_offers_every_lazy_edge_among_repeating_rectangles
);
