//! OMPL benchmark logs, the `.log` files `ompl_benchmark_statistics.py` and Planner Arena read:
//! written and read here.
//!
//! - [`benchmark_log`]: [`BenchmarkLog`](crate::BenchmarkLog), one problem instance's results
//!   as an OMPL log, built from the results and written as text (the writer).
//! - [`log_parser`]: [`BenchmarkLog::parse`](crate::BenchmarkLog::parse), reading a log back,
//!   strictly by the grammar (the reader).
//! - [`log_value`]: the pieces both use: property types, values, properties, enumerations.
//! - [`setup_description`]: the free-text setup description of a log (`<<<| … |>>>`).
//!
//! May use: [`crate::outcome`] (the results written), [`crate::error`].

pub(crate) mod benchmark_log;
pub(crate) mod log_parser;
pub(crate) mod log_value;
pub(crate) mod setup_description;
