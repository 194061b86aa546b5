//! [`RunJournal`]: every finished run is on disk before the next one starts.

use std::collections::HashMap;
use std::fs::{File, OpenOptions};
use std::io::{BufRead as _, BufReader, Write as _};
use std::path::{Path, PathBuf};

use crate::{
    BenchmarkLog, ExperimentResults, HarnessError, MachineInfo, PlannerArenaDatabase,
    ProblemInstance, RunRecord, raw_runs,
};

/// Appends finished runs to a results folder the moment they finish: one line to `runs.jsonl`
/// and one row to `runs.csv` (both flushed), and one transaction to the Planner Arena database
/// (the instance's experiment row is created by its first run and its `runcount` kept to the
/// runs recorded). A crash, SIGKILL or a job's time limit loses at most the runs in flight.
///
/// The raw files are only ever appended to: a second `bench` into the same folder adds its
/// runs after the first one's (see [`read_records`](Self::read_records) and `bench`'s resume).
#[derive(Debug)]
pub struct RunJournal {
    jsonl_path: PathBuf,
    jsonl: File,
    csv_path: PathBuf,
    csv: csv::Writer<File>,
    database: PlannerArenaDatabase,
    /// Per instance id: its experiment row in the database and the runs committed there,
    /// per planner.
    experiments: HashMap<String, (i64, HashMap<String, usize>)>,
    started: std::time::Instant,
}

impl RunJournal {
    /// Opens (creating if needed) the raw files and database of `folder` for appending.
    ///
    /// # Errors
    /// [`HarnessError::Io`] or [`HarnessError::Database`] if they cannot be opened.
    pub fn open(folder: &Path, database: &Path) -> Result<Self, HarnessError> {
        let append = |path: &Path| {
            OpenOptions::new()
                .create(true)
                .append(true)
                .open(path)
                .map_err(|source| HarnessError::Io {
                    path: path.to_path_buf(),
                    source,
                })
        };
        let jsonl_path = folder.join("runs.jsonl");
        let csv_path = folder.join("runs.csv");
        let jsonl = append(&jsonl_path)?;
        let csv_file = append(&csv_path)?;
        let empty = csv_file.metadata().map(|m| m.len() == 0).unwrap_or(true);
        let mut csv = csv::WriterBuilder::new().from_writer(csv_file);
        if empty {
            csv.write_record(raw_runs::csv_header())
                .and_then(|()| csv.flush().map_err(csv::Error::from))
                .map_err(|e| HarnessError::Serialise {
                    path: csv_path.clone(),
                    message: e.to_string(),
                })?;
        }
        Ok(Self {
            jsonl_path,
            jsonl,
            csv_path,
            csv,
            database: PlannerArenaDatabase::open(database)?,
            experiments: HashMap::new(),
            started: std::time::Instant::now(),
        })
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
        let instance = &results.instances[index];
        let line = raw_runs::json_line(&self.jsonl_path, instance, results.concurrency, record)?;
        let io = |path: &Path| {
            let path = path.to_path_buf();
            move |source| HarnessError::Io { path, source }
        };
        self.jsonl
            .write_all(format!("{line}\n").as_bytes())
            .and_then(|()| self.jsonl.flush())
            .map_err(io(&self.jsonl_path))?;
        self.csv
            .write_record(raw_runs::csv_row(instance, results.concurrency, record))
            .and_then(|()| self.csv.flush().map_err(csv::Error::from))
            .map_err(|e| HarnessError::Serialise {
                path: self.csv_path.clone(),
                message: e.to_string(),
            })?;
        self.commit(results, index, record)
    }

    /// Commits `record` to the database under its instance's experiment row.
    fn commit(
        &mut self,
        results: &ExperimentResults,
        index: usize,
        record: &RunRecord,
    ) -> Result<(), HarnessError> {
        let mut single = results.clone();
        single.runs = vec![Vec::new(); results.instances.len()];
        single.runs[index].push(record.clone());
        single.total_time = self.started.elapsed().as_secs_f64();
        let log = BenchmarkLog::from_results(&single, index);
        let id = single.instances[index].id.clone();
        match self.experiments.get_mut(&id) {
            None => {
                let experiment = self.database.insert(&log)?;
                let counts = HashMap::from([(record.planner.clone(), 1)]);
                self.experiments.insert(id, (experiment, counts));
            }
            Some((experiment, counts)) => {
                let count = counts.entry(record.planner.clone()).or_insert(0);
                *count += 1;
                let run_count = counts.values().copied().max().unwrap_or(0);
                self.database
                    .append_runs(*experiment, &log, run_count, single.total_time)?;
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
        let path = folder.join("runs.jsonl");
        let file = match File::open(&path) {
            Ok(file) => file,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
            Err(source) => return Err(HarnessError::Io { path, source }),
        };
        let lines: Vec<String> = BufReader::new(file)
            .lines()
            .collect::<Result<_, _>>()
            .map_err(|source| HarnessError::Io {
                path: path.clone(),
                source,
            })?;
        let mut records = Vec::with_capacity(lines.len());
        for (number, line) in lines.iter().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            match serde_json::from_str::<RunRecord>(line) {
                Ok(record) => records.push(record),
                Err(_) if number + 1 == lines.len() => {}
                Err(e) => {
                    return Err(HarnessError::Serialise {
                        path,
                        message: format!("line {}: {e}", number + 1),
                    });
                }
            }
        }
        Ok(records)
    }
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
