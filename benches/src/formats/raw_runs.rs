//! Raw runs: `runs.csv` (one row per run) and `runs.jsonl` (one JSON object per run, with its
//! trace and path).

use std::io::Write as _;
use std::path::Path;

use crate::definition::problem_instance::ProblemInstance;
use crate::error::HarnessError;
use crate::execution::executor::RunKey;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::run_record::RunRecord;

/// The fixed CSV columns before the counters (the trace column comes last).
pub const CSV_COLUMNS: [&str; 23] = [
    "instance",
    "problem",
    "dimension",
    "instance_seed",
    "budget",
    "concurrent_runs",
    "planner",
    "configuration",
    "run",
    "seed",
    "status",
    "success",
    "valid_path",
    "setup_time",
    "run_time",
    "initial_time",
    "initial_cost",
    "final_cost",
    "improvements",
    "path_states",
    "validation_checks",
    "validation_failure",
    "error",
];

fn optional(v: Option<f64>) -> String {
    v.filter(|x| x.is_finite())
        .map_or_else(String::new, |x| x.to_string())
}

/// The header of `runs.csv`: [`CSV_COLUMNS`], the counters, the trace.
pub(crate) fn csv_header() -> Vec<String> {
    let mut header: Vec<String> = CSV_COLUMNS.iter().map(|s| (*s).to_owned()).collect();
    header.extend(
        RunRecord::counter_names()
            .iter()
            .chain(&RunRecord::real_counter_names())
            .map(|n| (*n).to_owned()),
    );
    header.push("trace".into());
    header
}

/// `text` on one line: line breaks become spaces, so that every row of `runs.csv` is one line
/// (`runs.jsonl` keeps messages as they are).
fn one_line(text: &str) -> String {
    if text.contains(['\n', '\r']) {
        text.replace("\r\n", " ").replace(['\n', '\r'], " ")
    } else {
        text.to_owned()
    }
}

/// `fields` as one CSV record, terminated by a line break, ready to be appended with a single
/// write.
///
/// # Errors
/// [`HarnessError::Serialise`] naming `path` if the record cannot be encoded.
pub(crate) fn csv_bytes(path: &Path, fields: &[String]) -> Result<Vec<u8>, HarnessError> {
    let mut w = csv::Writer::from_writer(Vec::with_capacity(1024));
    w.write_record(fields)
        .and_then(|()| w.into_inner().map_err(|e| csv::Error::from(e.into_error())))
        .map_err(|e| HarnessError::Serialise {
            path: path.to_path_buf(),
            message: e.to_string(),
        })
}

/// One run's row of `runs.csv` (every field on one line).
pub(crate) fn csv_row(
    instance: &ProblemInstance,
    concurrency: usize,
    r: &RunRecord,
) -> Vec<String> {
    let mut row = vec![
        instance.id.clone(),
        instance.label.clone(),
        instance.dimension.to_string(),
        instance.instance.to_string(),
        instance.budget.to_string(),
        concurrency.to_string(),
        one_line(&r.planner),
        r.configuration.name().to_owned(),
        r.run.to_string(),
        r.seed.to_string(),
        r.status.name().to_owned(),
        r.is_success().to_string(),
        r.validation
            .as_ref()
            .map_or_else(String::new, |v| v.valid.to_string()),
        r.setup_time.to_string(),
        r.run_time.to_string(),
        optional(r.initial_time),
        optional(r.initial_cost),
        optional(r.final_cost),
        r.trace.len().to_string(),
        r.path.len().to_string(),
        r.validation
            .as_ref()
            .map_or_else(String::new, |v| v.states_checked.to_string()),
        r.validation
            .as_ref()
            .and_then(|v| v.failure.as_deref())
            .map_or_else(String::new, one_line),
        r.error.as_deref().map_or_else(String::new, one_line),
    ];
    row.extend(r.counter_values().iter().map(|(_, c)| c.to_string()));
    row.extend(r.real_counter_values().iter().map(|(_, c)| optional(*c)));
    row.push(
        r.trace
            .iter()
            .map(|p| format!("{}:{}", p.time, p.cost))
            .collect::<Vec<_>>()
            .join(" "),
    );
    row
}

/// One run as a line of `runs.jsonl` (without the newline): the record plus its instance's
/// problem, dimension and layout seed and the run's concurrency.
///
/// # Errors
/// [`HarnessError::Serialise`] naming `path` if the record cannot be serialised.
pub(crate) fn json_line(
    path: &Path,
    instance: &ProblemInstance,
    concurrency: usize,
    r: &RunRecord,
) -> Result<String, HarnessError> {
    let mut value = serde_json::to_value(r).map_err(|e| HarnessError::Serialise {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    if let Some(object) = value.as_object_mut() {
        object.insert("problem".into(), instance.label.clone().into());
        object.insert("dimension".into(), instance.dimension.into());
        object.insert("instance_seed".into(), instance.instance.into());
        object.insert("concurrent_runs".into(), concurrency.into());
    }
    Ok(value.to_string())
}

/// The runs a `runs.csv` holds: whether its header is the one this mit-star writes, and the
/// identity of each whole row (instance, planner, run), in file order. A last row without its
/// line break (an append cut short) is not counted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct CsvRuns {
    /// The first line is [`csv_header`]'s.
    pub(crate) header_matches: bool,
    /// The identity of every whole data row.
    pub(crate) keys: Vec<RunKey>,
}

/// Reads the runs of the `runs.csv` at `path`; `None` if it does not exist or is empty.
///
/// # Errors
/// [`HarnessError::Io`] if it cannot be read; [`HarnessError::Serialise`] naming the line if a
/// row of this mit-star's columns is not CSV or has no run index.
pub(crate) fn csv_runs(path: &Path) -> Result<Option<CsvRuns>, HarnessError> {
    let bytes = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(source) => {
            return Err(HarnessError::Io {
                path: path.to_path_buf(),
                source,
            });
        }
    };
    let whole = bytes
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(&bytes[..0], |end| &bytes[..=end]);
    if whole.is_empty() {
        return Ok((!bytes.is_empty()).then(|| CsvRuns {
            header_matches: false,
            keys: Vec::new(),
        }));
    }
    let header_end = whole.iter().position(|&b| b == b'\n').unwrap_or(0);
    let header = csv_bytes(path, &csv_header())?;
    if whole[..=header_end] != header[..] {
        return Ok(Some(CsvRuns {
            header_matches: false,
            keys: Vec::new(),
        }));
    }
    let bad = |line: u64, message: String| HarnessError::Serialise {
        path: path.to_path_buf(),
        message: format!("line {line}: {message}"),
    };
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(whole);
    let mut keys = Vec::new();
    let mut row = csv::StringRecord::new();
    loop {
        let line = reader.position().line();
        match reader.read_record(&mut row) {
            Ok(false) => break,
            Ok(true) => {}
            Err(e) => return Err(bad(line, e.to_string())),
        }
        let field = |i: usize| row.get(i).unwrap_or_default();
        let run = field(8)
            .parse::<usize>()
            .map_err(|_| bad(line, "no run index in the `run` column".into()))?;
        keys.push((field(0).to_owned(), field(6).to_owned(), run));
    }
    Ok(Some(CsvRuns {
        header_matches: true,
        keys,
    }))
}

/// Writes every run of `results` to `path` as CSV (a header, then one row per run).
///
/// # Errors
/// [`HarnessError::Serialise`] if the file cannot be written.
pub fn write_runs_csv(path: &Path, results: &ExperimentResults) -> Result<(), HarnessError> {
    let fail = |message: String| HarnessError::Serialise {
        path: path.to_path_buf(),
        message,
    };
    let mut w = csv::Writer::from_path(path).map_err(|e| fail(e.to_string()))?;
    w.write_record(csv_header())
        .map_err(|e| fail(e.to_string()))?;
    for (index, runs) in results.runs.iter().enumerate() {
        let instance = &results.instances[index];
        for r in runs {
            w.write_record(csv_row(instance, results.concurrency, r))
                .map_err(|e| fail(e.to_string()))?;
        }
    }
    w.flush().map_err(|e| fail(e.to_string()))
}

/// Writes every run of `results` to `path` as JSON lines.
///
/// # Errors
/// [`HarnessError::Io`] or [`HarnessError::Serialise`] if the file cannot be written.
pub fn write_runs_jsonl(path: &Path, results: &ExperimentResults) -> Result<(), HarnessError> {
    let io = |source| HarnessError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::create(path).map_err(io)?;
    let mut out = std::io::BufWriter::new(file);
    for (index, runs) in results.runs.iter().enumerate() {
        let instance = &results.instances[index];
        for r in runs {
            writeln!(
                out,
                "{}",
                json_line(path, instance, results.concurrency, r)?
            )
            .map_err(io)?;
        }
    }
    out.flush().map_err(io)
}
