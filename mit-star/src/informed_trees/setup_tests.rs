//! Tests of `setup` with thousands of goals: inserted in polled blocks, resumed where the stop
//! left them, and planning afterwards as if set up at once.

use std::time::Instant;

use crate::termination::SolveStop;
use crate::{IterationLimit, MitStar, Planner, TimeLimit};

/// Obstacle-free `[0, 1]^4` with the start at a corner and `count` goals spread
/// (deterministically) over the far half.
fn many_goals(count: usize) -> mit_star_problems::Problem {
    let world = mit_star_validity::World::new(vec![0.0; 4], vec![1.0; 4]);
    let goals = (0..count)
        .map(|i| {
            let t = i as f64 / count as f64;
            vec![0.6 + 0.3 * t, (7.0 * t).fract(), (13.0 * t).fract(), 0.5]
        })
        .collect();
    mit_star_problems::Problem::new("goals", world, vec![0.1; 4], goals).unwrap()
}

#[test]
fn goals_go_in_in_polled_blocks_and_setup_resumes_where_the_stop_left_it() {
    let problem = many_goals(5_000);
    let mut planner = MitStar::for_problem(&problem).build().unwrap();
    let expired = TimeLimit::until(Instant::now());
    let fired = SolveStop::new(&expired);
    // In R^4 a block is 2 048 goals (64 KB of coordinates); a fired stop lets one block in
    // per call. Before blocks, the first call inserted all 5 000 goals.
    planner.setup(&fired).unwrap();
    assert_eq!((planner.goal_ids.len(), planner.ready), (2_048, false));
    planner.setup(&fired).unwrap();
    assert_eq!((planner.goal_ids.len(), planner.ready), (4_096, false));
    // A solve under a fired stop goes on with setup and returns without searching.
    let outcome = planner.solve(&expired).unwrap();
    assert!(!outcome.is_solved());
    assert_eq!((planner.goal_ids.len(), planner.ready), (5_000, true));
    assert_eq!(planner.counters.iterations, 0);

    // Set up in pieces, it plans exactly as one set up in one go.
    let mut whole = MitStar::for_problem(&problem).build().unwrap();
    let limit = IterationLimit::new(300);
    let (a, b) = (planner.solve(&limit).unwrap(), whole.solve(&limit).unwrap());
    assert!(a.is_solved());
    assert_eq!(a.cost().to_bits(), b.cost().to_bits());
    assert_eq!(planner.graph().vertex_count(), whole.graph().vertex_count());
}
