//! Benchmark problems.

#![forbid(unsafe_code)]
