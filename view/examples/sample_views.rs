//! Writes synthetic view pages to a folder, for looking at and for the browser check
//! (`node view/web/browser_check.mjs FOLDER/*.html`):
//!
//! - `arm.html`: a toy arm (spheres and one box mesh per link), a plan and a timed trajectory;
//! - `world2d.html`: a 2-D box world with the search's tree and the informed ellipse;
//! - `world3d.html`: a 3-D box world;
//! - `stress_frames.html`, `stress_boxes.html`, `stress_cloud.html`, `stress_all.html`: a motion
//!   of 10⁶ frames, 10⁵ boxes, a 10⁶-point cloud, and all three at once with 10⁶ search edges.
//!
//! `cargo run -p mit-star-view --release --example sample_views -- FOLDER`

use std::f32::consts::PI;
use std::path::{Path, PathBuf};
use std::time::Instant;

use mit_star_view::{
    CloudView, InformedView, LinkView, MeshView, MotionView, RobotView, SearchOverlay, ShapeView,
    SolidView, ViewDocument, ViewError, ViewKind, ViewLimits,
};

/// A small deterministic generator (xorshift64*), so the pages are the same every run.
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 40) as f32 / (1u64 << 24) as f32
    }

    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
}

type Quat = [f32; 4];

fn quat_mul(a: Quat, b: Quat) -> Quat {
    [
        a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
        a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
        a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
        a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
    ]
}

fn rotate(q: Quat, v: [f32; 3]) -> [f32; 3] {
    let p = quat_mul(
        quat_mul(q, [v[0], v[1], v[2], 0.0]),
        [-q[0], -q[1], -q[2], q[3]],
    );
    [p[0], p[1], p[2]]
}

const LENGTHS: [f32; 3] = [0.3, 0.4, 0.35];

/// The toy arm's link poses (base, upper, fore, hand) at joints `q`, 7 values each.
fn arm_poses(q: [f32; 3], out: &mut Vec<f32>) {
    let yaw = [0.0, 0.0, (q[0] / 2.0).sin(), (q[0] / 2.0).cos()];
    let pitch = |a: f32| [0.0, (a / 2.0).sin(), 0.0, (a / 2.0).cos()];
    let r1 = quat_mul(yaw, pitch(q[1]));
    let r2 = quat_mul(yaw, pitch(q[1] + q[2]));
    let p1 = [0.0, 0.0, LENGTHS[0]];
    let d1 = rotate(r1, [LENGTHS[1], 0.0, 0.0]);
    let p2 = [p1[0] + d1[0], p1[1] + d1[1], p1[2] + d1[2]];
    let d2 = rotate(r2, [LENGTHS[2], 0.0, 0.0]);
    let p3 = [p2[0] + d2[0], p2[1] + d2[1], p2[2] + d2[2]];
    for (p, r) in [([0.0; 3], yaw), (p1, r1), (p2, r2), (p3, r2)] {
        out.extend_from_slice(&p);
        out.extend_from_slice(&r);
    }
}

/// A box mesh from `lo` to `hi` (12 triangles).
fn box_mesh(lo: [f32; 3], hi: [f32; 3], colour: [f32; 3]) -> MeshView {
    let mut positions = Vec::new();
    for k in 0..8 {
        for (axis, bit) in [(0, 1), (1, 2), (2, 4)] {
            positions.push(if k & bit == 0 { lo[axis] } else { hi[axis] });
        }
    }
    let faces = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let indices = faces
        .iter()
        .flat_map(|[a, b, c, d]| [*a, *b, *c, *a, *c, *d])
        .collect();
    MeshView {
        positions,
        indices,
        colour,
    }
}

fn toy_robot() -> RobotView {
    let along = |length: f32, r: f32, n: usize| -> Vec<f32> {
        (0..n)
            .flat_map(|i| [length * (i as f32 + 0.5) / n as f32, 0.0, 0.0, r])
            .collect()
    };
    let link = |name: &str, spheres: Vec<f32>, mesh: MeshView| LinkView {
        name: name.into(),
        spheres,
        meshes: vec![mesh],
    };
    RobotView {
        name: "toy arm".into(),
        links: vec![
            link(
                "base",
                vec![0.0, 0.0, 0.08, 0.09, 0.0, 0.0, 0.22, 0.07],
                box_mesh([-0.08, -0.08, 0.0], [0.08, 0.08, 0.3], [0.35, 0.35, 0.4]),
            ),
            link(
                "upper",
                along(LENGTHS[1], 0.05, 5),
                box_mesh([0.0, -0.05, -0.05], [0.4, 0.05, 0.05], [0.9, 0.45, 0.1]),
            ),
            link(
                "fore",
                along(LENGTHS[2], 0.04, 5),
                box_mesh([0.0, -0.04, -0.04], [0.35, 0.04, 0.04], [0.9, 0.55, 0.15]),
            ),
            link(
                "hand",
                vec![0.03, 0.0, 0.0, 0.045],
                box_mesh([0.0, -0.06, -0.03], [0.06, 0.06, 0.03], [0.2, 0.2, 0.25]),
            ),
        ],
        hand: 3,
    }
}

fn cuboid(name: String, centre: [f32; 3], half: [f32; 3]) -> SolidView {
    SolidView {
        name,
        shape: ShapeView::Cuboid { half_extents: half },
        position: centre,
        rotation: [0.0, 0.0, 0.0, 1.0],
    }
}

fn inside(solids: &[SolidView], p: [f32; 3]) -> bool {
    solids.iter().any(|s| match s.shape {
        ShapeView::Cuboid { half_extents } => {
            (0..3).all(|k| (p[k] - s.position[k]).abs() <= half_extents[k])
        }
        _ => false,
    })
}

/// An arm motion through joint waypoints, `per_leg` frames a leg; colliding where the hand is
/// inside a solid.
fn arm_motion(
    label: &str,
    waypoints: &[[f32; 3]],
    per_leg: usize,
    timed: bool,
    solids: &[SolidView],
) -> MotionView {
    let (mut joints, mut poses, mut marks) = (Vec::new(), Vec::new(), Vec::new());
    let frames = (waypoints.len() - 1) * per_leg + 1;
    for f in 0..frames {
        let leg = (f / per_leg).min(waypoints.len() - 2);
        let t = (f - leg * per_leg) as f32 / per_leg as f32;
        let q: [f32; 3] =
            std::array::from_fn(|k| waypoints[leg][k] * (1.0 - t) + waypoints[leg + 1][k] * t);
        joints.extend_from_slice(&q);
        arm_poses(q, &mut poses);
        if f % per_leg == 0 {
            marks.push(f);
        }
    }
    let colliding = (0..frames)
        .filter(|&f| inside(solids, std::array::from_fn(|k| poses[(f * 4 + 3) * 7 + k])))
        .collect();
    // A trajectory slows down at the ends: time grows like the arc sine of the progress.
    let times = timed.then(|| {
        (0..frames)
            .map(|f| {
                f64::from(2.0 * (f as f32 / (frames - 1) as f32) - 1.0).asin()
                    + std::f64::consts::FRAC_PI_2
            })
            .collect()
    });
    MotionView {
        label: label.into(),
        joint_names: vec!["yaw".into(), "shoulder".into(), "elbow".into()],
        frames,
        joints,
        poses,
        times,
        waypoints: marks,
        colliding,
        mover_positions: Vec::new(),
    }
}

fn arm_page() -> ViewDocument {
    let mut doc = ViewDocument::new(ViewKind::Arm, "Toy arm: a plan and its trajectory");
    doc.subtitle = vec![
        "problem: reach over the block".into(),
        "planner: synthetic".into(),
    ];
    doc.robot = Some(toy_robot());
    doc.scene.solids = vec![
        cuboid("block".into(), [0.45, 0.0, 0.1], [0.1, 0.25, 0.1]),
        cuboid("table".into(), [0.4, 0.0, -0.02], [0.4, 0.6, 0.02]),
    ];
    let waypoints = [
        [-1.2, -0.3, 0.9],
        [-0.4, -0.9, 1.2],
        [0.3, -0.2, 1.6],
        [1.1, 0.4, 1.0],
    ];
    let plan = arm_motion("plan", &waypoints, 33, false, &doc.scene.solids);
    let trajectory = arm_motion("trajectory", &waypoints, 33, true, &doc.scene.solids);
    doc.motions = vec![plan, trajectory];
    doc
}

/// A point moving through box-world waypoints, `per_leg` frames a leg.
fn point_motion(waypoints: &[[f32; 3]], per_leg: usize, solids: &[SolidView]) -> MotionView {
    let frames = (waypoints.len() - 1) * per_leg + 1;
    let mut poses = Vec::with_capacity(frames * 3);
    for f in 0..frames {
        let leg = (f / per_leg).min(waypoints.len() - 2);
        let t = (f - leg * per_leg) as f32 / per_leg as f32;
        poses.extend((0..3).map(|k| waypoints[leg][k] * (1.0 - t) + waypoints[leg + 1][k] * t));
    }
    let colliding = (0..frames)
        .filter(|&f| inside(solids, [poses[3 * f], poses[3 * f + 1], poses[3 * f + 2]]))
        .collect();
    MotionView {
        label: "plan".into(),
        joint_names: vec!["x".into(), "y".into(), "z".into()],
        frames,
        joints: poses.clone(),
        poses,
        times: None,
        waypoints: (0..waypoints.len()).map(|i| i * per_leg).collect(),
        colliding,
        mover_positions: Vec::new(),
    }
}

fn random_boxes(noise: &mut Noise, n: usize, size: f32, flat: bool) -> Vec<SolidView> {
    (0..n)
        .map(|i| {
            let z = if flat { 0.0 } else { noise.range(0.1, 0.9) };
            let hz = if flat {
                0.0
            } else {
                noise.range(0.2, 1.0) * size
            };
            let centre = [noise.range(0.1, 0.9), noise.range(0.1, 0.9), z];
            cuboid(
                format!("box {i}"),
                centre,
                [
                    noise.range(0.2, 1.0) * size,
                    noise.range(0.2, 1.0) * size,
                    hz,
                ],
            )
        })
        .collect()
}

/// A random tree grown towards samples, its edges as segments with their cost-to-come.
fn search_tree(noise: &mut Noise, n: usize, root: [f32; 3]) -> SearchOverlay {
    let mut nodes = vec![(root, 0.0_f32)];
    let (mut segments, mut costs) = (Vec::new(), Vec::new());
    while nodes.len() < n {
        let sample = [noise.next(), noise.next(), 0.0];
        let dist = |p: [f32; 3]| ((p[0] - sample[0]).powi(2) + (p[1] - sample[1]).powi(2)).sqrt();
        let (near, cost) = *nodes
            .iter()
            .min_by(|a, b| dist(a.0).total_cmp(&dist(b.0)))
            .expect("the root is there");
        let d = dist(near);
        let step = d.min(0.03);
        let new = [
            near[0] + (sample[0] - near[0]) * step / d.max(1e-9),
            near[1] + (sample[1] - near[1]) * step / d.max(1e-9),
            0.0,
        ];
        segments.extend_from_slice(&near);
        segments.extend_from_slice(&new);
        costs.push(cost + step);
        nodes.push((new, cost + step));
    }
    SearchOverlay {
        segments,
        costs,
        informed: None,
        label: format!("forward tree, {} edges", n - 1),
    }
}

fn world2d_page() -> ViewDocument {
    let mut noise = Noise(7);
    let mut doc = ViewDocument::new(ViewKind::World2d, "2-D box world: tree and informed set");
    doc.subtitle = vec!["30 boxes, unit square".into()];
    doc.scene.solids = random_boxes(&mut noise, 30, 0.06, true);
    doc.scene.bounds = Some([[0.0, 0.0, 0.0], [1.0, 1.0, 0.0]]);
    let path = [
        [0.05, 0.05, 0.0],
        [0.35, 0.2, 0.0],
        [0.6, 0.55, 0.0],
        [0.95, 0.95, 0.0],
    ];
    doc.motions = vec![point_motion(&path, 60, &doc.scene.solids)];
    let mut search = search_tree(&mut noise, 3000, path[0]);
    let cost: f32 = path
        .windows(2)
        .map(|w| ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt())
        .sum();
    search.informed = Some(InformedView {
        start: path[0],
        goal: path[3],
        cost,
    });
    doc.search = Some(search);
    doc
}

fn world3d_page(boxes: usize, per_leg: usize, title: &str) -> ViewDocument {
    let mut noise = Noise(11);
    let mut doc = ViewDocument::new(ViewKind::World3d, title);
    doc.subtitle = vec![format!("{boxes} boxes, unit cube")];
    let size = 0.5 / (boxes as f32).cbrt();
    doc.scene.solids = random_boxes(&mut noise, boxes, size, false);
    doc.scene.bounds = Some([[0.0; 3], [1.0; 3]]);
    let path = [
        [0.05, 0.05, 0.05],
        [0.5, 0.2, 0.6],
        [0.7, 0.8, 0.4],
        [0.95, 0.95, 0.95],
    ];
    doc.motions = vec![point_motion(&path, per_leg, &doc.scene.solids)];
    doc
}

fn cloud(noise: &mut Noise, n: usize) -> CloudView {
    let points = (0..n)
        .flat_map(|_| {
            let (a, b) = (noise.range(-PI, PI), noise.range(-0.4, 0.4));
            [
                0.55 + 0.25 * a.cos() * b.cos(),
                0.25 * a.sin() * b.cos(),
                0.25 + 0.25 * b.sin(),
            ]
        })
        .collect();
    CloudView {
        name: "scan".into(),
        points,
        radius: 0.004,
    }
}

fn stress_frames() -> ViewDocument {
    let mut doc = arm_page();
    doc.title = "Stress: a motion of 1 000 000 frames".into();
    let waypoints = [[-1.2, -0.3, 0.9], [0.0, -1.0, 1.4], [1.1, 0.4, 1.0]];
    doc.motions = vec![arm_motion(
        "plan",
        &waypoints,
        500_000,
        true,
        &doc.scene.solids,
    )];
    doc
}

fn stress_cloud() -> ViewDocument {
    let mut doc = arm_page();
    doc.title = "Stress: a cloud of 1 000 000 points".into();
    doc.scene.clouds = vec![cloud(&mut Noise(3), 1_000_000)];
    doc
}

fn stress_all() -> ViewDocument {
    let mut doc = stress_frames();
    doc.title = "Stress: 10⁶ frames, 10⁵ boxes, 10⁶ cloud points".into();
    let mut noise = Noise(5);
    doc.scene.solids.extend((0..100_000).map(|i| {
        let (x, y) = (noise.range(-1.0, 1.0), noise.range(-1.0, 1.0));
        cuboid(
            format!("clutter {i}"),
            [x, y, -0.05],
            [0.004, 0.004, noise.range(0.002, 0.02)],
        )
    }));
    doc.scene.clouds = vec![cloud(&mut noise, 1_000_000)];
    // 10⁶ short random edges over the table, costs growing with the distance from the base.
    let mut segments = Vec::with_capacity(6_000_000);
    let mut costs = Vec::with_capacity(1_000_000);
    for _ in 0..1_000_000 {
        let a = [
            noise.range(-0.8, 0.8),
            noise.range(-0.8, 0.8),
            noise.range(0.0, 0.8),
        ];
        let b = [
            a[0] + noise.range(-0.02, 0.02),
            a[1] + noise.range(-0.02, 0.02),
            a[2],
        ];
        segments.extend_from_slice(&a);
        segments.extend_from_slice(&b);
        costs.push((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt());
    }
    doc.search = Some(SearchOverlay {
        segments,
        costs,
        informed: None,
        label: "random edges, 10⁶".into(),
    });
    doc
}

fn write(folder: &Path, name: &str, doc: &ViewDocument) -> Result<(), ViewError> {
    let path: PathBuf = folder.join(format!("{name}.html"));
    let started = Instant::now();
    let bytes = doc.write_html(&path, ViewLimits::default())?;
    println!(
        "{:<22} {:>10} bytes, written in {:>6.0} ms",
        format!("{name}.html"),
        bytes,
        started.elapsed().as_secs_f64() * 1e3
    );
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let folder = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "target/sample_views".into()),
    );
    std::fs::create_dir_all(&folder)?;
    write(&folder, "arm", &arm_page())?;
    write(&folder, "world2d", &world2d_page())?;
    write(&folder, "world3d", &world3d_page(40, 60, "3-D box world"))?;
    write(&folder, "stress_frames", &stress_frames())?;
    write(
        &folder,
        "stress_boxes",
        &world3d_page(100_000, 400, "Stress: 100 000 boxes"),
    )?;
    write(&folder, "stress_cloud", &stress_cloud())?;
    write(&folder, "stress_all", &stress_all())?;
    Ok(())
}
