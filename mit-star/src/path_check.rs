//! [`check_path`]: judge a path produced anywhere by the rules the planners' own paths pass.

use mit_star_problems::PlanningProblem;
use mit_star_spaces::{Never, StateSpace};
use mit_star_validity::{DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::BuildError;

/// What [`check_path`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct PathVerdict {
    /// Every state lies in the space's bounds and is valid, and every edge passed the check on
    /// the problem's grid and its certification.
    pub valid: bool,
    /// The first state out of bounds or in collision.
    pub invalid_state: Option<usize>,
    /// The first edge (`i`: from state `i` to `i + 1`) that failed the grid check or the
    /// certification.
    pub invalid_edge: Option<usize>,
    /// Edges that failed.
    pub invalid_edges: usize,
    /// The path's first state is the problem's start and its last one of its goals, each within
    /// `tolerance` in every coordinate.
    pub joins_query: bool,
    /// The path's length in the problem's space.
    pub cost: f64,
}

/// [`BuildError::BadPath`] unless `path` has at least two states, each of the space's dimension
/// and finite.
pub(crate) fn check_states<S: StateSpace>(space: &S, path: &[Vec<f64>]) -> Result<(), BuildError> {
    let dimension = space.dimension();
    let bad = path
        .iter()
        .position(|s| s.len() != dimension || s.iter().any(|x| !x.is_finite()));
    if path.len() < 2 || bad.is_some() {
        return Err(BuildError::BadPath {
            states: path.len(),
            state: bad.unwrap_or(path.len()),
            dimension,
        });
    }
    Ok(())
}

/// Moves the first state of `path` onto the problem's start and the last onto the goal it is
/// nearest to, if they are within `tolerance` per coordinate (a path from a planner that
/// computes in `f32`); `false` (and `path` unchanged) if they are not, or the path is empty.
pub fn snap_ends<P: PlanningProblem>(problem: &P, path: &mut [Vec<f64>], tolerance: f64) -> bool {
    let close = |a: &[f64], b: &[f64]| {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tolerance)
    };
    let Some(last) = path.len().checked_sub(1) else {
        return false;
    };
    let Some(goal) = problem.goals().iter().find(|g| close(&path[last], g)) else {
        return false;
    };
    if !close(&path[0], problem.start()) {
        return false;
    }
    path[0].copy_from_slice(problem.start());
    path[last].copy_from_slice(goal);
    true
}

/// Checks `path` against `problem` as a planner's solution is checked: every state in bounds
/// and valid, every edge valid at every point of the problem's check grid and then on the grid
/// [`certification`](PlanningProblem::certification) times finer, and the ends at the start
/// and a goal (within `tolerance` per coordinate: paths from planners that compute in `f32`
/// differ in the last digits). Use it to judge another planner's paths by the same rules as
/// ours (`mit-star check-path`).
///
/// # Errors
/// [`BuildError::Problem`] if the problem refuses its check step; [`BuildError::BadPath`] for
/// fewer than two states, or a state of the wrong dimension or not finite.
///
/// ```
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let (start, goal) = (problem.start().to_vec(), problem.goals()[0].clone());
/// // Straight through the walls.
/// let verdict = mit_star::check_path(&problem, &[start, goal], 1e-9)?;
/// assert!(verdict.joins_query && !verdict.valid);
/// assert_eq!(verdict.invalid_edge, Some(0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check_path<P: PlanningProblem>(
    problem: &P,
    path: &[Vec<f64>],
    tolerance: f64,
) -> Result<PathVerdict, BuildError> {
    let space = problem.space();
    let validity = problem.validity();
    check_states(space, path)?;
    let mut checker = DenseChecker::new(problem.check_step()?)?;
    let certification = problem.certification();
    let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tolerance);
    let last = &path[path.len() - 1];
    let joins_query =
        close(&path[0], problem.start()) && problem.goals().iter().any(|g| close(last, g));
    let invalid_state = path
        .iter()
        .position(|x| space.check_state(x).is_err() || !validity.is_valid(x));
    let mut invalid_edges = 0;
    let mut invalid_edge = None;
    for (i, w) in path.windows(2).enumerate() {
        let (a, b) = (&w[0], &w[1]);
        let mut progress = EdgeProgress::UNTESTED;
        let full = checker.check_full(space, validity, a, b, &mut progress, &Never);
        let passed = full == EdgeStatus::Valid
            && (certification <= 1
                || checker.certify(space, validity, a, b, certification, &Never)
                    == EdgeStatus::Valid);
        if !passed {
            invalid_edges += 1;
            invalid_edge.get_or_insert(i);
        }
    }
    let cost = path.windows(2).map(|w| space.distance(&w[0], &w[1])).sum();
    Ok(PathVerdict {
        valid: invalid_state.is_none() && invalid_edges == 0,
        invalid_state,
        invalid_edge,
        invalid_edges,
        joins_query,
        cost,
    })
}
