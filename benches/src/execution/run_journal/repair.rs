//! What [`RunJournal::open`](super::RunJournal::open) repairs: a line an append cut short,
//! `runs.csv` rows missing behind `runs.jsonl`, and runs recorded twice.

use std::collections::HashSet;
use std::fs::{File, OpenOptions};
use std::io::{BufRead as _, BufReader, Read as _, Seek as _, SeekFrom};
use std::path::Path;

use crate::error::HarnessError;
use crate::execution::executor::RunKey;
use crate::outcome::run_record::RunRecord;

/// One line of `runs.jsonl`: the run, how many runs executed at the same time, and the line as
/// written (kept verbatim when the file is rewritten).
#[derive(Debug, Clone)]
pub(super) struct JournalLine {
    pub(super) record: RunRecord,
    pub(super) concurrency: usize,
    pub(super) text: String,
    /// Its line number in the file (from 1).
    pub(super) line: usize,
}

/// The `HarnessError::Io` of `path`.
pub(super) fn io(path: &Path) -> impl FnOnce(std::io::Error) -> HarnessError + use<> {
    let path = path.to_path_buf();
    move |source| HarnessError::Io { path, source }
}

/// Opens `path` for reading and appending, creating it if needed.
pub(super) fn open_for_append(path: &Path) -> Result<File, HarnessError> {
    OpenOptions::new()
        .read(true)
        .append(true)
        .create(true)
        .open(path)
        .map_err(io(path))
}

/// Removes a last line without its line break (an append a crash cut short); returns the
/// bytes removed.
pub(super) fn cut_partial_line(file: &mut File) -> std::io::Result<u64> {
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

/// Every line of a `runs.jsonl`, in file order, duplicates included; none if the file does not
/// exist. A malformed last line is skipped if `skip_cut_last` (a reader's view of a file an
/// append may be cutting short).
///
/// # Errors
/// [`HarnessError::Io`] if the file cannot be read, [`HarnessError::Serialise`] naming the
/// line for a malformed one.
pub(super) fn read_lines(
    path: &Path,
    skip_cut_last: bool,
) -> Result<Vec<JournalLine>, HarnessError> {
    let file = match File::open(path) {
        Ok(file) => file,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(source) => return Err(io(path)(source)),
    };
    let lines: Vec<String> = BufReader::new(file)
        .lines()
        .collect::<Result<_, _>>()
        .map_err(io(path))?;
    let count = lines.len();
    let mut entries = Vec::with_capacity(count);
    for (number, text) in lines.into_iter().enumerate() {
        if text.trim().is_empty() {
            continue;
        }
        let parsed = serde_json::from_str::<serde_json::Value>(&text).and_then(|value| {
            let concurrency = value["concurrent_runs"].as_u64().unwrap_or(1) as usize;
            serde_json::from_value::<RunRecord>(value).map(|r| (r, concurrency))
        });
        match parsed {
            Ok((record, concurrency)) => entries.push(JournalLine {
                record,
                concurrency,
                text,
                line: number + 1,
            }),
            Err(_) if skip_cut_last && number + 1 == count => {}
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

/// The first line of each run (by [`RunRecord::key`]), in file order: a run is recorded once,
/// whoever recorded it again.
pub(super) fn distinct(lines: Vec<JournalLine>) -> Vec<JournalLine> {
    let mut seen = HashSet::with_capacity(lines.len());
    lines
        .into_iter()
        .filter(|line| seen.insert(line.record.key()))
        .collect()
}

/// The first run recorded twice among `keys`, and how many repeats there are.
pub(crate) fn repeats<'a>(keys: impl IntoIterator<Item = &'a RunKey>) -> (Option<RunKey>, usize) {
    let mut seen = HashSet::new();
    let mut first = None;
    let mut count = 0;
    for key in keys {
        if !seen.insert(key) {
            count += 1;
            first.get_or_insert_with(|| key.clone());
        }
    }
    (first, count)
}

/// "run 3 of MIT* on `dividing-walls-n2`".
pub(crate) fn describe(key: &RunKey) -> String {
    format!("run {} of {} on `{}`", key.2, key.1, key.0)
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn repeats_name_the_first_run_recorded_twice() {
        let key = |run| ("i".to_owned(), "MIT*".to_owned(), run);
        let keys = [key(0), key(1), key(0), key(2), key(1), key(0)];
        assert_eq!(repeats(&keys), (Some(key(0)), 3));
        assert_eq!(repeats(&keys[..2]), (None, 0));
        assert_eq!(describe(&key(3)), "run 3 of MIT* on `i`");
    }
}
