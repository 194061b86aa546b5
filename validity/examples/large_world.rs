//! `large_world`: state checks in a world of 100 000 boxes, hierarchy against linear scan.
//!
//! ```text
//! cargo run --release -p mit-star-validity --example large_world
//! ```
//!
//! For R^2, R^4 and R^8: random boxes with sides 0.01–0.02 (so that states are in few of them)
//! in the unit cube; prints the hierarchy's build time and the mean time per state check with
//! the hierarchy and with a linear scan, measured in one run on the same states.

use std::hint::black_box;
use std::time::Instant;

use mit_star_validity::{AxisBox, StateValidity, World};

/// A small portable generator (SplitMix64), so the example needs no dependency.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn main() {
    // `LARGE_WORLD_BOXES=32` measures a small world instead (the scan/hierarchy threshold).
    let boxes: usize = std::env::var("LARGE_WORLD_BOXES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100_000);
    // `LARGE_WORLD_SIDE=0.1` draws sides in [0.1, 0.2] (PDT's random rectangles) instead.
    let side: Option<f64> = std::env::var("LARGE_WORLD_SIDE")
        .ok()
        .and_then(|v| v.parse().ok());
    let queries = 200_000;
    println!("| n | build (ms) | hierarchy (ns/check) | linear scan (ns/check) | speed-up |");
    println!("|---|---|---|---|---|");
    for n in [2, 4, 8, 16] {
        let mut rng = Mix(n as u64);
        let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
        for _ in 0..boxes {
            let center: Vec<f64> = (0..n).map(|_| rng.next() - 0.5).collect();
            let side = side.unwrap_or(if boxes > 1000 { 0.01 } else { 0.1 });
            let widths: Vec<f64> = (0..n).map(|_| side + side * rng.next()).collect();
            world.add_obstacle(AxisBox::new(center, widths)).unwrap();
        }
        let states: Vec<Vec<f64>> = (0..queries)
            .map(|_| (0..n).map(|_| rng.next() - 0.5).collect())
            .collect();
        let started = Instant::now();
        black_box(world.is_valid(&states[0])); // builds the hierarchy
        let build = started.elapsed().as_secs_f64();
        let started = Instant::now();
        let mut valid = 0;
        for s in &states {
            valid += usize::from(world.is_valid(black_box(s)));
        }
        let tree = started.elapsed().as_secs_f64() / queries as f64;
        let scan_count = queries / 100;
        let started = Instant::now();
        let mut scan_valid = 0;
        for s in &states[..scan_count] {
            let inside = world.obstacles().iter().any(|b| b.contains(black_box(s)));
            scan_valid += usize::from(!inside);
        }
        let scan = started.elapsed().as_secs_f64() / scan_count as f64;
        let agree = states[..scan_count]
            .iter()
            .all(|s| world.is_valid(s) != world.obstacles().iter().any(|b| b.contains(s)));
        assert!(agree, "the hierarchy and the scan disagree");
        println!(
            "| {n} | {:.1} | {:.0} | {:.0} | {:.0}× |",
            1e3 * build,
            1e9 * tree,
            1e9 * scan,
            scan / tree
        );
        black_box((valid, scan_valid));
    }
}
