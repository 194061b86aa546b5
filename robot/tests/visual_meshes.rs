//! Visual elements and their meshes: colours resolved, origins and scales applied, files
//! found under package roots, failures named, and every shipped robot's meshes loaded.

use std::path::PathBuf;

use glam::Vec3;
use mit_star_robot::{
    MeshLoadError, MeshResolver, ResolveError, RobotModel, ShippedRobot, VisualGeometry,
    VisualMeshes,
};

/// One triangle, facing `+z`, as ASCII STL.
const TRIANGLE_STL: &str = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\n\
    vertex 0 1 0\nvertex 0 0 0\nendloop\nendfacet\nendsolid t\n";

/// A two-link robot: a mesh under a package (origin, scale, top-level material), a mirrored
/// copy, a missing mesh, and primitives on a link without spheres.
const URDF: &str = r#"<robot name="viewed">
  <material name="steel"><color rgba="0.5 0.5 0.6 1"/></material>
  <link name="base">
    <visual>
      <origin xyz="1 2 3" rpy="0 0 1.5707963267948966"/>
      <geometry><mesh filename="package://parts/meshes/tri.stl" scale="2 3 4"/></geometry>
      <material name="steel"/>
    </visual>
    <visual>
      <geometry><mesh filename="meshes/tri.stl" scale="-1 1 1"/></geometry>
      <material name="paint"><color rgba="1 0 0 1"/></material>
    </visual>
    <visual><geometry><mesh filename="package://parts/meshes/gone.dae"/></geometry></visual>
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
  </link>
  <link name="frame_only">
    <visual><geometry><box size="0.2 0.4 0.6"/></geometry><material name="paint"/></visual>
    <visual><geometry><sphere radius="0.1"/></geometry></visual>
    <visual><geometry><cylinder radius="0.1" length="0.3"/></geometry></visual>
  </link>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="frame_only"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>"#;

/// A package root holding `parts/meshes/tri.stl`, and the URDF's folder holding
/// `meshes/tri.stl`.
fn folders(name: &str) -> (PathBuf, PathBuf) {
    let base = std::env::temp_dir().join(format!("visual-meshes-{name}-{}", std::process::id()));
    let root = base.join("packages");
    let urdf = base.join("robot");
    for dir in [root.join("parts/meshes"), urdf.join("meshes")] {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("tri.stl"), TRIANGLE_STL).unwrap();
    }
    (urdf, root)
}

fn vertex(positions: &[f32], i: usize) -> Vec3 {
    Vec3::from_slice(&positions[3 * i..3 * i + 3])
}

#[test]
fn visual_meshes_are_placed_coloured_and_their_failures_named() {
    let model = RobotModel::from_urdf_str(URDF).unwrap();
    let frame_only = model.link_index("frame_only").unwrap();
    assert!(model.link_sphere_range(frame_only).is_empty());
    assert_eq!(model.visuals().len(), 6);
    assert!(matches!(
        model.visuals()[3].geometry,
        VisualGeometry::Box { .. }
    ));
    let (urdf_folder, root) = folders("placed");
    let visuals = VisualMeshes::load(
        &model,
        &MeshResolver::new(Some(urdf_folder), vec![root.clone()]),
    );
    // The missing file is reported and the others load.
    assert_eq!(visuals.meshes.len(), 5);
    let [failure] = visuals.failures.as_slice() else {
        panic!("{:?}", visuals.failures)
    };
    assert_eq!(failure.filename, "package://parts/meshes/gone.dae");
    assert_eq!(failure.link_name, "base");
    let MeshLoadError::Unresolved(ResolveError::NotFound { tried, .. }) = &failure.reason else {
        panic!("{failure}")
    };
    assert_eq!(
        tried,
        &[
            root.join("parts/meshes/gone.dae"),
            root.join("meshes/gone.dae")
        ]
    );
    assert!(failure.to_string().contains("gone.dae"), "{failure}");

    // Scale (2, 3, 4), then a quarter turn about z, then (1, 2, 3).
    let placed = &visuals.meshes[0];
    assert_eq!(
        placed.filename.as_deref(),
        Some("package://parts/meshes/tri.stl")
    );
    assert_eq!((placed.link, placed.triangle_count()), (0, 1));
    assert_eq!(placed.colour, Some([0.5, 0.5, 0.6, 1.0]));
    let corners: Vec<Vec3> = (0..3).map(|i| vertex(&placed.positions, i)).collect();
    for expected in [Vec3::new(1.0, 4.0, 3.0), Vec3::new(-2.0, 2.0, 3.0)] {
        assert!(
            corners.iter().any(|c| c.distance(expected) < 1e-5),
            "{expected} not among {corners:?}"
        );
    }

    // Mirrored in x, the triangle still faces +z.
    let mirrored = &visuals.meshes[1];
    let [a, b, c] = [0, 1, 2].map(|k| vertex(&mirrored.positions, mirrored.indices[k] as usize));
    assert!((b - a).cross(c - a).z > 0.0);
    assert!(vertex(&mirrored.positions, 0).x <= 0.0);
    assert_eq!(mirrored.colour, Some([1.0, 0.0, 0.0, 1.0]));

    // Primitives ride on the sphere-less link, the box with the material named earlier.
    let primitives: Vec<_> = visuals.of_link(frame_only).collect();
    assert_eq!(primitives.len(), 3);
    assert_eq!(primitives[0].triangle_count(), 12);
    assert_eq!(primitives[0].colour, Some([1.0, 0.0, 0.0, 1.0]));
    let extent = |m: &mit_star_robot::LinkMesh| {
        (0..m.vertex_count())
            .map(|i| vertex(&m.positions, i).abs())
            .fold(Vec3::ZERO, Vec3::max)
    };
    assert!(extent(primitives[0]).distance(Vec3::new(0.1, 0.2, 0.3)) < 1e-6);
    assert!((extent(primitives[1]).max_element() - 0.1).abs() < 1e-6);
    assert!((extent(primitives[2]).z - 0.15).abs() < 1e-6);
}

#[test]
fn package_names_need_a_root_and_a_corrupt_file_is_named() {
    let model = RobotModel::from_urdf_str(URDF).unwrap();
    let (urdf_folder, root) = folders("corrupt");
    let visuals = VisualMeshes::load(
        &model,
        &MeshResolver::new(Some(urdf_folder.clone()), vec![]),
    );
    let package: Vec<_> = visuals
        .failures
        .iter()
        .filter(|f| {
            matches!(
                f.reason,
                MeshLoadError::Unresolved(ResolveError::NoPackageRoot { .. })
            )
        })
        .map(|f| f.filename.as_str())
        .collect();
    assert_eq!(
        package,
        [
            "package://parts/meshes/tri.stl",
            "package://parts/meshes/gone.dae"
        ]
    );
    std::fs::write(root.join("parts/meshes/tri.stl"), "solid broken\nfacet").unwrap();
    let visuals = VisualMeshes::load(&model, &MeshResolver::new(Some(urdf_folder), vec![root]));
    let unreadable: Vec<_> = visuals
        .failures
        .iter()
        .filter(|f| matches!(f.reason, MeshLoadError::Unreadable(_)))
        .collect();
    assert_eq!(unreadable.len(), 1);
    assert!(
        unreadable[0].to_string().contains("tri.stl"),
        "{}",
        unreadable[0]
    );
    // The same name beside the URDF still loads.
    assert_eq!(visuals.meshes.len(), 4);
}

/// Per shipped robot: visual elements, meshes loaded, and triangles drawn.
const SHIPPED: [(&str, usize, usize, usize); 4] = [
    ("panda", 11, 11, 3_472),
    ("ur5", 17, 17, 64_885),
    // Fetch's mesh files are not shipped (their licence forbids commercial use): only its
    // sphere primitive is drawn.
    ("fetch", 17, 1, 960),
    ("baxter", 30, 30, 152_414),
];

#[test]
fn every_shipped_robots_visual_meshes_load() {
    for (name, elements, loaded, triangles) in SHIPPED {
        let robot = ShippedRobot::find(name).unwrap();
        let model = robot.model(false).unwrap();
        let visuals = VisualMeshes::load(&model, &robot.mesh_resolver());
        let failures: Vec<String> = visuals.failures.iter().map(ToString::to_string).collect();
        eprintln!(
            "{name}: {} visual elements, {} meshes loaded, {} triangles; failures: {failures:?}",
            model.visuals().len(),
            visuals.meshes.len(),
            visuals.triangle_count()
        );
        assert_eq!(model.visuals().len(), elements, "{name}");
        assert_eq!(visuals.meshes.len(), loaded, "{name}: {failures:?}");
        assert_eq!(visuals.triangle_count(), triangles, "{name}");
        assert!(
            visuals.failures.iter().all(|f| matches!(
                f.reason,
                MeshLoadError::Unresolved(ResolveError::NotFound { .. })
            )),
            "{name}: {failures:?}"
        );
        for mesh in &visuals.meshes {
            assert!(
                mesh.positions
                    .iter()
                    .all(|c| c.is_finite() && c.abs() < 2.0),
                "{name}"
            );
        }
    }
}

#[test]
fn a_shipped_robot_without_its_data_folder_loads_without_meshes() {
    let ur5 = ShippedRobot::find("ur5").unwrap();
    let model = ur5.model(false).unwrap();
    let moved = MeshResolver::new(
        Some(PathBuf::from("/nonexistent/ur5")),
        vec![PathBuf::from("/nonexistent/ur5")],
    );
    let visuals = VisualMeshes::load(&model, &moved);
    assert!(visuals.meshes.is_empty());
    assert_eq!(visuals.failures.len(), model.visuals().len());
    assert!(ur5.data_folder().join("ur5_spherized.urdf").is_file());
}
