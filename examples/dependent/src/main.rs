//! Plans twice with the mit-star crates as a dependency: MIT* in one of PDT's box worlds, and
//! RRT-Connect for the shipped Franka Panda reaching past a box.

use std::time::Duration;

use glam::{DQuat, DVec3};
use mit_star::{MitStar, Parameters, Planner, RrtConnect, TimeLimit};
use mit_star_problems::{DividingWalls, PlanningProblem};
use mit_star_spaces::StateSpace;
use mit_star_robot::{ArmProblem, Obstacle, Scene, Shape};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // MIT* among PDT's dividing walls in R^4.
    let walls = DividingWalls::new(4).build()?.with_resolution(1e-4)?;
    let mut mit = MitStar::for_problem(&walls).seed(7).build()?;
    let outcome = mit.solve(&TimeLimit::new(Duration::from_millis(500)))?;
    let solution = outcome.solution().ok_or("MIT* found no path in 0.5 s")?;
    println!(
        "MIT*, dividing walls in R^4: cost {:.4} (optimum {:.4}), {} states",
        solution.cost,
        walls.optimum().unwrap_or(f64::NAN),
        solution.path.len()
    );

    // RRT-Connect for the Panda, a 20 cm box in front of it.
    let obstacle = Obstacle::new(
        Shape::Cuboid {
            half_extents: DVec3::splat(0.1),
        },
        DVec3::new(0.5, 0.0, 0.4),
        DQuat::IDENTITY,
    );
    let start = vec![0.0, -0.5, 0.0, -2.0, 0.0, 1.6, 0.8];
    let goal = vec![1.0, -0.3, 0.0, -2.0, 0.0, 1.8, 0.8];
    let arm = ArmProblem::new(
        "past a box",
        ArmProblem::panda()?,
        Scene::new(vec![obstacle]),
        start,
        goal,
    )?;
    let parameters = Parameters {
        seed: 7,
        ..Parameters::default()
    };
    let mut rrt = RrtConnect::for_problem(&arm, &parameters)?;
    let outcome = rrt.solve(&TimeLimit::new(Duration::from_secs(1)))?;
    let solution = outcome.solution().ok_or("RRT-Connect found no path in 1 s")?;
    println!(
        "RRT-Connect, Panda past a box: {} configurations, length {:.3} rad, {} of {} dimensions",
        solution.path.len(),
        solution.cost,
        arm.space().dimension(),
        arm.robot().joint_names().len()
    );
    Ok(())
}
