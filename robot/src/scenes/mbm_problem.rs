//! [`MbmProblem`]: one MotionBenchMaker problem, a scene and a request.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::{Scene, SceneError};

/// A MotionBenchMaker problem: `sceneNNNN.yaml` (a MoveIt planning scene) and
/// `requestNNNN.yaml` (a motion-plan request: the start state and a joint-space goal) of a
/// scene folder such as `bookshelf_small_panda/`, numbered from 1.
///
/// Joint values are kept by name; [`start_for`](Self::start_for) and
/// [`goal_for`](Self::goal_for) order them as a robot's joint space wants (values of other
/// joints, the fingers say, are ignored); a joint named twice in the start state or in the goal
/// is an error, never "the first one wins". The request's planning group (`group_name`) is
/// kept in [`group`](Self::group), for the caller to choose the robot's coordinates with
/// ([`RobotModel::with_group_str`](crate::RobotModel::with_group_str)); its `planner_id` and
/// `allowed_planning_time` are ignored.
///
/// ```
/// let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/cage_panda");
/// let indices = mit_star_robot::MbmProblem::indices(folder.as_ref())?;
/// assert_eq!(indices, [1, 2]);
/// let problem = mit_star_robot::MbmProblem::load(folder.as_ref(), 1)?;
/// assert_eq!(problem.name, "cage_panda/0001");
/// let start = problem.start_for(&["panda_joint1", "panda_joint4"])?;
/// assert_eq!(start.len(), 2);
/// assert_eq!(problem.group.as_deref(), Some("panda_arm"));
/// assert_eq!(mit_star_robot::MbmProblem::group_of(folder.as_ref(), 2)?.as_deref(), Some("panda_arm"));
/// # Ok::<(), mit_star_robot::SceneError>(())
/// ```
#[derive(Debug, Clone)]
pub struct MbmProblem {
    /// `<folder name>/<NNNN>`.
    pub name: String,
    /// The scene.
    pub scene: Scene,
    /// Start joint values by name.
    pub start: Vec<(String, f64)>,
    /// Goal joint values by name.
    pub goal: Vec<(String, f64)>,
    /// The planning group the request names (`group_name`), if it names one.
    pub group: Option<String>,
    request: PathBuf,
}

#[derive(Deserialize)]
struct RequestFile {
    start_state: StartState,
    goal_constraints: Vec<GoalConstraints>,
    #[serde(default)]
    group_name: Option<String>,
}

/// A request read for its planning group only.
#[derive(Deserialize)]
struct RequestGroup {
    #[serde(default)]
    group_name: Option<String>,
}

#[derive(Deserialize)]
struct StartState {
    joint_state: JointState,
}

#[derive(Deserialize)]
struct JointState {
    name: Vec<String>,
    position: Vec<f64>,
}

#[derive(Deserialize)]
struct GoalConstraints {
    #[serde(default)]
    joint_constraints: Vec<JointConstraint>,
}

#[derive(Deserialize)]
struct JointConstraint {
    joint_name: String,
    position: f64,
}

/// Request `index` of `folder`: its path, the path as text (for messages) and its text.
fn read_request(folder: &Path, index: usize) -> Result<(PathBuf, String, String), SceneError> {
    let request = folder.join(format!("request{index:04}.yaml"));
    let origin = request.display().to_string();
    let text =
        mit_star_problems::read_bounded(&request, mit_star_problems::TEXT_INPUT_LIMIT, "request")
            .map_err(std::io::Error::from)
            .map_err(|source| SceneError::Io {
                path: request.clone(),
                source,
            })?;
    Ok((request, origin, text))
}

/// A group name, trimmed; `None` if blank.
fn non_empty(group: Option<String>) -> Option<String> {
    group.map(|g| g.trim().to_owned()).filter(|g| !g.is_empty())
}

impl MbmProblem {
    /// The problem numbers present in `folder` (both files of each), sorted.
    ///
    /// # Errors
    /// [`SceneError::Io`] if the folder cannot be listed, [`SceneError::Folder`] if it holds
    /// no problem, or a scene without its request (or the reverse).
    pub fn indices(folder: &Path) -> Result<Vec<usize>, SceneError> {
        let entries = std::fs::read_dir(folder).map_err(|source| SceneError::Io {
            path: folder.to_path_buf(),
            source,
        })?;
        let (mut scenes, mut requests) = (Vec::new(), Vec::new());
        for entry in entries.flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            let number = |prefix: &str| {
                name.strip_prefix(prefix)
                    .and_then(|r| r.strip_suffix(".yaml"))
                    .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
                    .and_then(|d| d.parse::<usize>().ok())
            };
            if let Some(i) = number("scene") {
                scenes.push(i);
            } else if let Some(i) = number("request") {
                requests.push(i);
            }
        }
        scenes.sort_unstable();
        requests.sort_unstable();
        let folder_error = |message: String| SceneError::Folder {
            folder: folder.to_path_buf(),
            message,
        };
        if let Some(i) = scenes.iter().find(|i| requests.binary_search(i).is_err()) {
            return Err(folder_error(format!(
                "scene{i:04}.yaml has no request{i:04}.yaml"
            )));
        }
        if let Some(i) = requests.iter().find(|i| scenes.binary_search(i).is_err()) {
            return Err(folder_error(format!(
                "request{i:04}.yaml has no scene{i:04}.yaml"
            )));
        }
        if scenes.is_empty() {
            return Err(folder_error(
                "no MotionBenchMaker problem here (sceneNNNN.yaml + requestNNNN.yaml)".into(),
            ));
        }
        Ok(scenes)
    }

    /// Reads problem `index` (1-based) of `folder`.
    ///
    /// # Errors
    /// [`SceneError::Io`] for a missing file, [`SceneError::Yaml`], [`SceneError::Field`] or
    /// [`SceneError::Number`] for malformed ones (the scene's rules are
    /// [`Scene`]'s), [`SceneError::DuplicateJoint`] for a request giving a joint two values.
    pub fn load(folder: &Path, index: usize) -> Result<Self, SceneError> {
        let scene = Scene::from_yaml_file(&folder.join(format!("scene{index:04}.yaml")))?;
        let (request, origin, text) = read_request(folder, index)?;
        let file: RequestFile = crate::scenes::yaml_text::read_yaml(&text, &origin)?;
        let state = file.start_state.joint_state;
        if state.name.len() != state.position.len() {
            return Err(SceneError::Field {
                origin,
                field: "start_state.joint_state".into(),
                message: format!(
                    "{} names but {} positions",
                    state.name.len(),
                    state.position.len()
                ),
            });
        }
        let Some(goal) = file.goal_constraints.into_iter().next() else {
            return Err(SceneError::Field {
                origin,
                field: "goal_constraints".into(),
                message: "no goal constraint (a joint-space goal is needed)".into(),
            });
        };
        let start: Vec<(String, f64)> = state.name.into_iter().zip(state.position).collect();
        let goal: Vec<(String, f64)> = goal
            .joint_constraints
            .into_iter()
            .map(|c| (c.joint_name, c.position))
            .collect();
        for (what, values) in [
            ("start_state.joint_state.name", &start),
            ("goal_constraints[0].joint_constraints", &goal),
        ] {
            if let Some(joint) = repeated(values) {
                return Err(SceneError::DuplicateJoint {
                    origin,
                    what,
                    joint: joint.to_owned(),
                });
            }
        }
        for (what, values) in [
            ("start_state.joint_state.position", &start),
            ("goal_constraints[0].joint_constraints", &goal),
        ] {
            if let Some((name, v)) = values.iter().find(|(_, v)| !v.is_finite()) {
                return Err(SceneError::Field {
                    origin,
                    field: what.into(),
                    message: format!("joint `{name}` has the value {v}"),
                });
            }
        }
        let folder_name = folder.file_name().map_or_else(
            || folder.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        Ok(Self {
            name: format!("{folder_name}/{index:04}"),
            scene,
            start,
            goal,
            group: non_empty(file.group_name),
            request,
        })
    }

    /// The planning group request `index` of `folder` names (`group_name`), reading the
    /// request only: what a folder's problems are planned for, before any scene is read.
    ///
    /// # Errors
    /// [`SceneError::Io`] for a missing request, [`SceneError::Yaml`] for a malformed one.
    pub fn group_of(folder: &Path, index: usize) -> Result<Option<String>, SceneError> {
        let (_, origin, text) = read_request(folder, index)?;
        let file: RequestGroup = crate::scenes::yaml_text::read_yaml(&text, &origin)?;
        Ok(non_empty(file.group_name))
    }

    /// The start values of `joints`, in that order.
    ///
    /// # Errors
    /// [`SceneError::MissingJoint`] naming the first joint without a value.
    pub fn start_for(&self, joints: &[&str]) -> Result<Vec<f64>, SceneError> {
        self.pick(&self.start, joints, "start_state.joint_state")
    }

    /// The goal values of `joints`, in that order.
    ///
    /// # Errors
    /// [`SceneError::MissingJoint`] naming the first joint without a value.
    pub fn goal_for(&self, joints: &[&str]) -> Result<Vec<f64>, SceneError> {
        self.pick(&self.goal, joints, "goal_constraints[0].joint_constraints")
    }

    fn pick(
        &self,
        values: &[(String, f64)],
        joints: &[&str],
        what: &'static str,
    ) -> Result<Vec<f64>, SceneError> {
        joints
            .iter()
            .map(|joint| {
                values
                    .iter()
                    .find(|(name, _)| name == joint)
                    .map(|&(_, v)| v)
                    .ok_or_else(|| SceneError::MissingJoint {
                        origin: self.request.display().to_string(),
                        what,
                        joint: (*joint).to_owned(),
                    })
            })
            .collect()
    }
}

/// The first joint named twice in `values`.
fn repeated(values: &[(String, f64)]) -> Option<&str> {
    let mut seen = std::collections::HashSet::new();
    values
        .iter()
        .map(|(name, _)| name.as_str())
        .find(|name| !seen.insert(*name))
}
