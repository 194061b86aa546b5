//! Whether the files of a results folder agree about the runs it holds: `runs.jsonl` (the
//! journal of record), `runs.csv` and the Planner Arena database.

use std::collections::HashSet;
use std::path::Path;

use rusqlite::{Connection, OpenFlags};

use crate::error::HarnessError;
use crate::execution::executor::RunKey;
use crate::execution::results_folder::DATABASE_FILE;
use crate::execution::run_journal::RunJournal;
use crate::execution::run_journal::{describe, repeats};
use crate::execution::shard::Shard;
use crate::formats::raw_runs;

/// Checks that `runs.jsonl`, `runs.csv` and `benchmark.db` of `folder` hold the same runs, each
/// once: the same identities in both raw files, and as many runs in the database. A last line
/// an append is cutting short is not counted. Returns the number of runs.
///
/// # Errors
/// [`HarnessError::FolderInconsistent`] naming each file's count and the first difference, and
/// how to repair the folder; the errors of reading `runs.jsonl`.
pub(crate) fn check_agreement(folder: &Path) -> Result<usize, HarnessError> {
    let journal: Vec<RunKey> = RunJournal::read_records(folder)?
        .iter()
        .map(crate::RunRecord::key)
        .collect();
    let (repeated, repeat_count) = repeats(&journal);
    let distinct: HashSet<&RunKey> = journal.iter().collect();
    let mut differences = Vec::new();
    if let Some(key) = &repeated {
        differences.push(format!(
            "`runs.jsonl` records {} twice ({} runs recorded again: two processes wrote the \
             folder at once)",
            describe(key),
            repeat_count
        ));
    }
    let csv = raw_runs::csv_runs(&folder.join("runs.csv"))?;
    let csv_count = match &csv {
        None => "no `runs.csv`".to_owned(),
        Some(c) if !c.header_matches => {
            differences.push("`runs.csv` has other columns than this mit-star writes".into());
            "`runs.csv` of other columns".to_owned()
        }
        Some(c) => {
            let (repeated, _) = repeats(&c.keys);
            let in_csv: HashSet<&RunKey> = c.keys.iter().collect();
            if let Some(key) = repeated {
                differences.push(format!("`runs.csv` has {} twice", describe(&key)));
            } else if let Some(key) = distinct.iter().find(|k| !in_csv.contains(*k)) {
                differences.push(format!(
                    "`runs.csv` lacks {}, which `runs.jsonl` records",
                    describe(key)
                ));
            } else if let Some(key) = in_csv.iter().find(|k| !distinct.contains(*k)) {
                differences.push(format!(
                    "`runs.csv` has {}, which `runs.jsonl` does not record",
                    describe(key)
                ));
            }
            format!("`runs.csv` {} rows", c.keys.len())
        }
    };
    if csv.is_none() && !journal.is_empty() {
        differences.push("`runs.csv` is missing".into());
    }
    let database = folder.join(DATABASE_FILE);
    let database_count = if database.is_file() {
        match database_runs(&database) {
            Ok(runs) => {
                if runs != distinct.len() as i64 {
                    differences.push(format!(
                        "`{DATABASE_FILE}` holds {runs} runs for {} recorded",
                        distinct.len()
                    ));
                }
                format!("`{DATABASE_FILE}` {runs} runs")
            }
            Err(e) => {
                differences.push(format!("`{DATABASE_FILE}` cannot be read ({e})"));
                format!("`{DATABASE_FILE}` unreadable")
            }
        }
    } else {
        if !journal.is_empty() {
            differences.push(format!("`{DATABASE_FILE}` is missing"));
        }
        format!("no `{DATABASE_FILE}`")
    };
    if differences.is_empty() {
        return Ok(distinct.len());
    }
    let shard = match Shard::read(folder) {
        Ok(Some(s)) => format!(" --shard {s}"),
        _ => String::new(),
    };
    Err(HarnessError::FolderInconsistent {
        path: folder.to_path_buf(),
        counts: format!(
            "`runs.jsonl` {} lines ({} distinct runs), {csv_count}, {database_count}: {}",
            journal.len(),
            distinct.len(),
            differences.join("; ")
        ),
        advice: format!(
            "a `bench` killed before it finished leaves its folder so; resume it with \
             `mit-star bench {dir}/experiment.toml{shard} --output {dir}`, which repairs the \
             files (keeping the first record of a run recorded twice) and rebuilds the rest",
            dir = folder.display()
        ),
    })
}

/// The runs in the database at `path`, opened read-only.
fn database_runs(path: &Path) -> Result<i64, rusqlite::Error> {
    let connection = Connection::open_with_flags(
        path,
        OpenFlags::SQLITE_OPEN_READ_ONLY | OpenFlags::SQLITE_OPEN_NO_MUTEX,
    )?;
    connection.query_row("SELECT count(*) FROM runs", [], |r| r.get(0))
}
