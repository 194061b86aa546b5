//! [`merge_parts`]: the results folders of an experiment's shards combined into one.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::definition::experiment::Experiment;
use crate::error::HarnessError;
use crate::execution::executor::RunKey;
use crate::execution::results_folder::ResultsFolder;
use crate::execution::results_folder::folder_lock::FolderLock;
use crate::execution::run_job::RunJob;
use crate::execution::run_journal::{RunJournal, results_from_records};
use crate::execution::shard::Shard;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::machine_info::{MachineInfo, iso_timestamp};
use crate::outcome::run_record::RunRecord;

/// What [`merge_parts`] combined.
#[derive(Debug, Clone)]
pub struct MergeReport {
    /// The merged results (every run of the experiment).
    pub results: ExperimentResults,
    /// Runs taken from each part, in the order the parts were given.
    pub runs_per_part: Vec<usize>,
    /// The files written.
    pub files: Vec<PathBuf>,
}

/// Combines the results folders `parts` of `bench --shard K/N` runs into `output`: raw runs,
/// one OMPL log per problem instance, the Planner Arena database, the `figures` and the
/// KPI tables, exactly as if the experiment had run whole on one machine (runs in schedule
/// order, each with the seed and outcome its shard recorded).
///
/// It refuses, naming the folders: parts of different experiments (their `experiment.toml`
/// differ), a folder that is not a shard, parts of different shard counts, a shard given twice
/// or missing, a run recorded in a part it does not belong to or in two parts, and missing runs
/// (an interrupted shard: resume it first). `output` may be a fresh folder or an earlier merge
/// of the same experiment (runs it holds are kept, not duplicated). The parts are read under
/// their shared locks and `output` written under its write lock: a part still being written,
/// or an output another process writes, is refused.
///
/// # Errors
/// [`HarnessError::Usage`] for the refusals above, [`HarnessError::FolderLocked`] for a
/// folder in use, and the errors of reading the parts and of writing `output`.
pub fn merge_parts(
    parts: &[PathBuf],
    output: &Path,
    figures: crate::execution::figures::Figures,
) -> Result<MergeReport, HarnessError> {
    let shards = shards_of(parts)?;
    // No part changes while it is read: a shard still being written is refused.
    let _reading = parts
        .iter()
        .map(|part| FolderLock::shared(part))
        .collect::<Result<Vec<_>, _>>()?;
    let first = &parts[0];
    let count = shards[0].count();
    let experiment = Experiment::from_file(&first.join("experiment.toml"))?;
    let instances = experiment.instances()?;
    // Every run of the experiment, by identity: its position in the schedule.
    let schedule = RunJob::schedule(
        instances.len(),
        experiment.planners.len(),
        experiment.runs,
        experiment.seed,
    );
    let positions: HashMap<RunKey, usize> = schedule
        .iter()
        .enumerate()
        .map(|(position, job)| (job.key(&experiment, &instances), position))
        .collect();
    let mut slots: Vec<Option<(RunRecord, usize, usize)>> = vec![None; schedule.len()];
    let mut runs_per_part = Vec::with_capacity(parts.len());
    for (part_index, (part, shard)) in parts.iter().zip(&shards).enumerate() {
        let entries = RunJournal::read_entries(part)?;
        runs_per_part.push(entries.len());
        for (record, concurrency) in entries {
            let key = record.key();
            let Some(&position) = positions.get(&key) else {
                return Err(HarnessError::Usage(format!(
                    "`{}` records run {} of {} on `{}`, which the experiment does not have",
                    part.display(),
                    key.2,
                    key.1,
                    key.0
                )));
            };
            if !shard.owns(position) {
                return Err(HarnessError::Usage(format!(
                    "`{}` (shard {shard}) records run {} of {} on `{}`, which belongs to shard \
                     {}/{count}",
                    part.display(),
                    key.2,
                    key.1,
                    key.0,
                    Shard::of(position, count)
                )));
            }
            if slots[position].is_some() {
                return Err(HarnessError::Usage(format!(
                    "`{}` records run {} of {} on `{}` twice",
                    part.display(),
                    key.2,
                    key.1,
                    key.0
                )));
            }
            slots[position] = Some((record, concurrency, part_index));
        }
    }
    let missing: Vec<usize> = (0..slots.len()).filter(|&p| slots[p].is_none()).collect();
    if let Some(&position) = missing.first() {
        let job = &schedule[position];
        let part = &parts[shards
            .iter()
            .position(|s| s.owns(position))
            .unwrap_or_default()];
        return Err(HarnessError::Usage(format!(
            "{} of the experiment's {} runs {} missing, the first run {} of {} on `{}` of \
             shard {}/{count} (`{}`); finish that shard first (`mit-star bench \
             {}/experiment.toml --shard {}/{count} --output {}` resumes it)",
            missing.len(),
            schedule.len(),
            if missing.len() == 1 { "is" } else { "are" },
            job.run,
            experiment.planners[job.planner].name(),
            instances[job.instance].id,
            Shard::of(position, count),
            part.display(),
            part.display(),
            Shard::of(position, count),
            part.display()
        )));
    }
    if Shard::read(output)?.is_some() {
        return Err(HarnessError::Usage(format!(
            "`{}` is a shard's folder; merge into a folder of its own",
            output.display()
        )));
    }
    let mut folder = ResultsFolder::prepare(output)?;
    folder.claim(&experiment)?;
    let index_of: HashMap<&str, usize> = instances
        .iter()
        .enumerate()
        .map(|(i, instance)| (instance.id.as_str(), i))
        .collect();
    let mut journal = RunJournal::open(output, &experiment, &instances)?;
    let mut total_time = 0.0;
    for (record, concurrency, _) in slots.iter().flatten() {
        total_time += record.run_time;
        if !journal.recorded().contains(&record.key()) {
            journal.append_raw(
                &instances[index_of[record.instance.as_str()]],
                *concurrency,
                record,
            )?;
        }
    }
    drop(journal);
    let template = ExperimentResults {
        experiment,
        instances: instances.clone(),
        runs: vec![Vec::new(); instances.len()],
        started_at: iso_timestamp(SystemTime::now()),
        total_time,
        concurrency: slots.iter().flatten().map(|s| s.1).max().unwrap_or(1),
        interrupted: false,
        machine: MachineInfo::detect(),
    };
    let results = results_from_records(&template, RunJournal::read_records(output)?, &instances);
    let files = folder.finish(&results, figures)?;
    Ok(MergeReport {
        results,
        runs_per_part,
        files,
    })
}

/// The shard of each of `parts`, checked to be all N shards of one experiment, each once.
fn shards_of(parts: &[PathBuf]) -> Result<Vec<Shard>, HarnessError> {
    let first = parts
        .first()
        .ok_or_else(|| HarnessError::Usage("merge: give the shard folders to combine".into()))?;
    let text = experiment_text(first)?;
    let mut shards: Vec<Shard> = Vec::with_capacity(parts.len());
    for part in parts {
        if experiment_text(part)? != text {
            return Err(HarnessError::Usage(format!(
                "`{}` and `{}` hold different experiments (their experiment.toml differ); \
                 only the shards of one experiment can be merged",
                first.display(),
                part.display()
            )));
        }
        let shard = Shard::read(part)?.ok_or_else(|| {
            HarnessError::Usage(format!(
                "`{}` is not a shard's folder (it has no {}): merge combines the folders of \
                 `mit-star bench --shard K/N`",
                part.display(),
                crate::SHARD_FILE
            ))
        })?;
        if let Some(other) = shards.iter().position(|s| *s == shard) {
            return Err(HarnessError::Usage(format!(
                "`{}` and `{}` are both shard {shard}",
                parts[other].display(),
                part.display()
            )));
        }
        if shard.count() != shards.first().map_or(shard.count(), |s| s.count()) {
            return Err(HarnessError::Usage(format!(
                "`{}` is shard {shard} but `{}` is shard {}: all parts must split the \
                 experiment into the same number of shards",
                part.display(),
                first.display(),
                shards[0]
            )));
        }
        shards.push(shard);
    }
    let count = shards[0].count();
    if shards.len() != count {
        let missing: Vec<String> = (1..=count)
            .filter(|k| !shards.iter().any(|s| s.index() == *k))
            .map(|k| format!("{k}/{count}"))
            .collect();
        let (plural, verb) = if missing.len() == 1 {
            ("", "is")
        } else {
            ("s", "are")
        };
        return Err(HarnessError::Usage(format!(
            "shard{plural} {} {verb} missing: give all {count} shard folders",
            missing.join(", ")
        )));
    }
    Ok(shards)
}

/// The `experiment.toml` of a results folder.
fn experiment_text(folder: &Path) -> Result<String, HarnessError> {
    let path = folder.join("experiment.toml");
    std::fs::read_to_string(&path).map_err(|source| match source.kind() {
        std::io::ErrorKind::NotFound => HarnessError::Usage(format!(
            "`{}` is not a results folder (it has no experiment.toml)",
            folder.display()
        )),
        _ => HarnessError::Io { path, source },
    })
}
