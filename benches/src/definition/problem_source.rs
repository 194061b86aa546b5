//! [`ProblemSource`]: where an experiment's problem comes from (a built-in family or a file).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use mit_star_problems::Problem;

use crate::definition::mbm_folder::MbmFolder;
use crate::definition::problem_kind::InstanceProblem;
use crate::definition::robot_choice::RobotChoice;

use crate::error::HarnessError;

/// The built-in family names, comma separated.
pub(crate) fn builtin_names() -> String {
    mit_star_problems::catalogue()
        .iter()
        .map(|f| f.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// A problem: a built-in family of [`mit_star_problems::catalogue`] (built for any dimension), or a
/// TOML problem file (its dimension is fixed by the file).
///
/// ```
/// use mit_star_benches::ProblemSource;
/// let source = ProblemSource::parse("dividing-walls", None)?;
/// assert_eq!(source.label(), "dividing-walls");
/// let problem = source.build(4, 0, None)?;
/// assert_eq!(problem.dimension(), 4);
/// assert!(ProblemSource::parse("dividing-wall", None).is_err());
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ProblemSource {
    /// A built-in family, by name.
    Builtin(String),
    /// A problem file, read and checked once.
    File(ProblemFile),
    /// A MotionBenchMaker scene folder (`mbm:PATH`) and the robot planned for; instances are
    /// its problem indices (1-based).
    Mbm(MbmFolder),
}

/// A problem file read once: its path and the problem it defines (a world of 100 000 boxes is
/// several megabytes of TOML; every instance of an experiment shares the one parsed copy).
#[derive(Debug, Clone)]
pub struct ProblemFile {
    path: PathBuf,
    problem: Arc<Problem>,
}

impl ProblemFile {
    /// Reads and checks the file.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a folder, [`HarnessError::ProblemFile`] for an unreadable
    /// or malformed file.
    pub fn read(path: impl Into<PathBuf>) -> Result<Self, HarnessError> {
        let path = path.into();
        if path.is_dir() {
            return Err(HarnessError::Usage(format!(
                "`{}` is a folder, not a problem file (give a .toml file; see `problems/examples/`)",
                path.display()
            )));
        }
        let problem = Problem::from_file(&path).map_err(|source| HarnessError::ProblemFile {
            path: path.clone(),
            source,
        })?;
        Ok(Self {
            path,
            problem: Arc::new(problem),
        })
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The problem it defines.
    pub fn problem(&self) -> &Problem {
        &self.problem
    }
}

/// Files are the same source when their paths are.
impl PartialEq for ProblemFile {
    fn eq(&self, other: &Self) -> bool {
        self.path == other.path
    }
}

impl Eq for ProblemFile {}

impl ProblemSource {
    /// A built-in name, or else the path of an existing problem file (relative paths are
    /// taken relative to `base`, if given).
    ///
    /// # Errors
    /// [`HarnessError::UnknownProblem`] listing the built-in names when `text` is neither.
    pub fn parse(text: &str, base: Option<&Path>) -> Result<Self, HarnessError> {
        Self::parse_for_robot(text, base, &RobotChoice::default())
    }

    /// As [`parse`](Self::parse), a MotionBenchMaker folder planned for `robot`.
    ///
    /// # Errors
    /// As [`parse`](Self::parse); [`HarnessError::Robot`] if the robot's files cannot be loaded.
    pub fn parse_for_robot(
        text: &str,
        base: Option<&Path>,
        robot: &RobotChoice,
    ) -> Result<Self, HarnessError> {
        let text = text.trim();
        if let Some(folder) = text.strip_prefix("mbm:") {
            let path = match base {
                Some(base) if Path::new(folder).is_relative() => base.join(folder),
                _ => PathBuf::from(folder),
            };
            return MbmFolder::read(path, robot).map(Self::Mbm);
        }
        if mit_star_problems::catalogue()
            .iter()
            .any(|f| f.name() == text)
        {
            return Ok(Self::Builtin(text.to_owned()));
        }
        let path = match base {
            Some(base) if Path::new(text).is_relative() => base.join(text),
            _ => PathBuf::from(text),
        };
        if path.exists() {
            return Self::file(path);
        }
        Err(HarnessError::UnknownProblem {
            name: text.to_owned(),
            known: builtin_names(),
        })
    }

    /// A problem file, read and checked now (once).
    ///
    /// # Errors
    /// As [`ProblemFile::read`].
    pub fn file(path: impl Into<PathBuf>) -> Result<Self, HarnessError> {
        ProblemFile::read(path).map(Self::File)
    }

    /// `true` if the problem's layout depends on a seed (random rectangles).
    pub fn is_seeded(&self) -> bool {
        match self {
            Self::Builtin(name) => mit_star_problems::catalogue()
                .iter()
                .any(|f| f.name() == name && f.is_seeded()),
            Self::File(_) => false,
            Self::Mbm(_) => true,
        }
    }

    /// A short name without whitespace: the family's name or the file's stem.
    pub fn label(&self) -> String {
        let raw = match self {
            Self::Builtin(name) => name.clone(),
            Self::File(file) => file.path().file_stem().map_or_else(
                || "problem".to_owned(),
                |s| s.to_string_lossy().into_owned(),
            ),
            Self::Mbm(folder) => folder
                .path()
                .file_name()
                .map_or_else(|| "mbm".to_owned(), |s| s.to_string_lossy().into_owned()),
        };
        sanitise(&raw)
    }

    /// Builds the problem in `dimension` dimensions (files: must match the file's), with the
    /// layout seed `instance` (seeded families only) and, if given, another resolution.
    ///
    /// # Errors
    /// [`HarnessError::Problem`] for a dimension the family does not support or a bad
    /// resolution, [`HarnessError::ProblemFile`] for an unreadable or malformed file, and
    /// [`HarnessError::Usage`] when a file's dimension differs from `dimension`.
    pub fn build(
        &self,
        dimension: usize,
        instance: u64,
        resolution: Option<f64>,
    ) -> Result<InstanceProblem, HarnessError> {
        if let Self::Mbm(folder) = self {
            return folder.build(dimension, instance, resolution);
        }
        let problem =
            match self {
                Self::Mbm(_) => unreachable!("built above"),
                Self::Builtin(name) => mit_star_problems::builtin(name, dimension, instance)
                    .map_err(|source| HarnessError::Problem {
                        name: name.clone(),
                        dimension,
                        source,
                    })?,
                Self::File(file) => {
                    let problem = file.problem();
                    if problem.dimension() != dimension {
                        return Err(HarnessError::Usage(format!(
                            "problem file `{}` is {}-dimensional, not {dimension}-dimensional",
                            file.path().display(),
                            problem.dimension()
                        )));
                    }
                    problem.clone()
                }
            };
        match resolution {
            None => Ok(problem),
            Some(r) => problem
                .with_resolution(r)
                .map_err(|source| HarnessError::Problem {
                    name: self.label(),
                    dimension,
                    source,
                }),
        }
        .map(InstanceProblem::Boxes)
    }

    /// The dimension of a problem file (`None` for built-in families, which have any).
    ///
    /// # Errors
    /// [`HarnessError::ProblemFile`] for an unreadable or malformed file.
    pub fn fixed_dimension(&self) -> Result<Option<usize>, HarnessError> {
        match self {
            Self::Builtin(_) => Ok(None),
            Self::File(file) => Ok(Some(file.problem().dimension())),
            Self::Mbm(folder) => Ok(Some(folder.dimension())),
        }
    }
}

/// Keeps letters, digits, `-`, `_` and `.`; everything else becomes `-`.
pub(crate) fn sanitise(text: &str) -> String {
    let s: String = text
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '-'
            }
        })
        .collect();
    if s.is_empty() {
        "problem".to_owned()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_files_and_errors() {
        let s = ProblemSource::parse("random-rectangles", None).unwrap();
        assert!(s.is_seeded());
        assert_eq!(s.fixed_dimension().unwrap(), None);
        assert!(
            !ProblemSource::parse("flanking-gap", None)
                .unwrap()
                .is_seeded()
        );
        let e = ProblemSource::parse("nope", None).unwrap_err().to_string();
        assert!(
            e.contains("built-in problems: flanking-gap, dividing-walls"),
            "{e}"
        );
        let e = ProblemSource::Builtin("dividing-walls".into())
            .build(1, 0, None)
            .unwrap_err()
            .to_string();
        assert!(e.contains("dividing-walls") && e.contains("1"), "{e}");
        assert!(ProblemSource::file("/definitely/not/here.toml").is_err());
        assert_eq!(sanitise("my problem/1"), "my-problem-1");
    }

    #[test]
    fn problem_files_fix_the_dimension() {
        let dir = std::env::temp_dir().join(format!("mit-star-source-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("wall.toml");
        let problem = mit_star_problems::builtin("wall-gap", 2, 0).unwrap();
        std::fs::write(&path, problem.to_toml_string()).unwrap();
        let s = ProblemSource::parse("wall.toml", Some(&dir)).unwrap();
        assert_eq!(s, ProblemSource::file(&path).unwrap());
        let ProblemSource::File(file) = &s else {
            panic!("a file source")
        };
        assert_eq!(file.path(), path);
        assert_eq!(s.label(), "wall");
        assert_eq!(s.fixed_dimension().unwrap(), Some(2));
        assert_eq!(s.build(2, 0, Some(1e-4)).unwrap().resolution(), 1e-4);
        assert!(s.build(3, 0, None).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
