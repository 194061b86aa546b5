//! Criterion benchmarks of the point structure of cloud obstacles (issue 69): its build, and
//! its batched queries (a batch of the arm checker's lanes per walk), against clouds of 10³,
//! 10⁴, 10⁵ and 10⁶ points.
//!
//! Run: `cargo bench -p mit-star-benches --bench clouds`. The clouds are the surfaces of
//! boxes in front of a robot (clusters, as a depth camera sees them), in a cube of 1.2 m; the
//! queries are the robot's spheres (radii 2–10 cm) at random places in that cube, eight at a
//! time within a centimetre of each other (one sphere at a batch of nearby configurations), so
//! that a part of them touch the cloud, as in a planner's checks; the distance bounds look
//! 5 cm far, as certification's do.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use mit_star_robot::{CloudObstacle, PointCloud, PointTree};
use mit_star_spaces::SeededRng;
use rand::{RngExt, SeedableRng};

const SIZES: [usize; 4] = [1_000, 10_000, 100_000, 1_000_000];
const QUERIES: usize = 1024;
/// How far the distance bounds look (metres): about what certification asks (the sweep of a
/// piece of an edge, a few centimetres).
const LIMIT: f32 = 0.05;

/// `count` points on the faces of twenty boxes (a seeded table scene).
fn cloud(count: usize) -> Vec<Vec3> {
    let mut rng = SeededRng::seed_from_u64(11);
    let boxes: Vec<(Vec3, Vec3)> = (0..20)
        .map(|_| {
            let centre = Vec3::new(
                rng.random_range(0.2..1.0),
                rng.random_range(-0.6..0.6),
                rng.random_range(0.0..0.8),
            );
            let half = Vec3::new(
                rng.random_range(0.02..0.15),
                rng.random_range(0.02..0.15),
                rng.random_range(0.02..0.15),
            );
            (centre, half)
        })
        .collect();
    (0..count)
        .map(|i| {
            let (centre, half) = boxes[i % boxes.len()];
            let mut p = Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let axis = rng.random_range(0..3);
            p[axis] = p[axis].signum();
            centre + p * half
        })
        .collect()
}

/// Robot-sized spheres at random places in the cloud's cube, in groups of eight within a
/// centimetre of each other with one radius (a sphere of the robot at eight nearby
/// configurations: what a batch of the checker's lanes asks).
fn spheres() -> (Vec<Vec3>, Vec<f32>) {
    let mut rng = SeededRng::seed_from_u64(12);
    let (mut centres, mut radii) = (Vec::new(), Vec::new());
    while centres.len() < QUERIES {
        let base = Vec3::new(
            rng.random_range(0.0..1.2),
            rng.random_range(-0.7..0.7),
            rng.random_range(-0.1..1.0),
        );
        let radius = rng.random_range(0.02..0.1);
        for _ in 0..8 {
            let jitter = Vec3::new(
                rng.random_range(-0.01..0.01),
                rng.random_range(-0.01..0.01),
                rng.random_range(-0.01..0.01),
            );
            centres.push(base + jitter);
            radii.push(radius);
        }
    }
    (centres, radii)
}

fn clouds(c: &mut Criterion) {
    let mut group = c.benchmark_group("clouds");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    let (centres, radii) = spheres();
    for size in SIZES {
        let points = cloud(size);
        group.throughput(Throughput::Elements(size as u64));
        group.bench_with_input(BenchmarkId::new("build", size), &points, |b, points| {
            b.iter(|| PointTree::new(black_box(points)));
        });
        let obstacle = CloudObstacle::new("bench", PointCloud::new(points).unwrap());
        let tree = obstacle.tree();
        println!(
            "clouds/{size}: {:.1} bytes a point",
            tree.memory_bytes() as f64 / size as f64
        );
        group.throughput(Throughput::Elements(QUERIES as u64));
        let mut touched = vec![false; QUERIES];
        group.bench_function(BenchmarkId::new("touches_batched", size), |b| {
            b.iter(|| obstacle.touches_spheres(black_box(&centres), &radii, &mut touched));
        });
        group.bench_function(BenchmarkId::new("touches_single", size), |b| {
            b.iter(|| {
                centres
                    .iter()
                    .zip(&radii)
                    .filter(|&(c, &r)| obstacle.touches_sphere(*c, r))
                    .count()
            });
        });
        let mut bounds = vec![0.0; QUERIES];
        group.bench_function(BenchmarkId::new("distance_bounds_batched", size), |b| {
            b.iter(|| obstacle.distance_lower_bounds(black_box(&centres), LIMIT, &mut bounds));
        });
        let hits = touched.iter().filter(|&&t| t).count();
        println!("clouds/{size}: {hits} of {QUERIES} spheres touch the cloud");
    }
    group.finish();
}

criterion_group!(benches, clouds);
criterion_main!(benches);
