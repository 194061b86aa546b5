//! [`PyProblem`] (`mit_star.Problem`): a planning problem — a PDT family by name and
//! dimension, a TOML problem file, a box world from numpy arrays, or a MotionBenchMaker problem
//! for a robot — resolved exactly as `mit-star plan --problem … --dim …` resolves it.

use std::path::PathBuf;

use mit_star_benches::commands::{CloudArgs, ProblemArgs};
use mit_star_benches::{InstanceProblem, PoseGoalSpec};
use numpy::ndarray::ArrayView2;
use numpy::{PyArray1, PyArray2, PyReadonlyArray2};

use crate::arrays::{matrix, vector};
use mit_star_problems::{PlanningProblem, Problem};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use pyo3::prelude::*;

use crate::box_world::box_world;
use crate::error::{BindingError, BindingResult};

/// A planning problem: a space (bounds), a start, one or more goals, a collision-check
/// resolution and a built-in validity checker (a box world or a robot arm in a scene).
///
/// Build one with `Problem(name, dim=…)` (a PDT family, a TOML file or `mbm:FOLDER`, as the
/// command line's `--problem` takes them), `Problem.from_file`, `Problem.mbm` or
/// `Problem.boxes`.
#[pyclass(module = "mit_star._native", name = "Problem", frozen)]
#[derive(Debug, Clone)]
pub struct PyProblem {
    /// The problem the planners plan on.
    pub(crate) problem: InstanceProblem,
    /// The problem's identifier (`dividing-walls-R4`, `box_panda-R7-3`, …).
    pub(crate) id: String,
    /// A link's pose as the goal instead of the goal configuration (arms).
    pub(crate) pose_goal: Option<PoseGoalSpec>,
    /// Where an arm's visual mesh files are found, for `write_view`.
    pub(crate) meshes: Option<mit_star_robot::MeshResolver>,
}

impl PyProblem {
    /// Resolves a problem exactly as the command line's problem options do.
    fn resolve(args: &ProblemArgs) -> BindingResult<Self> {
        let instance = args.build(1.0)?;
        Ok(Self {
            meshes: instance.mesh_resolver(),
            problem: instance.problem,
            id: instance.id,
            pose_goal: None,
        })
    }

    /// A box-world problem built here (numpy arrays), checked as a problem file would be.
    pub(crate) fn from_boxes(problem: Problem) -> BindingResult<Self> {
        let boxes = InstanceProblem::Boxes(problem);
        boxes.check_step()?;
        let id = format!(
            "{}-R{}",
            boxes.as_boxes().map_or("boxes", |p| p.name()),
            boxes.dimension()
        );
        Ok(Self {
            problem: boxes,
            id,
            pose_goal: None,
            meshes: None,
        })
    }

    /// The space's lower and upper bounds.
    fn bounds_of(&self) -> (&[f64], &[f64]) {
        match &self.problem {
            InstanceProblem::Boxes(p) => (p.space().lower(), p.space().upper()),
            InstanceProblem::Arm(p) => (p.space().lower(), p.space().upper()),
        }
    }
}

// PyO3 extracts each argument as an owned value: taking it by value is the binding's shape.
#[allow(clippy::needless_pass_by_value)]
#[pymethods]
impl PyProblem {
    /// A problem named as the command line's `--problem` names it: a PDT family
    /// (`mit_star.problem_families()`, built for `dim` dimensions, default 2), a TOML problem
    /// file, or `mbm:FOLDER` (a MotionBenchMaker scene folder, planned for `robot`).
    ///
    /// `instance` is the layout seed of seeded families (random rectangles, default 0) or the
    /// problem index in a MotionBenchMaker folder (default its first); `resolution` replaces
    /// the problem's collision-check resolution; `robot` is a shipped robot (`panda`, `ur5`,
    /// `fetch`, `baxter`) or a folder holding one URDF and one SRDF; `group` plans only that
    /// SRDF planning group (the other joints held); `strict_robot` refuses SRDF entries
    /// naming links the robot lacks; `allow_coarse_step` allows a step coarser than the
    /// thinnest obstacle (or an arm without certification); `padding` (metres, arm problems,
    /// at most 1) is kept between every robot sphere and every obstacle along every path, as
    /// `--padding` keeps it.
    #[new]
    #[pyo3(signature = (name, dim=None, *, instance=None, resolution=None, robot=None, group=None, strict_robot=false, allow_coarse_step=false, padding=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        name: &str,
        dim: Option<usize>,
        instance: Option<u64>,
        resolution: Option<f64>,
        robot: Option<String>,
        group: Option<String>,
        strict_robot: bool,
        allow_coarse_step: bool,
        padding: Option<f64>,
    ) -> BindingResult<Self> {
        let file = name.ends_with(".toml").then(|| PathBuf::from(name));
        Self::resolve(&ProblemArgs {
            padding: padding_of(padding)?,
            problem: file.is_none().then(|| name.to_owned()),
            problem_file: file,
            robot,
            group,
            strict_robot,
            dim,
            instance,
            resolution,
            allow_coarse_step,
            clouds: CloudArgs::default(),
        })
    }

    /// A problem read from a TOML problem file (see `problems/examples/`).
    #[staticmethod]
    #[pyo3(signature = (path, *, resolution=None, allow_coarse_step=false))]
    fn from_file(
        path: PathBuf,
        resolution: Option<f64>,
        allow_coarse_step: bool,
    ) -> BindingResult<Self> {
        Self::resolve(&ProblemArgs {
            problem: None,
            problem_file: Some(path),
            robot: None,
            group: None,
            strict_robot: false,
            dim: None,
            instance: None,
            resolution,
            allow_coarse_step,
            padding: None,
            clouds: CloudArgs::default(),
        })
    }

    /// Problem `instance` (1-based; default the folder's first) of a MotionBenchMaker scene
    /// folder, planned for `robot` (a shipped robot name or a folder with a URDF and an SRDF;
    /// default the Panda) and its SRDF planning group `group` (default: the group the
    /// folder's requests name, where the SRDF has it; else every moving joint). The folders of
    /// the shipped Panda problems come from
    /// `tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/`.
    ///
    /// Point clouds join the scene's obstacles as `plan`'s cloud options add them: `cloud`, an
    /// (N, 3) array or list of numbers (copied: the checker keeps its own reordered copy in its tree;
    /// NaN rows dropped), `cloud_files` (PLY, PCD or `.npy` paths), `sensor_pose`
    /// (x, y, z, roll, pitch, yaw of the sensor in the robot's base frame, applied to both),
    /// `scene_as_cloud` (replace the primitives by N points sampled on each), `point_radius`
    /// (metres, default 0.0025), and the filters `crop_reach`, `remove_robot` (padding, at the
    /// start), `voxel` and `min_distance` (metres); `drop_primitives` plans among the clouds
    /// alone, `save_cloud` writes the filtered cloud (`.ply` or `.npy`).
    ///
    /// `padding` (metres, at most 1) is kept between every robot sphere and every obstacle or
    /// cloud point's ball along every path (certified, not between the robot's own links), as
    /// `--padding` keeps it; a start or goal within it raises `ValueError` naming the padding.
    #[staticmethod]
    #[pyo3(signature = (folder, instance=None, *, robot=None, group=None, strict_robot=false, resolution=None, padding=None, cloud=None, cloud_files=None, sensor_pose=None, scene_as_cloud=None, point_radius=None, crop_reach=false, remove_robot=None, voxel=None, min_distance=None, drop_primitives=false, save_cloud=None))]
    #[allow(clippy::too_many_arguments)]
    fn mbm(
        folder: PathBuf,
        instance: Option<u64>,
        robot: Option<String>,
        group: Option<String>,
        strict_robot: bool,
        resolution: Option<f64>,
        padding: Option<f64>,
        cloud: Option<&Bound<'_, PyAny>>,
        cloud_files: Option<Vec<PathBuf>>,
        sensor_pose: Option<[f64; 6]>,
        scene_as_cloud: Option<usize>,
        point_radius: Option<f64>,
        crop_reach: bool,
        remove_robot: Option<f64>,
        voxel: Option<f64>,
        min_distance: Option<f64>,
        drop_primitives: bool,
        save_cloud: Option<PathBuf>,
    ) -> BindingResult<Self> {
        let clouds = CloudArgs {
            cloud: cloud_files.unwrap_or_default(),
            scene_as_cloud,
            point_radius,
            sensor_pose: sensor_pose
                .map(|p| p.iter().map(f64::to_string).collect::<Vec<_>>().join(",")),
            crop_reach,
            remove_robot,
            voxel,
            min_distance,
            drop_primitives,
            save_cloud,
            points: cloud
                .map(cloud_points)
                .transpose()?
                .map(|c| c.points)
                .unwrap_or_default(),
        };
        Self::resolve(&ProblemArgs {
            problem: Some(format!("mbm:{}", folder.display())),
            problem_file: None,
            robot,
            group,
            strict_robot,
            dim: None,
            instance,
            resolution,
            allow_coarse_step: false,
            padding: padding_of(padding)?,
            clouds,
        })
    }

    /// A box world from numpy arrays: bounds `lower`, `upper` (length d), a `start` and a
    /// `goal` (length d, or `goals` of shape (k, d)), obstacles as `centers` and `widths` of
    /// shape (m, d) (full side lengths), and optionally anti-obstacles (free boxes carved out of
    /// obstacles) as `free_centers` and `free_widths`.
    #[staticmethod]
    #[pyo3(signature = (lower, upper, start, goal, *, centers=None, widths=None, free_centers=None, free_widths=None, resolution=None, name="boxes", allow_coarse_step=false))]
    #[allow(clippy::too_many_arguments)]
    fn boxes(
        lower: &Bound<'_, PyAny>,
        upper: &Bound<'_, PyAny>,
        start: &Bound<'_, PyAny>,
        goal: &Bound<'_, PyAny>,
        centers: Option<&Bound<'_, PyAny>>,
        widths: Option<&Bound<'_, PyAny>>,
        free_centers: Option<&Bound<'_, PyAny>>,
        free_widths: Option<&Bound<'_, PyAny>>,
        resolution: Option<f64>,
        name: &str,
        allow_coarse_step: bool,
    ) -> BindingResult<Self> {
        // Lists and integer arrays are converted; float64 arrays are read in place.
        let (lower, upper) = (vector("lower", lower)?, vector("upper", upper)?);
        let start = vector("start", start)?;
        let centers = centers.map(|a| matrix("centers", a)).transpose()?;
        let widths = widths.map(|a| matrix("widths", a)).transpose()?;
        let free_centers = free_centers
            .map(|a| matrix("free_centers", a))
            .transpose()?;
        let free_widths = free_widths.map(|a| matrix("free_widths", a)).transpose()?;
        let problem = box_world(
            name,
            (lower.as_array(), upper.as_array()),
            (start.as_array(), goal),
            (
                centers.as_ref().map(|c| c.as_array()),
                widths.as_ref().map(|w| w.as_array()),
            ),
            (
                free_centers.as_ref().map(|c| c.as_array()),
                free_widths.as_ref().map(|w| w.as_array()),
            ),
        )?;
        let problem = match resolution {
            Some(r) => problem.with_resolution(r)?,
            None => problem,
        };
        Self::from_boxes(problem.allowing_coarse_step(allow_coarse_step))
    }

    /// The same arm problem with a pose of `link` as its goal: planners built for it draw
    /// goal configurations by inverse kinematics while planning (collision-free, distinct; at
    /// most `ik_goals`, `ik_initial_goals` of them before planning starts), and a path ends
    /// at one of them.
    ///
    /// `pose` is `"goal"` (the default: the pose the goal configuration gives the link) or 7 numbers
    /// x, y, z, qx, qy, qz, qw (metres, a quaternion, normalised) in the robot's root frame;
    /// `tool`, 3 or 7 numbers, a frame fixed to the link whose pose is meant instead;
    /// `position_tolerance`, a ball radius or 3 box half-extents (metres; exact by default);
    /// `orientation_tolerance`, `"exact"` (default), `"free"`, `"cone:AXIS:ANGLE"` or
    /// `"axis:AXIS"` (AXIS `x`, `y`, `z` or `a;b;c`), as `mit-star plan --goal-pose` takes
    /// them. Raises `ValueError` for a box world, an unknown link or a malformed value.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (link, pose=None, *, tool=None, position_tolerance=None, orientation_tolerance=None, ik_goals=8, ik_initial_goals=1))]
    fn with_goal_pose(
        &self,
        link: String,
        pose: Option<&Bound<'_, PyAny>>,
        tool: Option<Vec<f64>>,
        position_tolerance: Option<&Bound<'_, PyAny>>,
        orientation_tolerance: Option<String>,
        ik_goals: usize,
        ik_initial_goals: usize,
    ) -> BindingResult<Self> {
        let Some(arm) = self.problem.as_arm() else {
            return Err(BindingError::Value(
                "a pose goal is a goal of arm problems; this is a box world".into(),
            ));
        };
        let pose = match pose {
            None => "goal".to_owned(),
            Some(value) => match value.extract::<String>() {
                Ok(text) => text,
                Err(_) => joined(&numbers_of("pose", value)?),
            },
        };
        let position_tolerance = match position_tolerance {
            None => None,
            Some(value) => Some(match value.extract::<f64>() {
                Ok(radius) => radius.to_string(),
                Err(_) => joined(&numbers_of("position_tolerance", value)?),
            }),
        };
        let spec = PoseGoalSpec {
            link,
            pose,
            tool: tool.map(|t| joined(&t)),
            position_tolerance,
            orientation_tolerance,
            ik_goals,
            ik_initial_goals,
        };
        // Refused now rather than at the first solve: an unknown link, a bad quaternion.
        spec.source(arm, 0)?;
        Ok(Self {
            pose_goal: Some(spec),
            ..self.clone()
        })
    }

    /// The problem's identifier (`dividing-walls-R4`, `box_panda-R7-3`, …).
    #[getter]
    fn id(&self) -> &str {
        &self.id
    }

    /// The problem's name.
    #[getter]
    fn name(&self) -> String {
        match &self.problem {
            InstanceProblem::Boxes(p) => p.name().to_owned(),
            InstanceProblem::Arm(p) => p.name().to_owned(),
        }
    }

    /// The dimension of the configuration space.
    #[getter]
    fn dimension(&self) -> usize {
        self.problem.dimension()
    }

    /// The start state, shape (d,).
    #[getter]
    fn start<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.problem.start())
    }

    /// The goal states, shape (k, d).
    #[getter]
    fn goals<'py>(&self, py: Python<'py>) -> BindingResult<Bound<'py, PyArray2<f64>>> {
        PyArray2::from_vec2(py, self.problem.goals())
            .map_err(|e| BindingError::Value(e.to_string()))
    }

    /// The space's bounds `(lower, upper)`, each of shape (d,).
    #[getter]
    fn bounds<'py>(
        &self,
        py: Python<'py>,
    ) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
        let (lower, upper) = self.bounds_of();
        (
            PyArray1::from_slice(py, lower),
            PyArray1::from_slice(py, upper),
        )
    }

    /// The collision-check resolution (a fraction of the space's maximum extent).
    #[getter]
    fn resolution(&self) -> f64 {
        self.problem.resolution()
    }

    /// The collision-check step in the space's units.
    #[getter]
    fn step(&self) -> f64 {
        self.problem.step()
    }

    /// The known optimal cost (PDT families with a closed form), else `None`.
    #[getter]
    fn optimum(&self) -> Option<f64> {
        self.problem.optimum()
    }

    /// `True` for a robot-arm problem (MotionBenchMaker), `False` for a box world.
    #[getter]
    fn is_arm(&self) -> bool {
        self.problem.as_arm().is_some()
    }

    /// Whether `state` is valid for the problem's built-in checker (the box world, or the arm
    /// among the scene's obstacles).
    fn is_valid(&self, state: &Bound<'_, PyAny>) -> BindingResult<bool> {
        let state = vector("state", state)?;
        let state = state
            .as_slice()
            .map_err(|e| BindingError::Value(e.to_string()))?;
        if state.len() != self.problem.dimension() {
            return Err(BindingError::Value(format!(
                "state has {} coordinates; the problem has {}",
                state.len(),
                self.problem.dimension()
            )));
        }
        Ok(match &self.problem {
            InstanceProblem::Boxes(p) => p.validity().is_valid(state),
            InstanceProblem::Arm(p) => p.validity().is_valid(state),
        })
    }

    /// The problem as a TOML problem file (box worlds), or a description (arms).
    fn describe(&self) -> String {
        self.problem.describe()
    }

    fn __repr__(&self) -> String {
        format!(
            "Problem({:?}, dimension={}, resolution={})",
            self.id,
            self.problem.dimension(),
            self.problem.resolution()
        )
    }
}

/// The points of an (N, 3) array (`float32` and `float64` read in place, anything else
/// numpy can convert to `float64` converted first), under the file readers' rules (NaN rows
/// dropped, at most `mit_star_robot::MAX_CLOUD_POINTS`).
fn cloud_points(array: &Bound<'_, PyAny>) -> BindingResult<mit_star_robot::InputCloud> {
    if let Ok(a) = array.extract::<PyReadonlyArray2<'_, f32>>() {
        return points_of(&a.as_array());
    }
    if let Ok(a) = array.extract::<PyReadonlyArray2<'_, f64>>() {
        return points_of(&a.as_array());
    }
    // Lists, integer arrays, …: converted by numpy (its own error if it cannot).
    let converted = array
        .py()
        .import("numpy")?
        .call_method1("asarray", (array, "float64"))?;
    let a = converted
        .extract::<PyReadonlyArray2<'_, f64>>()
        .map_err(|_| BindingError::Value("cloud: give an (N, 3) array of numbers".into()))?;
    points_of(&a.as_array())
}

fn points_of<T: Copy + Into<f64>>(
    a: &ArrayView2<'_, T>,
) -> BindingResult<mit_star_robot::InputCloud> {
    if a.ncols() != 3 {
        return Err(BindingError::Value(format!(
            "cloud: an (N, 3) array, not ({}, {})",
            a.nrows(),
            a.ncols()
        )));
    }
    match a.as_slice() {
        Some(xyz) => mit_star_robot::InputCloud::from_xyz("cloud", xyz),
        None => {
            mit_star_robot::InputCloud::from_xyz("cloud", &a.iter().copied().collect::<Vec<T>>())
        }
    }
    .map_err(|e| BindingError::Value(e.to_string()))
}

/// Numbers from a sequence or array (`pose`, `position_tolerance`).
fn numbers_of(name: &str, value: &Bound<'_, PyAny>) -> BindingResult<Vec<f64>> {
    value.extract::<Vec<f64>>().map_err(|_| {
        BindingError::Type(format!(
            "{name} must be a sequence of numbers, not {}",
            value
                .get_type()
                .name()
                .map_or_else(|_| "an unknown type".to_owned(), |n| n.to_string())
        ))
    })
}

/// Numbers as the command line writes them: `0.5,0,0.4`.
fn joined(values: &[f64]) -> String {
    values
        .iter()
        .map(f64::to_string)
        .collect::<Vec<_>>()
        .join(",")
}

/// The `padding` argument as a [`mit_star_robot::Padding`] (`None`: none given).
///
/// # Errors
/// `ValueError` naming `padding` for a value that is not a number, negative or above 1 m.
fn padding_of(padding: Option<f64>) -> BindingResult<Option<mit_star_robot::Padding>> {
    padding
        .map(|p| {
            mit_star_robot::Padding::new(p)
                .map_err(|e| BindingError::Value(format!("padding: {e}")))
        })
        .transpose()
}
