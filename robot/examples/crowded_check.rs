//! `crowded_check`: what one state check, a batch check and a certified motion cost the
//! Panda's checker in the MotionBenchMaker scenes and among thousands of small boxes.
//!
//! ```text
//! cargo run --release -p mit-star-robot --example crowded_check -- 20000
//! cargo run --release -p mit-star-robot --example crowded_check -- 300 0
//! ```
//!
//! For each scene shipped with the crate's tests (`tests/data/mbm/*_panda`, problem 1), as it
//! is and with `N` seeded 1 cm cubes added within 1.2 m of the base (up to 1.6 m high, as
//! `arm_deadline_stress --extra-boxes N` places them, less those the ends touch),
//! prints the time of `is_valid` on the problem's start (valid), per configuration of
//! `is_valid` on 2000 uniform configurations, of
//! `any_invalid` on them in batches of the checker's width, and per edge of `certify_motion`
//! on 200 short edges from valid configurations (the start where too few are), with the counts of valid configurations and
//! certified edges (identical answers give identical counts), and how long building the checker
//! took. A second argument `T` builds the
//! checker with a grid over a link's reachable obstacles from `T` of them on (0: always; the
//! default is `obstacle_grid.rs`'s threshold), to compare the grid with the linear scan:
//! `crowded_check 300 0` against `crowded_check 300 18446744073709551615`.

use std::path::PathBuf;
use std::time::Instant;

use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmChecker, ArmProblem};
use mit_star_spaces::StateSpace;
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};

#[path = "support/extra_cubes.rs"]
mod extra_cubes;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;

fn main() {
    let extra: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20_000);
    // A second argument: the checker's grid threshold (its default otherwise).
    let threshold: Option<usize> = std::env::args().nth(2).and_then(|a| a.parse().ok());
    let data = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm");
    for folder in mbm_scenes::SCENES {
        let scene = folder.trim_end_matches("_panda");
        let Ok(base) = ArmProblem::panda_mbm(&data.join(folder), 1) else {
            eprintln!("{scene}: cannot load");
            std::process::exit(2);
        };
        for count in [0, extra] {
            let problem = extra_cubes::with_extra_cubes(&base, count);
            report(&format!("{scene}+{count}"), &problem, threshold);
        }
    }
}

/// Times the three checks on `problem` and prints one line.
fn report(name: &str, problem: &ArmProblem, threshold: Option<usize>) {
    let space = problem.space();
    // The checker, timed as it is built (the problem's own was built with it).
    let clock = Instant::now();
    let own = match threshold {
        Some(t) => ArmChecker::with_grid_threshold(problem.robot(), problem.scene(), t),
        None => ArmChecker::new(problem.robot(), problem.scene()),
    };
    let built = clock.elapsed().as_secs_f64();
    let checker = if threshold.is_some() {
        &own
    } else {
        problem.validity()
    };
    let mut rng =
        <mit_star_spaces::SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(7);
    let mut states = vec![0.0; 7 * 2000];
    for q in states.chunks_exact_mut(7) {
        space.sample_uniform(&mut rng, q);
    }
    // Best of three passes, per configuration.
    let mut valid = 0;
    let mut scalar = f64::INFINITY;
    for _ in 0..3 {
        let clock = Instant::now();
        valid = states
            .chunks_exact(7)
            .filter(|q| checker.is_valid(std::hint::black_box(q)))
            .count();
        scalar = scalar.min(clock.elapsed().as_secs_f64() / 2000.0);
    }
    // The start (valid: what `validate_query` checks first), 200 times.
    let start = problem.start();
    let clock = Instant::now();
    let start_valid = (0..200)
        .filter(|_| checker.is_valid(std::hint::black_box(start)))
        .count();
    let at_start = clock.elapsed().as_secs_f64() / 200.0;
    let width = checker.batch_width() * 7;
    let mut hits = 0;
    let mut batched = f64::INFINITY;
    for _ in 0..3 {
        let clock = Instant::now();
        hits = states
            .chunks(width)
            .filter_map(|b| checker.any_invalid(std::hint::black_box(b), 7))
            .sum::<usize>();
        batched = batched.min(clock.elapsed().as_secs_f64() / 2000.0);
    }
    // Short edges (0.3 rad in each coordinate at most) from valid configurations: the
    // uniform ones, then (among thousands of cubes, where few are valid) the start.
    let starts: Vec<&[f64]> = states
        .chunks_exact(7)
        .filter(|q| checker.is_valid(q))
        .chain(std::iter::repeat(start))
        .take(200)
        .collect();
    let ends: Vec<Vec<f64>> = starts
        .iter()
        .enumerate()
        .map(|(i, q)| {
            q.iter()
                .enumerate()
                .map(|(j, x)| x + 0.3 * (((i * 7 + j) as f64 * 0.618).fract() - 0.5))
                .collect()
        })
        .collect();
    let clock = Instant::now();
    let mut certified = 0;
    for (a, b) in starts.iter().zip(&ends) {
        let mut progress = MotionProgress::new(0.0, 0.0);
        let status = checker.certify_motion(space, a, b, &mut progress, &mit_star_spaces::Never);
        certified += usize::from(status == Some(EdgeStatus::Valid));
    }
    let certify = clock.elapsed().as_secs_f64() / starts.len().max(1) as f64;
    println!(
        "{name:>22}: start {:8.2} µs ({start_valid}/200 valid)  is_valid {:8.2} µs \
         ({valid} valid)  any_invalid {:8.2} µs/conf \
         (sum {hits})  certify {:9.1} µs/edge ({certified}/{} certified)  built in {:.1} ms",
        1e6 * at_start,
        1e6 * scalar,
        1e6 * batched,
        1e6 * certify,
        starts.len(),
        1e3 * built,
    );
}
