//! [`RobotChoice`]: the robot MotionBenchMaker problems are planned for (`--robot`, `robot`).

use std::path::{Path, PathBuf};

use mit_star_robot::{RobotModel, RobotSource, ShippedRobot};

use crate::error::HarnessError;

/// A robot named on the command line or in an experiment file: a shipped robot
/// ([`ShippedRobot`], the Panda by default), a URDF (the SRDF beside it, if any) or a folder
/// with a URDF and an SRDF, read strictly
/// (SRDF and allowed-collision entries naming unknown links are errors) or leniently (they are
/// warnings).
///
/// ```
/// use mit_star_benches::RobotChoice;
/// let ur5 = RobotChoice::parse(Some("ur5"), None, false)?;
/// assert_eq!(ur5.label(), "ur5");
/// assert!(RobotChoice::default().is_default());
/// let e = RobotChoice::parse(Some("ur10"), None, false).unwrap_err().to_string();
/// assert!(e.contains("panda, ur5, fetch, baxter"), "{e}");
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct RobotChoice {
    source: RobotSource,
    strict: bool,
    group: Option<String>,
}

impl RobotChoice {
    /// The robot `text` names (none: the default), a relative folder taken relative to
    /// `base` if given; `strict` as `--strict-robot`.
    ///
    /// # Errors
    /// [`HarnessError::Robot`] for a name that is neither shipped nor a URDF nor a folder with
    /// one URDF and one SRDF, listing the shipped names.
    pub fn parse(
        text: Option<&str>,
        base: Option<&Path>,
        strict: bool,
    ) -> Result<Self, HarnessError> {
        let source = match text.map(str::trim) {
            None => RobotSource::default(),
            Some(name) if ShippedRobot::find(name).is_some() => RobotSource::parse(name)?,
            Some(folder) => {
                let path = match base {
                    Some(base) if Path::new(folder).is_relative() => base.join(folder),
                    _ => PathBuf::from(folder),
                };
                RobotSource::parse(&path.to_string_lossy()).map_err(|e| match e {
                    // Name what was written, not the joined path.
                    mit_star_robot::RobotSourceError::Unknown { known, .. } => {
                        mit_star_robot::RobotSourceError::Unknown {
                            name: folder.to_owned(),
                            known,
                        }
                    }
                    other => other,
                })?
            }
        };
        Ok(Self {
            source,
            strict,
            group: None,
        })
    }

    /// Where the robot's visual mesh files are found: a shipped robot's data folder (with
    /// the smaller meshes it ships in place of the URDF's), else the URDF's folder.
    pub fn mesh_resolver(&self) -> mit_star_robot::MeshResolver {
        self.source.mesh_resolver()
    }

    /// The same robot planning only the SRDF's planning group `group` (`--group`, `group`):
    /// the other joints are held at the request's start values.
    #[must_use]
    pub fn with_group(mut self, group: Option<&str>) -> Self {
        self.group = group.map(|g| g.trim().to_owned());
        self
    }

    /// The planning group, if one is named.
    pub fn group(&self) -> Option<&str> {
        self.group.as_deref()
    }

    /// `true` for the lenient default robot.
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }

    /// `true` if unknown link names are errors.
    pub fn is_strict(&self) -> bool {
        self.strict
    }

    /// The shipped name, or the URDF's path, and the group (`baxter/right_arm`).
    pub fn label(&self) -> String {
        match &self.group {
            Some(group) => format!("{}/{group}", self.source.label()),
            None => self.source.label(),
        }
    }

    /// What an experiment file's `robot` key holds for it: the shipped name, the URDF's
    /// absolute path, or the folder's.
    pub fn file_value(&self) -> String {
        match &self.source {
            RobotSource::Shipped(name) => (*name).to_owned(),
            RobotSource::Urdf { urdf, .. } => std::fs::canonicalize(urdf)
                .unwrap_or_else(|_| urdf.clone())
                .display()
                .to_string(),
            RobotSource::Files { urdf, .. } => {
                let folder = urdf.parent().unwrap_or(urdf);
                std::fs::canonicalize(folder)
                    .unwrap_or_else(|_| folder.to_path_buf())
                    .display()
                    .to_string()
            }
        }
    }

    /// Loads the model; prints what a lenient model ignored or stopped checking to stderr.
    ///
    /// # Errors
    /// [`HarnessError::Robot`] naming the robot and what is wrong with its files.
    pub fn load(&self) -> Result<RobotModel, HarnessError> {
        let model = self.load_quiet()?;
        for warning in model.warnings() {
            eprintln!("warning: robot `{}`: {warning}", self.label());
        }
        Ok(model)
    }

    /// As [`load`](Self::load), printing nothing.
    ///
    /// # Errors
    /// As [`load`](Self::load).
    pub fn load_quiet(&self) -> Result<RobotModel, HarnessError> {
        Ok(self.source.load_group(self.strict, self.group.as_deref())?)
    }
}
