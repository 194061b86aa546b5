//! The medial placement keeps the cover's guarantee on real meshes (issue 74, item 7): every
//! point of every triangle of the UR5's forearm and wrist meshes lies in some sphere, with
//! the protrusion bound within the tolerance, checked here with the spheres alone.

use std::path::Path;
use std::sync::atomic::AtomicBool;

use glam::DVec3;
use mit_star_robot::{CoverOptions, Placement, SphereCover, read_stl};

/// Points on a triangle: its corners and a barycentric grid of `n` steps per edge.
fn triangle_samples([a, b, c]: [DVec3; 3], n: u32) -> impl Iterator<Item = DVec3> {
    (0..=n).flat_map(move |i| {
        (0..=n - i).map(move |j| {
            let (u, v) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
            a + (b - a) * u + (c - a) * v
        })
    })
}

#[test]
fn the_medial_placement_holds_every_point_of_real_meshes() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/ur5/meshes/ur5/collision");
    let stop = AtomicBool::new(false);
    for file in ["forearm.stl", "wrist1.stl"] {
        let mesh = read_stl(&dir.join(file)).unwrap();
        let options = CoverOptions {
            tolerance: 0.02,
            max_spheres: None,
        };
        let cover = SphereCover::placed(&mesh, &options, Placement::Medial, &stop).unwrap();
        assert!(!cover.spheres.is_empty());
        assert!(
            cover.max_protrusion <= cover.tolerance + 1e-9 && cover.tolerance == 0.02,
            "{file}: bound {} tolerance {}",
            cover.max_protrusion,
            cover.tolerance
        );
        assert!(cover.measured_max <= cover.max_protrusion + 1e-9, "{file}");
        for t in 0..mesh.triangles().len() {
            for p in triangle_samples(mesh.corners(t), 6) {
                assert!(
                    cover
                        .spheres
                        .iter()
                        .any(|s| p.distance(s.centre) <= s.radius + 1e-12),
                    "{file}: triangle {t}: {p} outside every sphere"
                );
            }
        }
        // Fewer spheres than the grid placement at this tolerance, or as many.
        let grid = SphereCover::placed(&mesh, &options, Placement::Grid, &stop).unwrap();
        let fewest = SphereCover::placed(&mesh, &options, Placement::Fewest, &stop).unwrap();
        assert_eq!(
            fewest.spheres.len(),
            grid.spheres.len().min(cover.spheres.len()),
            "{file}"
        );
    }
}
