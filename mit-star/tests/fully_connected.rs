//! FCIT* ([`FcitStar`]): the informed-trees skeleton on a fully connected graph solves the
//! box worlds with sound paths, improves monotonically over repeated solves, and joins every
//! vertex to every other.

use crate::common;

use common::{assert_solution_sound, assert_trace_monotone};
use mit_star::{
    BitStar, Configuration, FcitStar, IterationLimit, Parameters, Planner, build_planner,
};

/// The box worlds FCIT* must solve within the budget.
const FAMILIES: [(&str, usize); 4] = [
    ("dividing-walls", 2),
    ("dividing-walls", 4),
    ("flanking-gap", 4),
    ("goal-enclosure", 2),
];

#[test]
fn fcit_solves_the_box_worlds_with_sound_paths() {
    for (family, n) in FAMILIES {
        for seed in 0..3 {
            let problem = mit_star_problems::builtin(family, n, 0).unwrap();
            let mut planner = FcitStar::for_problem(&problem).seed(seed).build().unwrap();
            assert_eq!(planner.name(), "FCIT*");
            let outcome = planner.solve(&IterationLimit::new(20_000)).unwrap();
            let solution = outcome
                .solution()
                .unwrap_or_else(|| panic!("FCIT* failed {family} R^{n} seed {seed}"));
            assert_solution_sound(&planner, solution, problem.start(), problem.goals());
            if let Some(optimum) = problem.optimum() {
                assert!(solution.cost >= optimum - 1e-9, "{family} R^{n}");
            }
            assert_trace_monotone(&planner);
        }
    }
}

#[test]
fn fcit_costs_do_not_increase_over_iterations() {
    for (family, n) in FAMILIES {
        let problem = mit_star_problems::builtin(family, n, 1).unwrap();
        let parameters = Parameters {
            seed: 5,
            ..Parameters::default()
        };
        let mut planner = build_planner(Configuration::FcitStar, &problem, &parameters).unwrap();
        let mut previous = f64::INFINITY;
        let mut improved = 0;
        for slice in 1..=12 {
            // Each call goes on from the last one's graph and trees.
            let cost = planner
                .solve(&IterationLimit::new(2_000 * slice))
                .unwrap()
                .cost();
            assert!(cost <= previous, "{family} R^{n}: {cost} after {previous}");
            improved += usize::from(cost < previous);
            previous = cost;
        }
        assert!(previous.is_finite(), "{family} R^{n} unsolved");
        assert!(improved >= 2, "{family} R^{n}: improved {improved} times");
        assert_trace_monotone(planner.as_ref());
    }
}

#[test]
fn every_vertex_is_a_neighbour_of_every_other() {
    let problem = mit_star_problems::builtin("dividing-walls", 4, 0).unwrap();
    let mut fcit = FcitStar::for_problem(&problem).seed(2).build().unwrap();
    let mut bit = BitStar::for_problem(&problem).seed(2).build().unwrap();
    for planner in [&mut fcit as &mut dyn Planner, &mut bit] {
        planner.solve(&IterationLimit::new(3_000)).unwrap();
    }
    // The same sampler: BIT*'s forward tree joins its vertices to near ones only, FCIT*'s
    // reaches across the graph; both only through checked edges.
    let longest = |graph: &mit_star::RandomGeometricGraph| {
        graph
            .forward_edges()
            .map(|(a, b)| {
                let (xa, xb) = (graph.state_of(a).unwrap(), graph.state_of(b).unwrap());
                mit_star_spaces::euclidean_distance(xa, xb)
            })
            .fold(0.0, f64::max)
    };
    let (fcit_longest, bit_longest) = (longest(fcit.graph()), longest(bit.graph()));
    assert!(
        fcit_longest > bit_longest,
        "FCIT*'s longest tree edge {fcit_longest} vs BIT*'s {bit_longest}"
    );
    assert!(fcit.counters().vertices > 100);
}
