//! [`RobotSource`]: a robot named on the command line — a shipped name, a URDF or a folder.

use std::path::{Path, PathBuf};

use crate::{MeshResolver, RobotModel, RobotSourceError, ShippedRobot};

/// Where a robot model comes from: a [`ShippedRobot`] by name, a URDF file with the SRDF
/// beside it if any ([`srdf_beside`](Self::srdf_beside)), or a folder holding one URDF (a
/// `*_spherized.urdf` is preferred when there are several) and one `*.srdf`.
///
/// ```
/// let ur5 = mit_star_robot::RobotSource::parse("ur5")?;
/// assert_eq!(ur5.label(), "ur5");
/// let model = ur5.load(false)?;
/// assert_eq!(model.joint_space().joints().len(), 6);
/// let e = mit_star_robot::RobotSource::parse("ur10").unwrap_err().to_string();
/// assert!(e.contains("panda, ur5, fetch, baxter"), "{e}");
/// # Ok::<(), mit_star_robot::RobotSourceError>(())
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
    /// A URDF named by its path, and the SRDF beside it if there is one
    /// ([`srdf_beside`](Self::srdf_beside)).
    Urdf {
        /// The URDF (spheres as collision geometry).
        urdf: PathBuf,
        /// The SRDF beside it; without one, the model checks every pair of links with spheres
        /// but those its spheres rule out, with a [`ModelWarning::NoSrdf`](crate::ModelWarning::NoSrdf).
        srdf: Option<PathBuf>,
    },
}

impl Default for RobotSource {
    fn default() -> Self {
        Self::Shipped(ShippedRobot::DEFAULT)
    }
}

impl RobotSource {
    /// A shipped robot's name, else a URDF file (`*.urdf`, its SRDF found by
    /// [`srdf_beside`](Self::srdf_beside)), else a folder holding the robot's URDF and SRDF.
    ///
    /// # Errors
    /// [`RobotSourceError::Unknown`] listing the shipped names when `text` is neither a name
    /// nor a URDF nor a folder; [`RobotSourceError::Missing`] or
    /// [`RobotSourceError::Ambiguous`] for a folder without one URDF and one SRDF (or a URDF
    /// beside several SRDFs, none of its stem); [`RobotSourceError::Io`] if a folder cannot be
    /// listed.
    pub fn parse(text: &str) -> Result<Self, RobotSourceError> {
        let text = text.trim();
        if let Some(robot) = ShippedRobot::find(text) {
            return Ok(Self::Shipped(robot.name));
        }
        let path = Path::new(text);
        if path.is_file() && text.to_ascii_lowercase().ends_with(".urdf") {
            return Ok(Self::Urdf {
                urdf: path.to_path_buf(),
                srdf: Self::srdf_beside(path)?,
            });
        }
        let folder = path;
        if !folder.is_dir() {
            return Err(RobotSourceError::Unknown {
                name: text.to_owned(),
                known: ShippedRobot::names(),
            });
        }
        let files = listing(folder)?;
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

    /// The SRDF of the URDF at `urdf`: in its folder, the file of its stem with `.srdf`
    /// (`ur5_spherized.srdf`), else of its stem without `_spherized` (`ur5.srdf`), else the
    /// folder's only `*.srdf`; `None` if the folder has none.
    ///
    /// # Errors
    /// [`RobotSourceError::Ambiguous`] for several SRDFs, none named after the URDF;
    /// [`RobotSourceError::Io`] if the folder cannot be listed.
    pub fn srdf_beside(urdf: &Path) -> Result<Option<PathBuf>, RobotSourceError> {
        let folder = match urdf.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let stem = urdf
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let base = stem.strip_suffix("_spherized").unwrap_or(&stem).to_owned();
        for name in [&stem, &base] {
            let srdf = urdf.with_file_name(format!("{name}.srdf"));
            if srdf.is_file() {
                return Ok(Some(srdf));
            }
        }
        let srdfs: Vec<PathBuf> = listing(folder)?
            .into_iter()
            .filter(|p| p.is_file() && p.to_string_lossy().ends_with(".srdf"))
            .collect();
        if srdfs.is_empty() {
            return Ok(None);
        }
        only(folder, "SRDF (*.srdf)", srdfs).map(Some)
    }

    /// Where the robot's visual mesh files are found: a shipped robot's data folder (with the
    /// smaller meshes it ships in place of some of its URDF's), else the URDF's folder.
    pub fn mesh_resolver(&self) -> MeshResolver {
        match self {
            Self::Shipped(name) => ShippedRobot::find(name)
                .map_or_else(MeshResolver::default, ShippedRobot::mesh_resolver),
            Self::Files { urdf, .. } | Self::Urdf { urdf, .. } => {
                MeshResolver::for_urdf_file(urdf, Vec::new())
            }
        }
    }

    /// The shipped name, or the URDF's path.
    pub fn label(&self) -> String {
        match self {
            Self::Shipped(name) => (*name).to_owned(),
            Self::Files { urdf, .. } | Self::Urdf { urdf, .. } => urdf.display().to_string(),
        }
    }

    /// The SRDF applied, if any: compiled in for a shipped robot (`None` here), found for
    /// the others.
    pub fn srdf(&self) -> Option<&Path> {
        match self {
            Self::Shipped(_) => None,
            Self::Files { srdf, .. } => Some(srdf),
            Self::Urdf { srdf, .. } => srdf.as_deref(),
        }
    }

    /// The planning groups of the robot's SRDF, in file order (empty without one).
    ///
    /// # Errors
    /// [`RobotSourceError::Model`] for an SRDF that cannot be read or parsed.
    pub fn groups(&self) -> Result<Vec<String>, RobotSourceError> {
        let model = |source| RobotSourceError::Model {
            robot: self.label(),
            source,
        };
        match self {
            Self::Shipped(name) => Ok(ShippedRobot::find(name)
                .map(ShippedRobot::groups)
                .unwrap_or_default()),
            _ => match self.srdf() {
                None => Ok(Vec::new()),
                Some(path) => {
                    let text = std::fs::read_to_string(path).map_err(|source| {
                        model(crate::ModelError::Io {
                            path: path.to_path_buf(),
                            source,
                        })
                    })?;
                    RobotModel::srdf_groups(&text).map_err(model)
                }
            },
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
            Self::Urdf {
                urdf,
                srdf: Some(srdf),
            } => Self::Files {
                urdf: urdf.clone(),
                srdf: srdf.clone(),
            }
            .load_group(strict, group),
            Self::Urdf { urdf, srdf: None } => {
                if let Some(group) = group {
                    return Err(RobotSourceError::NoGroups {
                        urdf: urdf.clone(),
                        group: group.to_owned(),
                    });
                }
                RobotModel::from_urdf_file(urdf)
                    .map(|m| {
                        m.strict(strict)
                            .with_warning(crate::ModelWarning::NoSrdf {
                                urdf: urdf.display().to_string(),
                            })
                            .without_model_pairs()
                    })
                    .map_err(model)
            }
        }
    }
}

/// The entries of `folder`, sorted.
fn listing(folder: &Path) -> Result<Vec<PathBuf>, RobotSourceError> {
    let entries = std::fs::read_dir(folder).map_err(|source| RobotSourceError::Io {
        path: folder.to_path_buf(),
        source,
    })?;
    let mut files: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
    files.sort();
    Ok(files)
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
