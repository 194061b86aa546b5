//! What the arm examples share: the MotionBenchMaker scenes (the five of the Panda's experiments,
//! the seven of every robot's set), the Panda problems with a valid start and goal, and a median.
#![allow(dead_code)] // each example uses its own part of it

use std::path::Path;

use mit_star_robot::{ArmProblem, RobotModel};

/// The five Panda scenes of the `panda-mbm` experiment and most arm tables, as folder names
/// (`robot/data/panda/mbm_problems.tar.bz2` also has `bookshelf_thin` and `table_under_pick`).
pub(crate) const SCENES: [&str; 5] = [
    "bookshelf_small_panda",
    "bookshelf_tall_panda",
    "box_panda",
    "cage_panda",
    "table_pick_panda",
];

/// The seven scenes of the UR5's (and Fetch's) MotionBenchMaker sets
/// (`robot/data/ur5/problems.tar.bz2`), without the robot's suffix.
pub(crate) const SEVEN_SCENES: [&str; 7] = [
    "bookshelf_small",
    "bookshelf_tall",
    "bookshelf_thin",
    "box",
    "cage",
    "table_pick",
    "table_under_pick",
];

/// Problems `1..=count` of `scene` under `folder` that load and have a valid start and goal,
/// with their 1-based index: [`problems_of`] for the shipped Panda.
pub(crate) fn problems(folder: &str, scene: &str, count: usize) -> Vec<(usize, ArmProblem)> {
    let panda = ArmProblem::panda().expect("the shipped Panda loads");
    problems_of(&panda, folder, scene, count)
}

/// Problems `1..=count` of `scene` (a folder name with the robot's suffix) under `folder` for
/// `robot` that load and have a valid start and goal, with their 1-based index.
pub(crate) fn problems_of(
    robot: &RobotModel,
    folder: &str,
    scene: &str,
    count: usize,
) -> Vec<(usize, ArmProblem)> {
    (1..=count)
        .filter_map(|index| {
            let problem =
                ArmProblem::mbm(robot.clone(), &Path::new(folder).join(scene), index).ok()?;
            problem.ends_are_valid().then_some((index, problem))
        })
        .collect()
}

/// The robot `robot=NAME` names for the arm examples: its name (the folders' suffix) and the
/// shipped model.
pub(crate) fn shipped_robot(name: &str) -> (String, RobotModel) {
    let shipped = mit_star_robot::ShippedRobot::find(name).expect("a shipped robot");
    let model = shipped.model(false).expect("its files load");
    (name.to_owned(), model)
}

/// The median of `values` (sorted in place); NaN if there are none.
pub(crate) fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}
