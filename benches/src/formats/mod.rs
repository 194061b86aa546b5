//! The result formats motion-planning researchers read with their own tools: each writer sits
//! beside its reader.
//!
//! - [`ompl_log`]: OMPL benchmark logs (`logs/<instance>.log`): the log, its writer and its
//!   strict parser.
//! - [`planner_arena_database`]: the SQLite database Planner Arena reads (`benchmark.db`), in
//!   the schema OMPL's `ompl_benchmark_statistics.py` builds, filled from OMPL logs.
//! - [`path_joints`]: the joint names of a path file `check-path` reads (a `joints:` line, or
//!   the JSON `plan --json` and `runs.jsonl` write) and the robot's coordinate order.
//! - [`raw_runs`]: `runs.csv` (one row per run) and `runs.jsonl` (one JSON object per run):
//!   their columns, rows and lines, and reading the CSV back.
//! - [`scene_summary`]: the summary by scene `bench` prints and `kpi.md` opens with;
//!   [`kpi_table`]: the KPI tables (`kpi.md`, the paper's Table I and the full KPIs);
//!   [`campaign_comparison`]: two results folders' KPIs side by side (`mit-star compare`).
//! - [`report_page`]: `report.html`, the KPI tables, the figures and the links to the 3-D
//!   views of each instance on one page.
//!
//! May use: [`crate::outcome`] (what is written), [`crate::definition`],
//! [`crate::statistics`], [`crate::error`], and from execution only the names of a run and of a
//! part ([`RunKey`](crate::RunKey), [`Shard`](crate::Shard)). Formats do not decide where files
//! go or when: that is [`crate::execution`]'s.

pub(crate) mod campaign_comparison;
pub(crate) mod kpi_table;
pub(crate) mod ompl_log;
pub(crate) mod path_joints;
pub(crate) mod planner_arena_database;
pub(crate) mod raw_runs;
pub(crate) mod report_page;
pub(crate) mod scene_summary;
