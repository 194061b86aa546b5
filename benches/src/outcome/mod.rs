//! What an experiment measured, in memory: the data every output format, picture and statistic
//! is computed from.
//!
//! - [`run_record`]: a [`RunRecord`](crate::RunRecord) (everything measured in one run of one
//!   planner: times, costs, counters, the anytime trace, the path and its validation) and its
//!   [`RunStatus`](crate::RunStatus).
//! - [`experiment_results`]: [`ExperimentResults`](crate::ExperimentResults), every finished
//!   run of an experiment per problem instance, with how, when and where it ran.
//! - [`machine_info`]: the host, its CPU and the date, as benchmark logs record them.
//! - [`scene`]: the instances of one problem in one dimension ([`Scene`](crate::Scene)), which
//!   `bench` summarises and draws together.
//!
//! May use: [`crate::definition`] (the experiment and its instances),
//! [`crate::path_validation`], and from execution only the names of a run and of a part
//! ([`RunKey`](crate::RunKey), [`Shard`](crate::Shard)). Reads and writes no files.

pub(crate) mod experiment_results;
pub(crate) mod machine_info;
pub(crate) mod run_record;
pub(crate) mod scene;
