//! `batch_cost`: what one batched call of the arm checker costs by the number of states it
//! holds — the question behind packing several small checks (a reverse search's sparse edge
//! checks, a sampler's few candidates) into one call.
//!
//! ```text
//! cargo run --release -p mit-star-robot --example batch_cost -- ur5 target/problems
//! cargo run --release -p mit-star-robot --example batch_cost -- panda target
//! ```
//!
//! On the first problem of bookshelf_small, cage and box for the named shipped robot (folders
//! `FOLDER/<scene>_<robot>`), draws 2 000 edges of 1 rad between collision-free
//! configurations, then times `any_invalid` over `k` evenly spaced states of each edge for
//! `k` = 1 … 16 (ns per call, and the share of edges found invalid), and `are_valid` (every
//! lane decided) over sixteen. Pin it to one CPU.
use std::hint::black_box;
use std::time::Instant;

use mit_star_problems::PlanningProblem;
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::StateValidity;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;

fn main() {
    let mut args = std::env::args().skip(1);
    let robot = mbm_scenes::shipped_robot(&args.next().unwrap_or_else(|| "panda".into()));
    let folder_root = args.next().unwrap_or_else(|| "target".into());
    for scene in ["bookshelf_small", "cage", "box"] {
        let folder = format!("{scene}_{}", robot.0);
        let problems = mbm_scenes::problems_of(&robot.1, &folder_root, &folder, 1);
        let (_, problem) = &problems[0];
        let space = problem.space();
        let checker = problem.validity();
        let d = space.dimension();
        let mut rng = SeededRng::seed_from_u64(7);
        // Edges of 1 rad (or up to a nearer target) between valid configurations.
        let mut edges: Vec<(Vec<f64>, Vec<f64>)> = Vec::new();
        let (mut a, mut b, mut target) = (vec![0.0; d], vec![0.0; d], vec![0.0; d]);
        while edges.len() < 2000 {
            space.sample_uniform(&mut rng, &mut a);
            space.sample_uniform(&mut rng, &mut target);
            let distance = space.distance(&a, &target);
            if !checker.is_valid(&a) || distance <= 0.0 {
                continue;
            }
            space.interpolate(&a, &target, distance.recip().min(1.0), &mut b);
            if checker.is_valid(&b) {
                edges.push((a.clone(), b.clone()));
            }
        }
        print!("{scene:16}");
        for k in [1usize, 2, 4, 6, 8, 12, 16] {
            let mut states = vec![0.0; k * d];
            let started = Instant::now();
            let mut invalid = 0;
            for _ in 0..5 {
                for (a, b) in &edges {
                    for (i, s) in states.chunks_exact_mut(d).enumerate() {
                        space.interpolate(a, b, (i as f64 + 1.0) / (k as f64 + 1.0), s);
                    }
                    invalid += usize::from(checker.any_invalid(black_box(&states), d).is_some());
                }
            }
            let ns = started.elapsed().as_secs_f64() * 1e9 / (5.0 * edges.len() as f64);
            print!(
                " k={k}: {ns:.0} ns ({:.2} inv)",
                invalid as f64 / (5.0 * edges.len() as f64)
            );
        }
        // All lanes decided (are_valid), sixteen points of one edge.
        let mut states = vec![0.0; 16 * d];
        let mut valid = vec![false; 16];
        let started = Instant::now();
        for _ in 0..5 {
            for (a, b) in &edges {
                for (i, s) in states.chunks_exact_mut(d).enumerate() {
                    space.interpolate(a, b, (i as f64 + 1.0) / 17.0, s);
                }
                checker.are_valid(black_box(&states), d, &mut valid);
            }
        }
        let ns = started.elapsed().as_secs_f64() * 1e9 / (5.0 * edges.len() as f64);
        println!(" all16: {ns:.0} ns");
    }
}
