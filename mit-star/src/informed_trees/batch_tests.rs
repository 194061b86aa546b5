//! Tests of a batch: the sample count its connection rules use, and where ABIT*'s search of it
//! ends.

use mit_star_heuristics::Euclidean;
use mit_star_samplers::{InformedSampler, NearTerminals, SampleOrigin};
use mit_star_spaces::StateSpace;
use mit_star_validity::{FixedSparseChecker, World};

use crate::graph::Neighbourhood;
use crate::termination::SolveStop;
use crate::{BitStar, Connection, Eit, IterationLimit, k_nearest, r_disc};

/// EIT* with half of its samples drawn near the start and the goal.
type NearEit = Eit<
    mit_star_spaces::RealVectorSpace,
    World,
    NearTerminals<InformedSampler>,
    FixedSparseChecker,
>;

#[test]
fn states_near_the_terminals_are_left_out_of_the_connection_rules() {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let (space, start, goals) = (problem.space(), problem.start(), problem.goals());
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    for connection in [Connection::RDisc, Connection::KNearest] {
        let inner = InformedSampler::new(space, start, goals, 3).unwrap();
        let sampler = NearTerminals::new(inner, space, start, goals, 3)
            .unwrap()
            .with_fraction(0.5)
            .unwrap();
        let mut planner = NearEit::for_problem(&problem)
            .sampler(sampler)
            .connection(connection)
            .batch_size(400)
            .build()
            .unwrap();
        planner.setup(&stop).unwrap();
        planner.add_batch(&stop);
        let graph = planner.graph();
        let near = graph
            .vertices()
            .filter(|&(id, _)| graph.origin(id) == SampleOrigin::NearTerminal)
            .count();
        assert!(
            (150..250).contains(&near),
            "{near} of 400 near the terminals"
        );
        // The start, the goal and the wrapped sampler's states.
        let q = graph.vertex_count() - near;
        assert_eq!(graph.density_count(), q);
        let (n, eta) = (space.dimension(), planner.parameters.rewire_factor);
        let expected = match connection {
            Connection::KNearest => Neighbourhood::Nearest(k_nearest(q, n, eta)),
            Connection::RDisc => Neighbourhood::Radius(r_disc(q, n, eta, space.measure())),
        };
        assert_eq!(graph.neighbourhood, expected, "{connection:?}");
    }
}

#[test]
fn abit_star_ends_a_batch_search_at_the_first_truncated_edge() {
    let problem = mit_star_problems::DividingWalls::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    let mut planner = BitStar::for_problem(&problem)
        .abit_star()
        .seed(2)
        .batch_size(200)
        .build()
        .unwrap();
    planner.setup(&stop).unwrap();
    // Edges taken that failed the truncation test `(g + ĉ + ĥ)·truncation < c_best`, and how
    // many of them the search went on after.
    let (mut truncated, mut went_on) = (0, 0);
    while planner.counters.batches < 6 && planner.counters.iterations < 200_000 {
        // The edge a forward step would take, and whether it fails the test.
        let fails = planner.best_cost.is_finite()
            && planner
                .forward
                .peek(planner.front())
                .is_some_and(|(edge, _)| {
                    let (source, target) = (edge.source, edge.target);
                    let g = planner.graph.vertex(source).g;
                    let h = planner.forward_h(target);
                    planner.graph.vertex(target).parent != source
                        && (g + edge.cost + h) * planner.truncation >= planner.best_cost
                });
        let steps = planner.counters.forward_iterations;
        planner.iterate(&stop);
        if fails && planner.counters.forward_iterations == steps + 1 {
            truncated += 1;
            went_on += usize::from(planner.continue_forward());
        }
    }
    assert!(planner.truncation > 1.0 && planner.best_cost.is_finite());
    assert!(truncated > 0, "no edge failed the truncation test");
    assert_eq!(
        went_on, 0,
        "the search went on after {went_on} of {truncated}"
    );
}

/// The suspension rule (spec §3.2's decision, `Parameters::suspend_reverse_when_forward_empty`):
/// with the forward queue empty and reverse edges left, MIT*-SR's guidance (`Suspending`)
/// hands control back (so the batch ends), EIT*'s (`EffortInformed`) goes on with the reverse
/// search, and the parameter overrides either guidance.
#[test]
fn an_empty_forward_queue_suspends_the_reverse_search_by_the_rule_in_force() {
    use crate::{EffortInformed, Guidance, Suspending};
    type Guided<G> = Eit<
        mit_star_spaces::RealVectorSpace,
        World,
        InformedSampler,
        FixedSparseChecker,
        Euclidean,
        G,
    >;
    fn continues<G: Guidance>(suspend: Option<bool>) -> bool {
        let problem = mit_star_problems::DividingWalls::new(4)
            .build()
            .unwrap()
            .with_resolution(1e-3)
            .unwrap();
        let builder = Guided::<G>::for_problem(&problem).batch_size(200);
        let builder = match suspend {
            Some(s) => builder.suspend_reverse_when_forward_empty(s),
            None => builder,
        };
        let mut planner = builder.build().unwrap();
        let limit = IterationLimit::new(u64::MAX);
        let stop = SolveStop::new(&limit);
        planner.setup(&stop).unwrap();
        planner.add_batch(&stop);
        for _ in 0..20 {
            planner.reverse_step(&stop);
        }
        assert!(
            planner.peek_reverse().is_some(),
            "the reverse queue ran dry"
        );
        planner.forward.clear();
        planner.continue_reverse()
    }
    assert!(!continues::<Suspending>(None));
    assert!(continues::<EffortInformed>(None));
    assert!(continues::<Suspending>(Some(false)));
    assert!(!continues::<EffortInformed>(Some(true)));
}
