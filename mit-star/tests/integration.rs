//! The crate's integration tests, built as one binary: every file beside this one is a
//! module of it, so the generic code they share is compiled and linked once, not once per
//! file. A new test file must be declared below (a test of `mit-star-benches` checks that
//! every file in a `tests/` folder is).

mod common;

mod ablation_parts;
mod certification;
mod certification_polls;
mod conformance;
mod convergence;
mod extreme_values;
mod fully_connected;
mod guarantees;
mod many_goals;
mod offered_solutions;
mod properties;
mod simplification;
mod smoothing_properties;
mod start_is_a_goal;
