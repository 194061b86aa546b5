//! `iteration_digest`: one line per seeded, iteration-limited run — final cost to 12 digits and
//! the work counters — so that two builds can be compared for identical behaviour (a refactor
//! that changes no decision must leave every line unchanged).
//!
//! ```text
//! cargo run --release -p mit-star --example iteration_digest > new.txt
//! # the same at the old commit (a `git worktree`), then:
//! diff old.txt new.txt
//! ```
//!
//! Seven configurations of the informed trees (six lazy searches and FCIT*) × four problems × batch sizes 20 and 100 × seeds 0–2, each
//! stopped after 30 000 iterations: most runs prune and restart their reverse search, so the
//! digest covers pruning, re-keying and the neighbour caches.
use mit_star::{Configuration, IterationLimit, Parameters, build_planner};

fn main() {
    for name in [
        "mit-star",
        "eit-star",
        "mit-star-sc",
        "bit-star",
        "ait-star",
        "abit-star",
        "fcit-star",
    ] {
        let configuration: Configuration = name.parse().unwrap();
        for (family, n) in [
            ("dividing-walls", 4),
            ("goal-enclosure", 8),
            ("flanking-gap", 4),
            ("wall-gap", 2),
        ] {
            for batch in [20_usize, 100] {
                for seed in 0..3 {
                    let problem = mit_star_problems::builtin(family, n, 0).unwrap();
                    let parameters = Parameters {
                        seed,
                        batch_size: Some(batch),
                        ..Parameters::default()
                    };
                    let mut p = build_planner(configuration, &problem, &parameters).unwrap();
                    let o = p.solve(&IterationLimit::new(30_000)).unwrap();
                    let c = p.counters();
                    println!(
                        "{name} {family} {n} b{batch} s{seed}: cost {:.12} pruned {} batches {} restarts {} points {} vertices {}",
                        o.cost(),
                        c.pruned,
                        c.batches,
                        c.reverse_restarts,
                        c.points_tested,
                        c.vertices
                    );
                }
            }
        }
    }
}
