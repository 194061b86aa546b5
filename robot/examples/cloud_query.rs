//! `cloud_query`: the cost of one [`PointTree`](mit_star_robot::PointTree) contact query on saved clouds,
//! beside VAMP's CAPT on the same clouds and spheres (`benches/peers/vamp/capt_query.cc`).
//!
//! ```text
//! cargo run --release -p mit-star-robot --example cloud_query -- OUT/clouds/table_pick_0001.npy …
//! ```
//!
//! For each cloud file (PLY, PCD or `.npy`): the tree's build, then 4096 spheres in groups of
//! eight within a centimetre of a centre drawn uniformly in the cloud's box, radii uniform in
//! [0.012, 0.08] m (VAMP's Panda radii), from xorshift64* seeded 7 — the draws of
//! `capt_query.cc`, bit for bit — each asked with the public one-at-a-time query
//! (`any_within`, reach = radius + 2.5 mm), best of five rounds. Prints: file, points, build
//! µs, ns a sphere, spheres touching (the same count as CAPT's up to `f32` rounding at a
//! sphere's border). The batched query of the arm checker is crate-private; the criterion group
//! `clouds` measures it on synthetic clouds.

use std::hint::black_box;
use std::time::Instant;

use glam::Vec3;

/// xorshift64*, 24 bits into [0, 1): `capt_query.cc`'s generator.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 40) as f32 * (1.0 / 16_777_216.0)
    }
}

fn main() {
    const COUNT: usize = 4096;
    println!("file,points,build_us,ns_one,touching");
    for file in std::env::args().skip(1) {
        let cloud = mit_star_robot::read_cloud(std::path::Path::new(&file)).expect("a cloud file");
        let points = cloud.points;
        let (lo, hi) = points.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let mut rng = Rng(7);
        let mut spheres = Vec::with_capacity(COUNT);
        while spheres.len() < COUNT {
            let mut c = [0.0_f32; 3];
            for k in 0..3 {
                c[k] = lo[k] + (hi[k] - lo[k]) * rng.next();
            }
            for _ in 0..8 {
                let mut s = [0.0_f32; 3];
                for k in 0..3 {
                    s[k] = c[k] + 0.01 * (2.0 * rng.next() - 1.0);
                }
                let r = 0.012 + (0.08 - 0.012) * rng.next();
                spheres.push((Vec3::from(s), r + 0.0025));
            }
        }
        let started = Instant::now();
        let tree = mit_star_robot::PointTree::new(&points);
        let build_us = started.elapsed().as_secs_f64() * 1e6;
        let mut best = f64::INFINITY;
        let mut touching = 0;
        for _ in 0..5 {
            let started = Instant::now();
            let hits = spheres
                .iter()
                .filter(|(c, reach)| tree.any_within(black_box(*c), *reach))
                .count();
            best = best.min(started.elapsed().as_secs_f64() * 1e9 / COUNT as f64);
            touching = hits;
        }
        println!("{file},{},{build_us:.1},{best:.2},{touching}", points.len());
    }
}
