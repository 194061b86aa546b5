//! Running experiments: the schedule, the workers, and everything that keeps a results folder
//! consistent while runs finish, fail, are interrupted or are spread over machines.
//!
//! - [`run_job`]: one run of one planner on one instance, its place in the shuffled, seeded
//!   schedule, and its execution under the time budget.
//! - [`executor`]: the jobs run in parallel with progress, each finished run handed to a sink.
//! - [`pending_run`]: finished runs awaiting their audit, which a worker runs for a few short
//!   runs together ([`AuditBatch`](pending_run::AuditBatch)).
//! - [`interrupt`]: SIGINT and SIGTERM, handled alike (finished runs are kept).
//! - [`run_journal`] (with `run_journal/repair.rs`): every finished run appended to
//!   `runs.jsonl`/`runs.csv` once audited and committed to the database in batches;
//!   reading them back, repairing a torn last line and runs recorded twice.
//! - [`figures`]: which figures and 3-D views a results folder gets (by scene, or every
//!   problem too).
//! - [`results_folder`] (with `results_folder/folder_lock.rs`, one writer per folder, and
//!   `results_folder/agreement.rs`, whether journal, CSV and database agree): where the outputs
//!   go, checked before work starts, and rebuilt from the journal at the end.
//! - [`shard`]: one of `N` disjoint parts of the schedule (`bench --shard K/N`);
//!   [`shard_merge`]: the parts' folders combined into one (`merge`).
//!
//! May use: [`crate::definition`], [`crate::outcome`], [`crate::formats`] (the journal and the
//! results folder write raw runs, OMPL logs, the database and KPI tables),
//! [`crate::pictures`] (the results folder's figures), [`crate::budget`] and
//! [`crate::error`]. Not the command line.

pub(crate) mod executor;
pub(crate) mod figures;
pub(crate) mod interrupt;
pub(crate) mod pending_run;
pub(crate) mod results_folder;
pub(crate) mod run_job;
pub(crate) mod run_journal;
pub(crate) mod shard;
pub(crate) mod shard_merge;
