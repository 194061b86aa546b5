//! Tests of a batch: the sample count its connection rules use.

use samplers::{InformedSampler, NearTerminals, SampleOrigin};
use spaces::StateSpace;
use validity::{FixedSparseChecker, World};

use crate::graph::Neighbourhood;
use crate::termination::SolveStop;
use crate::{Connection, Eit, IterationLimit, k_nearest, r_disc};

/// EIT* with half of its samples drawn near the start and the goal.
type NearEit =
    Eit<spaces::RealVectorSpace, World, NearTerminals<InformedSampler>, FixedSparseChecker>;

#[test]
fn states_near_the_terminals_are_left_out_of_the_connection_rules() {
    let problem = problems::DividingWalls::new(4)
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
