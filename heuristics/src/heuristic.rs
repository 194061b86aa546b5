//! The [`Heuristic`] trait.

use mit_star_spaces::StateSpace;

/// Admissible estimates for a path-length objective, and effort estimates, used to order a
/// planner's searches.
///
/// Cost estimates must never exceed the true cost of the cheapest obstacle-free path
/// (admissibility), or the planners' optimality guarantees are lost. Effort estimates count
/// state-validity checks (grid points of the canonical edge grid); they steer the search and
/// need not be admissible.
///
/// Object safe for a fixed space: `Box<dyn Heuristic<JointSpace>>` works.
pub trait Heuristic<S: StateSpace + ?Sized> {
    /// Lower bound `ĉ(a, b)` on the cost of any path from `a` to `b`.
    fn edge_cost(&self, space: &S, a: &[f64], b: &[f64]) -> f64;

    /// `ĉ(a, b)` when the space's distance between them, `distance = space.distance(a, b)`, is
    /// already known: where the bound is that distance (a Euclidean bound in a Euclidean space,
    /// the space's own metric), it is returned without measuring again. The default measures.
    #[inline]
    fn edge_cost_given_distance(&self, space: &S, a: &[f64], b: &[f64], distance: f64) -> f64 {
        let _ = distance;
        self.edge_cost(space, a, b)
    }

    /// Lower bound on the cost to come from `start` to `x`.
    fn cost_to_come(&self, space: &S, start: &[f64], x: &[f64]) -> f64 {
        self.edge_cost(space, start, x)
    }

    /// Lower bound on the cost to go from `x` to the nearest of `goals` (∞ if there is none).
    fn cost_to_go(&self, space: &S, x: &[f64], goals: &[Vec<f64>]) -> f64 {
        goals
            .iter()
            .map(|g| self.edge_cost(space, x, g))
            .fold(f64::INFINITY, f64::min)
    }

    /// Estimated number of state checks needed to validate a path from `a` to `b` at step
    /// `step`: the interior points of the straight edge's canonical grid, `⌈d / L⌉ − 1`.
    fn effort(&self, space: &S, a: &[f64], b: &[f64], step: f64) -> u64 {
        grid_points(space.distance(a, b), step)
    }
}

/// Interior points of the canonical grid of an edge of `length` at `step` (spec §2): the state
/// checks a full check of that edge performs. The grid is [`mit_star_validity::EdgeGrid`], the one every
/// edge checker walks.
#[inline]
pub fn grid_points(length: f64, step: f64) -> u64 {
    mit_star_validity::EdgeGrid::new(length, step).points()
}

impl<S: StateSpace + ?Sized, H: Heuristic<S> + ?Sized> Heuristic<S> for &H {
    fn edge_cost(&self, space: &S, a: &[f64], b: &[f64]) -> f64 {
        (**self).edge_cost(space, a, b)
    }
    fn edge_cost_given_distance(&self, space: &S, a: &[f64], b: &[f64], distance: f64) -> f64 {
        (**self).edge_cost_given_distance(space, a, b, distance)
    }
    fn cost_to_come(&self, space: &S, start: &[f64], x: &[f64]) -> f64 {
        (**self).cost_to_come(space, start, x)
    }
    fn cost_to_go(&self, space: &S, x: &[f64], goals: &[Vec<f64>]) -> f64 {
        (**self).cost_to_go(space, x, goals)
    }
    fn effort(&self, space: &S, a: &[f64], b: &[f64], step: f64) -> u64 {
        (**self).effort(space, a, b, step)
    }
}
