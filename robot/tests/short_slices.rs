//! Every planner, driven on an arm problem by many short `solve` calls — each stopped after a
//! few polls of its termination condition — still solves, and returns a certified path:
//! interrupted certifications resume where they stopped instead of starting over.

use std::cell::Cell;

use mit_star::{
    AitStar, Aorrtc, BitStar, EitStar, InformedRrtStar, MitStar, Parameters, Planner, Progress,
    RrtConnect, Termination,
};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, ParryChecker};
use mit_star_validity::StateValidity;

/// Fires from its `polls`-th poll on; [`rearm`](Self::rearm) starts a new slice.
struct Slice {
    seen: Cell<u64>,
    polls: u64,
}

impl Slice {
    fn rearm(&self) {
        self.seen.set(0);
    }
}

impl Termination for Slice {
    fn should_terminate(&self, progress: &Progress) -> bool {
        self.seen.set(self.seen.get() + 1);
        progress.best_cost.is_finite() || self.seen.get() >= self.polls
    }
}

fn problem() -> ArmProblem {
    let folder = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/mbm/table_pick_panda"
    );
    ArmProblem::panda_mbm(folder.as_ref(), 1).unwrap()
}

fn planners(problem: &ArmProblem, seed: u64) -> Vec<(&'static str, Box<dyn Planner>)> {
    let parameters = Parameters {
        seed,
        ..Parameters::default()
    };
    vec![
        (
            "MIT*",
            Box::new(MitStar::for_problem(problem).seed(seed).build().unwrap()),
        ),
        (
            "EIT*",
            Box::new(EitStar::for_problem(problem).seed(seed).build().unwrap()),
        ),
        (
            "AIT*",
            Box::new(AitStar::for_problem(problem).seed(seed).build().unwrap()),
        ),
        (
            "BIT*",
            Box::new(BitStar::for_problem(problem).seed(seed).build().unwrap()),
        ),
        (
            "Informed RRT*",
            Box::new(InformedRrtStar::for_problem(problem, &parameters).unwrap()),
        ),
        (
            "RRT-Connect",
            Box::new(RrtConnect::for_problem(problem, &parameters).unwrap()),
        ),
        (
            "AORRTC",
            Box::new(Aorrtc::for_problem(problem, &parameters).unwrap()),
        ),
    ]
}

#[test]
fn every_planner_solves_in_slices_of_a_few_polls() {
    let problem = problem();
    let reference = ParryChecker::new(problem.robot(), problem.scene());
    for (name, mut planner) in planners(&problem, 3) {
        let slice = Slice {
            seen: Cell::new(0),
            polls: 4,
        };
        let mut calls = 0;
        let path: Vec<Vec<f64>> = loop {
            calls += 1;
            slice.rearm();
            let outcome = planner.solve(&slice).unwrap();
            if let Some(solution) = outcome.solution() {
                break solution.path.iter().map(<[f64]>::to_vec).collect();
            }
            assert!(calls < 200_000, "{name}: no solution after {calls} slices");
        };
        assert!(
            calls > 1,
            "{name} solved in one slice: the test proves nothing"
        );
        assert_densely_clear(&reference, &path, name);
        assert!(problem.certification() > 1);
        eprintln!("{name}: solved after {calls} slices");
    }
}

/// The path is certified: dense `f64` re-check at 1e-3 rad.
fn assert_densely_clear(reference: &ParryChecker, path: &[Vec<f64>], name: &str) {
    for pair in path.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        let pieces = (mit_star_spaces::euclidean_distance(a, b) / 1e-3)
            .ceil()
            .max(1.0) as u32;
        for k in 0..=pieces {
            let t = f64::from(k) / f64::from(pieces);
            let q: Vec<f64> = a
                .iter()
                .zip(b.iter())
                .map(|(x, y)| x + (y - x) * t)
                .collect();
            assert!(reference.is_valid(&q), "{name}: {q:?} collides");
        }
    }
}

/// Fires from its `polls`-th poll on, whatever the cost: slices of an anytime search.
struct Polls {
    seen: Cell<u64>,
    polls: u64,
}

impl Termination for Polls {
    fn should_terminate(&self, _: &Progress) -> bool {
        self.seen.set(self.seen.get() + 1);
        self.seen.get() >= self.polls
    }
}

#[test]
fn aorrtc_improves_in_slices_and_every_path_stays_certified() {
    let problem = problem();
    let reference = ParryChecker::new(problem.robot(), problem.scene());
    let parameters = Parameters {
        seed: 5,
        ..Parameters::default()
    };
    let mut planner = Aorrtc::for_problem(&problem, &parameters).unwrap();
    let slice = Polls {
        seen: Cell::new(0),
        polls: 6,
    };
    let mut costs = Vec::new();
    for _ in 0..20_000 {
        slice.seen.set(0);
        let outcome = planner.solve(&slice).unwrap();
        if let Some(solution) = outcome.solution()
            && costs.last() != Some(&solution.cost)
        {
            costs.push(solution.cost);
            let path: Vec<Vec<f64>> = solution.path.iter().map(<[f64]>::to_vec).collect();
            assert_densely_clear(&reference, &path, "AORRTC");
        }
    }
    // The cost-bounded searches ran across slices and improved the first path.
    assert!(costs.len() > 2, "{costs:?}");
    assert!(costs.windows(2).all(|w| w[1] < w[0]), "{costs:?}");
}
