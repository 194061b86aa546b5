//! Shared plumbing of the problem families: the unit-cube world, walls and slots across it,
//! parameter checks, and points on the x-axis.

use mit_star_validity::{AxisBox, World};

use crate::ProblemError;

/// Every family lives in `[-HALF, HALF]^n`.
pub(crate) const HALF: f64 = 0.5;

/// A width spanning the bounds ("full extent"): the side of the unit cube. Membership is closed
/// (with an epsilon), so a box of this width centred at 0 covers the bounds exactly.
pub(crate) const FULL: f64 = 2.0 * HALF;

/// Refuses dimensions below 2 (every family uses the coordinates `x` and `y`).
pub(crate) fn check_dimension(problem: &'static str, n: usize) -> Result<(), ProblemError> {
    if n < 2 {
        return Err(ProblemError::Dimension { problem, n });
    }
    Ok(())
}

/// The empty world `[-0.5, 0.5]^n`.
pub(crate) fn unit_world(n: usize) -> World {
    World::new(vec![-HALF; n], vec![HALF; n])
}

/// The box centred at `(x, y, 0, …, 0)` in `R^n`, `x_width` wide in `x`, `y_width` in `y` and
/// `rest_width` in every other coordinate: a wall across the x-axis, or a slot through one.
pub(crate) fn xy_box(
    n: usize,
    (x, x_width): (f64, f64),
    (y, y_width): (f64, f64),
    rest_width: f64,
) -> AxisBox {
    let mut center = vec![0.0; n];
    center[0] = x;
    center[1] = y;
    let mut widths = vec![rest_width; n];
    widths[0] = x_width;
    widths[1] = y_width;
    AxisBox::new(center, widths)
}

/// The point `(x, 0, …, 0)` in `R^n`.
pub(crate) fn axis_point(n: usize, x: f64) -> Vec<f64> {
    let mut point = vec![0.0; n];
    if let Some(first) = point.first_mut() {
        *first = x;
    }
    point
}

/// `true` if every coordinate but the first is zero.
pub(crate) fn on_axis(point: &[f64]) -> bool {
    point.iter().skip(1).all(|&v| v == 0.0)
}

/// Checks that a parameter is finite.
pub(crate) fn check_finite(
    problem: &'static str,
    parameter: &'static str,
    value: f64,
) -> Result<(), ProblemError> {
    if !value.is_finite() {
        return Err(ProblemError::Parameter {
            problem,
            parameter,
            reason: format!("is {value}; it must be finite"),
        });
    }
    Ok(())
}

/// Checks that a parameter is finite and positive.
pub(crate) fn check_positive(
    problem: &'static str,
    parameter: &'static str,
    value: f64,
) -> Result<(), ProblemError> {
    if !(value.is_finite() && value > 0.0) {
        return Err(ProblemError::Parameter {
            problem,
            parameter,
            reason: format!("is {value}; it must be finite and positive"),
        });
    }
    Ok(())
}

/// Checks that a point parameter has `n` finite coordinates (bounds and collisions are checked
/// by [`Problem::new`](crate::Problem::new)).
pub(crate) fn check_point(
    problem: &'static str,
    parameter: &'static str,
    point: &[f64],
    n: usize,
) -> Result<(), ProblemError> {
    if point.len() != n {
        return Err(ProblemError::Parameter {
            problem,
            parameter,
            reason: format!(
                "has {} coordinates; the problem has {n} dimensions",
                point.len()
            ),
        });
    }
    if let Some((index, value)) = point.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(ProblemError::Parameter {
            problem,
            parameter,
            reason: format!("has coordinate {index} = {value}; it must be finite"),
        });
    }
    Ok(())
}

/// The checks every family starts its build with: `n ≥ 2`, and start and goal with `n` finite
/// coordinates each.
pub(crate) fn check_endpoints(
    problem: &'static str,
    n: usize,
    start: &[f64],
    goal: &[f64],
) -> Result<(), ProblemError> {
    check_dimension(problem, n)?;
    check_point(problem, "start", start, n)?;
    check_point(problem, "goal", goal, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_name_the_parameter() {
        assert!(check_dimension("x", 2).is_ok());
        assert_eq!(
            check_dimension("flanking-gap", 1).unwrap_err().to_string(),
            "flanking-gap needs at least 2 dimensions, got 1"
        );
        assert_eq!(
            check_positive("wall-gap", "thickness", -0.1)
                .unwrap_err()
                .to_string(),
            "wall-gap: `thickness` is -0.1; it must be finite and positive"
        );
        assert!(check_positive("p", "q", 0.0).is_err());
        assert!(check_finite("p", "q", f64::NAN).is_err());
        assert!(check_finite("p", "q", -3.0).is_ok());
        assert_eq!(
            check_point("p", "start", &[0.0, f64::INFINITY], 2)
                .unwrap_err()
                .to_string(),
            "p: `start` has coordinate 1 = inf; it must be finite"
        );
        assert!(check_point("p", "start", &[0.0; 3], 2).is_err());
    }

    #[test]
    fn axis_points() {
        assert_eq!(axis_point(3, -0.2), vec![-0.2, 0.0, 0.0]);
        assert!(on_axis(&axis_point(4, 0.3)));
        assert!(!on_axis(&[0.0, 0.1]));
    }
}
