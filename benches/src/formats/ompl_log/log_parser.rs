//! Reading OMPL benchmark logs back ([`BenchmarkLog::parse`]), strictly by the grammar.

use crate::error::HarnessError;
use crate::formats::ompl_log::benchmark_log::{BenchmarkLog, PlannerLog};
use crate::formats::ompl_log::log_value::{
    EnumType, ExperimentProperty, LogValue, Property, PropertyType,
};

/// The lines of a log with a cursor; errors carry 1-based line numbers.
struct Lines<'a> {
    lines: Vec<&'a str>,
    next: usize,
}

impl<'a> Lines<'a> {
    fn error(&self, message: impl Into<String>) -> HarnessError {
        HarnessError::LogSyntax {
            line: self.next.max(1),
            message: message.into(),
        }
    }

    fn peek(&self) -> Option<&'a str> {
        self.lines.get(self.next).copied()
    }

    fn take(&mut self, what: &str) -> Result<&'a str, HarnessError> {
        let line = self
            .peek()
            .ok_or_else(|| self.error(format!("the log ends where {what} was expected")))?;
        self.next += 1;
        Ok(line)
    }

    /// A line `<number> <suffix>`; returns the number's text.
    fn counted(&mut self, suffix: &str) -> Result<&'a str, HarnessError> {
        let line = self.take(suffix)?;
        match line.split_once(' ') {
            Some((n, rest)) if rest == suffix => Ok(n),
            _ => Err(self.error(format!("expected `<number> {suffix}`, found {line:?}"))),
        }
    }

    /// A count line `<int> <suffix>`.
    fn count(&mut self, suffix: &str) -> Result<usize, HarnessError> {
        let n = self.counted(suffix)?;
        n.parse()
            .map_err(|_| self.error(format!("`{n}` is not a count (in `{n} {suffix}`)")))
    }

    /// A real line `<float> <suffix>`.
    fn real(&mut self, suffix: &str) -> Result<f64, HarnessError> {
        let n = self.counted(suffix)?;
        n.parse()
            .map_err(|_| self.error(format!("`{n}` is not a number (in `{n} {suffix}`)")))
    }

    /// `true` if the next line is `<number> <suffix>`.
    fn next_is(&self, suffix: &str) -> bool {
        self.peek()
            .and_then(|l| l.split_once(' '))
            .is_some_and(|(n, rest)| rest == suffix && n.parse::<f64>().is_ok())
    }

    /// A `<<<|` … `|>>>` block.
    fn block(&mut self) -> Result<String, HarnessError> {
        let open = self.take("`<<<|`")?;
        if open != "<<<|" {
            return Err(self.error(format!("expected `<<<|`, found {open:?}")));
        }
        let mut text = String::new();
        loop {
            let line = self.take("`|>>>`")?;
            if line.starts_with("|>>>") {
                return Ok(text);
            }
            text.push_str(line);
            text.push('\n');
        }
    }

    /// A line `<prefix><rest>`; returns `rest`.
    fn prefixed(&mut self, prefix: &str) -> Result<&'a str, HarnessError> {
        let line = self.take(prefix)?;
        line.strip_prefix(prefix)
            .ok_or_else(|| self.error(format!("expected `{prefix}…`, found {line:?}")))
    }

    /// A property line `<name words> <TYPE>`.
    fn property(&mut self) -> Result<Property, HarnessError> {
        let line = self.take("a property")?;
        let (name, word) = line
            .rsplit_once(' ')
            .ok_or_else(|| self.error(format!("expected `<name> <TYPE>`, found {line:?}")))?;
        let kind = PropertyType::from_word(word)
            .ok_or_else(|| self.error(format!("unknown property type `{word}`")))?;
        Ok(Property::new(name, kind))
    }
}

/// Parses one field of the given type (`""`, `inf`, `nan` are `NULL`).
fn value(text: &str, kind: PropertyType) -> Result<LogValue, String> {
    let t = text.trim();
    if kind == PropertyType::String {
        return Ok(LogValue::Text(t.to_owned()));
    }
    if t.is_empty() || matches!(t, "inf" | "-inf" | "nan" | "-nan" | "NaN") {
        return Ok(LogValue::Null);
    }
    match kind {
        PropertyType::Real => t
            .parse::<f64>()
            .map(LogValue::real)
            .map_err(|_| format!("`{t}` is not a REAL")),
        _ => t
            .parse::<i64>()
            .map(LogValue::Integer)
            .map_err(|_| format!("`{t}` is not a valid {}", kind.word())),
    }
}

impl BenchmarkLog {
    /// Reads a log written by OMPL, MoveIt or this harness, following the grammar of OMPL's
    /// benchmark log (optional parts: version line, experiment properties, CPU block, run
    /// count, enum types, progress blocks).
    ///
    /// # Errors
    /// [`HarnessError::LogSyntax`] with the line number and what was expected.
    pub fn parse(text: &str) -> Result<Self, HarnessError> {
        let mut l = Lines {
            lines: text.lines().collect(),
            next: 0,
        };
        let (mut library, mut version) = (String::new(), String::new());
        if let Some(first) = l.peek() {
            let words: Vec<&str> = first.split_whitespace().collect();
            if words.len() >= 3 && words[1] == "version" {
                library = words[0].to_owned();
                version = words[words.len() - 1].to_owned();
                l.next += 1;
            }
        }
        let experiment = l.prefixed("Experiment ")?.to_owned();
        let mut properties = Vec::new();
        if l.next_is("experiment properties") {
            for _ in 0..l.count("experiment properties")? {
                let line = l.take("an experiment property")?;
                let (left, raw) = line.split_once(" = ").ok_or_else(|| {
                    l.error(format!(
                        "expected `<name> <TYPE> = <value>`, found {line:?}"
                    ))
                })?;
                let (name, word) = left
                    .rsplit_once(' ')
                    .ok_or_else(|| l.error(format!("no type in {line:?}")))?;
                let kind = PropertyType::from_word(word)
                    .ok_or_else(|| l.error(format!("unknown property type `{word}`")))?;
                let value = value(raw, kind).map_err(|m| l.error(m))?;
                properties.push(ExperimentProperty {
                    name: name.to_owned(),
                    kind,
                    value,
                });
            }
        }
        let hostname = l.prefixed("Running on ")?.to_owned();
        let date = l.prefixed("Starting at ")?.to_owned();
        let setup = l.block()?;
        let cpu_info = if l.peek() == Some("<<<|") {
            Some(l.block()?)
        } else {
            None
        };
        let seed_text = l.counted("is the random seed")?;
        let seed = seed_text
            .parse()
            .map_err(|_| l.error(format!("`{seed_text}` is not a seed")))?;
        let time_limit = l.real("seconds per run")?;
        let memory_limit = l.real("MB per run")?;
        let runs_per_planner = if l.next_is("runs per planner") {
            Some(l.count("runs per planner")?)
        } else {
            None
        };
        let total_time = l.real("seconds spent to collect the data")?;
        let mut enums = Vec::new();
        let enum_suffix = ["enum types", "enum type"]
            .into_iter()
            .find(|s| l.next_is(s));
        if let Some(suffix) = enum_suffix {
            for _ in 0..l.count(suffix)? {
                let line = l.take("an enum type")?;
                let mut parts = line.split('|');
                let name = parts.next().unwrap_or_default().to_owned();
                let values: Vec<String> = parts.map(str::to_owned).collect();
                if values.is_empty() {
                    return Err(l.error(format!("enum `{name}` has no values")));
                }
                enums.push(EnumType { name, values });
            }
        }
        let planner_count = l.count("planners")?;
        let mut planners = Vec::with_capacity(planner_count);
        for _ in 0..planner_count {
            planners.push(planner(&mut l)?);
        }
        if let Some(extra) = l.lines[l.next..].iter().find(|s| !s.trim().is_empty()) {
            return Err(l.error(format!("unexpected text after the last planner: {extra:?}")));
        }
        Ok(Self {
            library,
            version,
            experiment,
            properties,
            hostname,
            date,
            setup,
            cpu_info,
            seed,
            time_limit,
            memory_limit,
            runs_per_planner,
            total_time,
            enums,
            planners,
        })
    }
}

/// One planner block.
fn planner(l: &mut Lines<'_>) -> Result<PlannerLog, HarnessError> {
    let name = l.take("a planner name")?.to_owned();
    let mut common = Vec::new();
    for _ in 0..l.count("common properties")? {
        let line = l.take("a common property")?;
        let (k, v) = line
            .split_once(" = ")
            .ok_or_else(|| l.error(format!("expected `<name> = <value>`, found {line:?}")))?;
        common.push((k.to_owned(), v.to_owned()));
    }
    let mut run_properties = Vec::new();
    for _ in 0..l.count("properties for each run")? {
        run_properties.push(l.property()?);
    }
    let mut runs = Vec::new();
    for _ in 0..l.count("runs")? {
        let line = l.take("a run")?;
        let mut fields: Vec<&str> = line.split(';').collect();
        if fields.last().is_some_and(|f| f.trim().is_empty()) {
            fields.pop();
        } else {
            return Err(l.error(format!("a run line must end with `; `: {line:?}")));
        }
        if fields.len() != run_properties.len() {
            return Err(l.error(format!(
                "a run has {} values for {} properties",
                fields.len(),
                run_properties.len()
            )));
        }
        let row = fields
            .iter()
            .zip(&run_properties)
            .map(|(f, p)| value(f, p.kind))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|m| l.error(m))?;
        runs.push(row);
    }
    let (mut progress_properties, mut progress) = (Vec::new(), Vec::new());
    if l.peek().map(str::trim) != Some(".") {
        for _ in 0..l.count("progress properties for each run")? {
            progress_properties.push(l.property()?);
        }
        for _ in 0..l.count("runs")? {
            let line = l.take("a run's progress")?;
            let mut samples = Vec::new();
            let pieces: Vec<&str> = line.split(';').collect();
            let (last, complete) = pieces.split_last().unwrap_or((&"", &[]));
            if !last.trim().is_empty() {
                return Err(l.error(format!("progress samples must end with `;`: {line:?}")));
            }
            for sample in complete {
                let mut fields: Vec<&str> = sample.split(',').collect();
                if fields.pop().is_some_and(|f| !f.trim().is_empty()) {
                    return Err(l.error(format!("progress fields must end with `,`: {sample:?}")));
                }
                if fields.len() != progress_properties.len() {
                    return Err(l.error(format!(
                        "a progress sample has {} values for {} properties",
                        fields.len(),
                        progress_properties.len()
                    )));
                }
                let row = fields
                    .iter()
                    .zip(&progress_properties)
                    .map(|(f, p)| value(f, p.kind))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|m| l.error(m))?;
                samples.push(row);
            }
            progress.push(samples);
        }
    }
    let end = l.take("`.`")?;
    if end.trim() != "." {
        return Err(l.error(format!(
            "expected `.` closing planner `{name}`, found {end:?}"
        )));
    }
    Ok(PlannerLog {
        name,
        common,
        run_properties,
        runs,
        progress_properties,
        progress,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const OMPL_STYLE: &str = "OMPL version 1.6.0\nExperiment kitchen\nRunning on host\nStarting at 2024-01-01T00:00:00\n<<<|\nsetup line\n|>>>\n<<<|\ncpu\n|>>>\n42 is the random seed\n1 seconds per run\n4096 MB per run\n2 runs per planner\n2.5 seconds spent to collect the data\n1 enum type\nstatus|Unknown status|Timeout\n1 planners\ngeometric_RRT\n1 common properties\nrange = 0.5\n3 properties for each run\ntime REAL\nsolved BOOLEAN\nstatus ENUM\n2 runs\n0.1; 1; 1; \n; 0; inf; \n.\n";

    #[test]
    fn reads_an_ompl_style_log() {
        let log = BenchmarkLog::parse(OMPL_STYLE).unwrap();
        assert_eq!(
            (log.library.as_str(), log.version.as_str()),
            ("OMPL", "1.6.0")
        );
        assert_eq!(log.experiment, "kitchen");
        assert_eq!(log.setup, "setup line\n");
        assert_eq!(log.cpu_info.as_deref(), Some("cpu\n"));
        assert_eq!((log.seed, log.runs_per_planner), (42, Some(2)));
        assert_eq!(log.enums[0].values, ["Unknown status", "Timeout"]);
        let p = &log.planners[0];
        assert_eq!(p.settings(), "range = 0.5\n;");
        assert_eq!(
            p.runs[0],
            vec![
                LogValue::Real(0.1),
                LogValue::Integer(1),
                LogValue::Integer(1)
            ]
        );
        assert_eq!(
            p.runs[1],
            vec![LogValue::Null, LogValue::Integer(0), LogValue::Null]
        );
        assert!(p.progress.is_empty());
    }

    #[test]
    fn errors_give_the_line() {
        let bad = OMPL_STYLE.replace("0.1; 1; 1; ", "0.1; 1; ");
        let e = BenchmarkLog::parse(&bad).unwrap_err().to_string();
        assert!(
            e.contains("line 27") && e.contains("2 values for 3 properties"),
            "{e}"
        );
        let bad = OMPL_STYLE.replace("0.1; 1; 1; ", "0.1; yes; 1; ");
        let e = BenchmarkLog::parse(&bad).unwrap_err().to_string();
        assert!(e.contains("`yes` is not a valid BOOLEAN"), "{e}");
        let bad = OMPL_STYLE.replace("1 planners", "2 planners");
        assert!(
            BenchmarkLog::parse(&bad)
                .unwrap_err()
                .to_string()
                .contains("ends")
        );
        let bad = OMPL_STYLE.replace("Running on", "Runnin on");
        assert!(
            BenchmarkLog::parse(&bad)
                .unwrap_err()
                .to_string()
                .contains("line 3")
        );
        let bad = format!("{OMPL_STYLE}junk\n");
        assert!(BenchmarkLog::parse(&bad).is_err());
    }
}
