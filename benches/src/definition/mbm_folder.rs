//! [`MbmFolder`]: a MotionBenchMaker scene folder and the robot its problems are planned for.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use mit_star_robot::RobotModel;
use mit_star_spaces::StateSpace;

use crate::definition::problem_kind::InstanceProblem;
use crate::definition::robot_choice::RobotChoice;
use crate::error::HarnessError;

/// A MotionBenchMaker scene folder (`sceneNNNN.yaml` + `requestNNNN.yaml` pairs) and the
/// robot model its problems are planned for, read once.
#[derive(Debug, Clone)]
pub struct MbmFolder {
    path: PathBuf,
    indices: Vec<usize>,
    choice: RobotChoice,
    robot: Arc<RobotModel>,
    /// The scene warnings printed so far (each is printed once per folder).
    noted: Arc<Mutex<HashSet<String>>>,
}

impl MbmFolder {
    /// Lists the folder's problems and loads the robot model (printing its warnings).
    ///
    /// Without a group named (`--group`, `group`), the folder's problems are planned for the
    /// planning group its first request names (`group_name`) when the robot's SRDF has it and
    /// it moves other joints than the whole robot does (a note on stderr says so); a group the
    /// SRDF lacks is a warning, and every moving joint is planned.
    ///
    /// # Errors
    /// [`HarnessError::Arm`] for a folder without problems, or half of one, or an unreadable
    /// first request; [`HarnessError::Robot`] for a robot that cannot be loaded.
    pub fn read(path: impl Into<PathBuf>, robot: &RobotChoice) -> Result<Self, HarnessError> {
        let path = path.into();
        let arm = |e: mit_star_robot::SceneError| HarnessError::Arm {
            name: path.display().to_string(),
            source: e.into(),
        };
        let indices = mit_star_robot::MbmProblem::indices(&path).map_err(arm)?;
        let mut choice = robot.clone();
        let mut model = robot.load()?;
        if robot.group().is_none()
            && let Some(group) =
                mit_star_robot::MbmProblem::group_of(&path, indices[0]).map_err(arm)?
        {
            match robot.clone().with_group(Some(&group)).load_quiet() {
                Ok(grouped) if grouped.joint_names() != model.joint_names() => {
                    eprintln!(
                        "note: `{}`: planning group `{group}` of robot `{}`, as the requests \
                         name it (`--group` chooses another)",
                        path.display(),
                        robot.label()
                    );
                    choice = robot.clone().with_group(Some(&group));
                    // What only the group adds (members naming links the model lacks).
                    for warning in grouped.warnings() {
                        if !model.warnings().contains(warning) {
                            eprintln!("warning: robot `{}`: {warning}", choice.label());
                        }
                    }
                    model = grouped;
                }
                Ok(_) => {}
                Err(e) => eprintln!(
                    "warning: `{}`: the requests name planning group `{group}`; planning every \
                     moving joint of robot `{}` instead ({e})",
                    path.display(),
                    robot.label()
                ),
            }
        }
        Ok(Self {
            path,
            indices,
            choice,
            robot: Arc::new(model),
            noted: Arc::default(),
        })
    }

    /// The folder.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The problem indices it holds, ascending.
    pub fn indices(&self) -> &[usize] {
        &self.indices
    }

    /// The robot its problems are planned for.
    pub fn robot(&self) -> &RobotChoice {
        &self.choice
    }

    /// The robot's number of joints.
    pub fn dimension(&self) -> usize {
        self.robot.joint_space().dimension()
    }

    /// Problem `index`, checked every `resolution` if given; prints the scene's warnings
    /// (allowed-collision entries naming unknown links) once per folder.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for another dimension than the robot's or an index the folder
    /// lacks, [`HarnessError::Arm`] for unreadable files or unusable values.
    pub(crate) fn build(
        &self,
        dimension: usize,
        index: u64,
        resolution: Option<f64>,
    ) -> Result<InstanceProblem, HarnessError> {
        let joints = self.dimension();
        if dimension != joints {
            return Err(HarnessError::Usage(format!(
                "`{}` plans for robot `{}`'s {joints} joints, not {dimension} dimensions",
                self.path.display(),
                self.choice.label()
            )));
        }
        let Some(&index) = usize::try_from(index)
            .ok()
            .and_then(|i| self.indices.iter().find(|&&k| k == i))
        else {
            let (first, last) = (self.indices[0], self.indices[self.indices.len() - 1]);
            return Err(HarnessError::Usage(format!(
                "`{}` has no problem {index} (it holds {} problems, {first} to {last})",
                self.path.display(),
                self.indices.len()
            )));
        };
        let arm = |source: mit_star_robot::ArmError| HarnessError::Arm {
            name: format!("{}/{index:04}", self.path.display()),
            source,
        };
        let mut problem = mit_star_robot::ArmProblem::mbm((*self.robot).clone(), &self.path, index)
            .map_err(arm)?;
        let known = self.robot.warnings().len();
        if let Ok(mut noted) = self.noted.lock() {
            for warning in &problem.robot().warnings()[known..] {
                if noted.insert(warning.to_string()) {
                    eprintln!("warning: `{}`: {warning}", self.path.display());
                }
            }
        }
        if let Some(r) = resolution {
            problem = problem.with_resolution(r).map_err(arm)?;
        }
        Ok(InstanceProblem::Arm(Arc::new(problem)))
    }
}

/// Folders are the same source when their paths and robots are.
impl PartialEq for MbmFolder {
    fn eq(&self, other: &Self) -> bool {
        self.path == other.path && self.choice == other.choice
    }
}

impl Eq for MbmFolder {}
