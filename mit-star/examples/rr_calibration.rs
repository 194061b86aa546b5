//! `rr_calibration`: how hard is a random-rectangles layout? For candidate box counts and side
//! ranges it reports, over layouts 0–9, how often the straight line is blocked, whether each
//! layout is solvable, and EIT*'s final cost over the straight line — the figures behind the
//! cluttered variant's parameters (`docs/guide/src/reference/experiment-files.md`, "Random rectangles with teeth").
//!
//! ```text
//! cargo run --release -p mit-star --example rr_calibration -- DIMENSION COUNT MIN_SIDE MAX_SIDE [BUDGET] [RUNS]
//! cargo run --release -p mit-star --example rr_calibration -- 8 60 0.3 0.6 2.0 3
//! ```
//!
//! Per layout: whether the straight line from start to goal is blocked (exact segment test),
//! whether RRT-Connect connects start and goal within 10 s (solvable), and the median over
//! `RUNS` seeds (default 3) of EIT*'s final cost after `BUDGET` seconds (default: the paper's
//! random-rectangles budget for the dimension), divided by the straight line's length.

use std::time::Duration;

use mit_star::{
    Configuration, FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner,
};
use mit_star_problems::RandomRectangles;
use mit_star_validity::SegmentVerdict;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: rr_calibration DIMENSION COUNT MIN_SIDE MAX_SIDE [BUDGET] [RUNS]";
    if args.len() < 4 {
        eprintln!("{usage}");
        std::process::exit(2);
    }
    let number = |i: usize| -> f64 {
        args[i].parse().unwrap_or_else(|_| {
            eprintln!("{usage}");
            std::process::exit(2)
        })
    };
    let (n, count, min_side, max_side) =
        (number(0) as usize, number(1) as usize, number(2), number(3));
    let budget = args.get(4).map_or_else(
        || match n {
            ..=4 => 0.8,
            5..=8 => 2.0,
            _ => 4.0,
        },
        |_| number(4),
    );
    let runs = args.get(5).map_or(3, |_| number(5) as u64);
    println!("R^{n}: {count} boxes, sides {min_side}–{max_side}, EIT* {budget} s × {runs} seeds");
    let mut blocked = 0;
    let mut solvable = 0;
    let mut ratios = Vec::new();
    for layout in 0..10 {
        let problem = match RandomRectangles::new(n)
            .count(count)
            .min_side(min_side)
            .max_side(max_side)
            .seed(layout)
            .build()
        {
            Ok(p) => p,
            Err(e) => {
                println!("  layout {layout}: {e}");
                continue;
            }
        };
        let straight = problem.straight_line_cost();
        let is_blocked = !matches!(
            problem
                .world()
                .segment_verdict(problem.start(), &problem.goals()[0]),
            SegmentVerdict::Valid
        );
        blocked += usize::from(is_blocked);
        let parameters = |seed| Parameters {
            seed,
            ..Parameters::default()
        };
        let mut connect = build_planner(Configuration::RrtConnect, &problem, &parameters(0))
            .expect("RRT-Connect builds");
        let connected = connect
            .solve(&FirstSolution.or(TimeLimit::new(Duration::from_secs(10))))
            .is_ok_and(|o| o.is_solved());
        solvable += usize::from(connected);
        let mut costs: Vec<f64> = (0..runs)
            .map(|seed| {
                let mut eit = build_planner(Configuration::EitStar, &problem, &parameters(seed))
                    .expect("EIT* builds");
                eit.solve(&TimeLimit::new(Duration::from_secs_f64(budget)))
                    .map_or(f64::INFINITY, |o| o.cost())
            })
            .collect();
        costs.sort_by(f64::total_cmp);
        let ratio = costs[costs.len() / 2] / straight;
        ratios.push(ratio);
        println!(
            "  layout {layout}: blocked {is_blocked}, solvable {connected}, EIT* final / straight {ratio:.3} (costs {costs:.3?})"
        );
    }
    ratios.sort_by(f64::total_cmp);
    let median = ratios.get(ratios.len() / 2).copied().unwrap_or(f64::NAN);
    println!("=> blocked {blocked}/10, solvable {solvable}/10, median ratio {median:.3}");
}
