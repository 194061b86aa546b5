//! `end_pockets`: how free a shipped robot is, in an empty scene and around its problems'
//! starts and goals.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/fetch/problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example end_pockets -- fetch target/problems/bookshelf_small_fetch 3
//! ```
//!
//! First the share of 20 000 uniform configurations free of self-collision (no scene) and the
//! checked link pairs colliding most often. Then, for problems `1..=N` of the folder: the share
//! of 4 000 uniform configurations valid in the problem's scene, and for the start and the
//! goal the share of 4 000 straight motions of joint-space length 0.05, 0.2, 0.5 and 1 in random
//! directions that stay valid (inside the joint limits and free at 40 evenly spaced
//! configurations): how tight the pocket around each end is.

use std::collections::HashMap;
use std::path::Path;

use mit_star_problems::PlanningProblem;
use mit_star_spaces::rand::{RngExt, SeedableRng};
use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::StateValidity;

/// The share (%) of straight motions of length `length` from `end` in random directions that
/// stay inside the limits and valid at 40 evenly spaced configurations.
fn free_share(
    problem: &mit_star_robot::ArmProblem,
    end: &[f64],
    length: f64,
    state: &mut SeededRng,
) -> f64 {
    let (space, validity) = (problem.space(), problem.validity());
    let trials = 4000;
    let mut free = 0;
    let mut target = end.to_vec();
    let mut q = end.to_vec();
    for _ in 0..trials {
        for (t, e) in target.iter_mut().zip(end) {
            *t = e + (2.0 * state.random::<f64>() - 1.0);
        }
        let scale = length / space.distance(end, &target);
        for (t, e) in target.iter_mut().zip(end) {
            *t = e + (*t - e) * scale;
        }
        let stays = (1..=40).all(|k| {
            space.interpolate(end, &target, f64::from(k) / 40.0, &mut q);
            space.contains(&q) && validity.is_valid(&q)
        });
        free += usize::from(stays);
    }
    100.0 * free as f64 / f64::from(trials)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(name), Some(folder)) = (args.get(1), args.get(2)) else {
        eprintln!("usage: end_pockets ROBOT FOLDER [COUNT]");
        std::process::exit(2);
    };
    let count: usize = args
        .get(3)
        .map_or(3, |c| c.parse().expect("a problem count"));
    let model = mit_star_robot::ShippedRobot::find(name)
        .expect("a shipped robot")
        .model(false)
        .expect("the shipped files load");
    let link = |l: usize| model.links()[l].name.clone();
    let mut state = SeededRng::seed_from_u64(12_345);
    let space = model.joint_space();
    let mut q = vec![0.0; space.dimension()];
    let (samples, mut free) = (20_000, 0);
    let mut pairs: HashMap<(usize, usize), usize> = HashMap::new();
    for _ in 0..samples {
        space.sample_uniform(&mut state, &mut q);
        let colliding = model.colliding_link_pairs(&q);
        free += usize::from(colliding.is_empty());
        for pair in colliding {
            *pairs.entry(pair).or_default() += 1;
        }
    }
    println!(
        "{name}: {} checked pairs; {:.1} % of {samples} uniform configurations free of self-collision",
        model.self_collision_pairs().len(),
        100.0 * free as f64 / f64::from(samples)
    );
    let mut pairs: Vec<_> = pairs.into_iter().collect();
    pairs.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    for ((a, b), n) in pairs.iter().take(6) {
        println!(
            "  {:5.2} %  {}/{}",
            100.0 * *n as f64 / f64::from(samples),
            link(*a),
            link(*b)
        );
    }
    println!(
        "problem | uniform valid | start free at 0.05, 0.2, 0.5, 1 | goal free at 0.05, 0.2, 0.5, 1"
    );
    for index in 1..=count {
        let problem = match mit_star_robot::ArmProblem::mbm(model.clone(), Path::new(folder), index)
        {
            Ok(p) if p.ends_are_valid() => p,
            _ => {
                println!("#{index} | skipped");
                continue;
            }
        };
        let trials = 4000;
        let valid = (0..trials)
            .filter(|_| {
                space.sample_uniform(&mut state, &mut q);
                problem.validity().is_valid(&q)
            })
            .count();
        let mut line = format!(
            "#{index} | {:.1} %",
            100.0 * valid as f64 / f64::from(trials)
        );
        for end in [problem.start().to_vec(), problem.goals()[0].clone()] {
            let shares: Vec<String> = [0.05, 0.2, 0.5, 1.0]
                .iter()
                .map(|&l| format!("{:.0} %", free_share(&problem, &end, l, &mut state)))
                .collect();
            line += &format!(" | {}", shares.join(", "));
        }
        println!("{line}");
    }
}
