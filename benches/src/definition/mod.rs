//! Defining experiments: what is to run, decided and checked before anything runs.
//!
//! - [`experiment`]: an [`Experiment`](crate::Experiment), planners × problem instances × runs,
//!   with its seed and confidence; [`experiment_file`]: its TOML file format;
//!   [`shipped_experiment`]: the experiment files embedded in the binary.
//! - [`planner_spec`]: one planner of an experiment (a configuration and its parameters);
//!   [`parameter_overrides`]: `key = value` changes to the planners' parameters.
//! - [`problem_spec`]: one problem of an experiment over several dimensions and layouts;
//!   [`problem_source`]: where it comes from (a built-in family, a problem file, a
//!   MotionBenchMaker folder, [`mbm_folder`], planned for the robot of [`robot_choice`]);
//!   [`problem_instance`]: one concrete instance (id, dimension,
//!   layout, time budget); [`problem_kind`]: the problem an instance plans on, a box world or an
//!   arm, and how each kind builds planners, checks paths and describes itself;
//!   [`cloud_spec`]: the point cloud of an arm problem, and its preparation into the scene
//!   ([`cloud_option`]: its options' names; [`cloud_summary`]: what preparing it did;
//!   [`file_contents`]: what its files held);
//!   [`pose_goal_spec`]: a link's pose as an arm problem's goal, and [`pose_goal_source`]: the
//!   goal region inverse kinematics makes of it and the planner built towards it.
//!
//! May use: the planner and problem crates (`mit-star`, `problems`, `robot`, `spaces`,
//! `validity`), [`crate::error`], [`crate::budget`] and [`crate::path_validation`]; from
//! execution only the size of a run record (`RUN_RECORD_BYTES`, for the memory check of an
//! experiment). Nothing here runs a planner to completion, writes a results file or draws.

pub mod experiment_file;

pub(crate) mod cloud_option;
pub(crate) mod cloud_spec;
pub(crate) mod cloud_summary;
pub(crate) mod experiment;
pub(crate) mod file_contents;
pub(crate) mod mbm_folder;
pub(crate) mod parameter_overrides;
pub(crate) mod planner_spec;
pub(crate) mod pose_goal_source;
pub(crate) mod pose_goal_spec;
pub(crate) mod problem_instance;
pub(crate) mod problem_kind;
pub(crate) mod problem_source;
pub(crate) mod problem_spec;
pub(crate) mod robot_choice;
pub(crate) mod shipped_experiment;
