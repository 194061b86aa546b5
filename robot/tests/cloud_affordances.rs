//! The affordance structure of cloud obstacles against brute force: the same booleans as
//! `|c − p|² ≤ reach²` in `f32` over every point, and as the tree's, bit for bit, for single
//! and batched queries, centres on cell borders and reaches at a point's exact distance
//! included; reaches beyond its bound left to the tree; its memory budget at 10⁶ points.

use glam::Vec3;
use mit_star_robot::{AffordanceTree, CloudObstacle, PointCloud, PointTree};
use proptest::prelude::*;

/// Points in a box of half side `spread` around `(0.4, 0, 0.4)`: on a few planes (surfaces
/// sampled as a camera sees them), in clusters within 5 mm, or alone, from a seed.
fn cloud_points(count: usize, spread: f32, seed: u64) -> Vec<Vec3> {
    let mut state = seed | 1;
    let mut next = move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        ((state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 40) as f32 / (1u64 << 24) as f32) * 2.0 - 1.0
    };
    let mut points = Vec::with_capacity(count);
    while points.len() < count {
        let kind = next();
        let centre = Vec3::new(0.4, 0.0, 0.4) + spread * Vec3::new(next(), next(), next());
        if kind > 0.3 {
            // A cluster of up to 20 points within 5 mm.
            for _ in 0..20.min(count - points.len()) {
                points.push(centre + 0.005 * Vec3::new(next(), next(), next()));
            }
        } else if kind > -0.3 {
            // A patch of a plane z = const (the coordinates repeat exactly).
            for _ in 0..30.min(count - points.len()) {
                points.push(Vec3::new(
                    centre.x + 0.1 * next(),
                    centre.y + 0.1 * next(),
                    centre.z,
                ));
            }
        } else {
            points.push(centre);
        }
    }
    points
}

/// The definition: some point with `|c − p|² ≤ reach²`, in `f32`, in this order.
fn brute(points: &[Vec3], c: Vec3, reach: f32) -> bool {
    let r2 = reach * reach;
    points.iter().any(|p| {
        let (dx, dy, dz) = (c.x - p.x, c.y - p.y, c.z - p.z);
        dx * dx + dy * dy + dz * dz <= r2
    })
}

/// Queries: centres anywhere around the cloud, at a point (its coordinates are split values),
/// or a point moved along one axis (on a split plane); reaches anywhere up to the bound, or at
/// the exact `f32` distance of a point, a unit in the last place either side.
fn queries(
    points: &[Vec3],
    reach_max: f32,
    raw: &[(f32, f32, f32, f32, u8, u16)],
) -> Vec<(Vec3, f32)> {
    raw.iter()
        .map(|&(x, y, z, f, kind, pick)| {
            let p = points[pick as usize % points.len()];
            let c = match kind % 4 {
                0 => Vec3::new(x, y, z),
                1 => p,
                2 => Vec3::new(p.x, y, p.z),
                _ => p + 0.01 * Vec3::new(x, y, z),
            };
            let reach = match kind / 4 % 4 {
                0 => {
                    let q = points[(pick as usize / 3) % points.len()];
                    let (dx, dy, dz) = (c.x - q.x, c.y - q.y, c.z - q.z);
                    let d = (dx * dx + dy * dy + dz * dz).sqrt();
                    match kind / 16 % 3 {
                        0 => d,
                        1 => f32::from_bits(d.to_bits().saturating_add(1)),
                        _ => f32::from_bits(d.to_bits().saturating_sub(1)),
                    }
                }
                _ => f * reach_max,
            };
            (c, reach)
        })
        .collect()
}

fn raw_queries() -> impl Strategy<Value = Vec<(f32, f32, f32, f32, u8, u16)>> {
    prop::collection::vec(
        (
            -0.4..1.2_f32,
            -0.8..0.8_f32,
            -0.4..1.2_f32,
            0.0..1.0_f32,
            any::<u8>(),
            any::<u16>(),
        ),
        1..120,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every answer within the bound is brute force's and the tree's; beyond it, `None`.
    #[test]
    fn answers_are_brute_force(
        count in 1..2500_usize,
        spread in 0.005..0.6_f32,
        seed in any::<u64>(),
        reach_max in 0.0..0.2_f32,
        raw in raw_queries(),
    ) {
        let points = cloud_points(count, spread, seed);
        let tree = PointTree::new(&points);
        let built = AffordanceTree::new_polled(&tree, reach_max, &mit_star_spaces::Never);
        // Over the 8 MiB budget only if the lists (at most every point in each of at most
        // n/4 leaves, 12 bytes each) could be.
        let Some(affordances) = built else {
            prop_assert!(count > 1600, "{} points over budget", count);
            return Ok(());
        };
        prop_assert!(affordances.listed() >= points.len());
        for (c, reach) in queries(&points, reach_max, &raw) {
            let truth = brute(&points, c, reach);
            prop_assert_eq!(tree.any_within(c, reach), truth, "tree at {} {}", c, reach);
            match affordances.any_within(c, reach) {
                Some(answer) => prop_assert_eq!(answer, truth, "at {} {}", c, reach),
                None => prop_assert!(reach * reach > reach_max * reach_max, "{}", reach),
            }
            prop_assert_eq!(affordances.any_within(c, reach_max * 1.5 + 1e-3), None);
        }
    }

    /// An obstacle with affordances answers as one without, single and batched, for spheres
    /// within and beyond the radius they were built for.
    #[test]
    fn obstacles_answer_alike(
        count in 1..3000_usize,
        spread in 0.01..0.6_f32,
        seed in any::<u64>(),
        point_radius in 0.001..0.02_f64,
        max_radius in 0.0..0.12_f32,
        raw in raw_queries(),
    ) {
        let points = cloud_points(count, spread, seed);
        let cloud = PointCloud::new(points.clone()).unwrap().with_radius(point_radius).unwrap();
        let plain = CloudObstacle::new("plain", cloud.clone());
        let fast = CloudObstacle::new("fast", cloud).with_affordances(max_radius);
        prop_assert!(fast.affordances().is_some() || count > 1600, "{} points", count);
        let asked = queries(&points, max_radius * 1.2, &raw);
        let centers: Vec<Vec3> = asked.iter().map(|q| q.0).collect();
        let radii: Vec<f32> = asked.iter().map(|q| q.1).collect();
        let (mut a, mut b) = (vec![false; centers.len()], vec![false; centers.len()]);
        plain.touches_spheres(&centers, &radii, &mut a);
        fast.touches_spheres(&centers, &radii, &mut b);
        prop_assert_eq!(&a, &b);
        // Batches of three lanes: the affordances answer each lane.
        for (k, (cs, rs)) in centers.chunks(3).zip(radii.chunks(3)).enumerate() {
            let mut few = [false; 3];
            fast.touches_spheres(cs, rs, &mut few);
            prop_assert_eq!(&few[..cs.len()], &a[3 * k..3 * k + cs.len()]);
        }
        for (i, (&c, &r)) in centers.iter().zip(&radii).enumerate() {
            prop_assert_eq!(fast.touches_sphere(c, r), a[i], "at {} {}", c, r);
            prop_assert_eq!(plain.touches_sphere(c, r), a[i], "at {} {}", c, r);
        }
    }
}

/// A dense million points with a large reach outgrow the budget: the obstacle keeps its tree
/// alone, within 64 bytes a point; a sparse million with a small reach fits, within it too.
#[test]
fn a_million_points_stay_within_64_bytes_each() {
    let dense = cloud_points(1_000_000, 0.5, 7);
    let cloud = PointCloud::new(dense).unwrap();
    let obstacle = CloudObstacle::new("dense", cloud).with_affordances(0.08);
    assert!(obstacle.affordances().is_none());
    let sparse = cloud_points(1_000_000, 20.0, 9);
    let tree = PointTree::new(&sparse);
    let affordances = AffordanceTree::new_polled(&tree, 1e-4, &mit_star_spaces::Never).unwrap();
    let per_point = (tree.memory_bytes() + affordances.memory_bytes()) as f64 / 1e6;
    assert!(per_point <= 64.0, "{per_point} bytes a point");
    let c = sparse[123_456] + Vec3::new(5e-5, 0.0, 0.0);
    assert_eq!(affordances.any_within(c, 1e-4), Some(true));
    assert_eq!(
        affordances.any_within(c, 2e-5),
        Some(brute(&sparse, c, 2e-5))
    );
}

/// A build told to stop stops.
#[test]
fn a_polled_build_stops() {
    struct Always;
    impl mit_star_spaces::Stop for Always {
        fn should_stop(&self) -> bool {
            true
        }
    }
    let points = cloud_points(100_000, 0.5, 3);
    let tree = PointTree::new(&points);
    assert!(AffordanceTree::new_polled(&tree, 0.01, &Always).is_none());
}
