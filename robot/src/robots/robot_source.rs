//! [`RobotSource`]: a robot named on the command line — a shipped name or a folder.

use std::path::{Path, PathBuf};

use crate::{RobotModel, RobotSourceError, ShippedRobot};

/// Where a robot model comes from: a [`ShippedRobot`] by name, or a folder holding one URDF
/// (a `*_spherized.urdf` is preferred when there are several) and one `*.srdf`.
///
/// ```
/// let ur5 = robot::RobotSource::parse("ur5")?;
/// assert_eq!(ur5.label(), "ur5");
/// let model = ur5.load(false)?;
/// assert_eq!(model.joint_space().joints().len(), 6);
/// let e = robot::RobotSource::parse("ur10").unwrap_err().to_string();
/// assert!(e.contains("panda, ur5, fetch, baxter"), "{e}");
/// # Ok::<(), robot::RobotSourceError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RobotSource {
    /// A robot shipped with this crate.
    Shipped(&'static str),
    /// A URDF and an SRDF found in a folder.
    Files {
        /// The URDF (spheres as collision geometry).
        urdf: PathBuf,
        /// The SRDF.
        srdf: PathBuf,
    },
}

impl Default for RobotSource {
    fn default() -> Self {
        Self::Shipped(ShippedRobot::DEFAULT)
    }
}

impl RobotSource {
    /// A shipped robot's name, or else a folder holding the robot's URDF and SRDF.
    ///
    /// # Errors
    /// [`RobotSourceError::Unknown`] listing the shipped names when `text` is neither a name
    /// nor a folder; [`RobotSourceError::Missing`] or [`RobotSourceError::Ambiguous`] for a
    /// folder without one URDF and one SRDF; [`RobotSourceError::Io`] if it cannot be listed.
    pub fn parse(text: &str) -> Result<Self, RobotSourceError> {
        let text = text.trim();
        if let Some(robot) = ShippedRobot::find(text) {
            return Ok(Self::Shipped(robot.name));
        }
        let folder = Path::new(text);
        if !folder.is_dir() {
            return Err(RobotSourceError::Unknown {
                name: text.to_owned(),
                known: ShippedRobot::names(),
            });
        }
        let entries = std::fs::read_dir(folder).map_err(|source| RobotSourceError::Io {
            path: folder.to_path_buf(),
            source,
        })?;
        let mut files: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
        files.sort();
        let with = |suffix: &str| -> Vec<PathBuf> {
            files
                .iter()
                .filter(|p| p.is_file() && p.to_string_lossy().ends_with(suffix))
                .cloned()
                .collect()
        };
        let spherised = with("_spherized.urdf");
        let urdfs = if spherised.is_empty() {
            with(".urdf")
        } else {
            spherised
        };
        Ok(Self::Files {
            urdf: only(folder, "URDF (*.urdf)", urdfs)?,
            srdf: only(folder, "SRDF (*.srdf)", with(".srdf"))?,
        })
    }

    /// The shipped name, or the URDF's path.
    pub fn label(&self) -> String {
        match self {
            Self::Shipped(name) => (*name).to_owned(),
            Self::Files { urdf, .. } => urdf.display().to_string(),
        }
    }

    /// Loads the model, its SRDF applied, [strict](RobotModel::strict) or lenient about
    /// entries naming unknown links (lenient: see [`RobotModel::warnings`]), then
    /// [without the pairs its spheres rule out](RobotModel::without_model_pairs).
    ///
    /// # Errors
    /// [`RobotSourceError::Model`] naming the robot and what is wrong with its files.
    pub fn load(&self, strict: bool) -> Result<RobotModel, RobotSourceError> {
        self.load_group(strict, None)
    }

    /// As [`load`](Self::load), planning only the SRDF's planning group `group` if one is
    /// named ([`RobotModel::with_group_str`]; the other joints are held).
    ///
    /// # Errors
    /// As [`load`](Self::load); an unknown group is a [`RobotSourceError::Model`] listing the
    /// SRDF's groups.
    pub fn load_group(
        &self,
        strict: bool,
        group: Option<&str>,
    ) -> Result<RobotModel, RobotSourceError> {
        let model = |source| RobotSourceError::Model {
            robot: self.label(),
            source,
        };
        match self {
            Self::Shipped(name) => ShippedRobot::find(name)
                .ok_or_else(|| RobotSourceError::Unknown {
                    name: (*name).to_owned(),
                    known: ShippedRobot::names(),
                })?
                .model_of_group(strict, group)
                .map_err(model),
            Self::Files { urdf, srdf } => RobotModel::from_urdf_file(urdf)
                .and_then(|m| m.strict(strict).with_srdf_file(srdf))
                .and_then(|m| match group {
                    Some(group) => m.with_group_file(srdf, group),
                    None => Ok(m),
                })
                .map(RobotModel::without_model_pairs)
                .map_err(model),
        }
    }
}

/// The one file of `files`, or why there is not one.
fn only(
    folder: &Path,
    what: &'static str,
    files: Vec<PathBuf>,
) -> Result<PathBuf, RobotSourceError> {
    match <[PathBuf; 1]>::try_from(files) {
        Ok([file]) => Ok(file),
        Err(files) if files.is_empty() => Err(RobotSourceError::Missing {
            folder: folder.to_path_buf(),
            what,
        }),
        Err(files) => Err(RobotSourceError::Ambiguous {
            folder: folder.to_path_buf(),
            what,
            files: files
                .iter()
                .filter_map(|p| p.file_name())
                .map(|n| n.to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join(", "),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folders_need_one_urdf_and_one_srdf() {
        let dir = std::env::temp_dir().join(format!("robot-source-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let e = RobotSource::parse(dir.to_str().unwrap()).unwrap_err();
        assert!(matches!(e, RobotSourceError::Missing { what, .. } if what.starts_with("URDF")));
        let data = concat!(env!("CARGO_MANIFEST_DIR"), "/data/ur5/");
        for (from, to) in [
            ("ur5_spherized.urdf", "r_spherized.urdf"),
            ("ur5.srdf", "r.srdf"),
        ] {
            std::fs::copy(format!("{data}{from}"), dir.join(to)).unwrap();
        }
        std::fs::write(dir.join("r.urdf"), "<robot/>").unwrap();
        let source = RobotSource::parse(dir.to_str().unwrap()).unwrap();
        let RobotSource::Files { urdf, .. } = &source else {
            panic!("a folder")
        };
        assert!(
            urdf.ends_with("r_spherized.urdf"),
            "the spherised one is preferred"
        );
        let model = source.load(false).unwrap();
        assert_eq!(model.joint_names().len(), 6);
        std::fs::copy(format!("{data}ur5.srdf"), dir.join("s.srdf")).unwrap();
        let e = RobotSource::parse(dir.to_str().unwrap())
            .unwrap_err()
            .to_string();
        assert!(e.contains("r.srdf, s.srdf"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(matches!(
            RobotSource::parse("no/such/robot"),
            Err(RobotSourceError::Unknown { .. })
        ));
    }
}
