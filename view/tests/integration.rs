//! The view crate's integration tests: one binary, each file a module.

mod pages;
