//! `spherise` on what real robot packages ship (issue 74, item 7): OBJ and COLLADA meshes
//! (with COLLADA's `<unit meter>`), Git LFS pointers and corrupt files covered by the
//! fallback with the file named, a fallback without spheres for a link said so, and a
//! whole-model sphere budget that keeps every mesh point inside the spheres.

use std::path::{Path, PathBuf};

use glam::DVec3;
use mit_star_robot::{
    CoverOptions, LinkSource, RobotModel, SpheriseError, SpheriseOptions, SpherisedUrdf,
};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mesh-formats-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A box `[0, 0.1] × [0, 0.04] × [0, 0.04]` (metres) as OBJ, with quads.
const BAR_OBJ: &str = "v 0 0 0\nv 0.1 0 0\nv 0.1 0.04 0\nv 0 0.04 0\n\
    v 0 0 0.04\nv 0.1 0 0.04\nv 0.1 0.04 0.04\nv 0 0.04 0.04\n\
    f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

/// The same box in millimetres as COLLADA, with `<unit meter="0.001">` and `Y_UP` (which
/// ROS's tools, and so `spherise`, do not apply).
fn bar_dae() -> String {
    let corners: Vec<String> = (0..8)
        .map(|i| {
            format!(
                "{} {} {}",
                if i & 1 == 0 { 0 } else { 100 },
                if i & 2 == 0 { 0 } else { 40 },
                if i & 4 == 0 { 0 } else { 40 }
            )
        })
        .collect();
    // Quads of corner indices (bit 0: x, bit 1: y, bit 2: z), outward.
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let triangles: Vec<String> = quads
        .iter()
        .map(|[a, b, c, d]| format!("{a} {b} {c} {a} {c} {d}"))
        .collect();
    format!(
        r##"<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="0.001"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="bar" name="bar">
      <mesh>
        <source id="bar-positions">
          <float_array id="bar-array" count="24">{}</float_array>
          <technique_common>
            <accessor source="#bar-array" count="8" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="bar-vertices"><input semantic="POSITION" source="#bar-positions"/></vertices>
        <triangles count="12"><input semantic="VERTEX" source="#bar-vertices" offset="0"/><p>{}</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="bar-node" name="bar"><instance_geometry url="#bar"/></node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
"##,
        corners.join(" "),
        triangles.join(" ")
    )
}

/// A two-link URDF: `a` with collision `geometry_a`, `b` with `geometry_b`.
fn two_links(geometry_a: &str, geometry_b: &str) -> String {
    format!(
        r#"<robot name="r">
  <link name="a"><collision><geometry>{geometry_a}</geometry></collision></link>
  <link name="b"><collision><geometry>{geometry_b}</geometry></collision></link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"#
    )
}

fn options(tolerance: f64) -> SpheriseOptions {
    SpheriseOptions {
        cover: CoverOptions {
            tolerance,
            max_spheres: None,
        },
        ..SpheriseOptions::default()
    }
}

/// Whether `p` (in link `link`'s frame) is inside one of the model's spheres of that link.
fn covered(model: &RobotModel, link: usize, p: DVec3) -> bool {
    model
        .spheres()
        .iter()
        .any(|s| s.link == link && p.distance(s.center) <= s.radius)
}

/// Points of a grid over each face of the box `[0, size]` (corners and edges included).
fn box_points(size: DVec3) -> Vec<DVec3> {
    let mut points = Vec::new();
    for i in 0..=10 {
        for j in 0..=10 {
            let (u, v) = (f64::from(i) / 10.0, f64::from(j) / 10.0);
            for side in [0.0, 1.0] {
                for p in [
                    DVec3::new(side, u, v),
                    DVec3::new(u, side, v),
                    DVec3::new(u, v, side),
                ] {
                    points.push(p * size);
                }
            }
        }
    }
    points
}

#[test]
fn obj_and_collada_meshes_are_covered_with_collada_units_applied() {
    let dir = scratch("formats");
    std::fs::write(dir.join("bar.obj"), BAR_OBJ).unwrap();
    std::fs::write(dir.join("bar.DAE"), bar_dae()).unwrap();
    let urdf = two_links(
        r#"<mesh filename="bar.obj"/>"#,
        r#"<mesh filename="bar.DAE"/>"#,
    );
    let spherised = SpherisedUrdf::from_text(&urdf, &dir, "test", &options(0.01)).unwrap();
    let model = RobotModel::from_urdf_str(&spherised.text).unwrap();
    let size = DVec3::new(0.1, 0.04, 0.04);
    for (index, report) in spherised.links.iter().enumerate() {
        assert_eq!(report.source, LinkSource::Covered);
        assert_eq!(report.triangles, 12, "{}", report.link);
        assert!(report.closed, "{}", report.link);
        assert!(report.max_protrusion.unwrap() <= 0.01 + 1e-6);
        for p in box_points(size) {
            assert!(covered(&model, index, p), "{}: {p}", report.link);
        }
        // In metres, not millimetres (a 100 m box), and not turned by the up-axis: nothing
        // reaches 15 mm beyond the box.
        for p in [
            DVec3::new(0.05, 0.02, 0.04 + 0.015),
            DVec3::new(0.05, -0.015, 0.02),
            DVec3::new(0.115, 0.02, 0.02),
        ] {
            assert!(!covered(&model, index, p), "{}: {p}", report.link);
        }
    }
}

const POINTER: &str = "version https://git-lfs.github.com/spec/v1\n\
    oid sha256:6a1c5c4e2b0f0a7b1b7b0e3c8d1e1f8a9b0c1d2e3f4a5b6c7d8e9f0a1b2c3d4e\nsize 48213\n";

#[test]
fn unreadable_meshes_fall_back_with_the_file_named_or_are_refused_saying_why() {
    let dir = scratch("fallback");
    std::fs::write(dir.join("pointer.stl"), POINTER).unwrap();
    std::fs::write(dir.join("corrupt.dae"), "<COLLADA><library_geometries>").unwrap();
    std::fs::write(dir.join("bar.obj"), BAR_OBJ).unwrap();
    let urdf = two_links(
        r#"<mesh filename="pointer.stl"/>"#,
        r#"<mesh filename="corrupt.dae"/>"#,
    );
    let sphere = |x: f64| {
        format!(
            r#"<collision><geometry><sphere radius="0.05"/></geometry><origin xyz="{x} 0 0"/></collision>"#
        )
    };
    let fallback = format!(
        r#"<robot name="r"><link name="a">{}{}</link><link name="b">{}</link></robot>"#,
        sphere(0.0),
        sphere(0.1),
        sphere(0.2)
    );
    // With spheres for both links in the fallback: both fall back, each naming its file.
    let with = SpheriseOptions {
        fallback: Some(fallback.clone()),
        ..options(0.01)
    };
    let spherised = SpherisedUrdf::from_text(&urdf, &dir, "test", &with).unwrap();
    let [a, b] = &spherised.links[..] else {
        panic!("two links")
    };
    assert_eq!((a.source, a.spheres), (LinkSource::Fallback, 2));
    assert_eq!((b.source, b.spheres), (LinkSource::Fallback, 1));
    assert!(
        a.unusable[0].starts_with("pointer.stl (") && a.unusable[0].contains("Git LFS pointer"),
        "{:?}",
        a.unusable
    );
    assert!(
        b.unusable[0].starts_with("corrupt.dae (") && b.unusable[0].contains("COLLADA"),
        "{:?}",
        b.unusable
    );
    // A fallback without spheres for link `b`: refused, saying the fallback lacks them.
    let lacking = SpheriseOptions {
        fallback: Some(fallback.replace(&sphere(0.2), "")),
        ..options(0.01)
    };
    let e = SpherisedUrdf::from_text(&urdf, &dir, "test", &lacking).unwrap_err();
    let SpheriseError::MissingMeshes {
        missing,
        fallback_given: true,
    } = &e
    else {
        panic!("{e}")
    };
    assert_eq!(missing.len(), 1);
    assert_eq!(missing[0].0, "b");
    let message = e.to_string();
    assert!(
        message.contains("the fallback URDF has no spheres for these links")
            && !message.contains("(--fallback)"),
        "{message}"
    );
    // Without a fallback: both files named with why, and the advice to give one.
    let e = SpherisedUrdf::from_text(&urdf, &dir, "test", &options(0.01)).unwrap_err();
    let message = e.to_string();
    for needle in [
        "a: pointer.stl (",
        "Git LFS pointer",
        "b: corrupt.dae (",
        "(--fallback)",
    ] {
        assert!(message.contains(needle), "`{needle}` not in {message}");
    }
}

/// Points spread over every triangle of a model's mesh: its vertices, and `n × n` points of
/// a barycentric grid on each triangle.
fn surface_samples(mesh: &mit_star_robot::TriangleMesh, n: u32) -> Vec<DVec3> {
    let mut points = mesh.vertices().to_vec();
    for t in 0..mesh.triangles().len() {
        let [a, b, c] = mesh.corners(t);
        for i in 0..=n {
            for j in 0..=(n - i) {
                let (u, v) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
                points.push(a + (b - a) * u + (c - a) * v);
            }
        }
    }
    points
}

#[test]
fn a_sphere_budget_keeps_every_mesh_point_inside_and_reports_what_it_costs() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/ur5/meshes/ur5");
    let urdf = two_links(
        r#"<mesh filename="collision/forearm.stl"/>"#,
        r#"<mesh filename="collision/wrist1.stl"/>"#,
    );
    let free = SpherisedUrdf::from_text(&urdf, &dir, "test", &options(0.01)).unwrap();
    let total = |s: &SpherisedUrdf| s.links.iter().map(|l| l.spheres).sum::<usize>();
    let budget = 20;
    assert!(total(&free) > budget, "{}", total(&free));
    let capped = SpherisedUrdf::from_text(
        &urdf,
        &dir,
        "test",
        &SpheriseOptions {
            max_spheres: Some(budget),
            ..options(0.01)
        },
    )
    .unwrap();
    assert!(total(&capped) <= budget, "{}", total(&capped));
    let model = RobotModel::from_urdf_str(&capped.text).unwrap();
    assert_eq!(model.spheres().len(), total(&capped));
    for (index, (file, report)) in ["forearm", "wrist1"].iter().zip(&capped.links).enumerate() {
        // The price: a coarser tolerance, bounded and measured.
        assert!(report.tolerance > 0.01, "{}", report.tolerance);
        let bound = report.max_protrusion.unwrap();
        let measured = report.measured_max.unwrap();
        assert!(bound <= report.tolerance + 1e-6, "{bound}");
        assert!(
            measured > 0.0 && measured <= bound + 1e-9,
            "{measured} {bound}"
        );
        // Still conservative: every vertex and a dense grid on every triangle is inside.
        let mesh = mit_star_robot::read_stl(&dir.join(format!("collision/{file}.stl"))).unwrap();
        for p in surface_samples(&mesh, 6) {
            assert!(covered(&model, index, p), "{file}: {p}");
        }
    }
    // A budget below one sphere per mesh is refused, naming the least.
    let e = SpherisedUrdf::from_text(
        &urdf,
        &dir,
        "test",
        &SpheriseOptions {
            max_spheres: Some(1),
            ..options(0.01)
        },
    )
    .unwrap_err();
    assert!(e.to_string().contains("at least 2"), "{e}");
}

#[test]
fn a_stop_flag_ends_a_cover_with_a_named_error() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/ur5/meshes/ur5");
    let urdf = two_links(
        r#"<mesh filename="collision/forearm.stl"/>"#,
        r#"<mesh filename="collision/wrist1.stl"/>"#,
    );
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(true));
    let e = SpherisedUrdf::from_text(
        &urdf,
        &dir,
        "test",
        &SpheriseOptions {
            stop: Some(stop),
            ..options(0.003)
        },
    )
    .unwrap_err();
    assert!(matches!(e, SpheriseError::Stopped), "{e}");
}
