//! Covers under a sphere budget (issue 74, item 7), on random meshes: random unions of
//! boxes and prisms, hollow boxes of plates (a filled inside), and the same shapes written
//! as triangle soups with every corner jittered (a welded mesh). Checked with this file's own
//! geometry, not the cover's:
//! - conservative: every vertex and points on a barycentric grid of every triangle lie in a
//!   sphere;
//! - the outward error reported is at least the one measured by brute force: points of each
//!   sphere's surface outside every other sphere (on the union's boundary), at their
//!   distance to the nearest triangle;
//! - the budget is kept.

use glam::DVec3;
use mit_star_robot::{CoverOptions, SphereCover, TriangleMesh};
use proptest::prelude::*;

use crate::test_meshes::{Part, mesh_of, parts, surface_distance};

/// `n` points spread over the unit sphere.
fn unit_sphere(n: usize) -> impl Iterator<Item = DVec3> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n).map(move |i| {
        let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
        let r = (1.0 - z * z).sqrt();
        let (s, c) = (golden * i as f64).sin_cos();
        DVec3::new(r * c, r * s, z)
    })
}

fn check_cover(mesh: &TriangleMesh, options: &CoverOptions) -> Result<(), TestCaseError> {
    let cover = SphereCover::new(mesh, options).unwrap();
    let spheres = &cover.spheres;
    let inside = |p: DVec3| {
        spheres
            .iter()
            .any(|s| p.distance(s.centre) <= s.radius + 1e-9)
    };
    // Conservative: vertices, and a grid of 6 steps per edge on every triangle.
    for &v in mesh.vertices() {
        prop_assert!(inside(v), "vertex {v} outside");
    }
    for t in 0..mesh.triangles().len() {
        let [a, b, c] = mesh.corners(t);
        for i in 0..=6 {
            for j in 0..=6 - i {
                let (u, v) = (f64::from(i) / 6.0, f64::from(j) / 6.0);
                let p = a + (b - a) * u + (c - a) * v;
                prop_assert!(inside(p), "point {p} of triangle {t} outside");
            }
        }
    }
    // The reported outward error is at least the brute-force one.
    let mut brute: f64 = 0.0;
    for (i, s) in spheres.iter().enumerate() {
        for u in unit_sphere(300) {
            let p = s.centre + u * s.radius;
            let covered = spheres
                .iter()
                .enumerate()
                .any(|(j, o)| j != i && p.distance(o.centre) < o.radius);
            if !covered {
                brute = brute.max(surface_distance(mesh, p));
            }
        }
    }
    prop_assert!(
        brute <= cover.outward_error + 1e-9,
        "brute force {brute} above the reported {}",
        cover.outward_error
    );
    prop_assert!(cover.measured_max <= cover.outward_error + 1e-12);
    // The budget is kept unless the tolerance ran to its cap.
    if let Some(m) = options.max_spheres
        && cover.tolerance < 1e3 * options.tolerance
    {
        prop_assert!(
            spheres.len() <= m,
            "{} spheres for a budget of {m}",
            spheres.len()
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn budgeted_covers_hold_every_point_and_report_at_least_the_error(
        parts in parts(),
        tolerance in 0.012..0.04_f64,
        budget in prop::option::of(2_usize..30),
        jitter in prop::sample::select(vec![0.0, 2e-7]),
    ) {
        let mesh = mesh_of(&parts, jitter);
        check_cover(&mesh, &CoverOptions { tolerance, max_spheres: budget })?;
    }
}

#[test]
fn a_hollow_box_is_filled_and_a_cracked_one_welded() {
    // A hollow box of plates: the cover fills it, with few spheres at a coarse tolerance.
    let hollow = mesh_of(
        &[Part {
            kind: 2,
            size: [0.06, 0.05, 0.08],
            at: [0.0; 3],
            turn: 0.0,
        }],
        0.0,
    );
    let options = CoverOptions {
        tolerance: 0.03,
        max_spheres: None,
    };
    let cover = SphereCover::new(&hollow, &options).unwrap();
    assert!(cover.filled && cover.weld == 0.0);
    // The centre of the hollow is inside a sphere: the inside is filled.
    assert!(
        cover
            .spheres
            .iter()
            .any(|s| s.centre.length() + 0.02 <= s.radius)
    );
    check_cover(&hollow, &options).unwrap();
    // The same box as a jittered soup: open as given, closed by a merge.
    let cracked = mesh_of(
        &[Part {
            kind: 0,
            size: [0.06, 0.05, 0.08],
            at: [0.0; 3],
            turn: 0.3,
        }],
        2e-7,
    );
    assert!(!cracked.is_closed());
    let cover = SphereCover::new(&cracked, &options).unwrap();
    assert!(cover.closed && cover.weld > 0.0 && cover.weld < 0.03 / 20.0);
    check_cover(&cracked, &options).unwrap();
}
