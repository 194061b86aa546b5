//! [`RunJournal`]: every finished run is on disk before the next one starts.

mod repair;

use std::collections::hash_map::Entry;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::fs::File;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use repair::{JournalLine, cut_partial_line, distinct, io, open_for_append, read_lines};
pub(crate) use repair::{describe, repeats};

use crate::definition::problem_instance::ProblemInstance;
use crate::error::HarnessError;
use crate::execution::executor::RunKey;
use crate::execution::results_folder::folder_lock::FolderLock;
use crate::execution::results_folder::{DATABASE_FILE, write_replacing};
use crate::formats::ompl_log::benchmark_log::BenchmarkLog;
use crate::formats::planner_arena_database::PlannerArenaDatabase;
use crate::formats::raw_runs;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::machine_info::MachineInfo;
use crate::outcome::run_record::RunRecord;

/// How long [`RunJournal`] lets finished runs wait for the database by default: 10 s.
pub const DATABASE_COMMIT_INTERVAL: Duration = Duration::from_secs(10);

/// Appends finished runs to a results folder the moment they finish: one line to `runs.jsonl`,
/// then one row to `runs.csv` (each a single write of a whole line). A crash, SIGKILL or a
/// job's time limit loses at most the runs in flight and those awaiting their audit
/// ([`AuditBatch`](crate::AuditBatch)).
///
/// The Planner Arena database follows in batches: the runs appended since the last commit go
/// to it together, in one transaction (each instance's experiment row created by its first run,
/// or continued if an earlier `bench` created it, and its `runcount` kept to the runs
/// recorded), when [`DATABASE_COMMIT_INTERVAL`] has passed since the last commit (or the
/// interval [`commit_every`](Self::commit_every) sets). A transaction between two runs leaves
/// the next run's caches and branch predictors cold: measured on the Panda's RRT-Connect
/// (about 40 µs per solve), committing after every run added 8–12 µs to the next solve
/// (`benches/peers/vamp/harness_probe.patch` restores it as a switch). The
/// database is rebuilt from the raw files whenever a `bench` ends, and after a crash it lags
/// them by at most the interval, which readers report and a resume repairs.
///
/// A journal holds the folder's write lock (shared with the
/// [`ResultsFolder`](crate::ResultsFolder) of the same process, if any): a second process
/// cannot open one on the same folder.
///
/// The raw files are only ever appended to, except when [`open`](Self::open) repairs them. It
/// repairs what a crash in the middle of an append can leave: a line cut short at the end of a
/// file is removed, and rows `runs.csv` lacks behind `runs.jsonl` (the journal of record) are
/// appended. It heals a folder in which a run is recorded twice (by two `bench`es writing it
/// at once, before folders were locked): the first line of each run is kept, `runs.csv` is
/// rebuilt from `runs.jsonl` and the database emptied, to be rebuilt from the raw runs when
/// the writer finishes. It refuses files it cannot continue without mixing data: a `runs.csv`
/// with other columns or with runs `runs.jsonl` lacks, or a database holding more runs than
/// `runs.jsonl` has lines.
///
/// Hand it to the worker threads behind a `Mutex`: one writer, lines never interleave.
#[derive(Debug)]
pub struct RunJournal {
    jsonl_path: PathBuf,
    jsonl: File,
    csv_path: PathBuf,
    csv: File,
    database: PlannerArenaDatabase,
    /// Runs in the raw files and not yet in the database, with their instance indices.
    uncommitted: Vec<(usize, RunRecord)>,
    /// When the database was last committed to (or the journal opened).
    committed_at: Instant,
    /// How long appended runs may wait for the database.
    commit_interval: Duration,
    /// Per instance id: its experiment row in the database and the runs committed there,
    /// per planner.
    experiments: HashMap<String, (i64, HashMap<String, usize>)>,
    /// Every run recorded in the folder (earlier `bench`es and this one).
    recorded: HashSet<RunKey>,
    /// Lines of `runs.jsonl` dropped by [`open`](Self::open) as repeats of a recorded run.
    healed: usize,
    started: Instant,
    _lock: FolderLock,
}

/// The error for a line of `runs.jsonl` that records a run outside the experiment: its
/// `what` (instance, planner, run index) is not the experiment's.
fn foreign(path: &Path, entry: &JournalLine, what: &str) -> HarnessError {
    let r = &entry.record;
    HarnessError::Usage(format!(
        "`{}` line {}: run {} of planner `{}` on `{}` is not a run of this experiment (its \
         {what} is not the experiment's): the folder holds runs of another experiment or was \
         edited by hand; remove the line or write to another --output folder",
        path.display(),
        entry.line,
        r.run,
        mit_star_problems::excerpt(&r.planner, 80),
        mit_star_problems::excerpt(&r.instance, 80),
    ))
}

impl RunJournal {
    /// Opens (creating if needed) the raw files and the database of `folder` for appending,
    /// for an experiment with `instances`; takes the folder's write lock; repairs an append a
    /// crash cut short and heals runs recorded twice (see the type).
    ///
    /// # Errors
    /// [`HarnessError::FolderLocked`] if another process writes the folder;
    /// [`HarnessError::Io`] or [`HarnessError::Database`] if the files cannot be opened or
    /// repaired; [`HarnessError::Serialise`] for a malformed line of `runs.jsonl`;
    /// [`HarnessError::Usage`] for files this experiment cannot continue (see the type),
    /// and for a line of `runs.jsonl` recording a run outside `experiment` (an instance, a
    /// planner or a run index it does not have), naming the line.
    pub fn open(
        folder: &Path,
        experiment: &crate::Experiment,
        instances: &[ProblemInstance],
    ) -> Result<Self, HarnessError> {
        let lock = FolderLock::exclusive(folder)?;
        let jsonl_path = folder.join("runs.jsonl");
        let csv_path = folder.join("runs.csv");
        let mut jsonl = open_for_append(&jsonl_path)?;
        let mut csv = open_for_append(&csv_path)?;
        cut_partial_line(&mut jsonl).map_err(io(&jsonl_path))?;
        cut_partial_line(&mut csv).map_err(io(&csv_path))?;
        let lines = read_lines(&jsonl_path, false)?;
        let written = lines.len();
        let entries = distinct(lines);
        let by_id: HashMap<&str, &ProblemInstance> =
            instances.iter().map(|i| (i.id.as_str(), i)).collect();
        let instance_of = |record: &RunRecord| {
            by_id.get(record.instance.as_str()).copied().ok_or_else(|| {
                HarnessError::Usage(format!(
                    "`{}` records a run on `{}`, which this experiment does not have",
                    jsonl_path.display(),
                    record.instance
                ))
            })
        };
        for entry in &entries {
            instance_of(&entry.record).map_err(|_| foreign(&jsonl_path, entry, "instance"))?;
            if !experiment
                .planners
                .iter()
                .any(|p| p.name() == entry.record.planner)
            {
                return Err(foreign(&jsonl_path, entry, "planner"));
            }
            if entry.record.run >= experiment.runs {
                return Err(foreign(
                    &jsonl_path,
                    entry,
                    &format!("run index (runs 0 to {})", experiment.runs - 1),
                ));
            }
        }
        let recorded: HashSet<RunKey> = entries.iter().map(|e| e.record.key()).collect();
        let csv_runs = raw_runs::csv_runs(&csv_path)?;
        if csv_runs.as_ref().is_some_and(|c| !c.header_matches) {
            return Err(HarnessError::Usage(format!(
                "`{}` has other columns than this mit-star writes (written by another \
                 version?); write to another --output folder",
                csv_path.display()
            )));
        }
        let csv_keys = csv_runs.map(|c| c.keys);
        if let Some(extra) = csv_keys.iter().flatten().find(|k| !recorded.contains(k)) {
            return Err(HarnessError::Usage(format!(
                "`{}` has {} but `{}` does not ({} runs against {}): the files were changed \
                 by hand; restore them or write to another --output folder",
                csv_path.display(),
                describe(extra),
                jsonl_path.display(),
                csv_keys.as_ref().map_or(0, Vec::len),
                entries.len()
            )));
        }
        let database_path = folder.join(DATABASE_FILE);
        let database = PlannerArenaDatabase::open(&database_path)?;
        let in_database = database.count("runs")?;
        if in_database > written as i64 {
            return Err(HarnessError::Usage(format!(
                "`{}` holds {in_database} runs but `{}` only {written}: the database has runs \
                 the raw files do not (written by an older mit-star, or merged by hand), and \
                 rebuilding it would lose them; move it away or write to another --output folder",
                database_path.display(),
                jsonl_path.display(),
            )));
        }
        let csv_repeats = csv_keys.as_ref().map_or(0, |k| repeats(k).1);
        let healed = written - entries.len();
        if healed > 0 || csv_repeats > 0 {
            // Runs recorded twice: keep the first of each everywhere. The database is emptied
            // first and the journal of record rewritten last, so that a crash in between
            // leaves repeats for the next open to heal, never a database with more runs.
            clear_database(&database)?;
            let mut rows = raw_runs::csv_bytes(&csv_path, &raw_runs::csv_header())?;
            let mut text = String::new();
            for entry in &entries {
                let row = raw_runs::csv_row(
                    instance_of(&entry.record)?,
                    entry.concurrency,
                    &entry.record,
                );
                rows.extend(raw_runs::csv_bytes(&csv_path, &row)?);
                text.push_str(&entry.text);
                text.push('\n');
            }
            write_replacing(&csv_path, &rows)?;
            write_replacing(&jsonl_path, text.as_bytes())?;
            jsonl = open_for_append(&jsonl_path)?;
            csv = open_for_append(&csv_path)?;
        } else {
            let in_csv: HashSet<&RunKey> = csv_keys.iter().flatten().collect();
            if csv_keys.is_none() {
                csv.write_all(&raw_runs::csv_bytes(&csv_path, &raw_runs::csv_header())?)
                    .map_err(io(&csv_path))?;
            }
            for entry in entries.iter().filter(|e| !in_csv.contains(&e.record.key())) {
                let row = raw_runs::csv_row(
                    instance_of(&entry.record)?,
                    entry.concurrency,
                    &entry.record,
                );
                csv.write_all(&raw_runs::csv_bytes(&csv_path, &row)?)
                    .map_err(io(&csv_path))?;
            }
        }
        Ok(Self {
            jsonl_path,
            jsonl,
            csv_path,
            csv,
            database,
            experiments: HashMap::new(),
            uncommitted: Vec::new(),
            committed_at: Instant::now(),
            commit_interval: DATABASE_COMMIT_INTERVAL,
            recorded,
            healed,
            started: Instant::now(),
            _lock: lock,
        })
    }

    /// Commits appended runs to the database once `interval` has passed since the last commit
    /// ([`DATABASE_COMMIT_INTERVAL`] by default; [`Duration::ZERO`] commits every run as it is
    /// appended).
    #[must_use]
    pub fn commit_every(mut self, interval: Duration) -> Self {
        self.commit_interval = interval;
        self
    }

    /// Every run recorded in the folder: by earlier `bench`es, and appended since opening.
    pub fn recorded(&self) -> &HashSet<RunKey> {
        &self.recorded
    }

    /// How many lines of `runs.jsonl` [`open`](Self::open) dropped because they recorded a
    /// run already recorded (0 in a folder only ever written by one process at a time).
    pub fn healed(&self) -> usize {
        self.healed
    }

    /// Records one finished run of `results.experiment` on `instance` (index `index` of
    /// `results.instances`; `results.runs` may be empty — only `record` is written): in the
    /// raw files at once, in the database with the next batch (see the type). A run already
    /// recorded is not recorded again.
    ///
    /// # Errors
    /// [`HarnessError::Io`], [`HarnessError::Serialise`] or [`HarnessError::Database`].
    pub fn append(
        &mut self,
        results: &ExperimentResults,
        index: usize,
        record: &RunRecord,
    ) -> Result<(), HarnessError> {
        if self.recorded.contains(&record.key()) {
            return Ok(());
        }
        self.append_raw(&results.instances[index], results.concurrency, record)?;
        self.uncommitted.push((index, record.clone()));
        if self.committed_at.elapsed() >= self.commit_interval {
            self.commit(results)?;
        }
        Ok(())
    }

    /// Commits the runs appended since the last commit to the database now, in one
    /// transaction (a few disk syncs, however many instances the runs are on).
    ///
    /// # Errors
    /// [`HarnessError::Database`] (nothing of these runs is in the database then; the raw
    /// files hold them, and the database is rebuilt from those when `bench` ends or resumes).
    pub fn commit(&mut self, results: &ExperimentResults) -> Result<(), HarnessError> {
        let mut by_instance: BTreeMap<usize, Vec<RunRecord>> = BTreeMap::new();
        for (index, record) in std::mem::take(&mut self.uncommitted) {
            by_instance.entry(index).or_default().push(record);
        }
        self.database.begin()?;
        let written = by_instance
            .into_iter()
            .try_for_each(|(index, records)| self.commit_instance(results, index, &records))
            .and_then(|()| self.database.commit());
        if let Err(e) = written {
            self.database.rollback();
            // Rows and counts remembered from the rolled-back writes are not in the database.
            self.experiments.clear();
            return Err(e);
        }
        self.committed_at = Instant::now();
        Ok(())
    }

    /// Appends `record`, a run on `instance` made with `concurrency` runs at a time, to the raw
    /// files only, not to the database (for [`merge_parts`](crate::merge_parts), which rebuilds
    /// the database from the raw files once every run is in). A run already recorded is not
    /// recorded again.
    ///
    /// # Errors
    /// [`HarnessError::Io`] or [`HarnessError::Serialise`].
    pub fn append_raw(
        &mut self,
        instance: &ProblemInstance,
        concurrency: usize,
        record: &RunRecord,
    ) -> Result<(), HarnessError> {
        if self.recorded.contains(&record.key()) {
            return Ok(());
        }
        let mut line = raw_runs::json_line(&self.jsonl_path, instance, concurrency, record)?;
        line.push('\n');
        let row = raw_runs::csv_row(instance, concurrency, record);
        let row = raw_runs::csv_bytes(&self.csv_path, &row)?;
        self.jsonl
            .write_all(line.as_bytes())
            .map_err(io(&self.jsonl_path))?;
        self.csv.write_all(&row).map_err(io(&self.csv_path))?;
        self.recorded.insert(record.key());
        Ok(())
    }

    /// Writes `records`, runs on instance `index`, to the database under the instance's
    /// experiment row (inside [`commit`](Self::commit)'s transaction).
    fn commit_instance(
        &mut self,
        results: &ExperimentResults,
        index: usize,
        records: &[RunRecord],
    ) -> Result<(), HarnessError> {
        let total_time = self.started.elapsed().as_secs_f64();
        let log = BenchmarkLog::from_runs(results, index, records, total_time);
        let instance = &results.instances[index];
        if !self.experiments.contains_key(&instance.id) {
            let found = self.database.find_experiment(
                &instance.label,
                instance.dimension,
                instance.instance,
            )?;
            if let Some(found) = found {
                self.experiments.insert(instance.id.clone(), found);
            }
        }
        // A new row is inserted with its runs; a row found or made earlier gets them appended.
        let ((experiment, counts), continued) = match self.experiments.entry(instance.id.clone()) {
            Entry::Occupied(row) => (row.into_mut(), true),
            Entry::Vacant(slot) => (
                slot.insert((self.database.insert(&log)?, HashMap::new())),
                false,
            ),
        };
        for record in records {
            *counts.entry(record.planner.clone()).or_insert(0) += 1;
        }
        if continued {
            let run_count = counts.values().copied().max().unwrap_or(0);
            self.database
                .append_runs(*experiment, &log, run_count, total_time)?;
        }
        Ok(())
    }

    /// Every run recorded in `folder`'s `runs.jsonl` (none if it does not exist). A last line
    /// cut short by a crash is skipped.
    ///
    /// # Errors
    /// [`HarnessError::Io`] if the file cannot be read, [`HarnessError::Serialise`] for a
    /// malformed line other than a cut-short last one.
    /// Every line of `folder`'s `runs.jsonl` (none if it does not exist), a run recorded twice
    /// included (readers refuse or drop repeats, see [`results_from_records`]). A last line
    /// cut short by a crash is skipped.
    ///
    /// # Errors
    /// [`HarnessError::Io`] if the file cannot be read, [`HarnessError::Serialise`] for a
    /// malformed line other than a cut-short last one.
    pub fn read_records(folder: &Path) -> Result<Vec<RunRecord>, HarnessError> {
        Ok(Self::read_entries(folder)?
            .into_iter()
            .map(|(record, _)| record)
            .collect())
    }

    /// As [`read_records`](Self::read_records), with the number of runs that executed at the
    /// same time as each.
    ///
    /// # Errors
    /// As [`read_records`](Self::read_records).
    pub fn read_entries(folder: &Path) -> Result<Vec<(RunRecord, usize)>, HarnessError> {
        Ok(read_lines(&folder.join("runs.jsonl"), true)?
            .into_iter()
            .map(
                |JournalLine {
                     record,
                     concurrency,
                     ..
                 }| (record, concurrency),
            )
            .collect())
    }
}

/// Empties the Planner Arena database of its runs and experiments (it is rebuilt from the raw
/// runs when the writer finishes).
fn clear_database(database: &PlannerArenaDatabase) -> Result<(), HarnessError> {
    database
        .connection()
        .execute_batch(
            "BEGIN; DELETE FROM progress; DELETE FROM runs; DELETE FROM experiments; \
             DELETE FROM plannerConfigs; COMMIT;",
        )
        .map_err(|source| HarnessError::Database {
            path: database.path().to_path_buf(),
            source,
        })
}

/// The results of `experiment` on `instances` made of `records` (every run recorded in the
/// folder, in file order), grouped per instance and sorted by planner and run; records of
/// instances the experiment does not have are left out, and a run recorded twice counts once
/// (its first record).
pub fn results_from_records(
    template: &ExperimentResults,
    records: Vec<RunRecord>,
    instances: &[ProblemInstance],
) -> ExperimentResults {
    let mut results = template.clone();
    results.instances = instances.to_vec();
    results.runs = vec![Vec::new(); instances.len()];
    let order: HashMap<&str, usize> = results
        .experiment
        .planners
        .iter()
        .enumerate()
        .map(|(i, p)| (p.name(), i))
        .collect();
    let index_of: HashMap<&str, usize> = instances
        .iter()
        .enumerate()
        .map(|(i, instance)| (instance.id.as_str(), i))
        .collect();
    let mut seen = HashSet::with_capacity(records.len());
    for record in records {
        if let Some(&index) = index_of.get(record.instance.as_str())
            && seen.insert(record.key())
        {
            results.runs[index].push(record);
        }
    }
    for runs in &mut results.runs {
        runs.sort_by_key(|r| (order.get(r.planner.as_str()).copied(), r.run));
    }
    if results.machine.hostname.is_empty() {
        results.machine = MachineInfo::detect();
    }
    results
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::definition::experiment::Experiment;
    use crate::outcome::run_record::RunStatus;

    /// A folder, the results template of a one-instance, two-planner experiment, and a run.
    fn setup(name: &str) -> (PathBuf, ExperimentResults) {
        let folder =
            std::env::temp_dir().join(format!("mit-star-journal-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&folder);
        std::fs::create_dir_all(&folder).unwrap();
        let experiment = Experiment::from_toml_str(
            "planners = [\"mit-star\", \"eit-star\"]\nruns = 3\n[[problems]]\n\
             name = \"wall-gap\"\ndimensions = [2]\ntime = 0.05\n",
            "journal",
            None,
        )
        .unwrap();
        let instances = experiment.instances().unwrap();
        let results = ExperimentResults {
            runs: vec![Vec::new(); instances.len()],
            experiment,
            instances,
            started_at: "2026-01-01T00:00:00".into(),
            total_time: 0.0,
            concurrency: 2,
            interrupted: false,
            machine: MachineInfo::detect(),
        };
        (folder, results)
    }

    fn record(results: &ExperimentResults, planner: usize, run: usize) -> RunRecord {
        let spec = &results.experiment.planners[planner];
        RunRecord {
            instance: results.instances[0].id.clone(),
            planner: spec.name().to_owned(),
            configuration: spec.configuration(),
            run,
            seed: run as u64,
            budget: 0.05,
            status: RunStatus::Error,
            setup_time: 0.001,
            run_time: 0.002,
            initial_time: None,
            initial_cost: None,
            final_cost: None,
            trace: Vec::new(),
            path: Vec::new(),
            joints: Vec::new(),
            wrapping: Vec::new(),
            validation: None,
            counters: mit_star::Counters::default(),
            error: Some("line one\nline two".into()),
        }
    }

    fn lines(path: &Path) -> Vec<String> {
        std::fs::read_to_string(path)
            .unwrap()
            .lines()
            .map(str::to_owned)
            .collect()
    }

    /// A journal of `folder` committing to its database every `interval`.
    fn journal_committing_every(
        folder: &Path,
        results: &ExperimentResults,
        interval: Duration,
    ) -> RunJournal {
        RunJournal::open(folder, &results.experiment, &results.instances)
            .unwrap()
            .commit_every(interval)
    }

    fn runs_in_database(folder: &Path) -> (i64, i64, i64) {
        let db = PlannerArenaDatabase::open(&folder.join(DATABASE_FILE)).unwrap();
        let runcount = db
            .connection()
            .query_row(
                "SELECT coalesce(max(runcount), 0) FROM experiments",
                [],
                |r| r.get(0),
            )
            .unwrap();
        (
            db.count("experiments").unwrap(),
            db.count("runs").unwrap(),
            runcount,
        )
    }

    #[test]
    fn appends_one_line_per_run_and_continues_across_journals() {
        let (folder, results) = setup("append");
        let mut journal = journal_committing_every(&folder, &results, Duration::ZERO);
        assert!(journal.recorded().is_empty());
        journal
            .append(&results, 0, &record(&results, 0, 0))
            .unwrap();
        journal
            .append(&results, 0, &record(&results, 1, 0))
            .unwrap();
        journal
            .append(&results, 0, &record(&results, 0, 1))
            .unwrap();
        // On disk before the journal is closed.
        assert_eq!(lines(&folder.join("runs.jsonl")).len(), 3);
        let csv = lines(&folder.join("runs.csv"));
        assert_eq!(
            csv.len(),
            1 + 3,
            "header and one line per run, messages on one line"
        );
        assert!(csv[1].contains("line one line two"));
        assert_eq!(runs_in_database(&folder), (1, 3, 2));
        drop(journal);

        // A second journal (a resumed bench) knows the runs and continues the same row.
        let mut journal = journal_committing_every(&folder, &results, Duration::ZERO);
        assert_eq!(journal.recorded().len(), 3);
        assert!(
            journal
                .recorded()
                .contains(&(results.instances[0].id.clone(), "EIT*".into(), 0))
        );
        journal
            .append(&results, 0, &record(&results, 1, 1))
            .unwrap();
        journal
            .append(&results, 0, &record(&results, 1, 2))
            .unwrap();
        assert_eq!(runs_in_database(&folder), (1, 5, 3));
        drop(journal);
        let records = RunJournal::read_records(&folder).unwrap();
        assert_eq!(records.len(), 5);
        assert_eq!(records[0].error.as_deref(), Some("line one\nline two"));
        assert_eq!(lines(&folder.join("runs.csv")).len(), 6);
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn the_database_follows_in_batches() {
        let (folder, results) = setup("batches");
        // An interval no test outlasts (the default, 10 s, could pass on a stalled machine).
        let mut journal = journal_committing_every(&folder, &results, Duration::MAX);
        for (planner, run) in [(0, 0), (1, 0), (0, 1)] {
            journal
                .append(&results, 0, &record(&results, planner, run))
                .unwrap();
        }
        // In the raw files at once, in the database not before the interval has passed …
        assert_eq!(lines(&folder.join("runs.jsonl")).len(), 3);
        assert_eq!(runs_in_database(&folder), (0, 0, 0));
        // … or a commit is asked for: one experiment row, every run, its run count.
        journal.commit(&results).unwrap();
        assert_eq!(runs_in_database(&folder), (1, 3, 2));
        journal.commit(&results).unwrap();
        assert_eq!(
            runs_in_database(&folder),
            (1, 3, 2),
            "nothing committed twice"
        );
        // A journal closed with runs still waiting (a crash) leaves the database behind the
        // raw files; the next journal knows every run and continues the same row.
        journal
            .append(&results, 0, &record(&results, 1, 1))
            .unwrap();
        drop(journal);
        assert_eq!(runs_in_database(&folder), (1, 3, 2));
        let mut journal = journal_committing_every(&folder, &results, Duration::MAX);
        assert_eq!(journal.recorded().len(), 4);
        journal
            .append(&results, 0, &record(&results, 1, 2))
            .unwrap();
        journal.commit(&results).unwrap();
        assert_eq!(runs_in_database(&folder), (1, 4, 2));
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn a_cut_short_append_is_repaired() {
        let (folder, results) = setup("repair");
        let mut journal =
            RunJournal::open(&folder, &results.experiment, &results.instances).unwrap();
        for run in 0..2 {
            journal
                .append(&results, 0, &record(&results, 0, run))
                .unwrap();
        }
        drop(journal);
        // A crash after writing half of the next JSON line and before its CSV row …
        let jsonl = folder.join("runs.jsonl");
        let text = std::fs::read_to_string(&jsonl).unwrap();
        let second = text.lines().nth(1).unwrap();
        std::fs::write(&jsonl, format!("{text}{}", &second[..second.len() / 2])).unwrap();
        // … and one after writing a whole JSON line but not its CSV row.
        let csv = folder.join("runs.csv");
        let rows = lines(&csv);
        std::fs::write(&csv, format!("{}\n{}\n", rows[0], rows[1])).unwrap();

        let journal = RunJournal::open(&folder, &results.experiment, &results.instances).unwrap();
        assert_eq!(journal.recorded().len(), 2);
        drop(journal);
        assert_eq!(std::fs::read_to_string(&jsonl).unwrap(), text);
        assert_eq!(lines(&csv), rows, "the missing row is appended again");
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn files_that_cannot_be_continued_are_refused() {
        let (folder, results) = setup("refuse");
        std::fs::write(folder.join("runs.csv"), "instance,other\n").unwrap();
        let message = RunJournal::open(&folder, &results.experiment, &results.instances)
            .unwrap_err()
            .to_string();
        assert!(message.contains("other columns"), "{message}");

        std::fs::remove_file(folder.join("runs.csv")).unwrap();
        let mut database = PlannerArenaDatabase::open(&folder.join(DATABASE_FILE)).unwrap();
        let mut one = results.clone();
        one.runs[0].push(record(&results, 0, 0));
        database
            .insert(&BenchmarkLog::from_results(&one, 0))
            .unwrap();
        drop(database);
        let message = RunJournal::open(&folder, &results.experiment, &results.instances)
            .unwrap_err()
            .to_string();
        assert!(message.contains("holds 1 runs"), "{message}");
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn a_transaction_keeps_its_writes_together() {
        let (folder, results) = setup("transaction");
        let mut database = PlannerArenaDatabase::open(&folder.join(DATABASE_FILE)).unwrap();
        let mut one = results.clone();
        one.runs[0].push(record(&results, 0, 0));
        let log = BenchmarkLog::from_results(&one, 0);
        database.begin().unwrap();
        let id = database.insert(&log).unwrap();
        database.append_runs(id, &log, 2, 1.0).unwrap();
        database.insert(&log).unwrap();
        database.rollback();
        assert_eq!(database.count("experiments").unwrap(), 0);
        assert_eq!(database.count("runs").unwrap(), 0);
        database.begin().unwrap();
        let id = database.insert(&log).unwrap();
        database.append_runs(id, &log, 2, 1.0).unwrap();
        database.insert(&log).unwrap();
        assert!(database.begin().is_err(), "a transaction is already open");
        database.commit().unwrap();
        assert_eq!(database.count("experiments").unwrap(), 2);
        assert_eq!(database.count("runs").unwrap(), 3);
        // Outside a transaction each write is its own.
        database.insert(&log).unwrap();
        drop(database);
        let database = PlannerArenaDatabase::open(&folder.join(DATABASE_FILE)).unwrap();
        assert_eq!(database.count("experiments").unwrap(), 3);
        assert_eq!(database.count("runs").unwrap(), 4);
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn runs_recorded_twice_are_healed() {
        let (folder, results) = setup("heal");
        let mut journal = journal_committing_every(&folder, &results, Duration::ZERO);
        for run in 0..2 {
            journal
                .append(&results, 0, &record(&results, 0, run))
                .unwrap();
        }
        drop(journal);
        let jsonl = folder.join("runs.jsonl");
        let csv = folder.join("runs.csv");
        let (text, rows) = (std::fs::read_to_string(&jsonl).unwrap(), lines(&csv));
        // A second writer recorded run 0 again, in every file (as two unlocked `bench`es did).
        let first = text.lines().next().unwrap();
        std::fs::write(&jsonl, format!("{text}{first}\n")).unwrap();
        std::fs::write(&csv, format!("{}\n{}\n", rows.join("\n"), rows[1])).unwrap();
        let mut db = PlannerArenaDatabase::open(&folder.join(DATABASE_FILE)).unwrap();
        let mut one = results.clone();
        one.runs[0].push(record(&results, 0, 0));
        db.insert(&BenchmarkLog::from_results(&one, 0)).unwrap();
        drop(db);
        assert_eq!(runs_in_database(&folder).1, 3);

        let mut journal =
            RunJournal::open(&folder, &results.experiment, &results.instances).unwrap();
        assert_eq!((journal.recorded().len(), journal.healed()), (2, 1));
        assert_eq!(
            std::fs::read_to_string(&jsonl).unwrap(),
            text,
            "first lines kept"
        );
        assert_eq!(lines(&csv), rows);
        assert_eq!(runs_in_database(&folder).1, 0, "emptied, to be rebuilt");
        // Appending goes on in the rewritten files; a run already recorded is not written again.
        journal
            .append(&results, 0, &record(&results, 1, 0))
            .unwrap();
        journal
            .append(&results, 0, &record(&results, 0, 0))
            .unwrap();
        drop(journal);
        assert_eq!(lines(&jsonl).len(), 3);
        assert_eq!(lines(&csv).len(), 4);
        let journal = RunJournal::open(&folder, &results.experiment, &results.instances).unwrap();
        assert_eq!((journal.recorded().len(), journal.healed()), (3, 0));
        drop(journal);

        // Readers count a run once, even in files no journal healed.
        std::fs::write(
            &jsonl,
            format!("{}{first}\n", std::fs::read_to_string(&jsonl).unwrap()),
        )
        .unwrap();
        let records = RunJournal::read_records(&folder).unwrap();
        assert_eq!(records.len(), 4);
        let all = results_from_records(&results, records, &results.instances);
        assert_eq!(all.run_count(), 3);
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn a_csv_with_runs_the_journal_lacks_is_refused() {
        let (folder, results) = setup("extra");
        let mut journal =
            RunJournal::open(&folder, &results.experiment, &results.instances).unwrap();
        for run in 0..2 {
            journal
                .append(&results, 0, &record(&results, 0, run))
                .unwrap();
        }
        drop(journal);
        let jsonl = folder.join("runs.jsonl");
        let text = std::fs::read_to_string(&jsonl).unwrap();
        std::fs::write(&jsonl, format!("{}\n", text.lines().next().unwrap())).unwrap();
        let message = RunJournal::open(&folder, &results.experiment, &results.instances)
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("has run 1 of MIT* on `wall-gap-n2` but")
                && message.contains("changed by hand"),
            "{message}"
        );
        let _ = std::fs::remove_dir_all(&folder);
    }
}
