//! Tests of the start's side of the frontier: a start in a pocket hands the sampler the
//! states the start reaches, once the reverse tree holds most of the graph.

use mit_star_samplers::InformedSampler;

use crate::IterationLimit;
use crate::informed_trees::frontier_tests::{Recording, RecordingEit};
use crate::termination::SolveStop;

/// Half the side of the start enclosure's hollow (its `inside` is 0.2).
const HOLLOW: f64 = 0.1;

/// The planner once its first batch of 60 samples in the 4-D start enclosure, its opening
/// narrowed to 0.01 (a third of the samples in the start's hollow), has been searched without
/// a solution and the second one added.
fn searched(start_frontier: bool) -> RecordingEit {
    let problem = mit_star_problems::StartEnclosure::new(4)
        .gap(0.01)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let (space, start, goals) = (problem.space(), problem.start(), problem.goals());
    let sampler = Recording::new(InformedSampler::new(space, start, goals, 3).unwrap())
        .with_pocket(start, HOLLOW);
    let parameters = crate::Parameters {
        batch_size: Some(60),
        start_frontier,
        ..crate::Parameters::default()
    };
    let mut planner = RecordingEit::for_problem(&problem)
        .sampler(sampler)
        .parameters(parameters)
        .build()
        .unwrap();
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    planner.setup(&stop).unwrap();
    planner.add_batch(&stop);
    // Search the batch to exhaustion: the next batch begins by handing over the frontier.
    for _ in 0..1_000_000 {
        if planner.counters.batches >= 2 {
            break;
        }
        planner.iterate(&stop);
    }
    assert_eq!(planner.counters.batches, 2);
    assert!(!planner.best_cost.is_finite(), "the first batch solved it");
    planner
}

/// `true` if `state` lies in the enclosure's outer cube around `start` (side 0.25).
fn in_enclosure(state: &[f64], start: &[f64]) -> bool {
    state.iter().zip(start).all(|(x, s)| (x - s).abs() <= 0.125)
}

#[test]
fn a_start_in_a_pocket_hands_over_the_states_the_start_reaches() {
    let planner = searched(true);
    let start = planner.graph.state(planner.start_id).to_vec();
    // The rule fired at the end of the first batch: the start unreached, and the reverse tree
    // holding more than half of the graph.
    assert_eq!(planner.counters.start_frontiers, 1);
    let n = start.len();
    let sent = planner.sampler.sent.last().unwrap();
    assert_eq!(sent.len(), 4 * n);
    for state in sent.chunks(n) {
        assert!(
            in_enclosure(state, &start),
            "{state:?} is outside the pocket"
        );
    }
    // Farthest first: the costs from the start the search reached them at do not increase,
    // and they are the states sent.
    let costs: Vec<f64> = planner.frontier.iter().map(|e| e.0).collect();
    assert!(costs.windows(2).all(|w| w[0] >= w[1]), "{costs:?}");
    let states: Vec<f64> = planner
        .frontier
        .iter()
        .flat_map(|&(_, v)| planner.graph.state(v).to_vec())
        .collect();
    assert_eq!(*sent, states);
}

#[test]
fn without_the_setting_the_frontier_stays_on_the_goals_side() {
    let planner = searched(false);
    let start = planner.graph.state(planner.start_id).to_vec();
    let n = start.len();
    let sent = planner.sampler.sent.last().unwrap();
    assert_eq!(sent.len(), 4 * n);
    for state in sent.chunks(n) {
        assert!(!in_enclosure(state, &start), "{state:?} is in the pocket");
    }
    assert_eq!(planner.counters.start_frontiers, 0);
}
