//! `cloud_query`: the cost of one contact query on saved clouds — the
//! [`PointTree`](mit_star_robot::PointTree) and the [`AffordanceTree`](mit_star_robot::AffordanceTree),
//! one sphere at a time and a batch of the checker's lanes at once — beside VAMP's CAPT on the
//! same clouds and spheres (`benches/peers/vamp/capt_query.cc`).
//!
//! ```text
//! cargo run --release -p mit-star-robot --example cloud_query -- OUT/clouds/table_pick_0001.npy …
//! ```
//!
//! For each cloud file (PLY, PCD or `.npy`): the builds, then 4096 spheres in groups of
//! eight within a centimetre of a centre drawn uniformly in the cloud's box, radii uniform in
//! [0.012, 0.08] m (VAMP's Panda radii), from xorshift64* seeded 7 — the draws of
//! `capt_query.cc`, bit for bit — each asked of a cloud obstacle of points of radius 2.5 mm
//! (`touches_sphere` one at a time; `touches_spheres` a batch of the checker's lanes per
//! query, 8 or 16 with AVX-512; `touches_spheres` four at a time), best of five rounds; first
//! without affordances (the tree's answers), then with affordances for spheres up to 0.0801 m
//! (the Panda's largest sphere and the checker's margin), which answer single spheres and
//! batches of up to four (a full batch of lanes goes to the tree). Prints: file, points, the
//! tree's build µs, the affordances' build µs and points listed, ns a sphere (the three
//! queries without, then with affordances), spheres touching (the same count from every
//! query, as CAPT's up to `f32` rounding at a sphere's border).

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
    println!(
        "file,points,tree_build_us,afford_build_us,listed,ns_tree_one,ns_tree_lanes,ns_tree_fours,ns_afford_one,ns_afford_lanes,ns_afford_fours,touching"
    );
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
                spheres.push((Vec3::from(s), r));
            }
        }
        let started = Instant::now();
        let cloud = mit_star_robot::PointCloud::new(points.clone()).expect("a cloud");
        let plain = mit_star_robot::CloudObstacle::new("plain", cloud.clone());
        let tree_us = started.elapsed().as_secs_f64() * 1e6;
        let fast = mit_star_robot::CloudObstacle::new("fast", cloud);
        let started = Instant::now();
        let fast = fast.with_affordances(0.0801);
        let afford_us = started.elapsed().as_secs_f64() * 1e6;
        let listed = fast.affordances().map_or(0, |a| a.listed());
        let centers: Vec<Vec3> = spheres.iter().map(|s| s.0).collect();
        let radii: Vec<f32> = spheres.iter().map(|s| s.1).collect();
        let mut out = vec![false; COUNT];
        let mut row = Vec::new();
        let mut touching = Vec::new();
        for obstacle in [&plain, &fast] {
            let one = best_of_five(|| {
                spheres
                    .iter()
                    .filter(|(c, r)| obstacle.touches_sphere(black_box(*c), *r))
                    .count()
            });
            let lanes = best_of_five(|| {
                obstacle.touches_spheres(black_box(&centers), &radii, &mut out);
                out.iter().filter(|&&t| t).count()
            });
            let fours = best_of_five(|| {
                for ((c, r), o) in centers
                    .chunks(4)
                    .zip(radii.chunks(4))
                    .zip(out.chunks_mut(4))
                {
                    obstacle.touches_spheres(black_box(c), r, o);
                }
                out.iter().filter(|&&t| t).count()
            });
            row.extend([one.0, lanes.0, fours.0]);
            touching.extend([one.1, lanes.1, fours.1]);
        }
        assert!(touching.iter().all(|&t| t == touching[0]), "{touching:?}");
        println!(
            "{file},{},{tree_us:.1},{afford_us:.1},{listed},{:.2},{:.2},{:.2},{:.2},{:.2},{:.2},{}",
            points.len(),
            row[0],
            row[1],
            row[2],
            row[3],
            row[4],
            row[5],
            touching[0]
        );
    }
}

/// The best of five rounds of `query` over the 4096 spheres: ns a sphere, and its count.
fn best_of_five(mut query: impl FnMut() -> usize) -> (f64, usize) {
    let mut best = f64::INFINITY;
    let mut count = 0;
    for _ in 0..5 {
        let started = Instant::now();
        count = query();
        best = best.min(started.elapsed().as_secs_f64() * 1e9 / 4096.0);
    }
    (best, count)
}
