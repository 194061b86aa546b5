//! A crowded scene for the examples that measure checks and deadlines among many obstacles
//! (`arm_deadline_stress --extra-boxes`, `crowded_check`): seeded 1 cm cubes around the robot.

use glam::{DQuat, DVec3};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, Obstacle, Scene, Shape};

/// `problem` with `count` seeded 1 cm cubes added within 1.2 m of the robot's base (up to
/// 1.6 m high), less those touching its start or a goal (the fixed links would touch some in
/// every configuration otherwise). Says on stderr how many were kept.
pub(crate) fn with_extra_cubes(problem: &ArmProblem, count: usize) -> ArmProblem {
    if count == 0 {
        return problem.clone();
    }
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = move |low: f64, high: f64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        low + (high - low) * (state >> 11) as f64 / (1_u64 << 53) as f64
    };
    let mut obstacles = problem.scene().obstacles().to_vec();
    let first = obstacles.len();
    let cube = Shape::Cuboid {
        half_extents: DVec3::splat(0.005),
    };
    for _ in 0..count {
        let at = DVec3::new(uniform(-1.2, 1.2), uniform(-1.2, 1.2), uniform(0.0, 1.6));
        obstacles.push(Obstacle::new(cube, at, DQuat::IDENTITY));
    }
    // Drop the cubes the ends touch (ids `obstacle{i}` of a scene built from a list), until
    // the ends are valid again.
    let ends: Vec<Vec<f64>> = std::iter::once(problem.start().to_vec())
        .chain(problem.goals().iter().cloned())
        .collect();
    loop {
        let candidate = problem.clone().with_scene(Scene::new(obstacles.clone()));
        let mut touched = std::collections::BTreeSet::new();
        for q in &ends {
            for contact in candidate.diagnose(q).scene {
                if let Some(i) = contact.other.strip_prefix("obstacle") {
                    touched.extend(i.parse::<usize>().ok().filter(|&i| i >= first));
                }
            }
        }
        if touched.is_empty() {
            eprintln!("{} extra cubes kept of {count}", obstacles.len() - first);
            return candidate;
        }
        for &i in touched.iter().rev() {
            obstacles.remove(i);
        }
    }
}
