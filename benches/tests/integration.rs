//! The crate's integration tests, built as one binary: every file beside this one is a
//! module of it, so the generic code they share is compiled and linked once, not once per
//! file. A new test file must be declared below (a test of `mit-star-benches` checks that
//! every file in a `tests/` folder is).

mod common;

mod arm_experiment;
mod audit_batches;
mod cli;
mod cloud_experiments;
mod clouds;
mod durability;
mod extreme_values;
mod hostile_inputs;
mod outputs;
mod padding;
mod pose_goals;
mod reliability;
mod replanning;
mod robots;
mod scene_outputs;
mod shards;
mod single_writer;
mod spherise_limits;
mod test_layout;
mod trajectories;
mod views;
