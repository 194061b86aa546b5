//! [`PlannerArenaDatabase`]: the SQLite benchmark database Planner Arena reads, in the schema
//! OMPL's `ompl_benchmark_statistics.py` builds.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use rusqlite::types::Value;
use rusqlite::{CachedStatement, Connection, OptionalExtension as _, params_from_iter};

use crate::error::HarnessError;
use crate::formats::ompl_log::benchmark_log::BenchmarkLog;
use crate::formats::ompl_log::log_value::{LogValue, Property};

/// The tables, exactly as OMPL's log reader creates them.
const SCHEMA: &str = "
CREATE TABLE IF NOT EXISTS experiments
    (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512),
    totaltime REAL, timelimit REAL, memorylimit REAL, runcount INTEGER,
    version VARCHAR(128), hostname VARCHAR(1024), cpuinfo TEXT,
    date DATETIME, seed VARCHAR(24), setup TEXT);
CREATE TABLE IF NOT EXISTS plannerConfigs
    (id INTEGER PRIMARY KEY AUTOINCREMENT,
    name VARCHAR(512) NOT NULL, settings TEXT);
CREATE TABLE IF NOT EXISTS enums
    (name VARCHAR(512), value INTEGER, description TEXT,
    PRIMARY KEY (name, value));
CREATE TABLE IF NOT EXISTS runs
    (id INTEGER PRIMARY KEY AUTOINCREMENT, experimentid INTEGER, plannerid INTEGER,
    FOREIGN KEY (experimentid) REFERENCES experiments(id) ON DELETE CASCADE,
    FOREIGN KEY (plannerid) REFERENCES plannerConfigs(id) ON DELETE CASCADE);
CREATE TABLE IF NOT EXISTS progress
    (runid INTEGER, time REAL, PRIMARY KEY (runid, time),
    FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);
";

/// An experiment row's id and its runs per planner name.
pub(crate) type ExperimentRow = (i64, HashMap<String, usize>);

/// A Planner Arena benchmark database (SQLite), created if missing and appended to otherwise.
///
/// Tables: `experiments` (one row per problem instance; experiment properties such as
/// `dimension` and `concurrent_runs` become extra columns), `plannerConfigs` (one row per
/// distinct planner name and settings), `enums` (the `status` values), `runs` (one row per
/// run; one column per run property, spaces replaced by `_`) and `progress` (one row per
/// improvement of a run: `time`, `best_cost`). Inserting a [`BenchmarkLog`] does what OMPL's
/// reader does with the same log, so a database built from our `.log` files with OMPL's
/// script has the same content.
///
/// ```
/// # let dir = std::env::temp_dir().join(format!("pa-doc-{}", std::process::id()));
/// # std::fs::create_dir_all(&dir).unwrap();
/// use mit_star_benches::PlannerArenaDatabase;
/// let db = PlannerArenaDatabase::open(&dir.join("benchmark.db"))?;
/// assert_eq!(db.count("experiments")?, 0);
/// # std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug)]
pub struct PlannerArenaDatabase {
    path: PathBuf,
    connection: Connection,
}

impl PlannerArenaDatabase {
    /// Opens (or creates) the database and its tables.
    ///
    /// # Errors
    /// [`HarnessError::Database`] if the file cannot be opened or is not such a database.
    pub fn open(path: &Path) -> Result<Self, HarnessError> {
        let fail = |source| HarnessError::Database {
            path: path.to_path_buf(),
            source,
        };
        let connection = Connection::open(path).map_err(fail)?;
        connection
            .execute_batch("PRAGMA foreign_keys = ON;")
            .map_err(fail)?;
        // The tables in one transaction: one set of disk syncs, not one per table.
        connection
            .execute_batch(&format!("BEGIN; {SCHEMA} COMMIT;"))
            .map_err(|e| {
                if !connection.is_autocommit() {
                    let _ = connection.execute_batch("ROLLBACK");
                }
                fail(e)
            })?;
        Ok(Self {
            path: path.to_path_buf(),
            connection,
        })
    }

    /// The database file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The underlying connection, for queries.
    pub fn connection(&self) -> &Connection {
        &self.connection
    }

    /// Rows in `table`.
    ///
    /// # Errors
    /// [`HarnessError::Database`] if the table does not exist.
    pub fn count(&self, table: &str) -> Result<i64, HarnessError> {
        self.connection
            .query_row(&format!("SELECT count(*) FROM \"{table}\""), [], |r| {
                r.get(0)
            })
            .map_err(|source| self.fail(source))
    }

    fn fail(&self, source: rusqlite::Error) -> HarnessError {
        HarnessError::Database {
            path: self.path.clone(),
            source,
        }
    }

    /// Column names of `table`.
    fn columns(&self, table: &str) -> Result<Vec<String>, rusqlite::Error> {
        let mut statement = self
            .connection
            .prepare(&format!("PRAGMA table_info(\"{table}\")"))?;
        let names = statement
            .query_map([], |r| r.get::<_, String>(1))?
            .collect::<Result<Vec<_>, _>>()?;
        Ok(names)
    }

    /// Adds to `table` each `(column, SQL type)` it lacks, in the order given (its columns
    /// read once).
    fn ensure_columns<'k>(
        &self,
        table: &str,
        wanted: impl IntoIterator<Item = (String, &'k str)>,
    ) -> Result<(), rusqlite::Error> {
        let mut have = self.columns(table)?;
        for (column, kind) in wanted {
            if !have.contains(&column) {
                self.connection.execute(
                    &format!("ALTER TABLE \"{table}\" ADD \"{column}\" {kind}"),
                    [],
                )?;
                have.push(column);
            }
        }
        Ok(())
    }

    /// Appends one log (one experiment) atomically — its own transaction, or part of the one
    /// [`begin`](Self::begin) opened; returns the new experiment's id.
    ///
    /// # Errors
    /// [`HarnessError::Database`] if SQLite refuses (nothing of the log is written then).
    pub fn insert(&mut self, log: &BenchmarkLog) -> Result<i64, HarnessError> {
        self.atomically(|| self.insert_inner(log))
    }

    /// Opens a transaction that the [`insert`](Self::insert)s and
    /// [`append_runs`](Self::append_runs) up to [`commit`](Self::commit) join, so that they
    /// reach the disk together. SQLite syncs the file three or four times per transaction:
    /// hundreds of logs inserted one by one wait that many times on the disk, which other
    /// programs may keep busy (a results folder's database is written this way).
    ///
    /// # Errors
    /// [`HarnessError::Database`] if a transaction is already open or SQLite refuses.
    pub fn begin(&mut self) -> Result<(), HarnessError> {
        self.connection
            .execute_batch("BEGIN")
            .map_err(|e| self.fail(e))
    }

    /// Commits the transaction [`begin`](Self::begin) opened; if that fails, rolls it back.
    ///
    /// # Errors
    /// [`HarnessError::Database`] if SQLite refuses (nothing of the transaction is written
    /// then).
    pub fn commit(&mut self) -> Result<(), HarnessError> {
        self.connection.execute_batch("COMMIT").map_err(|e| {
            self.rollback();
            self.fail(e)
        })
    }

    /// Rolls back the transaction [`begin`](Self::begin) opened (nothing if none is open).
    pub fn rollback(&mut self) {
        if !self.connection.is_autocommit() {
            let _ = self.connection.execute_batch("ROLLBACK");
        }
    }

    /// Runs `work` under a savepoint: its writes are kept together or not at all, as a
    /// transaction of its own or inside an open one.
    fn atomically<T>(
        &self,
        work: impl FnOnce() -> Result<T, rusqlite::Error>,
    ) -> Result<T, HarnessError> {
        let c = &self.connection;
        c.execute_batch("SAVEPOINT arena_write")
            .map_err(|e| self.fail(e))?;
        match work() {
            Ok(value) => {
                c.execute_batch("RELEASE arena_write")
                    .map_err(|e| self.fail(e))?;
                Ok(value)
            }
            Err(e) => {
                let _ = c.execute_batch("ROLLBACK TO arena_write; RELEASE arena_write");
                Err(self.fail(e))
            }
        }
    }

    fn insert_inner(&self, log: &BenchmarkLog) -> Result<i64, rusqlite::Error> {
        let c = &self.connection;
        for e in &log.enums {
            let known: i64 = c.query_row(
                "SELECT count(*) FROM enums WHERE name = ?1",
                [&e.name],
                |r| r.get(0),
            )?;
            if known == 0 {
                for (value, description) in e.values.iter().enumerate() {
                    c.execute(
                        "INSERT INTO enums VALUES (?1, ?2, ?3)",
                        rusqlite::params![e.name, value as i64, description],
                    )?;
                }
            }
        }
        let mut names: Vec<String> = [
            "name",
            "totaltime",
            "timelimit",
            "memorylimit",
            "runcount",
            "version",
            "hostname",
            "cpuinfo",
            "date",
            "seed",
            "setup",
        ]
        .map(str::to_owned)
        .to_vec();
        let mut values: Vec<Value> = vec![
            Value::Text(log.experiment.clone()),
            Value::Real(log.total_time),
            Value::Real(log.time_limit),
            Value::Real(log.memory_limit),
            Value::Integer(log.runs_per_planner.map_or(-1, |r| r as i64)),
            Value::Text(format!("{} {}", log.library, log.version)),
            Value::Text(log.hostname.clone()),
            log.cpu_info.clone().map_or(Value::Null, Value::Text),
            Value::Text(log.date.clone()),
            Value::Text(log.seed.to_string()),
            Value::Text(log.setup.clone()),
        ];
        // New property columns are added in name order, as OMPL's reader adds them.
        let mut properties: Vec<_> = log
            .properties
            .iter()
            .map(|p| (p.name.replace('-', "_"), p))
            .collect();
        properties.sort_by(|a, b| a.0.cmp(&b.0));
        self.ensure_columns(
            "experiments",
            properties
                .iter()
                .map(|(column, p)| (column.clone(), p.kind.word())),
        )?;
        for p in &log.properties {
            names.push(p.name.replace('-', "_"));
            values.push(sql(&p.value));
        }
        c.execute(&insert("experiments", &names), params_from_iter(values))?;
        let experiment = c.last_insert_rowid();
        self.insert_planners(experiment, log)?;
        Ok(experiment)
    }

    /// The experiment row of a problem instance — OMPL experiment `name` with the experiment
    /// properties `dimension` and `instance` — and its runs per planner name; `None` if the
    /// database has no such row (the newest if it has several). How a resumed `bench` keeps
    /// committing to the row an earlier, interrupted `bench` created.
    ///
    /// # Errors
    /// [`HarnessError::Database`] if SQLite refuses the query.
    pub(crate) fn find_experiment(
        &self,
        name: &str,
        dimension: usize,
        instance: u64,
    ) -> Result<Option<ExperimentRow>, HarnessError> {
        let columns = self.columns("experiments").map_err(|e| self.fail(e))?;
        if !["dimension", "instance"]
            .iter()
            .all(|c| columns.iter().any(|k| k == c))
        {
            return Ok(None);
        }
        let id = self
            .connection
            .query_row(
                "SELECT id FROM experiments WHERE name = ?1 AND dimension = ?2 AND instance = ?3 \
                 ORDER BY id DESC LIMIT 1",
                rusqlite::params![name, dimension as i64, instance as i64],
                |r| r.get::<_, i64>(0),
            )
            .optional()
            .map_err(|e| self.fail(e))?;
        let Some(id) = id else { return Ok(None) };
        let mut statement = self
            .connection
            .prepare(
                "SELECT p.name, count(*) FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id \
                 WHERE r.experimentid = ?1 GROUP BY p.name",
            )
            .map_err(|e| self.fail(e))?;
        let counts = statement
            .query_map([id], |r| {
                Ok((r.get::<_, String>(0)?, r.get::<_, i64>(1)? as usize))
            })
            .and_then(Iterator::collect::<Result<HashMap<_, _>, _>>)
            .map_err(|e| self.fail(e))?;
        Ok(Some((id, counts)))
    }

    /// Appends the runs of `log` to the existing experiment `experiment` and sets its
    /// `runcount` and `totaltime`, atomically (as [`insert`](Self::insert)) — how a results
    /// folder's journal commits a batch of finished runs.
    ///
    /// # Errors
    /// [`HarnessError::Database`] if SQLite refuses (nothing of the log is written then).
    pub fn append_runs(
        &mut self,
        experiment: i64,
        log: &BenchmarkLog,
        run_count: usize,
        total_time: f64,
    ) -> Result<(), HarnessError> {
        self.atomically(|| {
            self.insert_planners(experiment, log)?;
            self.connection
                .execute(
                    "UPDATE experiments SET runcount = ?1, totaltime = ?2 WHERE id = ?3",
                    rusqlite::params![run_count as i64, total_time, experiment],
                )
                .map(|_| ())
        })
    }

    /// The statement inserting a row of `table` (prepared once per connection): the `leading`
    /// columns, then one per property, each added to the table if it lacks it.
    fn row_insert(
        &self,
        table: &str,
        leading: &[&str],
        properties: &[Property],
    ) -> Result<CachedStatement<'_>, rusqlite::Error> {
        self.ensure_columns(
            table,
            properties.iter().map(|p| (p.column(), p.kind.word())),
        )?;
        let columns: Vec<String> = leading
            .iter()
            .map(|&c| c.to_owned())
            .chain(properties.iter().map(Property::column))
            .collect();
        self.connection.prepare_cached(&insert(table, &columns))
    }

    /// Inserts the planner configurations, runs and progress samples of `log` under
    /// `experiment`.
    fn insert_planners(&self, experiment: i64, log: &BenchmarkLog) -> Result<(), rusqlite::Error> {
        let c = &self.connection;
        for planner in &log.planners {
            let settings = planner.settings();
            let existing = c
                .query_row(
                    "SELECT id FROM plannerConfigs WHERE name = ?1 AND settings = ?2",
                    [&planner.name, &settings],
                    |r| r.get::<_, i64>(0),
                )
                .ok();
            let planner_id = match existing {
                Some(id) => id,
                None => {
                    c.execute(
                        "INSERT INTO plannerConfigs (name, settings) VALUES (?1, ?2)",
                        [&planner.name, &settings],
                    )?;
                    c.last_insert_rowid()
                }
            };
            let mut insert_run = self.row_insert(
                "runs",
                &["experimentid", "plannerid"],
                &planner.run_properties,
            )?;
            let mut run_ids = Vec::with_capacity(planner.runs.len());
            for run in &planner.runs {
                let mut row = vec![Value::Integer(experiment), Value::Integer(planner_id)];
                row.extend(run.iter().map(sql));
                insert_run.execute(params_from_iter(row))?;
                run_ids.push(c.last_insert_rowid());
            }
            if planner.progress_properties.is_empty() {
                continue;
            }
            let mut insert_progress =
                self.row_insert("progress", &["runid"], &planner.progress_properties)?;
            for (run_id, samples) in run_ids.iter().zip(&planner.progress) {
                for sample in samples {
                    let mut row = vec![Value::Integer(*run_id)];
                    row.extend(sample.iter().map(sql));
                    insert_progress.execute(params_from_iter(row))?;
                }
            }
        }
        Ok(())
    }
}

/// `INSERT INTO table ("a","b") VALUES (?,?)`.
fn insert(table: &str, columns: &[String]) -> String {
    let quoted: Vec<String> = columns.iter().map(|c| format!("\"{c}\"")).collect();
    let marks = vec!["?"; columns.len()].join(",");
    format!(
        "INSERT INTO \"{table}\" ({}) VALUES ({marks})",
        quoted.join(",")
    )
}

/// A log value as an SQL value.
fn sql(value: &LogValue) -> Value {
    match value {
        LogValue::Null => Value::Null,
        LogValue::Integer(i) => Value::Integer(*i),
        LogValue::Real(r) if r.is_finite() => Value::Real(*r),
        LogValue::Real(_) => Value::Null,
        LogValue::Text(t) => Value::Text(t.clone()),
    }
}
