//! The crate's integration tests, built as one binary: every file beside this one is a
//! module of it, so the generic code they share is compiled and linked once, not once per
//! file. A new test file must be declared below (a test of `mit-star-benches` checks that
//! every file in a `tests/` folder is).

#[path = "support/arm_cases.rs"]
mod arm_cases;
#[path = "support/cage_batches.rs"]
mod cage_batches;
#[path = "support/test_meshes.rs"]
mod test_meshes;

mod audit_broad_phase;
mod batch_size_on_arms;
mod batches;
mod bridge_checks_on_arms;
mod budget_cover;
mod certified_motion;
mod cloud_affordances;
mod cloud_input_hostile;
mod cloud_input_properties;
mod cloud_motion;
mod cloud_structure;
mod hostile_models;
mod inverse_kinematics;
mod joint_kinds;
mod medial_placement;
mod mesh_formats;
mod mimic_limits;
mod model;
mod motion_audit;
mod obstacle_grid;
mod one_sided;
mod other_robots;
mod padding;
mod parry_agreement;
mod radius_connection_on_arms;
mod recycled_scratch;
mod reverse_repair_on_arms;
mod rrt_range_on_arms;
mod scenes;
mod searched_cover;
mod self_grazes;
mod short_slices;
mod simplified_arm_paths;
mod solution_samples_on_arms;
mod sparse_spacing_on_arms;
mod sphere_cover;
mod sphere_less_links;
mod trajectory;
mod visual_meshes;
