//! [`RunJournal`]: every finished run is on disk before the next one starts.

use std::collections::{HashMap, HashSet};
use std::fs::{File, OpenOptions};
use std::io::{BufRead as _, BufReader, Read as _, Seek as _, SeekFrom, Write as _};
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::results_folder::DATABASE_FILE;
use crate::{
    BenchmarkLog, ExperimentResults, HarnessError, MachineInfo, PlannerArenaDatabase,
    ProblemInstance, RunKey, RunRecord, raw_runs,
};

/// Appends finished runs to a results folder the moment they finish: one line to `runs.jsonl`,
/// then one row to `runs.csv` (each a single write of a whole line), then one transaction to
/// the Planner Arena database (the instance's experiment row is created by its first run, or
/// continued if an earlier `bench` created it, and its `runcount` kept to the runs recorded).
/// A crash, SIGKILL or a job's time limit loses at most the runs in flight.
///
/// The raw files are only ever appended to. [`open`](Self::open) repairs what a crash in the
/// middle of an append can leave: a line cut short at the end of a file is removed, and rows
/// `runs.csv` lacks behind `runs.jsonl` (the journal of record) are appended. It refuses files
/// it cannot continue without mixing data: a `runs.csv` with other columns, or a database
/// holding more runs than `runs.jsonl`.
///
/// Hand it to the worker threads behind a `Mutex`: one writer, lines never interleave.
#[derive(Debug)]
pub struct RunJournal {
    jsonl_path: PathBuf,
    jsonl: File,
    csv_path: PathBuf,
    csv: File,
    database: PlannerArenaDatabase,
    /// Per instance id: its experiment row in the database and the runs committed there,
    /// per planner.
    experiments: HashMap<String, (i64, HashMap<String, usize>)>,
    /// Every run recorded in the folder (earlier `bench`es and this one).
    recorded: HashSet<RunKey>,
    started: Instant,
}

impl RunJournal {
    /// Opens (creating if needed) the raw files and the database of `folder` for appending,
    /// for an experiment with `instances`, and repairs an append a crash cut short.
    ///
    /// # Errors
    /// [`HarnessError::Io`] or [`HarnessError::Database`] if they cannot be opened or
    /// repaired; [`HarnessError::Serialise`] for a malformed line of `runs.jsonl`;
    /// [`HarnessError::Usage`] for files this experiment cannot continue (see the type).
    pub fn open(folder: &Path, instances: &[ProblemInstance]) -> Result<Self, HarnessError> {
        let jsonl_path = folder.join("runs.jsonl");
        let csv_path = folder.join("runs.csv");
        let mut jsonl = open_for_append(&jsonl_path)?;
        let mut csv = open_for_append(&csv_path)?;
        cut_partial_line(&mut jsonl).map_err(io(&jsonl_path))?;
        cut_partial_line(&mut csv).map_err(io(&csv_path))?;
        let entries = read_entries(&jsonl_path, false)?;
        let header = raw_runs::csv_bytes(&csv_path, &raw_runs::csv_header())?;
        let rows = match csv_rows(&csv_path, &header)? {
            None => {
                csv.write_all(&header).map_err(io(&csv_path))?;
                0
            }
            Some(rows) => rows,
        };
        if rows > entries.len() {
            return Err(HarnessError::Usage(format!(
                "`{}` has {rows} runs but `{}` only {}: the files were changed by hand; \
                 restore them or write to another --output folder",
                csv_path.display(),
                jsonl_path.display(),
                entries.len()
            )));
        }
        for (record, concurrency) in &entries[rows..] {
            let instance = instances
                .iter()
                .find(|i| i.id == record.instance)
                .ok_or_else(|| {
                    HarnessError::Usage(format!(
                        "`{}` records a run on `{}`, which this experiment does not have",
                        jsonl_path.display(),
                        record.instance
                    ))
                })?;
            let row = raw_runs::csv_row(instance, *concurrency, record);
            csv.write_all(&raw_runs::csv_bytes(&csv_path, &row)?)
                .map_err(io(&csv_path))?;
        }
        let database_path = folder.join(DATABASE_FILE);
        let database = PlannerArenaDatabase::open(&database_path)?;
        let in_database = database.count("runs")?;
        if in_database > entries.len() as i64 {
            return Err(HarnessError::Usage(format!(
                "`{}` holds {in_database} runs but `{}` only {}: the database has runs the raw \
                 files do not (written by an older mit-star, or merged by hand), and rebuilding \
                 it would lose them; move it away or write to another --output folder",
                database_path.display(),
                jsonl_path.display(),
                entries.len()
            )));
        }
        let recorded = entries.iter().map(|(r, _)| r.key()).collect();
        Ok(Self {
            jsonl_path,
            jsonl,
            csv_path,
            csv,
            database,
            experiments: HashMap::new(),
            recorded,
            started: Instant::now(),
        })
    }

    /// Every run recorded in the folder: by earlier `bench`es, and appended since opening.
    pub fn recorded(&self) -> &HashSet<RunKey> {
        &self.recorded
    }

    /// Records one finished run of `results.experiment` on `instance` (index `index` of
    /// `results.instances`; `results.runs` may be empty — only `record` is written).
    ///
    /// # Errors
    /// [`HarnessError::Io`], [`HarnessError::Serialise`] or [`HarnessError::Database`].
    pub fn append(
        &mut self,
        results: &ExperimentResults,
        index: usize,
        record: &RunRecord,
    ) -> Result<(), HarnessError> {
        self.append_raw(&results.instances[index], results.concurrency, record)?;
        self.commit(results, index, record)
    }

    /// Appends `record`, a run on `instance` made with `concurrency` runs at a time, to the raw
    /// files only, not to the database (for [`merge_parts`](crate::merge_parts), which rebuilds
    /// the database from the raw files once every run is in).
    ///
    /// # Errors
    /// [`HarnessError::Io`] or [`HarnessError::Serialise`].
    pub fn append_raw(
        &mut self,
        instance: &ProblemInstance,
        concurrency: usize,
        record: &RunRecord,
    ) -> Result<(), HarnessError> {
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

    /// Commits `record` to the database under its instance's experiment row.
    fn commit(
        &mut self,
        results: &ExperimentResults,
        index: usize,
        record: &RunRecord,
    ) -> Result<(), HarnessError> {
        let total_time = self.started.elapsed().as_secs_f64();
        let log = BenchmarkLog::from_runs(results, index, std::slice::from_ref(record), total_time);
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
        match self.experiments.get_mut(&instance.id) {
            None => {
                let experiment = self.database.insert(&log)?;
                let counts = HashMap::from([(record.planner.clone(), 1)]);
                self.experiments
                    .insert(instance.id.clone(), (experiment, counts));
            }
            Some((experiment, counts)) => {
                *counts.entry(record.planner.clone()).or_insert(0) += 1;
                let run_count = counts.values().copied().max().unwrap_or(0);
                self.database
                    .append_runs(*experiment, &log, run_count, total_time)?;
            }
        }
        Ok(())
    }

    /// Every run recorded in `folder`'s `runs.jsonl` (none if it does not exist). A last line
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
        read_entries(&folder.join("runs.jsonl"), true)
    }
}

/// The `HarnessError::Io` of `path`.
fn io(path: &Path) -> impl FnOnce(std::io::Error) -> HarnessError + use<> {
    let path = path.to_path_buf();
    move |source| HarnessError::Io { path, source }
}

/// Opens `path` for reading and appending, creating it if needed.
fn open_for_append(path: &Path) -> Result<File, HarnessError> {
    OpenOptions::new()
        .read(true)
        .append(true)
        .create(true)
        .open(path)
        .map_err(io(path))
}

/// Removes a last line without its line break (an append a crash cut short); returns the
/// bytes removed.
fn cut_partial_line(file: &mut File) -> std::io::Result<u64> {
    let length = file.metadata()?.len();
    let mut end = length;
    let mut chunk = vec![0u8; 64 * 1024];
    while end > 0 {
        let start = end.saturating_sub(chunk.len() as u64);
        let part = &mut chunk[..(end - start) as usize];
        file.seek(SeekFrom::Start(start))?;
        file.read_exact(part)?;
        if let Some(at) = part.iter().rposition(|&b| b == b'\n') {
            end = start + at as u64 + 1;
            break;
        }
        end = start;
    }
    if end < length {
        file.set_len(end)?;
    }
    Ok(length - end)
}

/// The data rows of `runs.csv` (`None` if the file is empty).
///
/// # Errors
/// [`HarnessError::Usage`] if its header is not `header` (other columns: another version);
/// [`HarnessError::Serialise`] if it is not CSV.
fn csv_rows(path: &Path, header: &[u8]) -> Result<Option<usize>, HarnessError> {
    let file = File::open(path).map_err(io(path))?;
    let mut first = Vec::new();
    let mut reader = BufReader::new(file);
    reader.read_until(b'\n', &mut first).map_err(io(path))?;
    if first.is_empty() {
        return Ok(None);
    }
    if first != header {
        return Err(HarnessError::Usage(format!(
            "`{}` has other columns than this mit-star writes (written by another version?); \
             write to another --output folder",
            path.display()
        )));
    }
    let mut rows = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(reader);
    let mut count = 0;
    let mut record = csv::ByteRecord::new();
    while rows
        .read_byte_record(&mut record)
        .map_err(|e| HarnessError::Serialise {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?
    {
        count += 1;
    }
    Ok(Some(count))
}

/// The runs of a `runs.jsonl` with the concurrency each ran at; none if the file does not
/// exist. A malformed last line is skipped if `skip_cut_last`.
fn read_entries(path: &Path, skip_cut_last: bool) -> Result<Vec<(RunRecord, usize)>, HarnessError> {
    let file = match File::open(path) {
        Ok(file) => file,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(source) => return Err(io(path)(source)),
    };
    let lines: Vec<String> = BufReader::new(file)
        .lines()
        .collect::<Result<_, _>>()
        .map_err(io(path))?;
    let mut entries = Vec::with_capacity(lines.len());
    for (number, line) in lines.iter().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let parsed = serde_json::from_str::<serde_json::Value>(line).and_then(|value| {
            let concurrency = value["concurrent_runs"].as_u64().unwrap_or(1) as usize;
            serde_json::from_value::<RunRecord>(value).map(|r| (r, concurrency))
        });
        match parsed {
            Ok(entry) => entries.push(entry),
            Err(_) if skip_cut_last && number + 1 == lines.len() => {}
            Err(e) => {
                return Err(HarnessError::Serialise {
                    path: path.to_path_buf(),
                    message: format!("line {}: {e}", number + 1),
                });
            }
        }
    }
    Ok(entries)
}

/// The results of `experiment` on `instances` made of `records` (every run recorded in the
/// folder, in file order), grouped per instance and sorted by planner and run; records of
/// instances the experiment does not have are left out.
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
    for record in records {
        if let Some(index) = instances.iter().position(|i| i.id == record.instance) {
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
    use crate::{Experiment, RunStatus};

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

    fn runs_in_database(folder: &Path) -> (i64, i64, i64) {
        let db = PlannerArenaDatabase::open(&folder.join(DATABASE_FILE)).unwrap();
        let runcount = db
            .connection()
            .query_row("SELECT max(runcount) FROM experiments", [], |r| r.get(0))
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
        let mut journal = RunJournal::open(&folder, &results.instances).unwrap();
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
        let mut journal = RunJournal::open(&folder, &results.instances).unwrap();
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
    fn a_cut_short_append_is_repaired() {
        let (folder, results) = setup("repair");
        let mut journal = RunJournal::open(&folder, &results.instances).unwrap();
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

        let journal = RunJournal::open(&folder, &results.instances).unwrap();
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
        let message = RunJournal::open(&folder, &results.instances)
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
        let message = RunJournal::open(&folder, &results.instances)
            .unwrap_err()
            .to_string();
        assert!(message.contains("holds 1 runs"), "{message}");
        let _ = std::fs::remove_dir_all(&folder);
    }

    #[test]
    fn cut_partial_line_keeps_whole_lines() {
        let path = std::env::temp_dir().join(format!("mit-star-cut-{}", std::process::id()));
        for (text, kept) in [
            ("", ""),
            ("a\n", "a\n"),
            ("a\nb", "a\n"),
            ("partial", ""),
            ("a\nb\n", "a\nb\n"),
        ] {
            std::fs::write(&path, text).unwrap();
            let mut file = open_for_append(&path).unwrap();
            let cut = cut_partial_line(&mut file).unwrap();
            assert_eq!(std::fs::read_to_string(&path).unwrap(), kept, "{text:?}");
            assert_eq!(cut as usize, text.len() - kept.len());
        }
        // A line longer than the 64 KiB chunk.
        let long = format!("a\n{}", "x".repeat(200_000));
        std::fs::write(&path, &long).unwrap();
        cut_partial_line(&mut open_for_append(&path).unwrap()).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "a\n");
        let _ = std::fs::remove_file(&path);
    }
}
