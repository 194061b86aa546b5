//! Certification (`Parameters::certification`): edges are certified on a finer grid before
//! they join the forward tree or, with `Parameters::lazy_certification` (the default), before a
//! solution through them is recorded, so a wall thinner than the check step but thicker than the
//! certification step never lies across a returned path.

use mit_star::{EitStar, FirstSolution, MitStar, Planner, TerminationExt, TimeLimit};
use mit_star_spaces::RealVectorSpace;
use mit_star_validity::{AxisBox, World};

/// The unit square with a wall across `y ∈ [0.1, 0.9]`: 0.02 thick (the planning grid sees
/// it), except for a window `y ∈ [0.45, 0.55]` where it is 0.004 thick at x ∈ [0.503, 0.507]:
/// between the grid points x = 0.50 and 0.51 of the straight line from the start to the goal
/// (step 0.01), and across a point of the four-times-finer grid (x = 0.505).
///
/// (A wall thin everywhere defeats the lazy search itself: its sparse checks whitelist
/// thousands of crossing edges that certification then refuses one by one. Certification
/// catches what the grid grazes; it does not replace a step finer than the obstacles.)
fn thin_wall() -> (RealVectorSpace, World) {
    let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
    let world = World::new(vec![0.0; 2], vec![1.0; 2])
        .with_obstacle(AxisBox::new(vec![0.505, 0.275], vec![0.02, 0.35]))
        .and_then(|w| w.with_obstacle(AxisBox::new(vec![0.505, 0.725], vec![0.02, 0.35])))
        .and_then(|w| w.with_obstacle(AxisBox::new(vec![0.505, 0.5], vec![0.004, 0.1])))
        .unwrap();
    (space, world)
}

const STEP: f64 = 0.01;

/// Every segment of `path` against the wall, exactly (slab tests).
fn crosses_the_wall(world: &World, path: &[Vec<f64>]) -> bool {
    path.windows(2)
        .any(|w| !world.segment_verdict(&w[0], &w[1]).is_valid())
}

fn solve(certification: u32, seed: u64, mit: bool) -> (bool, Vec<Vec<f64>>, u64) {
    solve_with(certification, true, seed, mit)
}

/// [`solve`] with lazy certification on or off.
fn solve_with(certification: u32, lazy: bool, seed: u64, mit: bool) -> (bool, Vec<Vec<f64>>, u64) {
    let batch = mit_star::Parameters::default().samples_per_batch();
    let mut planner = thin_wall_planner(mit, certification, lazy, seed, batch);
    run(planner.as_mut(), &FirstSolution.or(TimeLimit::seconds(2.0)))
}

/// MIT* or EIT* from (0.1, 0.5) to (0.9, 0.5) across the thin wall.
fn thin_wall_planner(
    mit: bool,
    certification: u32,
    lazy: bool,
    seed: u64,
    batch: usize,
) -> Box<dyn Planner> {
    let (space, world) = thin_wall();
    let resolution = STEP / space_extent();
    let (start, goal) = (vec![0.1, 0.5], vec![0.9, 0.5]);
    if mit {
        Box::new(
            MitStar::builder(space, world, start, vec![goal])
                .resolution(resolution)
                .certification(certification)
                .lazy_certification(lazy)
                .batch_size(batch)
                .seed(seed)
                .build()
                .unwrap(),
        )
    } else {
        Box::new(
            EitStar::builder(space, world, start, vec![goal])
                .resolution(resolution)
                .certification(certification)
                .lazy_certification(lazy)
                .batch_size(batch)
                .seed(seed)
                .build()
                .unwrap(),
        )
    }
}

/// Solves with `planner` until `stop`: solved, the path, certification failures.
fn run(planner: &mut dyn Planner, stop: &dyn mit_star::Termination) -> (bool, Vec<Vec<f64>>, u64) {
    let outcome = planner.solve(stop).unwrap();
    (
        outcome.is_solved(),
        path_of(&outcome).unwrap_or_default(),
        planner.counters().certification_failures,
    )
}

/// The path of an outcome's solution, one state per row.
fn path_of(outcome: &mit_star::Outcome) -> Option<Vec<Vec<f64>>> {
    outcome
        .solution()
        .map(|s| s.path.iter().map(<[f64]>::to_vec).collect())
}

/// `calls` solve calls of `planner`, each until `stop`: the solution returned by each call
/// that had one, in order.
fn paths_of_calls(
    planner: &mut dyn Planner,
    stop: &dyn mit_star::Termination,
    calls: u64,
) -> Vec<Vec<Vec<f64>>> {
    (0..calls)
        .filter_map(|_| path_of(&planner.solve(stop).unwrap()))
        .collect()
}

fn space_extent() -> f64 {
    2.0_f64.sqrt()
}

#[test]
fn without_certification_the_straight_line_crosses_the_thin_wall() {
    // The premise: the planning grid alone misses the wall, so the test below can fail.
    let (_, world) = thin_wall();
    let (solved, path, failures) = solve(1, 0, true);
    assert!(solved);
    assert!(crosses_the_wall(&world, &path), "{path:?}");
    assert_eq!(failures, 0);
}

#[test]
fn certified_planners_never_cross_the_thin_wall() {
    let (_, world) = thin_wall();
    for lazy in [true, false] {
        let mut solved_runs = Vec::new();
        for mit in [true, false] {
            for seed in 0..6 {
                let (solved, path, failures) = solve_with(4, lazy, seed, mit);
                // Whatever happens, no returned path crosses the wall.
                assert!(!crosses_the_wall(&world, &path), "seed {seed}: {path:?}");
                // The straight line was whitelisted on the planning grid and refused by the
                // certification.
                assert!(failures >= 1, "seed {seed}");
                if solved {
                    solved_runs.push((mit, seed));
                }
            }
        }
        // Most runs find the way around within the budget (see `thin_wall` for why not all
        // must).
        assert!(
            solved_runs.len() >= 9,
            "lazy {lazy}, solved: {solved_runs:?}"
        );
    }
}

/// MIT* with certification 4 on a world of boxes no edge grazes, from (0.1, 0.1) to
/// (0.9, 0.1).
fn boxes_planner(lazy: bool) -> impl Planner {
    let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
    let world = World::new(vec![0.0; 2], vec![1.0; 2])
        .with_obstacle(AxisBox::new(vec![0.5, 0.3], vec![0.1, 0.6]))
        .and_then(|w| w.with_obstacle(AxisBox::new(vec![0.3, 0.8], vec![0.1, 0.2])))
        .unwrap();
    MitStar::builder(space, world, vec![0.1, 0.1], vec![vec![0.9, 0.1]])
        .resolution(STEP / space_extent())
        .certification(4)
        .lazy_certification(lazy)
        .batch_size(50)
        .seed(3)
        .build()
        .unwrap()
}

/// [`boxes_planner`] after `calls` solve calls until `stop`: its certifications and the
/// solution of every call.
fn certified_in_boxes(
    lazy: bool,
    stop: &dyn mit_star::Termination,
    calls: u64,
) -> (u64, Vec<Vec<Vec<f64>>>) {
    let mut planner = boxes_planner(lazy);
    let paths = paths_of_calls(&mut planner, stop, calls);
    (planner.counters().certifications, paths)
}

#[test]
fn lazy_certification_certifies_only_what_solutions_use() {
    // 200 calls of 100 iterations each.
    let slice = mit_star::IterationLimit::new(100);
    let (eager, eager_paths) = certified_in_boxes(false, &slice, 200);
    let (lazy, lazy_paths) = certified_in_boxes(true, &slice, 200);
    // No certification fails here, so both runs make the same decisions and find the same
    // solutions, every one returned (the planner refuses to return an uncertified edge).
    assert!(!lazy_paths.is_empty());
    assert_eq!(lazy_paths, eager_paths);
    // The lazy run certified only the edges its solutions' paths went through.
    assert!(lazy < eager, "lazy {lazy}, eager {eager}");
    // To the first solution: the lazy run certified that path's edges and nothing else.
    let first = FirstSolution.or(TimeLimit::seconds(10.0));
    let (eager, eager_paths) = certified_in_boxes(false, &first, 1);
    let (lazy, lazy_paths) = certified_in_boxes(true, &first, 1);
    assert_eq!(lazy_paths, eager_paths);
    let edges = lazy_paths[0].len() as u64 - 1;
    assert!(lazy <= edges, "lazy {lazy}, path edges {edges}");
    assert!(lazy < eager, "lazy {lazy}, eager {eager}");
}

/// RRT-Connect on the thin wall with `certification`: solved, the path, certification
/// failures.
fn solve_rrt_connect(certification: u32, seed: u64) -> (bool, Vec<Vec<f64>>, u64) {
    let (space, world) = thin_wall();
    let parameters = mit_star::Parameters {
        resolution: STEP / space_extent(),
        certification: Some(certification),
        seed,
        ..mit_star::Parameters::default()
    };
    let query = (vec![0.1, 0.5], vec![vec![0.9, 0.5]]);
    let mut planner = mit_star::RrtConnect::new(space, world, query, parameters).unwrap();
    run(&mut planner, &FirstSolution.or(TimeLimit::seconds(2.0)))
}

#[test]
fn rrt_connect_certifies_its_connection_and_cuts_the_edge_that_fails() {
    let (_, world) = thin_wall();
    // The premise: without certification, some connections go through the window.
    let crossing = (0..20)
        .filter(|&seed| crosses_the_wall(&world, &solve_rrt_connect(1, seed).1))
        .count();
    assert!(crossing >= 1, "no uncertified path crossed the wall");
    let mut refused = 0;
    for seed in 0..20 {
        let (solved, path, failures) = solve_rrt_connect(4, seed);
        // A refused connection is cut from its tree and the search goes on to a path around.
        assert!(solved, "seed {seed}");
        assert!(!crosses_the_wall(&world, &path), "seed {seed}: {path:?}");
        refused += failures;
    }
    assert!(
        refused >= 1,
        "no connection was refused: the test proves nothing"
    );
}

/// MIT* or EIT* on the thin wall, lazily certified, run in slices of `iterations` up to
/// `total`: every solution returned on the way.
fn anytime_on_the_thin_wall(
    mit: bool,
    seed: u64,
    iterations: u64,
    total: u64,
) -> Vec<Vec<Vec<f64>>> {
    let mut planner = thin_wall_planner(mit, 4, true, seed, 20);
    let slice = mit_star::IterationLimit::new(iterations);
    paths_of_calls(planner.as_mut(), &slice, total / iterations)
}

#[test]
fn every_solution_of_a_lazily_certified_anytime_run_is_whole_and_clear() {
    // Rewirings after the first solution move vertices of the best path; with lazy
    // certification they must not move it under an edge whose certification fails later.
    let (_, world) = thin_wall();
    let mut solutions = 0;
    for mit in [true, false] {
        for seed in 0..8 {
            for path in anytime_on_the_thin_wall(mit, seed, 50, 5_000) {
                assert_eq!(path[0], [0.1, 0.5], "seed {seed}: {path:?}");
                assert_eq!(path[path.len() - 1], [0.9, 0.5], "seed {seed}: {path:?}");
                assert!(!crosses_the_wall(&world, &path), "seed {seed}: {path:?}");
                solutions += 1;
            }
        }
    }
    assert!(
        solutions > 100,
        "{solutions} solutions: the test proves little"
    );
}
