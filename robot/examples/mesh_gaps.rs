//! `mesh_gaps`: how close the UR5's collision meshes come to each other and to the scene at
//! the starts and goals of the MotionBenchMaker problems.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/ur5/problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example mesh_gaps -- target/problems 100
//! ```
//!
//! First, per arm link, how many mesh vertices lie outside VAMP's hand-made spheres and how
//! far. Then, for each of the seven UR5 scenes and its first `N` problems, places the arm's seven
//! collision meshes (`robot/data/ur5/meshes/`) at the start and at the goal by the shipped
//! model's kinematics, and prints one line per configuration: the smallest distance between
//! two meshes whose pair the SRDF leaves checked (and the pair), and the smallest distance
//! from a mesh to an obstacle (and which). A distance of 0 means the meshes touch or cross.
//! These gaps bound what any conservative sphere cover can accept: a cover whose spheres
//! reach `t` beyond each mesh refuses a configuration whose gap is under `2t` (or `t` to an
//! obstacle), if the cover reaches that far where the meshes meet.

use std::path::Path;

use glam::{DAffine3, DQuat};
use mit_star_robot::{MbmProblem, ParryChecker, RobotModel};
use parry3d_f64::math::Pose;
use parry3d_f64::query::distance;
use parry3d_f64::shape::{SharedShape, TriMesh};

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::SEVEN_SCENES as SCENES;

const LINKS: [(&str, &str); 7] = [
    ("base_link", "base"),
    ("shoulder_link", "shoulder"),
    ("upper_arm_link", "upperarm"),
    ("forearm_link", "forearm"),
    ("wrist_1_link", "wrist1"),
    ("wrist_2_link", "wrist2"),
    ("wrist_3_link", "wrist3"),
];

fn pose(a: &DAffine3) -> Pose {
    Pose::from_parts(a.translation, DQuat::from_mat3(&a.matrix3))
}

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target/problems".into());
    let count: usize = args.next().map_or(20, |a| a.parse().expect("a count"));
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/ur5");
    let model =
        RobotModel::from_urdf_file(&data.join("ur5_spherized.urdf")).expect("the UR5 model");
    let srdf = std::fs::read_to_string(data.join("ur5.srdf")).expect("the SRDF");
    let disabled = |a: &str, b: &str| {
        srdf.lines().any(|l| {
            l.contains("disable_collisions")
                && ((l.contains(&format!("\"{a}\"")) && l.contains(&format!("\"{b}\""))) || a == b)
        })
    };
    let meshes: Vec<(usize, &str, SharedShape)> = LINKS
        .iter()
        .map(|(link, file)| {
            let mesh =
                mit_star_robot::read_stl(&data.join(format!("meshes/ur5/collision/{file}.stl")))
                    .expect("an STL");
            let shape =
                TriMesh::new(mesh.vertices().to_vec(), mesh.triangles().to_vec()).expect("a mesh");
            let index = model.link_index(link).expect("a UR5 link");
            (index, *link, SharedShape::new(shape))
        })
        .collect();
    // How far each mesh reaches outside the hand-made spheres of its link (they were fitted
    // by eye and make no promise to contain it).
    println!("link uncovered_vertices_of_all outside_max_mm");
    for (link, file) in LINKS {
        let mesh = mit_star_robot::read_stl(&data.join(format!("meshes/ur5/collision/{file}.stl")))
            .expect("an STL");
        let index = model.link_index(link).expect("a UR5 link");
        let outside: Vec<f64> = mesh
            .vertices()
            .iter()
            .map(|v| {
                model
                    .spheres()
                    .iter()
                    .filter(|s| s.link == index)
                    .map(|s| v.distance(s.center) - s.radius)
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        let uncovered = outside.iter().filter(|&&d| d > 0.0).count();
        let worst = outside.iter().copied().fold(0.0, f64::max);
        println!("{link} {uncovered}/{} {:.1}", outside.len(), worst * 1e3);
    }
    let fk = mit_star_robot::Kinematics::new(&model);
    let joints: Vec<&str> = model.joint_names().iter().map(String::as_str).collect();
    let mut poses = vec![DAffine3::IDENTITY; fk.link_count()];
    println!("scene instance which self_gap_mm pair obstacle_gap_mm obstacle_pair");
    for scene in SCENES {
        let dir = Path::new(&folder).join(format!("{scene}_ur5"));
        for index in 1..=count {
            let problem = MbmProblem::load(&dir, index).expect("a problem");
            let obstacles: Vec<(String, Pose, SharedShape)> = problem
                .scene
                .ids()
                .iter()
                .cloned()
                .zip(ParryChecker::obstacle_shapes(&problem.scene))
                .map(|(id, (pose, shape))| (id, pose, shape))
                .collect();
            for (which, q) in [
                ("start", problem.start_for(&joints).expect("start")),
                ("goal", problem.goal_for(&joints).expect("goal")),
            ] {
                fk.link_poses_f64(&q, &mut poses);
                let mut best = (f64::INFINITY, String::new());
                for (i, (a, an, sa)) in meshes.iter().enumerate() {
                    for (b, bn, sb) in &meshes[i + 1..] {
                        if disabled(an, bn) {
                            continue;
                        }
                        let d = distance(
                            &pose(&poses[*a]),
                            sa.as_ref(),
                            &pose(&poses[*b]),
                            sb.as_ref(),
                        )
                        .expect("a distance")
                        .distance;
                        if d < best.0 {
                            best = (d, format!("{an}/{bn}"));
                        }
                    }
                }
                let mut near = (f64::INFINITY, String::new());
                for (a, an, sa) in &meshes {
                    for (id, p, s) in &obstacles {
                        let d = distance(&pose(&poses[*a]), sa.as_ref(), p, s.as_ref())
                            .expect("a distance")
                            .distance;
                        if d < near.0 {
                            near = (d, format!("{an}/{id}"));
                        }
                    }
                }
                println!(
                    "{scene} {index} {which} {:.3} {} {:.3} {}",
                    best.0 * 1e3,
                    best.1,
                    near.0 * 1e3,
                    near.1
                );
            }
        }
    }
}
