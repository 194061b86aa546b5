//! `Planner::offer_solution`: a shorter valid path offered between `solve` calls becomes the
//! planner's best solution and bounds its search; an invalid one, or one that does not join the
//! query, is refused; planners that return their first solution ignore offers.

use crate::common;

use common::path_is_valid;
use mit_star::{
    Configuration, FirstSolution, Parameters, PathSimplifier, Planner, Solution, TerminationExt,
    TimeLimit, build_planner,
};
use mit_star_spaces::States;

fn states(rows: &[Vec<f64>]) -> States {
    let mut s = States::new(rows[0].len());
    for row in rows {
        s.push(row);
    }
    s
}

#[test]
fn asymptotically_optimal_planners_take_shorter_valid_paths_and_refuse_bad_ones() {
    let problem = mit_star_problems::DividingWalls::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-4)
        .unwrap();
    let (start, goal) = (problem.start().to_vec(), problem.goals()[0].clone());
    for configuration in [
        Configuration::MitStar,
        Configuration::EitStar,
        Configuration::BitStar,
        Configuration::InformedRrtStar,
        Configuration::Aorrtc,
        Configuration::RrtConnect,
    ] {
        let parameters = Parameters {
            seed: 3,
            aorrtc_simplify: false,
            ..Parameters::default()
        };
        let mut planner = build_planner(configuration, &problem, &parameters).unwrap();
        let first = planner
            .solve(&FirstSolution.or(TimeLimit::seconds(5.0)))
            .unwrap();
        let first = first.solution().expect("a first solution").clone();
        // Through the walls: refused by every planner.
        let straight = Solution {
            path: states(&[start.clone(), goal.clone()]),
            cost: problem.straight_line_cost(),
        };
        assert!(!planner.offer_solution(&straight), "{configuration}");
        assert_eq!(planner.best_cost(), first.cost);
        let rows: Vec<Vec<f64>> = first.path.iter().map(<[f64]>::to_vec).collect();
        let shorter = PathSimplifier::new()
            .simplify(&problem, &rows, &mit_star_spaces::Never)
            .unwrap();
        assert!(shorter.cost < first.cost);
        let offer = Solution {
            path: states(&shorter.path),
            cost: shorter.cost,
        };
        // Not joining the query: refused.
        let reversed: Vec<Vec<f64>> = shorter.path.iter().rev().cloned().collect();
        let backwards = Solution {
            path: states(&reversed),
            cost: shorter.cost,
        };
        assert!(!planner.offer_solution(&backwards), "{configuration}");
        let taken = planner.offer_solution(&offer);
        assert_eq!(
            taken,
            configuration.is_asymptotically_optimal(),
            "{configuration}"
        );
        if !taken {
            assert_eq!(planner.best_cost(), first.cost);
            continue;
        }
        assert!((planner.best_cost() - shorter.cost).abs() < 1e-12);
        assert_eq!(planner.trace().last().unwrap().cost, planner.best_cost());
        // A second offer of the same cost is not an improvement.
        assert!(!planner.offer_solution(&offer), "{configuration}");
        // The search goes on under the shorter bound; whatever it returns is valid and no
        // worse than the offered path.
        let later = planner.solve(&TimeLimit::seconds(0.05)).unwrap();
        let solution = later.solution().unwrap();
        assert!(solution.cost <= shorter.cost + 1e-12, "{configuration}");
        assert!(
            path_is_valid(problem.world(), &solution.path, problem.step()),
            "{configuration}"
        );
        // `clear` forgets the offered path too.
        planner.clear();
        assert_eq!(planner.best_cost(), f64::INFINITY);
    }
}
