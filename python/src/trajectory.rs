//! `mit_star.time_parameterise`: a planned arm path timed under the robot's velocity and
//! acceleration limits, returned as numpy arrays.

use std::path::PathBuf;

use mit_star_benches::commands::{Corners, LimitArgs};
use mit_star_robot::TrajectoryFile;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{BindingError, BindingResult};
use crate::problem::PyProblem;

/// Times `path` (shape (n, d), or a list of states; repeated states merged) for the arm of
/// `problem` and returns a dict of numpy arrays: `time` (m,), `position`, `velocity`,
/// `acceleration` (m, d), with `joints` (the coordinates' joint names), `duration` and
/// `corners` (`(blended, blended after shrinking, stops)`, `None` with `corners="stop"`).
///
/// `corners="blend"` (default) passes corners on parabolic blends, each certified
/// collision-free along its motion (shrunk, or a stop, where it cannot be); `"stop"` stops at
/// every waypoint, every configuration on the planned segments. Limits: the URDF's
/// velocities, or a MoveIt `joint_limits` YAML's, which also gives accelerations;
/// `max_acceleration` one acceleration limit for every joint; the scaling factors in (0, 1]
/// as MoveIt's. The samples are the knots, or every `sample_period` seconds (and the end).
///
/// Raises `ValueError` for a box world, a missing or bad limit (naming the joint), a path of
/// fewer than two distinct states, of the wrong width or not finite.
#[pyfunction]
#[pyo3(signature = (problem, path, *, corners="blend", joint_limits=None, max_acceleration=None, velocity_scaling=1.0, acceleration_scaling=1.0, sample_period=None))]
#[allow(clippy::too_many_arguments, clippy::needless_pass_by_value)]
pub(crate) fn time_parameterise<'py>(
    py: Python<'py>,
    problem: PyRef<'_, PyProblem>,
    path: &Bound<'_, PyAny>,
    corners: &str,
    joint_limits: Option<PathBuf>,
    max_acceleration: Option<f64>,
    velocity_scaling: f64,
    acceleration_scaling: f64,
    sample_period: Option<f64>,
) -> BindingResult<Bound<'py, PyDict>> {
    let corners = match corners {
        "blend" => Corners::Blend,
        "stop" => Corners::Stop,
        other => {
            return Err(BindingError::Value(format!(
                "corners must be \"blend\" or \"stop\", not {other:?}"
            )));
        }
    };
    let Some(arm) = problem.problem.as_arm() else {
        return Err(BindingError::Value(
            "time parameterisation is for arm problems (joints with velocity and acceleration limits)"
                .into(),
        ));
    };
    let path: Vec<Vec<f64>> = path.extract().map_err(|_| {
        BindingError::Type("path must be an (n, d) array or a list of states".into())
    })?;
    if let Some(period) = sample_period
        && !(period > 0.0 && period.is_finite())
    {
        return Err(BindingError::Value(format!(
            "sample_period must be a positive number of seconds, not {period}"
        )));
    }
    let limits = LimitArgs {
        joint_limits,
        max_acceleration,
        velocity_scaling,
        acceleration_scaling,
    }
    .limits(arm)?;
    let value = |e: mit_star_robot::TrajectoryError| BindingError::Value(e.to_string());
    let (trajectory, report) = py
        .detach(|| corners.time(arm, &limits, &path))
        .map_err(value)?;
    let file = TrajectoryFile::of(&trajectory, sample_period).map_err(value)?;
    let matrix = |rows: Vec<Vec<f64>>| {
        PyArray2::from_vec2(py, &rows).map_err(|e| BindingError::Value(e.to_string()))
    };
    let out = PyDict::new(py);
    out.set_item("joints", file.joints.clone())?;
    out.set_item(
        "time",
        PyArray1::from_vec(py, file.samples.iter().map(|s| s.time).collect()),
    )?;
    out.set_item(
        "position",
        matrix(file.samples.iter().map(|s| s.position.clone()).collect())?,
    )?;
    out.set_item(
        "velocity",
        matrix(file.samples.iter().map(|s| s.velocity.clone()).collect())?,
    )?;
    out.set_item(
        "acceleration",
        matrix(
            file.samples
                .iter()
                .map(|s| s.acceleration.clone())
                .collect(),
        )?,
    )?;
    out.set_item("duration", trajectory.duration())?;
    out.set_item("corners", report.map(|r| (r.blended, r.shrunk, r.stopped)))?;
    Ok(out)
}
