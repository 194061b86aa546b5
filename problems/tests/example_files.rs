//! The problem files shipped in `problems/examples/` load, and mean what their comments say.

use std::path::PathBuf;

use mit_star_problems::{Problem, WallGap};
use mit_star_validity::StateValidity;

fn example(name: &str) -> Problem {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name);
    Problem::from_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn every_example_loads_and_round_trips() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let problem =
                Problem::from_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(problem.validate().is_ok());
            let back = Problem::from_toml_str(&problem.to_toml_string()).unwrap();
            assert_eq!(back, problem, "{}", path.display());
            count += 1;
        }
    }
    assert!(count >= 3, "only {count} example files");
}

#[test]
fn wall_with_slot_is_the_builtin_wall_gap() {
    let file = example("wall-with-slot-2d.toml");
    let builtin = WallGap::new(2).build().unwrap();
    assert_eq!(file.world(), builtin.world());
    assert_eq!(file.start(), builtin.start());
    assert_eq!(file.goals(), builtin.goals());
}

#[test]
fn two_rooms_has_two_goals_and_a_door() {
    let p = example("two-rooms-3d.toml");
    assert_eq!(p.dimension(), 3);
    assert_eq!(p.goals().len(), 2);
    assert!(p.world().is_valid(&[0.0, 0.2, -0.2]));
    assert!(!p.world().is_valid(&[0.0, 0.0, 0.0]));
}

#[test]
fn unit_square_goal_enclosure_opens_to_the_right() {
    let p = example("goal-enclosure-unit-square.toml");
    assert!(p.world().is_valid(&[0.7125, 0.5]));
    assert!(!p.world().is_valid(&[0.4875, 0.5]));
    assert!(!p.world().is_valid(&[0.6, 0.6125]));
}

#[test]
fn lattice_example_is_four_dimensional() {
    let p = example("lattice-4d.toml");
    assert_eq!(p.dimension(), 4);
    assert_eq!(p.resolution(), 1e-5);
    assert!(!p.world().is_valid(&[0.0, 0.0, 0.0, 0.0]));
    assert!(p.world().is_valid(&[0.05, 0.0, 0.0, 0.0]));
}
