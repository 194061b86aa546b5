//! [`box_world`]: a box-world [`Problem`] from numpy arrays (bounds, start, goals, obstacle
//! and anti-obstacle centres and widths).

use mit_star_problems::Problem;
use mit_star_validity::{AxisBox, World};
use numpy::ndarray::{ArrayView1, ArrayView2};
use pyo3::prelude::*;

use crate::error::{BindingError, BindingResult};

/// Box centres and widths, each (m, d), if given.
pub(crate) type Boxes<'a> = (Option<ArrayView2<'a, f64>>, Option<ArrayView2<'a, f64>>);

/// The problem `name` in the box `lower`–`upper` from `start` to `goal` (one state of shape
/// (d,) or several of shape (k, d)), among the `obstacles` with the `anti_obstacles` carved out.
///
/// # Errors
/// [`BindingError::Value`] for arrays of mismatched shapes, [`BindingError::Type`] for a goal
/// that is not an array of floats, and the world's and problem's own refusals (bounds, a start
/// or goal out of bounds or in collision).
pub(crate) fn box_world(
    name: &str,
    (lower, upper): (ArrayView1<'_, f64>, ArrayView1<'_, f64>),
    (start, goal): (ArrayView1<'_, f64>, &Bound<'_, PyAny>),
    obstacles: Boxes<'_>,
    anti_obstacles: Boxes<'_>,
) -> BindingResult<Problem> {
    let d = lower.len();
    if upper.len() != d || start.len() != d {
        return Err(BindingError::Value(format!(
            "lower, upper and start must have the same length (got {}, {}, {})",
            d,
            upper.len(),
            start.len()
        )));
    }
    let goals = goal_states(goal, d)?;
    let mut world = World::new(lower.to_vec(), upper.to_vec());
    for axis_box in boxes("centers", "widths", obstacles, d)? {
        world.add_obstacle(axis_box)?;
    }
    for axis_box in boxes("free_centers", "free_widths", anti_obstacles, d)? {
        world.add_anti_obstacle(axis_box)?;
    }
    Ok(Problem::new(name, world, start.to_vec(), goals)?)
}

/// One goal of shape (d,) or several of shape (k, d) (lists and integer arrays converted).
fn goal_states(goal: &Bound<'_, PyAny>, d: usize) -> BindingResult<Vec<Vec<f64>>> {
    let goals: Vec<Vec<f64>> = if let Ok(one) = crate::arrays::vector("goal", goal) {
        vec![one.as_array().to_vec()]
    } else {
        crate::arrays::matrix("goal", goal)
            .map_err(|_| {
                BindingError::Type(
                    "goal must be an array of numbers of shape (d,) or (k, d)".into(),
                )
            })?
            .as_array()
            .rows()
            .into_iter()
            .map(|r| r.to_vec())
            .collect()
    };
    if let Some(bad) = goals.iter().find(|g| g.len() != d) {
        return Err(BindingError::Value(format!(
            "a goal has {} coordinates; the bounds have {d}",
            bad.len()
        )));
    }
    Ok(goals)
}

/// The boxes of `centers` and `widths` (both or neither, each (m, d)).
fn boxes(
    centers_name: &str,
    widths_name: &str,
    (centers, widths): Boxes<'_>,
    d: usize,
) -> BindingResult<Vec<AxisBox>> {
    match (centers, widths) {
        (None, None) => Ok(Vec::new()),
        (Some(c), Some(w)) if c.dim() == w.dim() && c.ncols() == d => Ok(c
            .rows()
            .into_iter()
            .zip(w.rows())
            .map(|(c, w)| AxisBox::new(c.to_vec(), w.to_vec()))
            .collect()),
        (Some(c), Some(w)) => Err(BindingError::Value(format!(
            "{centers_name} {:?} and {widths_name} {:?} must both have shape (m, {d})",
            c.dim(),
            w.dim()
        ))),
        _ => Err(BindingError::Value(format!(
            "give both {centers_name} and {widths_name}, or neither"
        ))),
    }
}
