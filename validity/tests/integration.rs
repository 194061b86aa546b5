//! The crate's integration tests, built as one binary: every file beside this one is a
//! module of it, so the generic code they share is compiled and linked once, not once per
//! file. A new test file must be declared below (a test of `mit-star-benches` checks that
//! every file in a `tests/` folder is).

mod batched_walks;
mod edge_checkers;
mod edge_direction;
mod exact_certification;
mod motion_ends;
mod non_finite_ends;
mod segment_validation;
mod world_acceleration;
mod world_segments;
