//! [`PathValidation`]: an independent, full-resolution check of a returned path.

use problems::Problem;
use serde::{Deserialize, Serialize};
use spaces::euclidean_distance;
use validity::StateValidity;

/// The result of re-checking a path independently of the planner: the path must start at the
/// start, end at a goal, and every state along it — each segment interpolated at a step no
/// larger than the problem's collision-check step — must be valid in the world (bounds
/// included). Its length must match the cost the planner reported.
///
/// ```
/// let problem = problems::builtin("obstacle-free", 2, 0)?;
/// let path = vec![problem.start().to_vec(), problem.goals()[0].clone()];
/// let v = mit_star_benches::PathValidation::check(&problem, &path, problem.straight_line_cost());
/// assert!(v.valid, "{:?}", v.failure);
/// assert!(v.states_checked > 1000);
/// # Ok::<(), problems::ProblemError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathValidation {
    /// `true` if every check passed.
    pub valid: bool,
    /// States tested with the world's validity check.
    pub states_checked: u64,
    /// The path's length, recomputed.
    pub length: f64,
    /// What failed first, if anything.
    pub failure: Option<String>,
}

impl PathValidation {
    /// Checks `path` (states, start first) against `problem`, and its length against
    /// `reported_cost`.
    pub fn check(problem: &Problem, path: &[Vec<f64>], reported_cost: f64) -> Self {
        let world = problem.world();
        let step = problem.step();
        let mut checked = 0_u64;
        let mut length = 0.0;
        let fail = |checked: u64, length: f64, why: String| Self {
            valid: false,
            states_checked: checked,
            length,
            failure: Some(why),
        };
        let close = |a: &[f64], b: &[f64]| a.len() == b.len() && euclidean_distance(a, b) <= 1e-9;
        let (Some(first), Some(last)) = (path.first(), path.last()) else {
            return fail(0, 0.0, "the path is empty".into());
        };
        if !close(first, problem.start()) {
            return fail(
                0,
                0.0,
                format!("the path starts at {first:?}, not at the start"),
            );
        }
        if !problem.goals().iter().any(|g| close(last, g)) {
            return fail(0, 0.0, format!("the path ends at {last:?}, not at a goal"));
        }
        let n = problem.dimension();
        let mut point = vec![0.0; n];
        for (i, state) in path.iter().enumerate() {
            if state.len() != n || state.iter().any(|x| !x.is_finite()) {
                return fail(
                    checked,
                    length,
                    format!("state {i} is malformed: {state:?}"),
                );
            }
            checked += 1;
            if !world.is_valid(state) {
                return fail(checked, length, format!("state {i} {state:?} is invalid"));
            }
            if i == 0 {
                continue;
            }
            let a = &path[i - 1];
            let d = euclidean_distance(a, state);
            length += d;
            let segments = (d / step).ceil().max(1.0) as u64;
            for k in 1..segments {
                let t = k as f64 / segments as f64;
                for (p, (x, y)) in point.iter_mut().zip(a.iter().zip(state)) {
                    *p = x + t * (y - x);
                }
                checked += 1;
                if !world.is_valid(&point) {
                    return fail(
                        checked,
                        length,
                        format!("segment {} → {i} collides at {point:?}", i - 1),
                    );
                }
            }
        }
        if (length - reported_cost).abs() > 1e-9 * reported_cost.abs().max(1.0) {
            return fail(
                checked,
                length,
                format!(
                    "the path's length {length} differs from the reported cost {reported_cost}"
                ),
            );
        }
        Self {
            valid: true,
            states_checked: checked,
            length,
            failure: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wall() -> Problem {
        // A wall at x = 0 spanning the bounds except y > 0.3.
        problems::builtin("wall-gap", 2, 0).unwrap()
    }

    #[test]
    fn a_path_through_a_wall_fails() {
        let p = wall();
        let path = vec![p.start().to_vec(), p.goals()[0].clone()];
        let v = PathValidation::check(&p, &path, p.straight_line_cost());
        assert!(!v.valid);
        assert!(v.failure.as_deref().unwrap().contains("collides"), "{v:?}");
    }

    #[test]
    fn wrong_ends_and_costs_fail() {
        let p = problems::builtin("obstacle-free", 2, 0).unwrap();
        let (s, g) = (p.start().to_vec(), p.goals()[0].clone());
        let v = PathValidation::check(&p, &[g.clone(), s.clone()], 0.8);
        assert!(v.failure.unwrap().contains("starts at"));
        let v = PathValidation::check(&p, &[s.clone(), s.clone()], 0.0);
        assert!(v.failure.unwrap().contains("not at a goal"));
        let v = PathValidation::check(&p, &[s.clone(), g.clone()], 0.5);
        assert!(
            v.failure
                .unwrap()
                .contains("differs from the reported cost")
        );
        let v = PathValidation::check(&p, &[s, vec![0.0, 0.9], g], 2.0);
        assert!(
            v.failure.unwrap().contains("invalid"),
            "out of bounds is invalid"
        );
        assert!(!PathValidation::check(&p, &[], 0.0).valid);
    }

    #[test]
    fn the_step_is_at_most_the_problems() {
        let p = problems::builtin("obstacle-free", 2, 0).unwrap();
        let path = vec![p.start().to_vec(), p.goals()[0].clone()];
        let v = PathValidation::check(&p, &path, p.straight_line_cost());
        let needed = (p.straight_line_cost() / p.step()).ceil() as u64 + 1;
        assert!(v.valid && v.states_checked >= needed, "{v:?}");
    }
}
