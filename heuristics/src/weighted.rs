//! [`Weighted`]: inflates a heuristic's cost-to-go (weighted A*).

use mit_star_spaces::StateSpace;

use crate::Heuristic;

/// Multiplies the cost-to-go of an inner heuristic by `weight ≥ 1` (weighted A*): greedier, and
/// inadmissible by at most that factor. Edge-cost and cost-to-come bounds stay admissible, so
/// pruning and informed sampling remain exact. Remove the wrapper and the heuristic is admissible
/// again.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weighted<H> {
    inner: H,
    weight: f64,
}

impl<H> Weighted<H> {
    /// Wraps `inner` with `weight`; `None` unless `weight` is finite and at least 1.
    pub fn new(inner: H, weight: f64) -> Option<Self> {
        (weight.is_finite() && weight >= 1.0).then_some(Self { inner, weight })
    }

    /// The inflation factor.
    pub fn weight(&self) -> f64 {
        self.weight
    }
}

impl<S: StateSpace + ?Sized, H: Heuristic<S>> Heuristic<S> for Weighted<H> {
    fn edge_cost(&self, space: &S, a: &[f64], b: &[f64]) -> f64 {
        self.inner.edge_cost(space, a, b)
    }
    fn edge_cost_given_distance(&self, space: &S, a: &[f64], b: &[f64], distance: f64) -> f64 {
        self.inner.edge_cost_given_distance(space, a, b, distance)
    }
    fn cost_to_come(&self, space: &S, start: &[f64], x: &[f64]) -> f64 {
        self.inner.cost_to_come(space, start, x)
    }
    fn cost_to_go(&self, space: &S, x: &[f64], goals: &[Vec<f64>]) -> f64 {
        self.weight * self.inner.cost_to_go(space, x, goals)
    }
    fn effort(&self, space: &S, a: &[f64], b: &[f64], step: f64) -> u64 {
        self.inner.effort(space, a, b, step)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Euclidean;
    use mit_star_spaces::RealVectorSpace;

    #[test]
    fn inflates_only_cost_to_go() {
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let h = Weighted::new(Euclidean, 2.0).unwrap();
        let (a, b) = ([0.0, 0.0], [0.3, 0.4]);
        assert!((h.edge_cost(&space, &a, &b) - 0.5).abs() < 1e-12);
        assert!((h.cost_to_go(&space, &a, &[b.to_vec()]) - 1.0).abs() < 1e-12);
        assert!(Weighted::new(Euclidean, 0.5).is_none());
        assert!(Weighted::new(Euclidean, f64::NAN).is_none());
    }
}
