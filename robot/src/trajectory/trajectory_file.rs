//! [`TrajectoryFile`]: a sampled trajectory as a file — JSON or CSV, joint names included.

use std::fmt::Write as _;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::{Sample, Trajectory, TrajectoryError};

/// Samples of a trajectory with the joints' names: what the writers write and the reader
/// reads.
///
/// - **JSON**: `{"joints": [names], "samples": [{"time": t, "position": [..], "velocity":
///   [..], "acceleration": [..]}, ..]}`.
/// - **CSV**: a header `time,position.NAME…,velocity.NAME…,acceleration.NAME…` (each group in
///   joint order), then one line per sample.
///
/// Chosen by the file's extension (`.json`, `.csv`). Numbers are written in Rust's shortest
/// round-trip form: reading gives back the same values.
#[derive(Debug, Clone, PartialEq)]
pub struct TrajectoryFile {
    /// The joints, in the order of the samples' vectors.
    pub joints: Vec<String>,
    /// The samples, in time order.
    pub samples: Vec<Sample>,
}

#[derive(Serialize, Deserialize)]
struct JsonSample {
    time: f64,
    position: Vec<f64>,
    velocity: Vec<f64>,
    acceleration: Vec<f64>,
}

#[derive(Serialize, Deserialize)]
struct JsonFile {
    joints: Vec<String>,
    samples: Vec<JsonSample>,
}

/// The largest trajectory file read, in bytes.
const MAX_BYTES: u64 = 1 << 30;

impl TrajectoryFile {
    /// `trajectory` sampled every `period` seconds (and at its end), or at its knots
    /// (`None`).
    ///
    /// # Errors
    /// [`TrajectoryError::BadPeriod`].
    pub fn of(trajectory: &Trajectory, period: Option<f64>) -> Result<Self, TrajectoryError> {
        let samples = match period {
            Some(p) => trajectory.sample(p)?,
            None => trajectory.knots().to_vec(),
        };
        Ok(Self {
            joints: trajectory.names().to_vec(),
            samples,
        })
    }

    /// The JSON text.
    pub fn to_json(&self) -> String {
        let file = JsonFile {
            joints: self.joints.clone(),
            samples: self
                .samples
                .iter()
                .map(|s| JsonSample {
                    time: s.time,
                    position: s.position.clone(),
                    velocity: s.velocity.clone(),
                    acceleration: s.acceleration.clone(),
                })
                .collect(),
        };
        serde_json::to_string(&file).unwrap_or_default()
    }

    /// The CSV text.
    pub fn to_csv(&self) -> String {
        let mut out = String::from("time");
        for group in ["position", "velocity", "acceleration"] {
            for name in &self.joints {
                let _ = write!(out, ",{group}.{name}");
            }
        }
        out.push('\n');
        for s in &self.samples {
            let _ = write!(out, "{:?}", s.time);
            for v in s.position.iter().chain(&s.velocity).chain(&s.acceleration) {
                let _ = write!(out, ",{v:?}");
            }
            out.push('\n');
        }
        out
    }

    /// Reads JSON text; `origin` names it in errors.
    ///
    /// # Errors
    /// [`TrajectoryError::Format`] for malformed JSON or a sample whose vectors do not have
    /// one value per joint.
    pub fn from_json(text: &str, origin: &str) -> Result<Self, TrajectoryError> {
        let file: JsonFile =
            serde_json::from_str(text).map_err(|e| format(origin, e.to_string()))?;
        let samples = file
            .samples
            .into_iter()
            .map(|s| Sample {
                time: s.time,
                position: s.position,
                velocity: s.velocity,
                acceleration: s.acceleration,
            })
            .collect();
        Self::checked(file.joints, samples, origin)
    }

    /// Reads CSV text; `origin` names it in errors.
    ///
    /// # Errors
    /// [`TrajectoryError::Format`] for a header that is not this format's, a line of the
    /// wrong length or a value that is not a number.
    pub fn from_csv(text: &str, origin: &str) -> Result<Self, TrajectoryError> {
        let mut lines = text.lines().filter(|l| !l.trim().is_empty());
        let header: Vec<&str> = lines
            .next()
            .ok_or_else(|| format(origin, "no header".into()))?
            .split(',')
            .map(str::trim)
            .collect();
        if header.first() != Some(&"time") || !(header.len() - 1).is_multiple_of(3) {
            return Err(format(
                origin,
                "the header is not `time,position.…,velocity.…,acceleration.…`".into(),
            ));
        }
        let n = (header.len() - 1) / 3;
        let mut joints = Vec::with_capacity(n);
        for (g, group) in ["position", "velocity", "acceleration"].iter().enumerate() {
            for j in 0..n {
                let column = header[1 + g * n + j];
                let name = column
                    .strip_prefix(group)
                    .and_then(|c| c.strip_prefix('.'))
                    .ok_or_else(|| {
                        format(
                            origin,
                            format!("header column `{column}` is not `{group}.NAME`"),
                        )
                    })?;
                if g == 0 {
                    joints.push(name.to_owned());
                } else if name != joints[j] {
                    return Err(format(
                        origin,
                        format!("header column `{column}` should name joint `{}`", joints[j]),
                    ));
                }
            }
        }
        let mut samples = Vec::new();
        for (line, text) in lines.enumerate() {
            let values = text
                .split(',')
                .map(|v| v.trim().parse::<f64>())
                .collect::<Result<Vec<f64>, _>>()
                .map_err(|e| format(origin, format!("sample {line}: {e}")))?;
            if values.len() != header.len() {
                return Err(format(
                    origin,
                    format!(
                        "sample {line} has {} values, the header {}",
                        values.len(),
                        header.len()
                    ),
                ));
            }
            samples.push(Sample {
                time: values[0],
                position: values[1..=n].to_vec(),
                velocity: values[1 + n..=2 * n].to_vec(),
                acceleration: values[1 + 2 * n..].to_vec(),
            });
        }
        Self::checked(joints, samples, origin)
    }

    /// Writes the file, JSON or CSV by its extension.
    ///
    /// # Errors
    /// [`TrajectoryError::Io`] for another extension or a failed write.
    pub fn write(&self, path: &Path) -> Result<(), TrajectoryError> {
        let text = match extension(path)? {
            Kind::Json => self.to_json(),
            Kind::Csv => self.to_csv(),
        };
        std::fs::write(path, text).map_err(|e| io(path, e.to_string()))
    }

    /// Reads a file, JSON or CSV by its extension.
    ///
    /// # Errors
    /// [`TrajectoryError::Io`] for another extension, a file that cannot be read or over
    /// 1 GiB; [`TrajectoryError::Format`] as [`from_json`](Self::from_json) and
    /// [`from_csv`](Self::from_csv).
    pub fn read(path: &Path) -> Result<Self, TrajectoryError> {
        let kind = extension(path)?;
        let size = std::fs::metadata(path)
            .map_err(|e| io(path, e.to_string()))?
            .len();
        if size > MAX_BYTES {
            return Err(io(path, format!("{size} bytes, over {MAX_BYTES}")));
        }
        let text = std::fs::read_to_string(path).map_err(|e| io(path, e.to_string()))?;
        let origin = path.display().to_string();
        match kind {
            Kind::Json => Self::from_json(&text, &origin),
            Kind::Csv => Self::from_csv(&text, &origin),
        }
    }

    fn checked(
        joints: Vec<String>,
        samples: Vec<Sample>,
        origin: &str,
    ) -> Result<Self, TrajectoryError> {
        let n = joints.len();
        for (i, s) in samples.iter().enumerate() {
            if s.position.len() != n || s.velocity.len() != n || s.acceleration.len() != n {
                return Err(format(
                    origin,
                    format!("sample {i} does not have {n} values per vector"),
                ));
            }
        }
        Ok(Self { joints, samples })
    }
}

enum Kind {
    Json,
    Csv,
}

fn extension(path: &Path) -> Result<Kind, TrajectoryError> {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("json") => Ok(Kind::Json),
        Some("csv") => Ok(Kind::Csv),
        _ => Err(io(path, "a trajectory file is .json or .csv".into())),
    }
}

fn io(path: &Path, message: String) -> TrajectoryError {
    TrajectoryError::Io {
        path: path.to_owned(),
        message,
    }
}

fn format(origin: &str, message: String) -> TrajectoryError {
    TrajectoryError::Format {
        origin: origin.to_owned(),
        message,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file() -> TrajectoryFile {
        TrajectoryFile {
            joints: vec!["a".into(), "b".into()],
            samples: vec![
                Sample {
                    time: 0.0,
                    position: vec![0.1, -0.2],
                    velocity: vec![0.0, 0.0],
                    acceleration: vec![1.0 / 3.0, 2.0],
                },
                Sample {
                    time: 0.5,
                    position: vec![0.3, 1e-17],
                    velocity: vec![0.25, -1.5],
                    acceleration: vec![0.0, 0.0],
                },
            ],
        }
    }

    #[test]
    fn round_trips_json_and_csv() {
        let f = file();
        assert_eq!(TrajectoryFile::from_json(&f.to_json(), "t").unwrap(), f);
        assert_eq!(TrajectoryFile::from_csv(&f.to_csv(), "t").unwrap(), f);
        assert!(
            f.to_csv()
                .starts_with("time,position.a,position.b,velocity.a,velocity.b,acceleration.a")
        );
    }

    #[test]
    fn refuses_malformed_files() {
        assert!(matches!(
            TrajectoryFile::from_csv("t,x\n", "t"),
            Err(TrajectoryError::Format { .. })
        ));
        let bad = "time,position.a,velocity.b,acceleration.a\n0,1,2,3\n";
        assert!(TrajectoryFile::from_csv(bad, "t").is_err());
        let short = "time,position.a,velocity.a,acceleration.a\n0,1,2\n";
        assert!(TrajectoryFile::from_csv(short, "t").is_err());
        assert!(TrajectoryFile::from_json("{\"joints\":[\"a\"],\"samples\":[{\"time\":0,\"position\":[],\"velocity\":[0],\"acceleration\":[0]}]}", "t").is_err());
    }
}
