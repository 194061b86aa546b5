//! `held_out`: seeded table-and-shelf problems for any sphere robot, written as a
//! MotionBenchMaker folder (`sceneNNNN.yaml` + `requestNNNN.yaml`) that `mit-star bench
//! --problem mbm:FOLDER --robot URDF` plans and audits.
//!
//! ```text
//! cargo run --release -p mit-star-robot --example held_out -- ROBOT.urdf OUT_FOLDER [COUNT=24] [SEED=1] [SPREAD=1]
//! ```
//!
//! For robots that ship nowhere in this repository (cuRobo's, converted by
//! `benches/peers/curobo/convert.py`): the robot's reach is estimated from the tip (the last
//! sphere of the last link, in tree order, that has spheres) over random configurations; then
//! each problem draws
//! - a goal configuration whose tip is within 35–85 % of the horizontal reach, and a shelf
//!   around that tip (bottom and top plates, a back wall and two sides, opening towards the
//!   robot's base), with one or two boxes on its bottom plate;
//! - a start configuration whose tip is at least 60° around from the goal's, and a table
//!   below that tip with two or three boxes on it;
//!
//! and keeps the scene when both ends are valid (collision-free, within limits, joinable by
//! certified motions: [`ArmProblem::ends_are_valid`]); else it draws again. Sizes scale with
//! the reach (a UR5's 0.85 m is scale 1). `SPREAD` (in (0, 1]) draws every joint within that
//! fraction of its range around the range's middle (two arms drawn over their whole ranges
//! end up folded around each other, in poses no motion joins). Prints, per problem, the
//! attempts it took.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use glam::{DAffine3, DQuat, DVec3};
use mit_star_robot::{ArmProblem, Kinematics, Obstacle, RobotModel, RobotSource, Scene, Shape};
use mit_star_spaces::JointKind;

/// A seeded xorshift generator of uniform numbers.
struct Uniform(u64);

impl Uniform {
    fn next(&mut self, low: f64, high: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        low + (high - low) * (self.0 >> 11) as f64 / (1_u64 << 53) as f64
    }
}

/// A box obstacle: id, full side lengths, centre and yaw.
struct BoxSpec {
    id: String,
    size: DVec3,
    centre: DVec3,
    yaw: f64,
}

/// Draws configurations and finds the tip of the robot.
struct Drawer {
    model: RobotModel,
    fk: Kinematics,
    tip: usize,
    spread: f64,
    links: Vec<DAffine3>,
    centres: Vec<(DVec3, f64)>,
}

impl Drawer {
    fn new(model: RobotModel, spread: f64) -> Self {
        let fk = Kinematics::new(&model);
        let tip = (0..model.links().len())
            .rev()
            .find_map(|l| model.link_sphere_range(l).last())
            .expect("a robot with spheres");
        let links = vec![DAffine3::IDENTITY; fk.link_count()];
        let centres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        Self {
            model,
            fk,
            tip,
            spread,
            links,
            centres,
        }
    }

    fn configuration(&self, rng: &mut Uniform) -> Vec<f64> {
        self.model
            .joint_space()
            .joints()
            .iter()
            .map(|j| match j.kind {
                JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper } => {
                    let (middle, half) = ((lower + upper) / 2.0, (upper - lower) / 2.0);
                    rng.next(middle - half * self.spread, middle + half * self.spread)
                }
                JointKind::Continuous => {
                    let half = std::f64::consts::PI * self.spread;
                    rng.next(-half, half)
                }
            })
            .collect()
    }

    fn tip_of(&mut self, q: &[f64]) -> DVec3 {
        self.fk
            .sphere_centers_f64(q, &mut self.links, &mut self.centres);
        self.centres[self.tip].0
    }
}

fn box_obstacle(b: &BoxSpec) -> Obstacle {
    Obstacle::new(
        Shape::Cuboid {
            half_extents: b.size / 2.0,
        },
        b.centre,
        DQuat::from_rotation_z(b.yaw),
    )
}

/// The shelf around `tip` (opening towards the base) with boxes on its bottom plate.
fn shelf(tip: DVec3, scale: f64, rng: &mut Uniform, out: &mut Vec<BoxSpec>) {
    let yaw = tip.y.atan2(tip.x);
    let (u, v) = (
        DVec3::new(yaw.cos(), yaw.sin(), 0.0),
        DVec3::new(-yaw.sin(), yaw.cos(), 0.0),
    );
    let depth = 0.35 * scale;
    let width = rng.next(0.5, 0.7) * scale;
    let (below, above) = (rng.next(0.08, 0.14) * scale, rng.next(0.18, 0.3) * scale);
    let thick = 0.02;
    let front = tip - u * rng.next(0.05, 0.12) * scale;
    let middle = front + u * depth / 2.0;
    let height = below + above;
    let floor = tip.z - below;
    let mut add = |id: &str, size: DVec3, centre: DVec3| {
        out.push(BoxSpec {
            id: id.to_owned(),
            size,
            centre,
            yaw,
        });
    };
    add(
        "shelf_bottom",
        DVec3::new(depth, width, thick),
        middle.with_z(floor - thick / 2.0),
    );
    add(
        "shelf_top",
        DVec3::new(depth, width, thick),
        middle.with_z(floor + height + thick / 2.0),
    );
    add(
        "shelf_back",
        DVec3::new(thick, width, height),
        (front + u * (depth + thick / 2.0)).with_z(floor + height / 2.0),
    );
    for (side, sign) in [("shelf_left", 1.0), ("shelf_right", -1.0)] {
        add(
            side,
            DVec3::new(depth, thick, height),
            (middle + v * sign * (width + thick) / 2.0).with_z(floor + height / 2.0),
        );
    }
    let boxes = if rng.next(0.0, 1.0) < 0.5 { 1 } else { 2 };
    for k in 0..boxes {
        let size = DVec3::new(
            rng.next(0.05, 0.09),
            rng.next(0.05, 0.09),
            rng.next(0.06, below + above * 0.5),
        ) * scale;
        let side = if k == 0 { 1.0 } else { -1.0 };
        let lateral = side * rng.next(0.12, 0.2) * width;
        let centre =
            (front + u * rng.next(0.1, 0.25) * scale + v * lateral).with_z(floor + size.z / 2.0);
        add(&format!("shelf_box{k}"), size, centre);
    }
}

/// A table below `tip` with two or three boxes on it.
fn table(tip: DVec3, scale: f64, rng: &mut Uniform, out: &mut Vec<BoxSpec>) {
    let yaw = tip.y.atan2(tip.x);
    let u = DVec3::new(yaw.cos(), yaw.sin(), 0.0);
    let top = tip.z - rng.next(0.1, 0.2) * scale;
    let size = DVec3::new(rng.next(0.5, 0.7) * scale, rng.next(0.7, 1.0) * scale, 0.04);
    let centre = (tip + u * rng.next(0.0, 0.15) * scale).with_z(top - size.z / 2.0);
    out.push(BoxSpec {
        id: "table".into(),
        size,
        centre,
        yaw,
    });
    let count = 2 + usize::from(rng.next(0.0, 1.0) < 0.5);
    let rotation = DQuat::from_rotation_z(yaw);
    for k in 0..count {
        let b = DVec3::new(
            rng.next(0.05, 0.12),
            rng.next(0.05, 0.12),
            rng.next(0.05, 0.15),
        ) * scale;
        let local = DVec3::new(
            rng.next(-0.4, 0.4) * size.x,
            rng.next(-0.4, 0.4) * size.y,
            0.0,
        );
        out.push(BoxSpec {
            id: format!("table_box{k}"),
            size: b,
            centre: (centre + rotation * local).with_z(top + b.z / 2.0),
            yaw: yaw + rng.next(-0.5, 0.5),
        });
    }
}

fn list(values: impl IntoIterator<Item = f64>) -> String {
    let v: Vec<String> = values.into_iter().map(|x| format!("{x:.9}")).collect();
    format!("[{}]", v.join(", "))
}

fn scene_yaml(boxes: &[BoxSpec]) -> String {
    let mut text = String::from("world:\n  collision_objects:\n");
    for b in boxes {
        let q = DQuat::from_rotation_z(b.yaw);
        let _ = write!(
            text,
            "    - id: {}\n      primitives:\n        - type: box\n          dimensions: {}\n      \
             primitive_poses:\n        - position: {}\n          orientation: {}\n",
            b.id,
            list(b.size.to_array()),
            list(b.centre.to_array()),
            list([q.x, q.y, q.z, q.w])
        );
    }
    text
}

fn request_yaml(names: &[String], start: &[f64], goal: &[f64]) -> String {
    let mut text = format!(
        "start_state:\n  joint_state:\n    name: [{}]\n    position: {}\ngoal_constraints:\n  - \
         joint_constraints:\n",
        names.join(", "),
        list(start.iter().copied())
    );
    for (name, value) in names.iter().zip(goal) {
        let _ = write!(
            text,
            "      - joint_name: {name}\n        position: {value:.9}\n"
        );
    }
    text
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(robot), Some(out)) = (args.first(), args.get(1)) else {
        eprintln!("usage: held_out ROBOT.urdf OUT_FOLDER [COUNT=24] [SEED=1] [SPREAD=1]");
        std::process::exit(2);
    };
    let count: usize = args.get(2).map_or(24, |a| a.parse().expect("a count"));
    let seed: u64 = args.get(3).map_or(1, |a| a.parse().expect("a seed"));
    let spread: f64 = args.get(4).map_or(1.0, |a| a.parse().expect("a spread"));
    assert!(spread > 0.0 && spread <= 1.0, "SPREAD must be in (0, 1]");
    let model = RobotSource::parse(robot)
        .and_then(|s| s.load(false))
        .expect("a robot");
    let names = model.joint_names().to_vec();
    let mut drawer = Drawer::new(model.clone(), spread);
    let mut rng = Uniform(0x9e37_79b9_7f4a_7c15 ^ seed.wrapping_mul(0x2545_f491_4f6c_dd1d));
    let reach = (0..2000)
        .map(|_| {
            let q = drawer.configuration(&mut rng);
            drawer.tip_of(&q).truncate().length()
        })
        .fold(0.0_f64, f64::max);
    let scale = reach / 0.85;
    println!(
        "{}: {} joints, {} spheres, tip reach {reach:.2} m (scale {scale:.2})",
        model.name(),
        names.len(),
        model.spheres().len()
    );
    let folder = PathBuf::from(out);
    std::fs::create_dir_all(&folder).expect("an output folder");
    let mut attempts_total = 0;
    for index in 1..=count {
        let mut attempts = 0;
        let (boxes, start, goal) = loop {
            attempts += 1;
            assert!(
                attempts <= 20_000,
                "problem {index}: no valid scene in 20000 draws"
            );
            let goal = drawer.configuration(&mut rng);
            let start = drawer.configuration(&mut rng);
            let (g, s) = (drawer.tip_of(&goal), drawer.tip_of(&start));
            let (rg, rs) = (g.truncate().length(), s.truncate().length());
            let apart = g.truncate().angle_to(s.truncate()).abs();
            if !(0.35 * reach..=0.85 * reach).contains(&rg)
                || !(0.35 * reach..=0.85 * reach).contains(&rs)
                || apart < std::f64::consts::FRAC_PI_3
            {
                continue;
            }
            let mut boxes = Vec::new();
            shelf(g, scale, &mut rng, &mut boxes);
            table(s, scale, &mut rng, &mut boxes);
            let scene = Scene::new(boxes.iter().map(box_obstacle).collect());
            let problem =
                ArmProblem::new("draw", model.clone(), scene, start.clone(), goal.clone())
                    .expect("ends within the limits");
            if problem.ends_are_valid() {
                break (boxes, start, goal);
            }
        };
        attempts_total += attempts;
        write(
            &folder,
            index,
            &scene_yaml(&boxes),
            &request_yaml(&names, &start, &goal),
        );
        println!("problem {index}: {attempts} draws");
    }
    println!(
        "{count} problems in {}: {attempts_total} draws",
        folder.display()
    );
}

fn write(folder: &Path, index: usize, scene: &str, request: &str) {
    std::fs::write(folder.join(format!("scene{index:04}.yaml")), scene).expect("a scene file");
    std::fs::write(folder.join(format!("request{index:04}.yaml")), request)
        .expect("a request file");
}
