//! The searched placement (`--placement searched`, what a sphere budget uses) keeps the
//! guarantee: on random unions of boxes, prisms and hollow boxes, no point of the solid
//! escapes the cover. Points are drawn on every triangle (a barycentric grid) and inside the
//! solid (a grid over the bounds, kept where this file's ray parity says inside), and each
//! must lie in a sphere; the cover's reported bound must hold at its spheres' surface
//! points outside every other sphere.

use std::sync::atomic::AtomicBool;

use glam::DVec3;
use mit_star_robot::{CoverOptions, Placement, SphereCover, TriangleMesh};
use proptest::prelude::*;

use crate::test_meshes::{inside, mesh_of, parts, prism, surface_distance};

/// The first point of the solid found outside every sphere, if any.
fn escaped(mesh: &TriangleMesh, cover: &SphereCover) -> Option<DVec3> {
    let held = |p: DVec3| {
        cover
            .spheres
            .iter()
            .any(|s| p.distance(s.centre) <= s.radius + 1e-12)
    };
    for t in 0..mesh.triangles().len() {
        let [a, b, c] = mesh.corners(t);
        for i in 0..=8 {
            for j in 0..=8 - i {
                let p = a + (b - a) * (f64::from(i) / 8.0) + (c - a) * (f64::from(j) / 8.0);
                if !held(p) {
                    return Some(p);
                }
            }
        }
    }
    let (lo, hi) = mesh.bounds();
    let steps = 14;
    for i in 0..=steps {
        for j in 0..=steps {
            for k in 0..=steps {
                let f = DVec3::new(f64::from(i), f64::from(j), f64::from(k)) / f64::from(steps);
                let p = lo + (hi - lo) * f;
                if inside(mesh, p) == Some(true) && !held(p) {
                    return Some(p);
                }
            }
        }
    }
    None
}

fn searched(mesh: &TriangleMesh, tolerance: f64) -> SphereCover {
    let options = CoverOptions {
        tolerance,
        max_spheres: None,
    };
    SphereCover::placed(mesh, &options, Placement::Searched, &AtomicBool::new(false)).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn no_point_escapes_a_searched_cover(
        parts in parts(),
        tolerance in 0.015..0.04_f64,
    ) {
        let mesh = mesh_of(&parts, 0.0);
        let cover = searched(&mesh, tolerance);
        prop_assert!(escaped(&mesh, &cover).is_none(), "{:?} escapes", escaped(&mesh, &cover));
        prop_assert!(cover.max_protrusion <= cover.tolerance + 1e-6);
        // The bound holds where the brute force looks: sphere surface points outside every
        // other sphere, at their distance to the mesh.
        for (i, s) in cover.spheres.iter().enumerate() {
            for k in 0..60 {
                let z = 1.0 - 2.0 * (f64::from(k) + 0.5) / 60.0;
                let (sin, cos) = (2.4 * f64::from(k)).sin_cos();
                let u = DVec3::new((1.0 - z * z).sqrt() * cos, (1.0 - z * z).sqrt() * sin, z);
                let p = s.centre + u * s.radius;
                let other = cover
                    .spheres
                    .iter()
                    .enumerate()
                    .any(|(j, o)| j != i && p.distance(o.centre) < o.radius);
                if !other {
                    prop_assert!(surface_distance(&mesh, p) <= cover.outward_error + 1e-9);
                }
            }
        }
    }
}

#[test]
fn the_check_catches_a_point_outside_and_the_search_takes_fewer_spheres() {
    // A link-like prism at 15 mm.
    let mesh = prism(0.05, 0.4, 16);
    let cover = searched(&mesh, 0.015);
    assert_eq!(escaped(&mesh, &cover), None);
    // The check is not blind: every sphere 2 mm smaller lets a point out.
    let mut shrunk = cover.clone();
    for s in &mut shrunk.spheres {
        s.radius -= 0.002;
    }
    assert!(escaped(&mesh, &shrunk).is_some());
    // The search starts from the medial placement's candidates and greedy cover, and ends
    // with no more spheres than the medial placement's merge of pairs.
    let medial = SphereCover::placed(
        &mesh,
        &CoverOptions {
            tolerance: 0.015,
            max_spheres: None,
        },
        Placement::Medial,
        &AtomicBool::new(false),
    )
    .unwrap();
    assert!(
        cover.spheres.len() <= medial.spheres.len(),
        "searched {} medial {}",
        cover.spheres.len(),
        medial.spheres.len()
    );
}
